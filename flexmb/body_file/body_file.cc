#include "flexmb/body_file/body_file.h"

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/body_file/body_file_mesh.h"
#include "flexmb/body_file/hdf5_file.h"

#ifndef FLEXMB_VERSION
#define FLEXMB_VERSION "unknown"
#endif

namespace flexmb::io {

namespace {

using hdf5::Blocks;
using hdf5::Dims;
using hdf5::DimsText;
using hdf5::RowMat;
using hdf5::Size;
using reduction::InertiaInvariants;
using reduction::Mat3;
using reduction::MatX;
using reduction::ReducedBody;
using reduction::StressModes;
using reduction::StressTable;

// the stress tables with their groups in the file
std::vector<std::pair<std::string, const StressTable*>> StressTables(const StressModes& s) {
  return {{"/stress/shell", &s.shell},
          {"/stress/beam", &s.beam},
          {"/stress/solid", &s.solid},
          {"/stress/beam_fibre", &s.beam_fibre},
          {"/stress/solid_node", &s.solid_node}};
}

// the body is consistent (shapes, finite values) before anything is written
void CheckBody(const ReducedBody& b, const std::string& path) {
  const Eigen::Index n = b.modes.cols();
  const Eigen::Index nn = static_cast<Eigen::Index>(b.mesh.nodes.size());
  auto fail = [&](const std::string& field, const std::string& message) {
    throw InputError("cannot write the body: " + message, {path, 0, field});
  };
  auto shape = [&](const std::string& field, const MatX& m, Eigen::Index rows, Eigen::Index cols) {
    if (m.rows() != rows || m.cols() != cols) {
      fail(field, "is " + std::to_string(m.rows()) + " x " + std::to_string(m.cols()) + ", expected " +
                      std::to_string(rows) + " x " + std::to_string(cols) + " (" + std::to_string(nn) + " nodes, " +
                      std::to_string(n) + " modes)");
    }
  };
  auto finite = [&](const std::string& field, const double* p, size_t count) {
    for (size_t k = 0; k < count; ++k) {
      if (!std::isfinite(p[k])) fail(field, "holds a non-finite value at entry " + std::to_string(k));
    }
  };
  auto finite_m = [&](const std::string& field, const MatX& m) { finite(field, m.data(), m.size()); };
  auto finite_v = [&](const std::string& field, const std::vector<Mat3>& v) {
    for (size_t i = 0; i < v.size(); ++i) finite(field + "[" + std::to_string(i) + "]", v[i].data(), 9);
  };

  shape("modes", b.modes, 6 * nn, n);
  if (b.frequencies_hz.size() != n) fail("frequencies_hz", "has " + std::to_string(b.frequencies_hz.size()) +
                                                               " entries for " + std::to_string(n) + " modes");
  shape("mass", b.mass, n, n);
  shape("stiffness", b.stiffness, n, n);
  shape("damping", b.damping, n, n);
  const InertiaInvariants& v = b.invariants;
  if (v.n != n) fail("invariants", "are for " + std::to_string(v.n) + " modes, the body has " + std::to_string(n));
  const size_t un = static_cast<size_t>(n);
  if (v.mvo1.size() != un || v.moo1.size() != un || v.moo2.size() != un * un || v.mow1.size() != un) {
    fail("invariants", "mvo1, moo1, moo2, mow1 have " + std::to_string(v.mvo1.size()) + ", " +
                           std::to_string(v.moo1.size()) + ", " + std::to_string(v.moo2.size()) + ", " +
                           std::to_string(v.mow1.size()) + " entries; expected n, n, n^2, n for n = " +
                           std::to_string(n));
  }
  shape("invariants.mvw", v.mvw, 3, n);
  shape("invariants.mow0", v.mow0, 3, n);
  for (size_t i = 0; i < un; ++i) shape("invariants.mow1[" + std::to_string(i) + "]", v.mow1[i], 3, n);
  shape("invariants.mww", v.mww, n, n);
  for (const auto& [group, t] : StressTables(b.stress)) {
    const std::string field = "stress table '" + t->name + "'";
    const Eigen::Index rows = static_cast<Eigen::Index>(t->elements.size()) * t->Locations() * t->Components();
    // a table never filled (0 x 0) is written as 0 x n
    if (rows != 0 || t->modes.size() != 0) shape(field + " modes", t->modes, rows, n);
    if (t->axes.size() != t->elements.size()) {
      fail(field, "has " + std::to_string(t->axes.size()) + " element axes for " +
                      std::to_string(t->elements.size()) + " elements");
    }
    for (int e : t->elements) {
      if (e < 0 || e >= static_cast<int>(b.mesh.elements.size())) {
        fail(field, "names element index " + std::to_string(e) + ", the mesh has " +
                        std::to_string(b.mesh.elements.size()) + " elements");
      }
    }
    finite_m(field + " modes", t->modes);
    finite_v(field + " axes", t->axes);
  }

  finite_m("modes", b.modes);
  finite("frequencies_hz", b.frequencies_hz.data(), b.frequencies_hz.size());
  finite_m("mass", b.mass);
  finite_m("stiffness", b.stiffness);
  finite_m("damping", b.damping);
  for (const auto& [name, m] : {std::pair<const char*, const Mat3*>{"invariants.mvv", &v.mvv},
                                {"invariants.mvo0", &v.mvo0},
                                {"invariants.moo0", &v.moo0}}) {
    finite(name, m->data(), 9);
  }
  finite_v("invariants.mvo1", v.mvo1);
  finite_v("invariants.moo1", v.moo1);
  finite_v("invariants.moo2", v.moo2);
  finite_m("invariants.mvw", v.mvw);
  finite_m("invariants.mow0", v.mow0);
  for (size_t i = 0; i < un; ++i) finite_m("invariants.mow1[" + std::to_string(i) + "]", v.mow1[i]);
  finite_m("invariants.mww", v.mww);
  for (const fe::Element& e : b.mesh.elements) {
    if (!HasBodyFileTypeCode(e.type)) fail("element " + std::to_string(e.id), "has an unknown element type");
  }
  if (!b.geometric_stiffness.empty() && b.geometric_stiffness.size() != 6) {
    fail("geometric_stiffness", "has " + std::to_string(b.geometric_stiffness.size()) +
                                    " load cases, expected 6 (centrifugal) or none");
  }
  for (size_t c = 0; c < b.geometric_stiffness.size(); ++c) {
    const std::string field = "geometric_stiffness[" + std::to_string(c) + "]";
    shape(field, b.geometric_stiffness[c], n, n);
    finite_m(field, b.geometric_stiffness[c]);
  }
  if (!b.deformation_stiffness.empty() && b.deformation_stiffness.size() != un) {
    fail("deformation_stiffness", "has " + std::to_string(b.deformation_stiffness.size()) +
                                      " matrices, expected one per mode (" + std::to_string(un) + ") or none");
  }
  for (size_t j = 0; j < b.deformation_stiffness.size(); ++j) {
    const std::string field = "deformation_stiffness[" + std::to_string(j) + "]";
    shape(field, b.deformation_stiffness[j], n, n);
    finite_m(field, b.deformation_stiffness[j]);
  }
}

// a non-negative count attribute of /counts
int CountOf(const hdf5::Reader& r, const std::string& name) {
  const int v = r.AttributeInt("/counts", name);
  if (v < 0) r.Fail("attribute " + name + " of /counts", "is negative: " + std::to_string(v));
  return v;
}

// the whole file: root attributes, counts, mesh, interface, modes, reduced
// matrices, invariants, stress tables
void WriteContents(hdf5::Writer& w, const ReducedBody& body) {
  const int n = static_cast<int>(body.modes.cols());
  const int nn = static_cast<int>(body.mesh.nodes.size());
  const hsize_t hn = Size(n), hnn = Size(nn);
  w.AttributeString("/", "format", kBodyFileFormat);
  w.AttributeInt("/", "version", ReducedBody::kFormatVersion);
  w.AttributeString("/", "units", body.units);
  w.AttributeString("/", "writer", std::string("flexmb ") + FLEXMB_VERSION);
  std::vector<std::string> prov;
  for (const auto& [k, v] : body.provenance) {
    prov.push_back(k);
    prov.push_back(v);
  }
  w.AttributeStrings("/", "provenance", prov, {Size(body.provenance.size()), 2});

  w.Group("/counts");
  w.AttributeInt("/counts", "nodes", nn);
  w.AttributeInt("/counts", "elements", static_cast<int>(body.mesh.elements.size()));
  w.AttributeInt("/counts", "modes", n);
  w.AttributeInt("/counts", "static_modes", body.static_modes);
  w.AttributeInt("/counts", "normal_modes", body.normal_modes);
  w.AttributeInt("/counts", "rigid_modes_removed", body.rigid_modes_removed);
  w.AttributeInt("/counts", "interface_nodes", static_cast<int>(body.interface_nodes.size()));

  WriteBodyMesh(w, body.mesh);

  w.Group("/interface");
  w.Ints("/interface/nodes", body.interface_nodes);
  std::vector<int> ids;
  for (int k : body.interface_nodes) ids.push_back(k >= 0 && k < nn ? body.mesh.nodes[k].id : 0);
  w.Ints("/interface/node_ids", ids);

  w.Group("/modes");
  w.Doubles("/modes/shapes", {hn, hnn, 6}, body.modes.data());
  w.Doubles("/modes/frequencies_hz", {hn}, body.frequencies_hz.data());

  w.Group("/reduced");
  w.Matrix("/reduced/mass", body.mass);
  w.Matrix("/reduced/stiffness", body.stiffness);
  w.Matrix("/reduced/damping", body.damping);

  const InertiaInvariants& v = body.invariants;
  w.Group("/invariants");
  w.Doubles("/invariants/mvv", {3, 3}, Blocks({v.mvv}).data());
  w.Doubles("/invariants/mvo0", {3, 3}, Blocks({v.mvo0}).data());
  w.Doubles("/invariants/mvo1", {hn, 3, 3}, Blocks(v.mvo1).data());
  w.Matrix("/invariants/mvw", v.mvw);
  w.Doubles("/invariants/moo0", {3, 3}, Blocks({v.moo0}).data());
  w.Doubles("/invariants/moo1", {hn, 3, 3}, Blocks(v.moo1).data());
  w.Doubles("/invariants/moo2", {hn, hn, 3, 3}, Blocks(v.moo2).data());
  w.Matrix("/invariants/mow0", v.mow0);
  {
    std::vector<double> mow1;
    mow1.reserve(3 * n * n);
    for (const MatX& m : v.mow1) {
      const RowMat rm = m;
      mow1.insert(mow1.end(), rm.data(), rm.data() + rm.size());
    }
    w.Doubles("/invariants/mow1", {hn, 3, hn}, mow1.data());
  }
  w.Matrix("/invariants/mww", v.mww);

  if (!body.geometric_stiffness.empty()) {
    // optional (older files have none): six n x n centrifugal cases
    std::vector<double> kg;
    kg.reserve(6 * static_cast<size_t>(n) * n);
    for (const MatX& m : body.geometric_stiffness) {
      const RowMat rm = m;
      kg.insert(kg.end(), rm.data(), rm.data() + rm.size());
    }
    w.Group("/geometric_stiffness");
    w.Doubles("/geometric_stiffness/centrifugal", {6, hn, hn}, kg.data());
  }
  if (!body.deformation_stiffness.empty()) {
    // optional: n x n x n, matrix j = G_j of mode j
    std::vector<double> gd;
    gd.reserve(static_cast<size_t>(n) * n * n);
    for (const MatX& m : body.deformation_stiffness) {
      const RowMat rm = m;
      gd.insert(gd.end(), rm.data(), rm.data() + rm.size());
    }
    if (body.geometric_stiffness.empty()) w.Group("/geometric_stiffness");
    w.Doubles("/geometric_stiffness/deformation", {hn, hn, hn}, gd.data());
  }

  w.Group("/stress");
  for (const auto& [group, t] : StressTables(body.stress)) {
    w.Group(group);
    w.AttributeString(group, "name", t->name);
    w.Strings(group + "/components", t->components);
    w.Strings(group + "/locations", t->locations);
    w.Ints(group + "/elements", t->elements);
    const hsize_t ne_t = Size(t->elements.size());
    w.Doubles(group + "/axes", {ne_t, 3, 3}, Blocks(t->axes).data());
    w.Doubles(group + "/modes", {hn, ne_t, Size(t->locations.size()), Size(t->components.size())},
              t->modes.size() != 0 ? t->modes.data() : nullptr);
  }
}

}  // namespace

void WriteBody(const ReducedBody& body, const std::string& path) {
  CheckBody(body, path);
  const hdf5::QuietHdf5 quiet;
  hdf5::WriteFileAtomically(path, "body file", [&](hdf5::Writer& w) { WriteContents(w, body); });
}

ReducedBody ReadBody(const std::string& path) {
  const hdf5::QuietHdf5 quiet;
  const hdf5::Handle file = hdf5::OpenFileForReading(
      path, "body file", "not an HDF5 file (a flexmb body file is HDF5, written by flexmb reduce)");
  const hdf5::Reader r(file.get(), path);

  if (H5Aexists_by_name(file.get(), "/", "format", H5P_DEFAULT) <= 0) {
    r.Fail("attribute format", "is missing: this HDF5 file is not a flexmb body file");
  }
  const std::string format = r.AttributeString("/", "format");
  if (format != kBodyFileFormat) {
    r.Fail("attribute format", "is '" + format + "': not a flexmb body file (expected '" + kBodyFileFormat + "')");
  }
  const int version = r.AttributeInt("/", "version");
  if (version != ReducedBody::kFormatVersion) {
    const std::string v = std::to_string(version), mine = std::to_string(ReducedBody::kFormatVersion);
    r.Fail("attribute version",
           version > ReducedBody::kFormatVersion
               ? "body file format version " + v + " is newer than this flexmb reads (" + mine +
                     "): update flexmb"
               : "body file format version " + v + " is older than this flexmb reads (" + mine +
                     "): reduce the body again with this flexmb");
  }

  ReducedBody body;
  body.units = r.AttributeString("/", "units");
  {
    Dims dims;
    const std::vector<std::string> prov = r.AttributeStrings("/", "provenance", &dims);
    if (dims.size() != 2 || dims[1] != 2) {
      r.Fail("attribute provenance", "has shape " + DimsText(dims) + ", expected [n, 2] (key, value)");
    }
    for (size_t k = 0; k + 1 < prov.size(); k += 2) body.provenance.emplace_back(prov[k], prov[k + 1]);
  }

  const int nn = CountOf(r, "nodes"), ne = CountOf(r, "elements"), n = CountOf(r, "modes");
  body.static_modes = CountOf(r, "static_modes");
  body.normal_modes = CountOf(r, "normal_modes");
  body.rigid_modes_removed = CountOf(r, "rigid_modes_removed");
  const int ni = CountOf(r, "interface_nodes");
  const hsize_t hn = Size(n), hnn = Size(nn);

  body.mesh = ReadBodyMesh(r, nn, ne, path);

  body.interface_nodes = r.Ints("/interface/nodes", ni);
  r.InRange("/interface/nodes", body.interface_nodes, 0, nn, "node");
  const std::vector<int> ids = r.Ints("/interface/node_ids", ni);
  for (int k = 0; k < ni; ++k) {
    if (ids[k] != body.mesh.nodes[body.interface_nodes[k]].id) {
      r.Fail("dataset /interface/node_ids", "entry " + std::to_string(k) + " is node " + std::to_string(ids[k]) +
                                                ", but /interface/nodes names node " +
                                                std::to_string(body.mesh.nodes[body.interface_nodes[k]].id));
    }
  }

  body.modes.resize(6 * static_cast<Eigen::Index>(nn), n);
  r.DoublesInto("/modes/shapes", {hn, hnn, 6}, body.modes.data());
  body.frequencies_hz.resize(n);
  r.DoublesInto("/modes/frequencies_hz", {hn}, body.frequencies_hz.data());

  body.mass = r.Matrix("/reduced/mass", n, n);
  body.stiffness = r.Matrix("/reduced/stiffness", n, n);
  body.damping = r.Matrix("/reduced/damping", n, n);

  InertiaInvariants& v = body.invariants;
  v.n = n;
  v.mvv = r.Block("/invariants/mvv");
  v.mvo0 = r.Block("/invariants/mvo0");
  v.mvo1 = r.Blocks("/invariants/mvo1", {hn, 3, 3});
  v.mvw = r.Matrix("/invariants/mvw", 3, n);
  v.moo0 = r.Block("/invariants/moo0");
  v.moo1 = r.Blocks("/invariants/moo1", {hn, 3, 3});
  v.moo2 = r.Blocks("/invariants/moo2", {hn, hn, 3, 3});
  v.mow0 = r.Matrix("/invariants/mow0", 3, n);
  {
    const std::vector<double> mow1 = r.Doubles("/invariants/mow1", {hn, 3, hn});
    v.mow1.resize(n);
    for (int i = 0; i < n; ++i) {
      v.mow1[i] = Eigen::Map<const RowMat>(mow1.data() + 3 * static_cast<size_t>(n) * i, 3, n);
    }
  }
  v.mww = r.Matrix("/invariants/mww", n, n);
  if (r.Exists("/geometric_stiffness/centrifugal")) {
    const std::vector<double> kg = r.Doubles("/geometric_stiffness/centrifugal", {6, hn, hn});
    body.geometric_stiffness.resize(6);
    for (int c = 0; c < 6; ++c) {
      body.geometric_stiffness[c] =
          Eigen::Map<const RowMat>(kg.data() + static_cast<size_t>(n) * n * c, n, n);
    }
  }
  if (r.Exists("/geometric_stiffness/deformation")) {
    const std::vector<double> gd = r.Doubles("/geometric_stiffness/deformation", {hn, hn, hn});
    body.deformation_stiffness.resize(n);
    for (int j = 0; j < n; ++j) {
      body.deformation_stiffness[j] =
          Eigen::Map<const RowMat>(gd.data() + static_cast<size_t>(n) * n * j, n, n);
    }
  }

  const std::pair<std::string, StressTable*> tables[] = {{"/stress/shell", &body.stress.shell},
                                                         {"/stress/beam", &body.stress.beam},
                                                         {"/stress/solid", &body.stress.solid},
                                                         {"/stress/beam_fibre", &body.stress.beam_fibre},
                                                         {"/stress/solid_node", &body.stress.solid_node}};
  for (const auto& [group, table] : tables) {
    StressTable& t = *table;
    // beam fibre and solid corner stresses came later (format 1 still):
    // a body file without them has none
    if ((group == "/stress/beam_fibre" || group == "/stress/solid_node") && !r.Exists(group)) {
      t = StressTable{};
      t.name = group.substr(std::string("/stress/").size());
      t.modes.resize(0, n);
      continue;
    }
    t.name = r.AttributeString(group, "name");
    t.components = r.Strings(group + "/components", r.Length(group + "/components"));
    t.locations = r.Strings(group + "/locations", r.Length(group + "/locations"));
    const size_t ne_t = r.Length(group + "/elements");
    t.elements = r.Ints(group + "/elements", ne_t);
    r.InRange(group + "/elements", t.elements, 0, ne, "element");
    t.axes = r.Blocks(group + "/axes", {Size(ne_t), 3, 3});
    const Dims dims = {hn, Size(ne_t), Size(t.locations.size()), Size(t.components.size())};
    t.modes.resize(static_cast<Eigen::Index>(ne_t * t.locations.size() * t.components.size()), n);
    r.DoublesInto(group + "/modes", dims, t.modes.data());
  }
  if (!r.unchecked().empty()) {
    LogWarning(path + ": body file without checksums (" + std::to_string(r.unchecked().size()) +
               " datasets, e.g. " + r.unchecked().front() +
               "; written by an older flexmb): damage to its data cannot be detected; reduce the body again "
               "with this flexmb to protect it");
  }
  return body;
}

}  // namespace flexmb::io
