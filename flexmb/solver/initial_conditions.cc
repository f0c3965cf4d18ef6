#include "flexmb/solver/initial_conditions.h"

#include <Eigen/OrderingMethods>
#include <Eigen/QR>
#include <Eigen/SparseQR>
#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/sparse_lu.h"

namespace flexmb {
namespace {

/// Joint equation with the largest |phi| among the active rows.
std::string WorstEquation(const Model& model, const Workspace& ws, double* value) {
  int worst = -1;
  double wv = -1.0;
  for (int e = 0; e < model.nc; ++e) {
    const int r = ws.row_of_eq[e];
    if (r >= 0 && std::abs(ws.phi(r)) > wv) wv = std::abs(ws.phi(r)), worst = e;
  }
  if (value) *value = wv;
  return worst >= 0 ? DescribeEquation(model, worst) : "no constraint";
}

/// Solves [[M, B^T], [B, 0]] x = ws.rhs in place.
void SolveAugmented(const Model& model, const State& s, Workspace& ws, SparseLu& lu,
                    const char* what) {
  AssembleIterationMatrix(model, s, ws, MatrixCoefficients{1.0, 0.0, 0.0, false});
  if (!lu.Factorize(ws.S)) {
    const int c = lu.singular_column();
    std::string where = "a constraint row";
    if (c >= 0 && c < model.nv) {
      for (const auto& b : model.bodies)
        if (c >= b->v_offset && c < b->v_offset + b->nv()) where = "body '" + b->name() + "'";
    } else if (c >= model.nv) {
      for (int e = 0; e < model.nc; ++e)
        if (ws.row_of_eq[e] == c - model.nv) where = DescribeEquation(model, e);
    }
    throw NumericalError(std::string(what) + ": singular constraint system near " + where);
  }
  lu.Solve(ws.rhs);
}

/// B v + Phi_t at state s (evaluates markers and constraints).
void VelocityConstraint(const Model& model, const State& s, Workspace& ws, VecX& c) {
  EvaluateMarkers(model, s, ws);
  EvaluateConstraints(model, s, ws);
  c = ws.B * s.v + ws.phi_t;
}

}  // namespace

std::vector<int> FindRedundantEquations(const Model& model, const State& s, double tol) {
  std::vector<int> redundant;
  if (model.nc == 0) return redundant;
  Workspace ws;
  InitWorkspace(model, ws);
  EvaluateMarkers(model, s, ws);
  EvaluateConstraints(model, s, ws);
  const int nc = model.nc;
  if (static_cast<long>(nc) * model.nv <= 2'000'000L) {
    // greedy modified Gram-Schmidt over the rows in model order (twice, for
    // numerical orthogonality): a row that adds nothing to the earlier ones
    // is redundant
    const MatX B = MatX(ws.B);
    MatX basis(model.nv, std::min(nc, model.nv));
    int rank = 0;
    for (int e = 0; e < nc; ++e) {
      VecX r = B.row(e).transpose();
      const double n0 = r.norm();
      for (int pass = 0; pass < 2; ++pass)
        for (int k = 0; k < rank; ++k) r -= basis.col(k).dot(r) * basis.col(k);
      const double n1 = r.norm();
      if (n0 == 0.0 || n1 <= tol * n0 || rank == model.nv) {
        redundant.push_back(e);
      } else {
        basis.col(rank++) = r / n1;
      }
    }
  } else {
    SparseMat Bt = ws.B.transpose();
    Eigen::SparseQR<SparseMat, Eigen::COLAMDOrdering<int>> qr;
    qr.setPivotThreshold(tol);
    qr.compute(Bt);
    const int rank = static_cast<int>(qr.rank());
    for (int k = rank; k < nc; ++k) redundant.push_back(qr.colsPermutation().indices()(k));
    std::sort(redundant.begin(), redundant.end());
  }
  return redundant;
}

void AssemblePositions(const Model& model, State& s, Workspace& ws, SparseLu& lu) {
  const int nv = model.nv;
  VecX dx(nv), q0 = s.q;
  double last = INFINITY;
  for (int it = 0; it < 60; ++it) {
    EvaluateMarkers(model, s, ws);
    EvaluateConstraints(model, s, ws);
    const double res = ws.n_active ? ws.phi.lpNorm<Eigen::Infinity>() : 0.0;
    if (!std::isfinite(res)) break;
    if (res <= model.solver.assembly_tol) return;
    if (it > 10 && res > 0.5 * last) break;  // not converging
    last = res;
    ws.rhs.head(nv).setZero();
    ws.rhs.tail(ws.n_active) = -ws.phi;
    SolveAugmented(model, s, ws, lu, "position assembly");
    dx = ws.rhs.head(nv);
    q0 = s.q;
    RetractAll(model, q0, dx, s.q);
  }
  double value = 0.0;
  const std::string where = WorstEquation(model, ws, &value);
  throw NumericalError("position assembly failed: the constraints cannot be satisfied from the "
                       "initial positions; largest residual " +
                       std::to_string(value) + " in " + where);
}

void ProjectVelocities(const Model& model, State& s, Workspace& ws, SparseLu& lu) {
  VecX c;
  VelocityConstraint(model, s, ws, c);
  ws.rhs.head(model.nv).setZero();
  ws.rhs.tail(ws.n_active) = -c;
  SolveAugmented(model, s, ws, lu, "velocity projection");
  s.v += ws.rhs.head(model.nv);
}

void InitialAccelerations(const Model& model, State& s, Workspace& ws, SparseLu& lu) {
  // zeta = d/dt (B v + Phi_t) at fixed v, by central differences along the motion
  const double h = 1e-6;
  State sp = s, sm = s;
  sp.t += h;
  sm.t -= h;
  RetractAll(model, s.q, h * s.v, sp.q);
  RetractAll(model, s.q, -h * s.v, sm.q);
  VecX cp, cm;
  VelocityConstraint(model, sp, ws, cp);
  VelocityConstraint(model, sm, ws, cm);
  const VecX zeta = (cp - cm) / (2 * h);
  EvaluateMarkers(model, s, ws);
  EvaluateConstraints(model, s, ws);
  EvaluateForces(model, s, ws, false);
  ws.rhs.head(model.nv) = ws.Q;
  ws.rhs.tail(ws.n_active) = -zeta;
  SolveAugmented(model, s, ws, lu, "initial accelerations");
  ws.vdot = ws.rhs.head(model.nv);
  s.lambda.setZero(model.nc);
  for (int e = 0; e < model.nc; ++e)
    if (ws.row_of_eq[e] >= 0) s.lambda(e) = ws.rhs(model.nv + ws.row_of_eq[e]);
  if (!ws.vdot.allFinite() || !s.lambda.allFinite())
    throw NumericalError("initial accelerations are not finite");
}

ConstraintReport MakeConsistent(const Model& model, State& s, Workspace& ws) {
  ConstraintReport rep;
  rep.equations = model.nc;
  SparseLu lu;
  const double tol = model.solver.redundancy_tol;
  rep.redundant = FindRedundantEquations(model, s, tol);
  InitWorkspace(model, ws, rep.redundant);
  AssemblePositions(model, s, ws, lu);
  std::vector<int> again = FindRedundantEquations(model, s, tol);
  if (again != rep.redundant) {
    rep.redundant = again;
    lu.Reset();
    InitWorkspace(model, ws, rep.redundant);
    AssemblePositions(model, s, ws, lu);
  }
  // removed equations must hold too, or the model is over-constrained
  for (int e : rep.redundant) {
    for (size_t k = 0; k < model.joints.size(); ++k) {
      const Joint& j = *model.joints[k];
      if (e < j.lambda_offset || e >= j.lambda_offset + j.NumEquations()) continue;
      const double v = ws.joints[k].phi(e - j.lambda_offset);
      if (std::abs(v) > 1e-6)
        throw InputError("over-constrained: equation '" + j.EquationName(e - j.lambda_offset) +
                             "' depends on the other constraints but is violated by " +
                             std::to_string(v) + " after assembly; remove or change this joint",
                         {"", 0, "joint '" + j.name() + "'"});
    }
    const std::string msg = DescribeEquation(model, e) +
                            ": redundant constraint equation removed (the motion is determined "
                            "without it; its reaction share is carried by the other joints)";
    rep.messages.push_back(msg);
    LogWarning(msg);
  }
  rep.dof = model.nv - (model.nc - static_cast<int>(rep.redundant.size()));
  ProjectVelocities(model, s, ws, lu);
  InitialAccelerations(model, s, ws, lu);
  return rep;
}

}  // namespace flexmb
