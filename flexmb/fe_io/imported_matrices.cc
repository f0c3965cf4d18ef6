#include "flexmb/fe_io/imported_matrices.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/common/text.h"
#include "flexmb/fe_io/abaqus/abaqus_matrix.h"
#include "flexmb/fe_io/calculix_matrices.h"
#include "flexmb/fe_io/dof_map.h"
#include "flexmb/fe_io/format_registry.h"
#include "flexmb/fe_io/matrix_text.h"

namespace flexmb::io {

namespace {

// reads one matrix by its extension; `n` is the DOF count for CalculiX files
fe::SparseMat ReadMatrix(const std::string& path, const std::string& what, int n) {
  const FeFileFormat* format = FindMatrixFormat(path);
  if (!format)
    throw InputError("unknown matrix file type " + QuoteToken(LowerExtension(path)) + " (expected " +
                         MatrixFormatList() + ")",
                     {path, 0, what});
  return format->read_matrix(path, what, n);
}

fe::Mesh ReadGeometry(const std::string& path) {
  if (path.empty()) throw InputError("imported matrices need a geometry file (node coordinates)");
  const FeFileFormat* format = FindMeshFormat(path);
  if (!format)
    throw InputError("unknown geometry file type " + QuoteToken(LowerExtension(path)) + " (expected " +
                         MeshFormatList() + ")",
                     {path, 0, "geometry"});
  return format->read_mesh(path);
}

std::string RowName(const MatrixRowMap& map, int r) {
  const DofMapRow& d = map.rows[static_cast<size_t>(r)];
  return "row " + std::to_string(r + 1) + " = node " + std::to_string(d.node_id) + " " + fe::kDofComponentNames[d.component - 1];
}

// square, finite, symmetric to 1e-10 of the largest entry; returns the
// exactly symmetric matrix (the mean of A and its transpose if it differs)
fe::SparseMat CheckMatrix(const fe::SparseMat& A, const std::string& path, const std::string& what,
                          const MatrixRowMap& map) {
  if (A.rows() != A.cols()) {
    throw InputError(what + " is " + std::to_string(A.rows()) + " x " + std::to_string(A.cols()) + ", must be square",
                     {path, 0, what});
  }
  for (int j = 0; j < A.outerSize(); ++j) {
    for (fe::SparseMat::InnerIterator it(A, j); it; ++it) {
      if (!std::isfinite(it.value())) {
        throw InputError("value is not finite", {path, 0,
                         what + " entry (" + RowName(map, static_cast<int>(it.row())) + ", column " +
                             std::to_string(it.col() + 1) + ")"});
      }
    }
  }
  const Asymmetry a = MeasureAsymmetry(A);
  if (a.worst > 1e-10 * a.max_abs) {
    const double aij = A.coeff(a.row, a.col), aji = A.coeff(a.col, a.row);
    const DofMapRow& r = map.rows[static_cast<size_t>(a.row)];
    const DofMapRow& c = map.rows[static_cast<size_t>(a.col)];
    throw InputError("matrix is not symmetric: worst entry " + what + "(" + std::to_string(a.row + 1) + "," +
                         std::to_string(a.col + 1) + ") = " + FormatExact(aij) + " but " + what + "(" +
                         std::to_string(a.col + 1) + "," + std::to_string(a.row + 1) + ") = " + FormatExact(aji) +
                         ", difference more than 1e-10 of the largest |entry| " + FormatExact(a.max_abs) +
                         " (row " + std::to_string(a.row + 1) + " = node " + std::to_string(r.node_id) + " " +
                         fe::kDofComponentNames[r.component - 1] + ", column " + std::to_string(a.col + 1) + " = node " +
                         std::to_string(c.node_id) + " " + fe::kDofComponentNames[c.component - 1] + ")",
                     {path, 0, what});
  }
  if (a.worst == 0.0) return A;
  const fe::SparseMat At = A.transpose();
  fe::SparseMat S = 0.5 * (A + At);
  S.makeCompressed();
  return S;
}

// the DOF map of matrices given without one: 3 or 6 rows per node of the
// geometry, in its node order (what a package writes for a model of solids,
// or of shells and beams, without constraints); anything else is an error
MatrixRowMap DefaultDofMap(int rows, const fe::Mesh& geometry, const ImportedMatricesSpec& spec) {
  const int nodes = static_cast<int>(geometry.nodes.size());
  const int per_node = nodes > 0 && rows == 3 * nodes ? 3 : nodes > 0 && rows == 6 * nodes ? 6 : 0;
  if (per_node == 0)
    throw InputError("no DOF map is given, and the " + std::to_string(rows) + " rows of the matrices are not 3 or 6 "
                         "per node of the " + std::to_string(nodes) + " nodes of the geometry " + spec.geometry +
                         ": give a DOF map (docs/formats.md, \"DOF map\")",
                     {spec.stiffness, 0, "K"});
  MatrixRowMap map;
  map.file = spec.geometry;
  for (const fe::Node& node : geometry.nodes)
    for (int c = 1; c <= per_node; ++c) map.rows.push_back({node.id, c, 0});
  LogWarning(spec.stiffness + ": no DOF map given: its " + std::to_string(rows) + " rows are taken as " +
             std::to_string(per_node) + " DOF per node (" + (per_node == 3 ? "ux uy uz" : "ux uy uz rx ry rz") +
             ") of the " + std::to_string(nodes) + " nodes of " + spec.geometry +
             " in their order there; give a DOF map if the package numbered them otherwise");
  return map;
}

}  // namespace

fe::FeModel ReadImportedMatrices(const ImportedMatricesSpec& spec) {
  if (spec.stiffness.empty() || spec.mass.empty()) {
    throw InputError("imported matrices need a stiffness and a mass matrix file");
  }

  // DOF map: flexmb's format, a CalculiX job.dof (given, or next to
  // job.sti), or none: 3 or 6 rows per node of the geometry (DefaultDofMap)
  std::string dof_path = spec.dof_map;
  if (dof_path.empty() && LowerExtension(spec.stiffness) == ".sti")
    dof_path = std::filesystem::path(spec.stiffness).replace_extension(".dof").string();
  MatrixRowMap map;
  fe::SparseMat K, M;
  fe::Mesh geometry;
  const bool default_map = dof_path.empty();
  auto labelled = [](const std::string& path) {
    return LowerExtension(path) == ".mtx" && IsAbaqusLabelledMatrixFile(path);
  };
  if (labelled(spec.stiffness) || labelled(spec.mass)) {
    // Abaqus's FORMAT=MATRIX INPUT: the files name every row's node and DOF
    const bool k_labelled = labelled(spec.stiffness);
    if (!k_labelled || !labelled(spec.mass))
      throw InputError("is in Abaqus's labelled format (FORMAT=MATRIX INPUT) but " +
                           (k_labelled ? spec.mass : spec.stiffness) + " is not: write both in the same format",
                       {k_labelled ? spec.stiffness : spec.mass, 0, k_labelled ? "K" : "M"});
    if (!default_map)
      throw InputError("Abaqus's labelled matrices (FORMAT=MATRIX INPUT) name the node and DOF of every row "
                       "themselves: leave out the DOF map",
                       {spec.dof_map, 0, "dof_map"});
    AbaqusLabelledMatrices read = ReadAbaqusLabelledMatrices(spec.stiffness, spec.mass);
    K = std::move(read.K);
    M = std::move(read.M);
    map.file = spec.stiffness;
    for (const auto& [node, component] : read.dofs) map.rows.push_back({node, component, 0});
    dof_path = spec.stiffness;
    geometry = ReadGeometry(spec.geometry);
  } else if (default_map) {
    geometry = ReadGeometry(spec.geometry);
    K = ReadMatrix(spec.stiffness, "K", 0);
    M = ReadMatrix(spec.mass, "M", 0);
    map = DefaultDofMap(static_cast<int>(K.rows()), geometry, spec);
    dof_path = spec.geometry;
  } else {
    map = LowerExtension(dof_path) == ".dof" ? ReadCalculixDofs(dof_path) : ReadDofMap(dof_path);
    K = ReadMatrix(spec.stiffness, "K", static_cast<int>(map.rows.size()));
    M = ReadMatrix(spec.mass, "M", static_cast<int>(map.rows.size()));
  }
  const int n_map = static_cast<int>(map.rows.size());

  // sizes: K square, M the same, one DOF map row per matrix row
  if (K.rows() != K.cols()) {
    throw InputError("K is " + std::to_string(K.rows()) + " x " + std::to_string(K.cols()) + ", must be square",
                     {spec.stiffness, 0, "K"});
  }
  if (M.rows() != K.rows() || M.cols() != K.cols()) {
    throw InputError("M is " + std::to_string(M.rows()) + " x " + std::to_string(M.cols()) + " but K (" +
                         spec.stiffness + ") is " + std::to_string(K.rows()) + " x " + std::to_string(K.cols()),
                     {spec.mass, 0, "M"});
  }
  const int n = static_cast<int>(K.rows());
  if (n_map < n) {
    throw InputError("row " + std::to_string(n_map + 1) + " of the " + std::to_string(n) + " x " + std::to_string(n) +
                         " matrices (" + spec.stiffness + ") is not mapped: the DOF map has " +
                         std::to_string(n_map) + " rows",
                     {dof_path, 0, "row " + std::to_string(n_map + 1)});
  }
  if (n_map > n) {
    throw InputError("the DOF map has " + std::to_string(n_map) + " rows but the matrices (" + spec.stiffness +
                         ") only " + std::to_string(n),
                     {dof_path, map.rows[static_cast<size_t>(n)].line, "row " + std::to_string(n + 1)});
  }

  // each (node, component) once
  {
    std::map<std::pair<int, int>, int> seen;
    for (int r = 0; r < n; ++r) {
      const DofMapRow& d = map.rows[static_cast<size_t>(r)];
      const auto [it, inserted] = seen.emplace(std::make_pair(d.node_id, d.component), r);
      if (!inserted) {
        throw InputError("node " + std::to_string(d.node_id) + " " + fe::kDofComponentNames[d.component - 1] +
                             " is mapped twice (rows " + std::to_string(it->second + 1) + " and " +
                             std::to_string(r + 1) + ")",
                         {dof_path, d.line, "row " + std::to_string(r + 1)});
      }
    }
  }

  K = CheckMatrix(K, spec.stiffness, "K", map);
  M = CheckMatrix(M, spec.mass, "M", map);

  fe::FeModel model;
  model.mesh = default_map ? std::move(geometry) : ReadGeometry(spec.geometry);
  model.mesh.IndexNodes();
  // constraints, links and masses of a geometry deck are taken to be in the
  // matrices already (a package exports what it assembled); say so
  {
    const fe::Mesh& g = model.mesh;
    std::string dropped;
    auto count = [&](size_t n, const char* what) {
      if (n > 0) dropped += (dropped.empty() ? "" : ", ") + std::to_string(n) + " " + what;
    };
    count(g.constraints.size(), "single-point constraints");
    count(g.rigid_links.size(), "rigid links");
    count(g.linear_constraints.size(), "linear constraint rows");
    count(g.point_masses.size(), "point masses");
    count(g.springs.size(), "springs");
    if (!dropped.empty())
      LogWarning(spec.geometry + ": its " + dropped +
                 " are not applied to the imported matrices, which are taken to hold them already; if the export "
                 "did not include them, list constraints, rigid links and point masses under 'fixed', "
                 "'rigid_links' and 'point_masses' of an FE model file (docs/model-file.md, \"Imported "
                 "matrices\"); springs and linear constraints (RBE3, MPC) cannot be added there");
  }
  model.mesh.constraints.clear();
  model.mesh.rigid_links.clear();
  model.mesh.linear_constraints.clear();
  model.mesh.point_masses.clear();
  model.mesh.springs.clear();

  fe::AssembledModel a;
  std::array<int, 6> none;
  none.fill(-1);
  a.dofs.full.assign(model.mesh.nodes.size(), none);
  for (int r = 0; r < n; ++r) {
    const DofMapRow& d = map.rows[static_cast<size_t>(r)];
    const int node = model.mesh.NodeIndex(d.node_id);
    if (node < 0) {
      throw InputError("node " + std::to_string(d.node_id) + " does not exist in the geometry " + spec.geometry,
                       {dof_path, d.line, "row " + std::to_string(r + 1)});
    }
    a.dofs.full[static_cast<size_t>(node)][static_cast<size_t>(d.component - 1)] = r;
  }
  a.dofs.free = a.dofs.full;
  for (const fe::Node& node : model.mesh.nodes) a.dofs.node_ids.push_back(node.id);
  a.dofs.n_full = n;
  a.dofs.n_free = n;
  a.K = std::move(K);
  a.M = std::move(M);
  a.M_full = a.M;
  a.T.resize(n, n);
  a.T.setIdentity();
  a.T.makeCompressed();
  model.imported = std::move(a);
  return model;
}

}  // namespace flexmb::io
