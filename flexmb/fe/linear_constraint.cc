#include "flexmb/fe/linear_constraint.h"

#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "flexmb/common/error.h"

namespace flexmb::fe {

namespace {

using LinConDof = std::pair<int, int>;  // node index, component

// row of the rigid-body map of DOF (node at r from the reference, component
// c) on the reference motion (t, theta): u = t + theta x r, theta = theta
Eigen::Matrix<double, 1, 6> LinConRigidRow(const Vec3& r, int c) {
  Eigen::Matrix<double, 1, 6> s = Eigen::Matrix<double, 1, 6>::Zero();
  s(c) = 1.0;
  if (c < 3) {
    const int j = (c + 1) % 3, k = (c + 2) % 3;
    // (theta x r)_c = theta_j r_k - theta_k r_j
    s(3 + j) = r[k];
    s(3 + k) = -r[j];
  }
  return s;
}

// the terms of one row, zeros and round-off (relative to the row's largest) left out
std::vector<MpcTerm> LinConTerms(const std::vector<LinConDof>& dofs, const Eigen::RowVectorXd& row) {
  std::vector<MpcTerm> terms;
  const double big = row.cwiseAbs().maxCoeff();
  for (int k = 0; k < static_cast<int>(dofs.size()); ++k) {
    if (std::abs(row(k)) <= 1e-14 * big) continue;
    terms.push_back(MpcTerm{dofs[k].first, dofs[k].second, row(k)});
  }
  return terms;
}

}  // namespace

std::vector<LinearConstraint> Rbe3Constraints(const Mesh& mesh, const Rbe3Spec& spec) {
  const ErrorContext where{spec.origin.file, spec.origin.line, spec.card + " " + std::to_string(spec.id)};
  const int nn = static_cast<int>(mesh.nodes.size());
  if (spec.ref_node < 0 || spec.ref_node >= nn) throw InputError("reference node does not exist", where);
  if (spec.ref_components <= 0 || spec.ref_components > 0b111111)
    throw InputError("reference components REFC must be a subset of 123456", where);
  if (spec.groups.empty()) throw InputError("has no independent nodes", where);
  // weight of every independent DOF (a node listed in two groups adds up)
  std::map<LinConDof, double> weight;
  std::set<int> independent;
  for (const Rbe3Group& g : spec.groups) {
    if (!(std::isfinite(g.weight) && g.weight > 0.0))
      throw InputError("weight " + std::to_string(g.weight) + " must be > 0", where);
    if (g.components <= 0 || g.components > 0b111111)
      throw InputError("independent components must be a subset of 123456", where);
    if (g.nodes.empty()) throw InputError("a weight group has no nodes", where);
    for (int n : g.nodes) {
      if (n < 0 || n >= nn) throw InputError("an independent node does not exist", where);
      if (n == spec.ref_node)
        throw InputError("reference node " + std::to_string(mesh.nodes[n].id) + " is also an independent node", where);
      independent.insert(n);
      for (int c = 0; c < 6; ++c)
        if (g.components & (1 << c)) weight[{n, c}] += g.weight;
    }
  }
  // characteristic length: mean distance of the independent nodes from the reference
  const Vec3 x0 = mesh.nodes[spec.ref_node].x;
  double lc = 0.0;
  for (int n : independent) lc += (mesh.nodes[n].x - x0).norm();
  lc /= static_cast<double>(independent.size());
  if (!(lc > 0.0)) lc = 1.0;
  // weighted least squares: A = S^T W S, B = S^T W
  std::vector<LinConDof> dofs;
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::MatrixXd b(6, static_cast<Eigen::Index>(weight.size()));
  for (const auto& [dof, w0] : weight) {
    const Eigen::Matrix<double, 1, 6> s = LinConRigidRow(mesh.nodes[dof.first].x - x0, dof.second);
    const double w = dof.second < 3 ? w0 : w0 * lc * lc;
    a += w * s.transpose() * s;
    b.col(static_cast<Eigen::Index>(dofs.size())) = w * s.transpose();
    dofs.push_back(dof);
  }
  // rotations scaled by lc so that A's blocks compare; its inverse via that
  Eigen::Matrix<double, 6, 1> d;
  d << 1.0, 1.0, 1.0, 1.0 / lc, 1.0 / lc, 1.0 / lc;
  const Eigen::Matrix<double, 6, 6> as = d.asDiagonal() * a * d.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(as);
  const Eigen::Matrix<double, 6, 1> ev = eig.eigenvalues();
  if (!(ev(0) > 1e-10 * ev(5))) {
    throw InputError(
        "the independent components cannot carry every rigid motion of reference node " +
            std::to_string(mesh.nodes[spec.ref_node].id) +
            " (collinear or coincident nodes with translations only? Nastran's rule: components Ci must react the "
            "rigid-body motion of REFC)",
        where);
  }
  const Eigen::Matrix<double, 6, 6> ainv =
      d.asDiagonal() * (eig.eigenvectors() * ev.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose()) *
      d.asDiagonal();
  const Eigen::MatrixXd g = ainv * b;
  std::vector<LinearConstraint> rows;
  for (int c = 0; c < 6; ++c) {
    if (!(spec.ref_components & (1 << c))) continue;
    LinearConstraint row;
    row.id = spec.id;
    row.card = spec.card;
    row.node = spec.ref_node;
    row.component = c;
    row.terms = LinConTerms(dofs, g.row(c));
    row.origin = spec.origin;
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<LinearConstraint> MakeNodesIndependent(const Mesh& mesh, const std::vector<LinearConstraint>& constraints,
                                                   const std::vector<int>& nodes,
                                                   const std::function<bool(int, int)>& eligible) {
  const std::set<int> target(nodes.begin(), nodes.end());
  std::set<LinConDof> dependent;
  for (const LinearConstraint& row : constraints) dependent.insert({row.node, row.component});
  // rows to rewrite, grouped by card
  std::map<std::pair<std::string, int>, std::vector<int>> groups;
  std::vector<LinearConstraint> out;
  for (int r = 0; r < static_cast<int>(constraints.size()); ++r) {
    if (target.count(constraints[r].node)) {
      groups[{constraints[r].card, constraints[r].id}].push_back(r);
    } else {
      out.push_back(constraints[r]);
    }
  }
  // independent DOF of each card: a pivot must not be one of another card's
  std::map<LinConDof, std::set<std::pair<std::string, int>>> used_by;
  for (const LinearConstraint& row : constraints)
    for (const MpcTerm& t : row.terms) used_by[{t.node, t.component}].insert({row.card, row.id});
  for (const auto& [key, rows] : groups) {
    const LinearConstraint& first = constraints[rows.front()];
    const ErrorContext where{first.origin.file, first.origin.line, key.first + " " + std::to_string(key.second)};
    const int k = static_cast<int>(rows.size());
    // C (k x m) over the independent DOF, and the eligible columns
    std::vector<LinConDof> cols;
    std::map<LinConDof, int> col_of;
    for (int r : rows)
      for (const MpcTerm& t : constraints[r].terms)
        if (col_of.emplace(LinConDof{t.node, t.component}, static_cast<int>(cols.size())).second)
          cols.push_back({t.node, t.component});
    Eigen::MatrixXd c = Eigen::MatrixXd::Zero(k, static_cast<Eigen::Index>(cols.size()));
    for (int i = 0; i < k; ++i)
      for (const MpcTerm& t : constraints[rows[i]].terms) c(i, col_of[{t.node, t.component}]) += t.coef;
    std::vector<int> cand;
    for (int j = 0; j < static_cast<int>(cols.size()); ++j) {
      const LinConDof& dof = cols[j];
      if (target.count(dof.first) || dependent.count(dof) || !eligible(dof.first, dof.second)) continue;
      if (used_by[dof].size() > 1) continue;
      cand.push_back(j);
    }
    // fewer candidates than rows: no choice (and no QR of an empty matrix)
    Eigen::MatrixXd cc(k, static_cast<Eigen::Index>(cand.size()));
    for (int j = 0; j < static_cast<int>(cand.size()); ++j) cc.col(j) = c.col(cand[j]);
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
    qr.setThreshold(1e-10);
    if (cand.size() >= static_cast<size_t>(k)) qr.compute(cc);
    if (cand.size() < static_cast<size_t>(k) || qr.rank() < k) {
      throw InputError("node " + std::to_string(mesh.nodes[first.node].id) +
                           " must be independent (an interface node), but its constraint has no " + std::to_string(k) +
                           " independent DOF that could become dependent in its place",
                       where);
    }
    std::vector<int> pivot(k);
    std::vector<char> is_pivot(cols.size(), 0);
    for (int i = 0; i < k; ++i) {
      pivot[i] = cand[qr.colsPermutation().indices()(i)];
      is_pivot[pivot[i]] = 1;
    }
    // u_D = C_P u_P + C_R u_R  ->  u_P = C_P^-1 u_D - C_P^-1 C_R u_R
    Eigen::MatrixXd cp(k, k);
    for (int i = 0; i < k; ++i) cp.col(i) = c.col(pivot[i]);
    const Eigen::MatrixXd cpi = cp.fullPivLu().inverse();
    std::vector<LinConDof> terms_dofs;
    Eigen::MatrixXd coef(k, k + static_cast<Eigen::Index>(cols.size()) - k);
    for (int i = 0; i < k; ++i) terms_dofs.push_back({first.node, constraints[rows[i]].component});
    coef.leftCols(k) = cpi;
    int q = k;
    for (int j = 0; j < static_cast<int>(cols.size()); ++j) {
      if (is_pivot[j]) continue;
      terms_dofs.push_back(cols[j]);
      coef.col(q++) = -cpi * c.col(j);
    }
    for (int i = 0; i < k; ++i) {
      LinearConstraint row;
      row.id = first.id;
      row.card = first.card;
      row.node = cols[pivot[i]].first;
      row.component = cols[pivot[i]].second;
      row.terms = LinConTerms(terms_dofs, coef.row(i));
      row.origin = first.origin;
      dependent.insert(cols[pivot[i]]);
      out.push_back(std::move(row));
    }
  }
  return out;
}

}  // namespace flexmb::fe
