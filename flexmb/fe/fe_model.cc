#include "flexmb/fe/fe_model.h"

#include <cstdint>
#include <string>

#include "flexmb/common/error.h"

namespace flexmb::fe {
namespace {

// removes the free DOF selected by mask[node] (bit c = component c) from K,
// M, the columns of T and the free numbering; kept DOF keep their order
AssembledModel RemoveDofs(const AssembledModel& model, const std::vector<uint8_t>& mask) {
  const DofMap& dm = model.dofs;
  const int nf = dm.n_free;
  std::vector<int> renumber(nf, -1);
  std::vector<uint8_t> drop(nf, 0);
  for (size_t n = 0; n < dm.free.size(); ++n) {
    for (int c = 0; c < 6; ++c) {
      const int f = dm.free[n][c];
      if ((mask[n] & (1 << c)) && f >= 0) drop[f] = 1;
    }
  }
  int kept = 0;
  for (int f = 0; f < nf; ++f)
    if (!drop[f]) renumber[f] = kept++;

  AssembledModel out;
  out.dofs.full = dm.full;
  out.dofs.n_full = dm.n_full;
  out.dofs.n_free = kept;
  out.dofs.free = dm.free;
  out.dofs.node_ids = dm.node_ids;
  for (auto& node : out.dofs.free)
    for (int& f : node)
      if (f >= 0) f = renumber[f];

  // columns (and, for square matrices, rows) of a column-major matrix
  auto select = [&](const SparseMat& a, bool rows_too) {
    SparseMat b(rows_too ? kept : a.rows(), kept);
    int64_t nnz = 0;
    for (int j = 0; j < a.outerSize(); ++j) {
      if (drop[j]) continue;
      for (SparseMat::InnerIterator it(a, j); it; ++it)
        if (!rows_too || !drop[it.row()]) ++nnz;
    }
    b.resizeNonZeros(static_cast<Eigen::Index>(nnz));
    int* outer = b.outerIndexPtr();
    int* inner = b.innerIndexPtr();
    double* value = b.valuePtr();
    int p = 0, col = 0;
    outer[0] = 0;
    for (int j = 0; j < a.outerSize(); ++j) {
      if (drop[j]) continue;
      for (SparseMat::InnerIterator it(a, j); it; ++it) {
        const int i = static_cast<int>(it.row());
        if (rows_too && drop[i]) continue;
        inner[p] = rows_too ? renumber[i] : i;
        value[p] = it.value();
        ++p;
      }
      outer[++col] = p;
    }
    return b;
  };
  out.K = select(model.K, true);
  out.M = select(model.M, true);
  out.T = select(model.T, false);
  out.M_full = model.M_full;
  return out;
}

void CheckModel(const AssembledModel& model) {
  const int nf = model.dofs.n_free;
  if (model.K.rows() != nf || model.K.cols() != nf || model.M.rows() != nf || model.M.cols() != nf ||
      model.T.cols() != nf || model.T.rows() != model.dofs.n_full ||
      model.dofs.free.size() != model.dofs.full.size())
    throw InputError("the assembled model is inconsistent: K, M, T and the DOF map differ in size");
}

}  // namespace

AssembledModel FixNodes(const AssembledModel& model, const std::vector<int>& node_indices) {
  CheckModel(model);
  const DofMap& dm = model.dofs;
  const int nn = static_cast<int>(dm.free.size());
  // a dependent DOF (rigid link) has a non-empty row of T but no free index
  std::vector<uint8_t> mask(nn, 0);
  std::vector<int> t_row_count;
  for (int n : node_indices) {
    if (n < 0 || n >= nn)
      throw InputError("fixed node index " + std::to_string(n) + " does not exist in the model (" +
                       std::to_string(nn) + " nodes)");
    mask[n] = 0b111111;
    for (int c = 0; c < 6; ++c) {
      if (dm.full[n][c] < 0 || dm.free[n][c] >= 0) continue;
      if (t_row_count.empty()) {
        t_row_count.assign(dm.n_full, 0);
        for (int k = 0; k < model.T.outerSize(); ++k)
          for (SparseMat::InnerIterator it(model.T, k); it; ++it) ++t_row_count[it.row()];
      }
      if (t_row_count[dm.full[n][c]] > 0)
        throw InputError(std::string("cannot fix node index ") + std::to_string(n) + ": its component " +
                         kDofComponentNames[c] + " is dependent on a rigid link");
    }
  }
  return RemoveDofs(model, mask);
}

AssembledModel BuildMatrices(const FeModel& model, const AssemblyOptions& options) {
  if (!model.imported) return Assemble(model.mesh, options);
  const AssembledModel& imported = *model.imported;
  CheckModel(imported);
  const Mesh& mesh = model.mesh;
  // what the FE model file adds to the matrices (nodes, rigid links, point
  // masses, springs, linear constraints) is assembled with them; without
  // additions the rows keep the files' order
  if (!mesh.rigid_links.empty() || !mesh.point_masses.empty() || !mesh.springs.empty() ||
      !mesh.linear_constraints.empty() || imported.dofs.full.size() != mesh.nodes.size())
    return AssembleImported(mesh, imported, options);
  const int nn = static_cast<int>(imported.dofs.free.size());  // == the mesh's nodes (above)
  std::vector<uint8_t> mask(nn, 0);
  if (options.apply_constraints) {
    for (const Constraint& c : mesh.constraints) {
      if (c.node < 0 || c.node >= nn)
        throw InputError("refers to a node that does not exist", {c.origin.file, c.origin.line, "constraint"});
      if (c.dofs < 0 || c.dofs > 0b111111)
        throw InputError("component mask must be a subset of 123456", {c.origin.file, c.origin.line, "constraint"});
      mask[c.node] |= static_cast<uint8_t>(c.dofs);
    }
  }
  for (int n : options.extra_fixed_nodes) {
    if (n < 0 || n >= nn)
      throw InputError("fixed node index " + std::to_string(n) + " does not exist in the mesh", {mesh.source, 0, ""});
    mask[n] = 0b111111;
  }
  AssembledModel out = RemoveDofs(imported, mask);
  // imported numbering: full = free before any DOF is removed
  if (out.M_full.size() == 0) out.M_full = imported.M;
  return out;
}

}  // namespace flexmb::fe
