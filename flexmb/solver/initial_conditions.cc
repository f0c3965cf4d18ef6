#include "flexmb/solver/initial_conditions.h"

#include <Eigen/OrderingMethods>
#include <Eigen/QR>
#include <Eigen/SparseQR>
#include <algorithm>
#include <cmath>
#include <cstdio>

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

namespace {

/// Joints whose equations may be redundant: all but the tree parts of the
/// joint graph. A body held by a single joint (a leaf) gives that joint's
/// equations their own columns, so they are independent of every other
/// equation; pruning leaves repeatedly leaves the loops (and the paths that
/// join them to the ground).
std::vector<char> LoopJoints(const Model& model) {
  const int nb = static_cast<int>(model.bodies.size());
  const int nj = static_cast<int>(model.joints.size());
  std::vector<int> degree(nb, 0);
  std::vector<std::vector<int>> joints_of(nb);
  for (int k = 0; k < nj; ++k)
    for (int mk : {model.joints[k]->marker_i, model.joints[k]->marker_j}) {
      const int b = model.markers[mk].body;
      ++degree[b];
      joints_of[b].push_back(k);
    }
  std::vector<char> alive(nj, 1);
  std::vector<int> leaves;
  for (int b = 1; b < nb; ++b)
    if (degree[b] == 1 && model.bodies[b]->MarkerJacobianFullRank()) leaves.push_back(b);
  while (!leaves.empty()) {
    const int b = leaves.back();
    leaves.pop_back();
    if (degree[b] != 1) continue;
    for (int k : joints_of[b]) {
      if (!alive[k]) continue;
      alive[k] = 0;
      for (int mk : {model.joints[k]->marker_i, model.joints[k]->marker_j}) {
        const int o = model.markers[mk].body;
        if (--degree[o] == 1 && o != 0 && model.bodies[o]->MarkerJacobianFullRank()) leaves.push_back(o);
      }
      break;
    }
  }
  return alive;
}

}  // namespace

std::vector<int> FindRedundantEquations(const Model& model, const State& s, double tol) {
  std::vector<int> redundant;
  if (model.nc == 0) return redundant;
  // candidate rows: equations of loop joints; candidate columns: their bodies
  const std::vector<char> loop = LoopJoints(model);
  std::vector<int> rows, col_of(model.nv, -1);
  int ncols = 0;
  for (size_t k = 0; k < model.joints.size(); ++k) {
    if (!loop[k]) continue;
    const Joint& j = *model.joints[k];
    for (int q = 0; q < j.NumEquations(); ++q) rows.push_back(j.lambda_offset + q);
    for (int mk : {j.marker_i, j.marker_j}) {
      const Body& b = *model.bodies[model.markers[mk].body];
      for (int c = b.v_offset; c < b.v_offset + b.nv(); ++c)
        if (col_of[c] < 0) col_of[c] = ncols++;
    }
  }
  if (rows.empty()) return redundant;
  Workspace ws;
  InitWorkspace(model, ws);
  EvaluateMarkers(model, s, ws);
  EvaluateConstraints(model, s, ws);
  // the candidate block of B (rows in model order)
  std::vector<int> row_pos(model.nc, -1);
  for (size_t r = 0; r < rows.size(); ++r) row_pos[rows[r]] = static_cast<int>(r);
  std::vector<Eigen::Triplet<double, int>> trip;
  for (int c = 0; c < ws.B.outerSize(); ++c)
    for (SparseMat::InnerIterator it(ws.B, c); it; ++it)
      if (row_pos[it.row()] >= 0 && col_of[c] >= 0) trip.emplace_back(row_pos[it.row()], col_of[c], it.value());
  const int nr = static_cast<int>(rows.size());
  SparseMat Bs(nr, ncols);
  Bs.setFromTriplets(trip.begin(), trip.end());
  if (static_cast<long>(nr) * ncols <= 4'000'000L) {
    // greedy modified Gram-Schmidt over the rows in model order (twice, for
    // numerical orthogonality): a row that adds nothing to the earlier ones
    // is redundant
    const MatX B = MatX(Bs);
    MatX basis(ncols, std::min(nr, ncols));
    int rank = 0;
    for (int e = 0; e < nr; ++e) {
      VecX r = B.row(e).transpose();
      const double n0 = r.norm();
      for (int pass = 0; pass < 2; ++pass)
        for (int k = 0; k < rank; ++k) r -= basis.col(k).dot(r) * basis.col(k);
      const double n1 = r.norm();
      if (n0 == 0.0 || n1 <= tol * n0 || rank == ncols) {
        redundant.push_back(rows[e]);
      } else {
        basis.col(rank++) = r / n1;
      }
    }
  } else {
    SparseMat Bt = Bs.transpose();
    Eigen::SparseQR<SparseMat, Eigen::COLAMDOrdering<int>> qr;
    qr.setPivotThreshold(tol);
    qr.compute(Bt);
    const int rank = static_cast<int>(qr.rank());
    for (int k = rank; k < nr; ++k) redundant.push_back(rows[qr.colsPermutation().indices()(k)]);
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
  // removed equations must hold too, or the model is over-constrained;
  // one message per joint, naming all of its removed equations
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const Joint& j = *model.joints[k];
    std::vector<std::string> names;
    for (int e : rep.redundant) {
      if (e < j.lambda_offset || e >= j.lambda_offset + j.NumEquations()) continue;
      const double v = ws.joints[k].phi(e - j.lambda_offset);
      if (std::abs(v) > 1e-6) {
        char value[32];
        std::snprintf(value, sizeof(value), "%.3g", v);
        throw InputError("over-constrained: equation '" + j.EquationName(e - j.lambda_offset) +
                             "' depends on the other constraints but is violated by " + value +
                             " after assembly; remove or change this joint",
                         {"", 0, "joint '" + j.name() + "'"});
      }
      names.push_back(j.EquationName(e - j.lambda_offset));
    }
    if (names.empty()) continue;
    std::string list;
    for (size_t n = 0; n < names.size(); ++n) list += (n ? ", " : "") + names[n];
    const bool one = names.size() == 1;
    const std::string msg = "joint '" + j.name() + "': " + std::to_string(names.size()) + " redundant constraint " +
                            (one ? "equation" : "equations") + " removed (" + list +
                            ") (the motion is determined without " + (one ? "it" : "them") +
                            "; the reaction share is carried by the other joints)";
    rep.messages.push_back(msg);
    LogWarning(msg);
  }
  rep.dof = model.nv - (model.nc - static_cast<int>(rep.redundant.size()));
  ProjectVelocities(model, s, ws, lu);
  InitialAccelerations(model, s, ws, lu);
  return rep;
}

}  // namespace flexmb
