#include "flexmb/solver/residual_share.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace flexmb {

namespace {

// one contribution to one dynamic row
struct ShareTerm {
  int entity;  // index into the entity list
  int row;     // velocity coordinate
  double value;
};

}  // namespace

std::vector<ResidualShare> LargestResidualShares(const Model& m, const Workspace& ws, const VecX& res,
                                                 const VecX& lambda, double bp, int count) {
  const int nv = m.nv;
  const int nb = static_cast<int>(m.bodies.size()), nj = static_cast<int>(m.joints.size());
  const int nf = static_cast<int>(m.forces.size());
  // entities: bodies, then joints, then force elements
  std::vector<ResidualShare> all(nb + nj + nf);
  for (int k = 0; k < nb; ++k) all[k] = {"body", m.bodies[k]->name()};
  for (int k = 0; k < nj; ++k) all[nb + k] = {"joint", m.joints[k]->name()};
  for (int k = 0; k < nf; ++k) all[nb + nj + k] = {"force element", m.forces[k]->name()};

  // row scale 1 / (beta' M_ii) and the body of each row
  VecX scale = VecX::Ones(nv);
  std::vector<int> body_of(nv, -1);
  for (int k = 0; k < nb; ++k) {
    const Body& b = *m.bodies[k];
    for (int i = 0; i < b.nv(); ++i) {
      const double mii = k < static_cast<int>(ws.mass.size()) && ws.mass[k].rows() > i ? ws.mass[k](i, i) : 0.0;
      scale(b.v_offset + i) = 1.0 / (std::abs(bp) * (mii > 0.0 ? mii : 1.0));
      body_of[b.v_offset + i] = k;
    }
  }

  std::vector<ShareTerm> terms;
  VecX rest = res;  // the bodies' own part: what the forces and joints leave
  // force elements: -J^T wrench on each marker's columns
  for (int k = 0; k < nf; ++k) {
    const ForceElement& f = *m.forces[k];
    const ForceEval& e = ws.forces[k];
    for (int side = 0; side < f.NumMarkers(); ++side) {
      const int mk = f.MarkerAt(side);
      const MarkerState& ms = ws.markers[mk];
      const std::pair<int, int>& cols = ws.marker_cols[mk];
      if (cols.second <= 0) continue;
      const Vec6 w = MarkerWrench(e, f.NumMarkers(), side);
      const VecX q = -(ms.J.middleCols(cols.first, cols.second).transpose() * w);
      for (int c = 0; c < cols.second; ++c) {
        const int row = ms.v_offset + cols.first + c;
        terms.push_back({nb + nj + k, row, q(c)});
        rest(row) -= q(c);
      }
    }
  }
  // joints: B^T lambda, and |Phi| of their rows
  std::vector<int> joint_of_row(ws.n_active, -1);
  VecX lam_row = VecX::Zero(ws.n_active);
  for (int k = 0; k < nj; ++k) {
    const Joint& j = *m.joints[k];
    for (int e = 0; e < j.NumEquations(); ++e) {
      const int r = ws.row_of_eq[j.lambda_offset + e];
      if (r < 0) continue;
      joint_of_row[r] = k;
      lam_row(r) = lambda(j.lambda_offset + e);
      const double phi = ws.phi(r);
      ResidualShare& s = all[nb + k];
      if (!std::isfinite(phi)) s.non_finite = true;
      else s.share += std::abs(phi);
    }
  }
  for (int col = 0; col < ws.B.outerSize(); ++col) {
    for (SparseMat::InnerIterator it(ws.B, col); it; ++it) {
      const int k = joint_of_row[it.row()];
      if (k < 0) continue;
      const double v = it.value() * lam_row(it.row());
      terms.push_back({nb + k, col, v});
      rest(col) -= v;
    }
  }
  // a row made non-finite by a force or joint is theirs, not the body's
  std::vector<char> row_non_finite(nv, 0);
  for (const ShareTerm& t : terms)
    if (!std::isfinite(t.value)) row_non_finite[t.row] = 1;
  for (int i = 0; i < nv; ++i)
    if (body_of[i] >= 0 && (std::isfinite(rest(i)) || !row_non_finite[i])) terms.push_back({body_of[i], i, rest(i)});

  // each row's scaled residual, shared in proportion to the contributions
  VecX row_sum = VecX::Zero(nv);
  for (const ShareTerm& t : terms) {
    if (!std::isfinite(t.value)) all[t.entity].non_finite = true;
    else row_sum(t.row) += std::abs(t.value);
  }
  for (const ShareTerm& t : terms) {
    if (!std::isfinite(t.value) || row_sum(t.row) <= 0.0 || !std::isfinite(res(t.row))) continue;
    all[t.entity].share += std::abs(res(t.row)) * scale(t.row) * std::abs(t.value) / row_sum(t.row);
  }
  double total = 0.0;
  for (const ResidualShare& s : all) total += s.share;
  for (ResidualShare& s : all) s.share = s.non_finite ? 1.0 : (total > 0.0 ? s.share / total : 0.0);
  std::stable_sort(all.begin(), all.end(), [](const ResidualShare& a, const ResidualShare& b) {
    if (a.non_finite != b.non_finite) return a.non_finite;
    return a.share > b.share;
  });
  // non-finite contributions, if any, are the fault: only they are named
  const bool any_non_finite = !all.empty() && all.front().non_finite;
  std::vector<ResidualShare> top;
  for (const ResidualShare& s : all) {
    if (static_cast<int>(top.size()) >= count || (!s.non_finite && (any_non_finite || s.share < 0.01))) break;
    top.push_back(s);
  }
  return top;
}

std::string DescribeResidualShares(const std::vector<ResidualShare>& shares) {
  if (shares.empty()) return "";
  std::string text = "largest share of the scaled Newton residual: ";
  for (size_t k = 0; k < shares.size(); ++k) {
    const ResidualShare& s = shares[k];
    text += (k == 0 ? "" : k == 1 ? ", then " : ", ") + s.Entity() +
            (s.non_finite ? std::string(" (non-finite)") : fmt::format(" ({:.0f} %)", 100.0 * s.share));
  }
  return text;
}

}  // namespace flexmb
