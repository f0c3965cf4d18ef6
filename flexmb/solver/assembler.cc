#include "flexmb/solver/assembler.h"

#include <algorithm>

#include "flexmb/common/error.h"

namespace flexmb {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

void PatternBlock(Triplets& t, int r0, int nr, int c0, int nc) {
  for (int j = 0; j < nc; ++j)
    for (int i = 0; i < nr; ++i) t.emplace_back(r0 + i, c0 + j, 0.0);
}

/// Adds scale * blk to the entries of S at (r0, c0). The pattern holds the
/// whole block, so each column's rows r0..r0+nr-1 are consecutive entries.
template <typename Block>
void AddBlock(SparseMat& S, int r0, int c0, const Block& blk, double scale) {
  const int nr = static_cast<int>(blk.rows()), ncol = static_cast<int>(blk.cols());
  const int* outer = S.outerIndexPtr();
  const int* inner = S.innerIndexPtr();
  double* val = S.valuePtr();
  for (int j = 0; j < ncol; ++j) {
    const int* begin = inner + outer[c0 + j];
    const int* end = inner + outer[c0 + j + 1];
    const int* p = std::lower_bound(begin, end, r0);
    double* v = val + (p - inner);
    for (int i = 0; i < nr; ++i) v[i] += scale * blk(i, j);
  }
}

/// Indices of the bodies a joint or force element couples (marker bodies).
int BodyOf(const Model& m, int marker) { return marker < 0 ? 0 : m.markers[marker].body; }

/// Adds scale * Ja^T K6 Rb at body blocks (a, b) of the top-left of S, where
/// Rb (6 x nv_b) is marker b's twist Jacobian or its twist tangent.
template <typename Right>
void AddCoupling(SparseMat& S, const MarkerState& ma, const MarkerState& mb, const Right& Rb,
                 const Eigen::Ref<const Eigen::Matrix<double, 6, 6>>& K6, double scale, MatX& tmp,
                 MatX& blk) {
  if (ma.nv == 0 || mb.nv == 0 || scale == 0.0) return;
  auto t = tmp.topLeftCorner(6, mb.nv);
  auto b = blk.topLeftCorner(ma.nv, mb.nv);
  t.noalias() = K6 * Rb;
  b.noalias() = ma.J.transpose() * t;
  AddBlock(S, ma.v_offset, mb.v_offset, b, scale);
}

}  // namespace

void InitWorkspace(const Model& model, Workspace& ws, const std::vector<int>& removed) {
  const int nb = static_cast<int>(model.bodies.size());
  ws.markers.assign(model.markers.size(), MarkerState{});
  for (size_t k = 0; k < model.markers.size(); ++k) {
    const Body& b = *model.bodies[model.markers[k].body];
    ws.markers[k].J.setZero(6, b.nv());
    ws.markers[k].nv = b.nv();
    ws.markers[k].v_offset = b.v_offset;
  }
  ws.joints.resize(model.joints.size());
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const int n = model.joints[k]->NumEquations();
    ws.joints[k].phi.setZero(n);
    ws.joints[k].phi_t.setZero(n);
    ws.joints[k].D.setZero(n, 12);
  }
  ws.forces.assign(model.forces.size(), ForceEval{});
  ws.mass.resize(nb);
  ws.dQdq.resize(nb);
  ws.dQdv.resize(nb);
  int max_nv = 1;
  for (int k = 0; k < nb; ++k) {
    const int n = model.bodies[k]->nv();
    max_nv = std::max(max_nv, n);
    ws.mass[k].setZero(n, n);
    ws.dQdq[k].setZero(n, n);
    ws.dQdv[k].setZero(n, n);
  }
  const State s0 = model.InitialState();
  for (int k = 0; k < nb; ++k)
    if (model.bodies[k]->nv() > 0) model.bodies[k]->MassMatrix(s0.q.data() + model.bodies[k]->q_offset, ws.mass[k]);
  ws.Q.setZero(model.nv);
  ws.vdot.setZero(model.nv);
  ws.G.setZero(6, max_nv);
  ws.GtK.setZero(max_nv, max_nv);
  ws.twist_dq.setZero(6, max_nv);

  // active constraint rows
  ws.row_of_eq.assign(model.nc, 0);
  for (int e : removed) ws.row_of_eq.at(e) = -1;
  int row = 0;
  for (int e = 0; e < model.nc; ++e)
    if (ws.row_of_eq[e] >= 0) ws.row_of_eq[e] = row++;
  ws.n_active = row;
  ws.phi.setZero(row);
  ws.phi_t.setZero(row);

  // sparse patterns
  const int nv = model.nv;
  Triplets tb, ts;
  for (const auto& b : model.bodies) PatternBlock(ts, b->v_offset, b->nv(), b->v_offset, b->nv());
  auto couple = [&](int ba, int bb) {
    const Body& A = *model.bodies[ba];
    const Body& Bb = *model.bodies[bb];
    PatternBlock(ts, A.v_offset, A.nv(), Bb.v_offset, Bb.nv());
    PatternBlock(ts, Bb.v_offset, Bb.nv(), A.v_offset, A.nv());
  };
  for (const auto& f : model.forces)
    if (f->marker_j >= 0) couple(BodyOf(model, f->marker_i), BodyOf(model, f->marker_j));
  for (const auto& j : model.joints) {
    couple(BodyOf(model, j->marker_i), BodyOf(model, j->marker_j));
    for (int k = 0; k < j->NumEquations(); ++k) {
      const int r = ws.row_of_eq[j->lambda_offset + k];
      if (r < 0) continue;
      for (int mk : {j->marker_i, j->marker_j}) {
        const Body& b = *model.bodies[BodyOf(model, mk)];
        PatternBlock(tb, r, 1, b.v_offset, b.nv());
        PatternBlock(ts, nv + r, 1, b.v_offset, b.nv());
        PatternBlock(ts, b.v_offset, b.nv(), nv + r, 1);
      }
    }
  }
  ws.B.resize(ws.n_active, nv);
  ws.B.setFromTriplets(tb.begin(), tb.end());
  ws.B.makeCompressed();
  ws.S.resize(nv + ws.n_active, nv + ws.n_active);
  ws.S.setFromTriplets(ts.begin(), ts.end());
  ws.S.makeCompressed();
  ws.rhs.setZero(nv + ws.n_active);
}

void EvaluateMarkers(const Model& model, const State& s, Workspace& ws) {
  for (size_t k = 0; k < model.markers.size(); ++k) {
    const Marker& m = model.markers[k];
    const Body& b = *model.bodies[m.body];
    b.EvaluateMarker(s.q.data() + b.q_offset, s.v.data() + b.v_offset, m, ws.markers[k]);
  }
}

void EvaluateConstraints(const Model& model, const State& s, Workspace& ws) {
  std::fill(ws.B.valuePtr(), ws.B.valuePtr() + ws.B.nonZeros(), 0.0);
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const Joint& j = *model.joints[k];
    JointEval& e = ws.joints[k];
    const MarkerState& mi = ws.markers[j.marker_i];
    const MarkerState& mj = ws.markers[j.marker_j];
    e.phi_t.setZero();
    j.Evaluate(mi, mj, s.t, e);
    const int n = j.NumEquations();
    int first = -1, count = 0;
    for (int q = 0; q < n; ++q) {
      const int r = ws.row_of_eq[j.lambda_offset + q];
      if (r < 0) continue;
      if (first < 0) first = r;
      ws.phi(r) = e.phi(q);
      ws.phi_t(r) = e.phi_t(q);
      ++count;
    }
    if (count == 0) continue;
    // B rows of the active equations: D_i J_i and D_j J_j
    const MarkerState* m[2] = {&mi, &mj};
    for (int q = 0, r = 0; q < n; ++q) {
      if (ws.row_of_eq[j.lambda_offset + q] < 0) continue;
      for (int a = 0; a < 2; ++a) {
        if (m[a]->nv == 0) continue;
        auto row = ws.G.topLeftCorner(1, m[a]->nv);
        row.noalias() = e.D.block(q, 6 * a, 1, 6) * m[a]->J;
        AddBlock(ws.B, first + r, m[a]->v_offset, row, 1.0);
      }
      ++r;
    }
  }
}

void EvaluateForces(const Model& model, const State& s, Workspace& ws, bool tangents) {
  ws.Q.setZero();
  for (size_t k = 0; k < model.bodies.size(); ++k) {
    const Body& b = *model.bodies[k];
    if (b.nv() == 0) continue;
    const double* q = s.q.data() + b.q_offset;
    if (!b.HasConstantMass()) b.MassMatrix(q, ws.mass[k]);
    ws.dQdq[k].setZero();
    ws.dQdv[k].setZero();
    b.AddForces(q, s.v.data() + b.v_offset, model.gravity_W, ws.Q.segment(b.v_offset, b.nv()),
                ws.dQdq[k], ws.dQdv[k]);
  }
  static const MarkerState kNoMarker{};
  for (size_t k = 0; k < model.forces.size(); ++k) {
    const ForceElement& f = *model.forces[k];
    ForceEval& e = ws.forces[k];
    const MarkerState& mi = ws.markers[f.marker_i];
    const MarkerState& mj = f.marker_j >= 0 ? ws.markers[f.marker_j] : kNoMarker;
    e.wrench.setZero();
    if (tangents) {
      e.K.setZero();
      e.C.setZero();
    }
    f.Evaluate(mi, mj, s.t, e);
    if (mi.nv > 0) ws.Q.segment(mi.v_offset, mi.nv).noalias() += mi.J.transpose() * e.wrench.head<6>();
    if (f.marker_j >= 0 && mj.nv > 0)
      ws.Q.segment(mj.v_offset, mj.nv).noalias() += mj.J.transpose() * e.wrench.tail<6>();
  }
  (void)tangents;
}

void AssembleIterationMatrix(const Model& model, const State& s, Workspace& ws,
                             const MatrixCoefficients& c) {
  SparseMat& S = ws.S;
  std::fill(S.valuePtr(), S.valuePtr() + S.nonZeros(), 0.0);
  const int nv = model.nv;
  // bodies: mass and own force derivatives
  for (size_t k = 0; k < model.bodies.size(); ++k) {
    const Body& b = *model.bodies[k];
    if (b.nv() == 0) continue;
    AddBlock(S, b.v_offset, b.v_offset, ws.mass[k], c.mass);
    if (c.damping != 0.0) AddBlock(S, b.v_offset, b.v_offset, ws.dQdv[k], -c.damping);
    if (c.stiffness != 0.0) AddBlock(S, b.v_offset, b.v_offset, ws.dQdq[k], -c.stiffness);
  }
  // force elements: -d(J^T w)/dq and -d(J^T w)/dv
  for (size_t k = 0; k < model.forces.size() && (c.damping != 0.0 || c.stiffness != 0.0); ++k) {
    const ForceElement& f = *model.forces[k];
    const ForceEval& e = ws.forces[k];
    const int nm = f.marker_j >= 0 ? 2 : 1;
    const int mk[2] = {f.marker_i, f.marker_j};
    for (int a = 0; a < nm; ++a) {
      const MarkerState& ma = ws.markers[mk[a]];
      const Marker& marker = model.markers[mk[a]];
      const Body& body = *model.bodies[marker.body];
      if (ma.nv > 0 && c.stiffness != 0.0) {
        auto blk = ws.GtK.topLeftCorner(ma.nv, ma.nv);
        blk.setZero();
        const Vec6 w = e.wrench.segment<6>(6 * a);
        body.AddMarkerWrenchTangent(s.q.data() + body.q_offset, marker, w, blk);
        AddBlock(S, ma.v_offset, ma.v_offset, blk, -c.stiffness);
      }
      for (int b = 0; b < nm; ++b) {
        const MarkerState& mb = ws.markers[mk[b]];
        AddCoupling(S, ma, mb, mb.J, e.K.block<6, 6>(6 * a, 6 * b), -c.stiffness, ws.G, ws.GtK);
        AddCoupling(S, ma, mb, mb.J, e.C.block<6, 6>(6 * a, 6 * b), -c.damping, ws.G, ws.GtK);
        if (mb.nv == 0 || c.stiffness == 0.0 || e.C.block<6, 6>(6 * a, 6 * b).isZero(0.0)) continue;
        // dampers: the twist of marker b turns with its body at fixed v
        const Marker& mkb = model.markers[mk[b]];
        const Body& bb = *model.bodies[mkb.body];
        auto td = ws.twist_dq.leftCols(mb.nv);
        bb.MarkerTwistTangent(s.q.data() + bb.q_offset, s.v.data() + bb.v_offset, mkb, td);
        AddCoupling(S, ma, mb, td, e.C.block<6, 6>(6 * a, 6 * b), -c.stiffness, ws.G, ws.GtK);
      }
    }
  }
  // joints: B, B^T and the geometric stiffness d(B^T lambda)/dq
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const Joint& j = *model.joints[k];
    const JointEval& e = ws.joints[k];
    const MarkerState* m[2] = {&ws.markers[j.marker_i], &ws.markers[j.marker_j]};
    const int n = j.NumEquations();
    double lam[16] = {0};
    bool any_lambda = false;
    for (int q = 0, r = -1; q < n; ++q) {
      r = ws.row_of_eq[j.lambda_offset + q];
      if (r < 0) continue;
      lam[q] = s.lambda(j.lambda_offset + q);
      any_lambda |= lam[q] != 0.0;
      for (int a = 0; a < 2; ++a) {
        if (m[a]->nv == 0) continue;
        auto row = ws.G.topLeftCorner(1, m[a]->nv);
        row.noalias() = e.D.block(q, 6 * a, 1, 6) * m[a]->J;
        AddBlock(S, nv + r, m[a]->v_offset, row, 1.0);
        AddBlock(S, m[a]->v_offset, nv + r, row.transpose(), 1.0);
      }
    }
    if (!c.geometric || c.stiffness == 0.0 || !any_lambda) continue;
    ws.H.setZero();
    j.AddGeometricStiffness(*m[0], *m[1], lam, ws.H);
    Vec12 w = Vec12::Zero();
    for (int q = 0; q < n; ++q) w += lam[q] * e.D.row(q).transpose();
    const int mk[2] = {j.marker_i, j.marker_j};
    for (int a = 0; a < 2; ++a) {
      if (m[a]->nv == 0) continue;
      const Marker& marker = model.markers[mk[a]];
      const Body& body = *model.bodies[marker.body];
      auto blk = ws.GtK.topLeftCorner(m[a]->nv, m[a]->nv);
      blk.setZero();
      body.AddMarkerWrenchTangent(s.q.data() + body.q_offset, marker, w.segment<6>(6 * a), blk);
      AddBlock(S, m[a]->v_offset, m[a]->v_offset, blk, c.stiffness);
      for (int b = 0; b < 2; ++b)
        AddCoupling(S, *m[a], *m[b], m[b]->J, ws.H.block<6, 6>(6 * a, 6 * b), c.stiffness, ws.G,
                    ws.GtK);
    }
  }
}

void MassTimes(const Model& model, const Workspace& ws, const VecX& a, VecX& r) {
  for (size_t k = 0; k < model.bodies.size(); ++k) {
    const Body& b = *model.bodies[k];
    if (b.nv() == 0) continue;
    r.segment(b.v_offset, b.nv()).noalias() = ws.mass[k] * a.segment(b.v_offset, b.nv());
  }
}

void RetractAll(const Model& model, const VecX& q, const VecX& dx, VecX& q_out) {
  for (const auto& b : model.bodies)
    if (b->nv() > 0)
      b->Retract(q.data() + b->q_offset, dx.data() + b->v_offset, q_out.data() + b->q_offset);
}

void AddConstraintForces(const Model& model, const Workspace& ws, const VecX& lambda, VecX& r) {
  (void)model;
  r.noalias() += ws.B.transpose() * lambda;
}

std::string DescribeEquation(const Model& model, int eq) {
  for (const auto& j : model.joints)
    if (eq >= j->lambda_offset && eq < j->lambda_offset + j->NumEquations())
      return "joint '" + j->name() + "' (" + j->EquationName(eq - j->lambda_offset) + ")";
  return "equation " + std::to_string(eq);
}

}  // namespace flexmb
