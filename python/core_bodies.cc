// FE models and body files as numpy: the modes of a full FE model with
// their shapes (flexmb._core.fe_mode_shapes, as `fe modes`), and the reduced
// body of a body file (read_body: io::ReadBody) with its frequencies,
// reduced matrices, inertia invariants, mode shapes, stress modes and mesh.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/fe/modal.h"
#include "flexmb/body_file/body_file.h"
#include "apps/flexmb/commands/command_support.h"
#include "flexmb/fe_io/fe_model_file.h"
#include "flexmb/kinematics/marker.h"
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

// runs f; an error without a file is rethrown naming `path` (as the fe commands do)
template <class F>
auto BodiesInFile(const std::string& path, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    if (!e.context().file.empty()) throw;
    throw InputError(e.message(), {path, 0, e.context().entity});
  } catch (const NumericalError& e) {
    if (!e.context().file.empty()) throw;
    throw NumericalError(e.message(), {path, 0, e.context().entity});
  }
}

}  // namespace

void BindBodies(py::module_& m) {
  m.def("fe_mode_shapes", [](const std::string& path, int count, const std::string& fix, bool lumped,
                             double shift) {
    if (count < 1) throw InputError("count must be at least 1, got " + std::to_string(count));
    fe::FeModel model;
    fe::AssembledModel a;
    fe::ModalResult r;
    {
      py::gil_scoped_release release;
      model = BodiesInFile(path, [&] { return io::LoadFeModel(path); });
      fe::AssemblyOptions ao;
      ao.mass_form = lumped ? fe::MassForm::kLumped : fe::MassForm::kConsistent;
      ao.extra_fixed_nodes = io::command::NodeListOption(model.mesh, fix, path);
      a = BodiesInFile(path, [&] { return fe::BuildMatrices(model, ao); });
      if (a.dofs.n_free == 0)
        throw InputError("the model has no free DOF (all constrained or fixed): nothing to solve", {path, 0, ""});
      fe::ModalOptions mo;
      mo.count = count;
      mo.shift = shift;
      r = BodiesInFile(path, [&] { return fe::SolveModes(a, mo); });
    }
    // u_full = T u_free, then per node its 6 slots (0 where inactive)
    const MatX full = a.T * r.modes;
    const int nn = static_cast<int>(a.dofs.full.size());
    py::array_t<double> shapes({static_cast<py::ssize_t>(nn) * 6, static_cast<py::ssize_t>(full.cols())});
    auto sh = shapes.mutable_unchecked<2>();
    for (int k = 0; k < nn; ++k)
      for (int c = 0; c < 6; ++c) {
        const int row = a.dofs.full[k][c];
        for (Eigen::Index j = 0; j < full.cols(); ++j) sh(6 * k + c, j) = row >= 0 ? full(row, j) : 0.0;
      }
    py::array_t<double> xyz({static_cast<py::ssize_t>(nn), py::ssize_t{3}});
    std::fill(xyz.mutable_data(), xyz.mutable_data() + 3 * nn, 0.0);
    for (int k = 0; k < nn && k < static_cast<int>(model.mesh.nodes.size()); ++k)
      for (int i = 0; i < 3; ++i) xyz.mutable_at(k, i) = model.mesh.nodes[k].x(i);
    py::dict d;
    d["frequencies_hz"] = py::array_t<double>(r.frequencies_hz.size(), r.frequencies_hz.data());
    d["shapes"] = shapes;
    d["nodes"] = xyz;
    d["node_ids"] = a.dofs.node_ids;
    d["dofs"] = a.dofs.n_free;
    return d;
  }, py::arg("model"), py::arg("count") = 10, py::arg("fix") = "", py::arg("lumped") = false,
        py::arg("shift") = 0.0,
        "Modes of a full FE model as `fe modes` solves them, with their shapes: frequencies_hz, shapes (6 rows "
        "per node: ux uy uz rx ry rz, mass-normalized, x count), nodes (N x 3) [m], node_ids, dofs.");

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
    stress["beam_fibre"] = BodiesStressTable(b.stress.beam_fibre);
    stress["solid_node"] = BodiesStressTable(b.stress.solid_node);
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
