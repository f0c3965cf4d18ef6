// Body files as numpy (flexmb._core.read_body): the reduced body of a body
// file (io::ReadBody) with its frequencies, reduced matrices, inertia
// invariants, mode shapes, stress modes and mesh.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "flexmb/io/body_file.h"
#include "flexmb/reduction/reduced_body.h"
#include "python/core_bindings.h"

namespace flexmb::python {
namespace py = pybind11;

namespace {

// a copy of an Eigen matrix (column-major) as a C-ordered numpy array
py::array BodiesMatrix(const MatX& a) {
  py::array_t<double> out({static_cast<py::ssize_t>(a.rows()), static_cast<py::ssize_t>(a.cols())});
  auto r = out.mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) r(i, j) = a(i, j);
  return out;
}

py::array BodiesMat3List(const std::vector<Mat3>& list) {
  py::array_t<double> out({static_cast<py::ssize_t>(list.size()), py::ssize_t{3}, py::ssize_t{3}});
  auto r = out.mutable_unchecked<3>();
  for (size_t k = 0; k < list.size(); ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r(k, i, j) = list[k](i, j);
  return out;
}

py::dict BodiesStressTable(const reduction::StressTable& t) {
  py::dict d;
  d["components"] = t.components;
  d["locations"] = t.locations;
  d["elements"] = t.elements;
  d["axes"] = BodiesMat3List(t.axes);
  d["modes"] = BodiesMatrix(t.modes);
  return d;
}

}  // namespace

void BindBodies(py::module_& m) {
  m.def("read_body", [](const std::string& path) {
    reduction::ReducedBody b;
    {
      py::gil_scoped_release release;
      b = io::ReadBody(path);
    }
    py::dict d;
    d["frequencies_hz"] = py::array_t<double>(b.frequencies_hz.size(), b.frequencies_hz.data());
    d["mass"] = BodiesMatrix(b.mass);
    d["stiffness"] = BodiesMatrix(b.stiffness);
    d["damping"] = BodiesMatrix(b.damping);
    d["modes"] = BodiesMatrix(b.modes);
    const int nn = static_cast<int>(b.mesh.nodes.size());
    py::array_t<double> xyz({static_cast<py::ssize_t>(nn), py::ssize_t{3}});
    py::array_t<int> ids(nn);
    for (int k = 0; k < nn; ++k) {
      for (int i = 0; i < 3; ++i) xyz.mutable_at(k, i) = b.mesh.nodes[k].x(i);
      ids.mutable_at(k) = b.mesh.nodes[k].id;
    }
    d["node_ids"] = ids;
    d["nodes"] = xyz;
    py::list elements;
    for (const fe::Element& e : b.mesh.elements)
      elements.append(py::make_tuple(e.id, fe::TypeName(e.type), e.nodes));
    d["elements"] = elements;
    d["interface_nodes"] = b.interface_nodes;
    const reduction::InertiaInvariants& inv = b.invariants;
    py::dict iv;
    iv["n"] = inv.n;
    iv["mvv"] = BodiesMatrix(inv.mvv);
    iv["mvo0"] = BodiesMatrix(inv.mvo0);
    iv["mvo1"] = BodiesMat3List(inv.mvo1);
    iv["mvw"] = BodiesMatrix(inv.mvw);
    iv["moo0"] = BodiesMatrix(inv.moo0);
    iv["moo1"] = BodiesMat3List(inv.moo1);
    iv["mow0"] = BodiesMatrix(inv.mow0);
    iv["mww"] = BodiesMatrix(inv.mww);
    d["invariants"] = iv;
    py::dict stress;
    stress["shell"] = BodiesStressTable(b.stress.shell);
    stress["beam"] = BodiesStressTable(b.stress.beam);
    stress["solid"] = BodiesStressTable(b.stress.solid);
    d["stress"] = stress;
    d["units"] = b.units;
    d["provenance"] = b.provenance;
    d["static_modes"] = b.static_modes;
    d["normal_modes"] = b.normal_modes;
    d["rigid_modes_removed"] = b.rigid_modes_removed;
    return d;
  }, py::arg("path"),
        "Reads a body file (.h5): dict of frequencies_hz, mass/stiffness/damping (n x n), modes (6 rows "
        "per node x n), nodes (N x 3) [m], node_ids, elements (id, type, node indices), "
        "interface_nodes, invariants, stress tables, units, provenance.");
}

}  // namespace flexmb::python
