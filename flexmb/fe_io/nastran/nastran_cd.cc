#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

namespace {

// true if the components of a 3-block (translations or rotations) do not
// depend on the orientation of the displacement system: none or all three
bool CdBlockFree(int mask3) { return mask3 == 0 || mask3 == 0b111; }

}  // namespace

fe::Mat3 Builder::CdBasis(int node) {
  const int cd = node_cd_[node];
  if (cd == 0) return fe::Mat3::Identity();
  return BasisAt(coords_.at(cd), mesh_.nodes[node].x);
}

std::vector<fe::LinearConstraint> CdRows(const fe::Mesh& mesh, int node, int block, const fe::Mat3& basis, int mask3,
                                         int independent) {
  // constrained axes D (3 x k): D^T u = D^T W u_ind, W = [I, -skew(r)]
  // for translations, [0, I] for rotations
  std::vector<int> axes;
  for (int c = 0; c < 3; ++c)
    if (mask3 & (1 << c)) axes.push_back(c);
  const int k = static_cast<int>(axes.size());
  Eigen::MatrixXd a(k, 3);
  for (int i = 0; i < k; ++i) a.row(i) = basis.col(axes[i]).transpose();
  Eigen::Matrix<double, 3, 6> w = Eigen::Matrix<double, 3, 6>::Zero();
  if (independent >= 0) {
    if (block == 0) {
      const fe::Vec3 r = mesh.nodes[node].x - mesh.nodes[independent].x;
      w.leftCols<3>().setIdentity();
      w.rightCols<3>() << 0.0, r.z(), -r.y(), -r.z(), 0.0, r.x(), r.y(), -r.x(), 0.0;
    } else {
      w.rightCols<3>().setIdentity();
    }
  }
  // dependent basic components: the best conditioned k of the three
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  std::vector<int> pivot(k), free_components;
  std::vector<char> is_pivot(3, 0);
  for (int i = 0; i < k; ++i) {
    pivot[i] = qr.colsPermutation().indices()(i);
    is_pivot[pivot[i]] = 1;
  }
  for (int c = 0; c < 3; ++c)
    if (!is_pivot[c]) free_components.push_back(c);
  Eigen::MatrixXd ap(k, k), af(k, 3 - k);
  for (int i = 0; i < k; ++i) ap.col(i) = a.col(pivot[i]);
  for (int j = 0; j < 3 - k; ++j) af.col(j) = a.col(free_components[j]);
  const Eigen::MatrixXd api = ap.inverse();
  const Eigen::MatrixXd g_free = -api * af;
  const Eigen::MatrixXd g_ind = api * a * w;
  std::vector<fe::LinearConstraint> rows;
  for (int i = 0; i < k; ++i) {
    fe::LinearConstraint row;
    row.node = node;
    row.component = block + pivot[i];
    // round-off of axes that are basic axes is left out
    for (int j = 0; j < 3 - k; ++j)
      if (std::abs(g_free(i, j)) > 1e-12) row.terms.push_back(fe::MpcTerm{node, block + free_components[j], g_free(i, j)});
    if (independent >= 0) {
      const double scale = std::max(1.0, g_ind.row(i).cwiseAbs().maxCoeff());
      for (int c = 0; c < 6; ++c)
        if (std::abs(g_ind(i, c)) > 1e-12 * scale) row.terms.push_back(fe::MpcTerm{independent, c, g_ind(i, c)});
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

void Builder::AddFixed(const Entry& e, int node, int mask) {
  if (node_cd_[node] == 0) {
    mesh_.constraints.push_back(fe::Constraint{node, mask, OriginOf(e)});
    return;
  }
  // components along axes of the displacement system: merged per node (an
  // SPC 1 and an SPC 23 of one grid fix all three), written by FinishCdFixed
  auto [it, inserted] = cd_fixed_.emplace(node, std::make_pair(0, OriginOf(e)));
  it->second.first |= mask;
}

void Builder::FinishCdFixed() {
  for (const auto& [node, fixed] : cd_fixed_) {
    const int mask = fixed.first;
    const fe::Mat3 basis = CdBasis(node);
    for (int block : {0, 3}) {
      const int mask3 = (mask >> block) & 0b111;
      if (CdBlockFree(mask3)) {
        if (mask3) mesh_.constraints.push_back(fe::Constraint{node, mask3 << block, fixed.second});
        continue;
      }
      for (fe::LinearConstraint& row : CdRows(mesh_, node, block, basis, mask3, -1)) {
        // an axis that is a basic axis: an ordinary constraint
        if (row.terms.empty()) {
          mesh_.constraints.push_back(fe::Constraint{node, 1 << row.component, fixed.second});
          continue;
        }
        row.id = mesh_.nodes[node].id;
        row.card = "SPC";
        row.origin = fixed.second;
        mesh_.linear_constraints.push_back(std::move(row));
      }
    }
  }
  cd_fixed_.clear();
}

bool Builder::AddCdRigid(const Entry& e, int id, int independent, int dependent, int mask) {
  if (node_cd_[dependent] == 0 || (CdBlockFree(mask & 0b111) && CdBlockFree(mask >> 3))) return false;
  const fe::Mat3 basis = CdBasis(dependent);
  for (int block : {0, 3}) {
    const int mask3 = (mask >> block) & 0b111;
    if (mask3 == 0) continue;
    for (fe::LinearConstraint& row : CdRows(mesh_, dependent, block, basis, mask3, independent)) {
      row.id = id;
      row.card = e.name();
      row.origin = OriginOf(e);
      mesh_.linear_constraints.push_back(std::move(row));
    }
  }
  return true;
}

}  // namespace flexmb::io::nastran
