#include "flexmb/solver/statics.h"

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/sparse_lu.h"

namespace flexmb {
namespace {

/// Residual [Q - B^T lambda ... as B^T lambda - Q ; Phi] at s (active lambda in lam).
double Residual(const Model& m, const State& s, Workspace& ws, const VecX& lam, VecX& r) {
  EvaluateMarkers(m, s, ws);
  EvaluateConstraints(m, s, ws);
  EvaluateForces(m, s, ws, true);
  r.head(m.nv) = -ws.Q;
  r.head(m.nv).noalias() += ws.B.transpose() * lam;
  r.tail(ws.n_active) = ws.phi;
  return r.allFinite() ? r.lpNorm<Eigen::Infinity>() : INFINITY;
}

std::string BodyAtColumn(const Model& m, const Workspace& ws, int c) {
  if (c >= 0 && c < m.nv)
    for (const auto& b : m.bodies)
      if (c >= b->v_offset && c < b->v_offset + b->nv())
        return "body '" + b->name() + "' (velocity coordinate " + std::to_string(c - b->v_offset) + ")";
  for (int e = 0; e < m.nc; ++e)
    if (c >= m.nv && ws.row_of_eq[e] == c - m.nv) return DescribeEquation(m, e);
  return "an unknown coordinate";
}

}  // namespace

StaticsResult SolveStatics(const Model& m, State& s, Workspace& ws, const StaticsSettings& set) {
  const int nv = m.nv, na = ws.n_active;
  s.v.setZero();
  VecX lam = VecX::Zero(na), r(nv + na), dx(nv), q0(m.nq), lam0(na);
  for (int e = 0; e < m.nc; ++e)
    if (ws.row_of_eq[e] >= 0) lam(ws.row_of_eq[e]) = s.lambda(e);
  SparseLu lu;
  StaticsResult res;
  double norm = Residual(m, s, ws, lam, r);
  // force scale for the relative residual test
  double fscale = std::max(1.0, ws.Q.lpNorm<Eigen::Infinity>());
  for (int it = 0; it < set.max_iterations; ++it) {
    res.iterations = it + 1;
    s.lambda.setZero();
    for (int e = 0; e < m.nc; ++e)
      if (ws.row_of_eq[e] >= 0) s.lambda(e) = lam(ws.row_of_eq[e]);
    AssembleIterationMatrix(m, s, ws, MatrixCoefficients{0.0, 0.0, 1.0, m.solver.geometric_stiffness});
    if (!lu.Factorize(ws.S))
      throw NumericalError("static equilibrium: singular tangent stiffness at " +
                           BodyAtColumn(m, ws, lu.singular_column()) +
                           "; the mechanism has a free motion without stiffness or load path");
    ws.rhs = -r;
    lu.Solve(ws.rhs);
    dx = ws.rhs.head(nv);
    const double step_norm = dx.lpNorm<Eigen::Infinity>();
    // backtracking line search on the residual
    q0 = s.q;
    lam0 = lam;
    double alpha = 1.0, trial = INFINITY;
    for (int ls = 0; ls < 12; ++ls) {
      RetractAll(m, q0, alpha * dx, s.q);
      lam = lam0 + alpha * ws.rhs.tail(na);
      trial = Residual(m, s, ws, lam, r);
      if (trial < (1.0 - 1e-4 * alpha) * norm || trial < 1e-14) break;
      alpha *= 0.5;
    }
    norm = trial;
    fscale = std::max(fscale, ws.Q.lpNorm<Eigen::Infinity>());
    res.residual = r.head(nv).lpNorm<Eigen::Infinity>();
    const double phi_norm = na > 0 ? r.tail(na).lpNorm<Eigen::Infinity>() : 0.0;
    if (alpha * step_norm <= set.tolerance && res.residual <= set.residual_tol * fscale &&
        phi_norm <= m.solver.assembly_tol) {
      s.lambda.setZero();
      for (int e = 0; e < m.nc; ++e)
        if (ws.row_of_eq[e] >= 0) s.lambda(e) = lam(ws.row_of_eq[e]);
      return res;
    }
  }
  throw NumericalError("static equilibrium: Newton did not converge in " +
                       std::to_string(set.max_iterations) + " iterations (residual " +
                       std::to_string(res.residual) + ")");
}

}  // namespace flexmb
