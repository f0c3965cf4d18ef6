#include "flexmb/solver/linearization.h"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/solver/assembler.h"

namespace flexmb {
namespace {

// the top-left nv x nv block of the iteration matrix ws.S, dense
MatX LinearizationTopLeft(const Workspace& ws, int nv) {
  MatX out = MatX::Zero(nv, nv);
  for (int c = 0; c < nv; ++c)
    for (SparseMat::InnerIterator it(ws.S, c); it; ++it)
      if (it.row() < nv) out(it.row(), c) = it.value();
  return out;
}

// names the first body whose mass block has a (near) zero diagonal entry,
// "" if none
std::string LinearizationMasslessBody(const Model& m, const Workspace& ws) {
  double scale = 0.0;
  for (const MatX& blk : ws.mass)
    if (blk.size() > 0) scale = std::max(scale, blk.diagonal().cwiseAbs().maxCoeff());
  for (size_t k = 0; k < m.bodies.size(); ++k) {
    const MatX& blk = ws.mass[k];
    for (int i = 0; i < blk.rows(); ++i)
      if (!(blk(i, i) > 1e-12 * scale))
        return "body '" + m.bodies[k]->name() + "' has no mass or inertia in its velocity coordinate " +
               std::to_string(i);
  }
  return "";
}

}  // namespace

std::string VelocityCoordinateName(const Model& m, int c) {
  for (const auto& b : m.bodies)
    if (c >= b->v_offset && c < b->v_offset + b->nv())
      return "body '" + b->name() + "' (velocity coordinate " + std::to_string(c - b->v_offset) + ")";
  return "velocity coordinate " + std::to_string(c);
}

MatX PartitionedNullSpace(const MatX& B, double tol, std::vector<int>& independent) {
  const int nv = static_cast<int>(B.cols());
  independent.clear();
  if (B.rows() == 0) {
    for (int c = 0; c < nv; ++c) independent.push_back(c);
    return MatX::Identity(nv, nv);
  }
  Eigen::ColPivHouseholderQR<MatX> qr(B);
  qr.setThreshold(tol);
  const int r = static_cast<int>(qr.rank());
  std::vector<char> dep(nv, 0);
  std::vector<int> dependent;
  for (int k = 0; k < r; ++k) dep[qr.colsPermutation().indices()(k)] = 1;
  for (int c = 0; c < nv; ++c) (dep[c] ? dependent : independent).push_back(c);
  const int n = nv - r;
  MatX Bd(B.rows(), r), Bi(B.rows(), n);
  for (int k = 0; k < r; ++k) Bd.col(k) = B.col(dependent[k]);
  for (int k = 0; k < n; ++k) Bi.col(k) = B.col(independent[k]);
  // B_d x_d + B_i x_i = 0: x_d = -B_d^+ B_i x_i (B_d has full column rank)
  const MatX X = -Bd.colPivHouseholderQr().solve(Bi);
  MatX N = MatX::Zero(nv, n);
  for (int k = 0; k < n; ++k) N(independent[k], k) = 1.0;
  for (int k = 0; k < r; ++k) N.row(dependent[k]) = X.row(k);
  return N;
}

void ReduceWithBasis(LinearizedSystem& L, const MatX& N) {
  L.N = N;
  L.Mr = N.transpose() * L.M * N;
  L.Mr = 0.5 * (L.Mr + L.Mr.transpose()).eval();
  L.Cr = N.transpose() * L.C * N;
  L.Kr = N.transpose() * L.K * N;
}

LinearizedSystem Linearize(const Model& m, const State& s, const VecX& a, Workspace& ws) {
  const int nv = m.nv;
  if (nv == 0) throw InputError("the model has no degrees of freedom (no body with velocities)");
  LinearizedSystem L;
  EvaluateMarkers(m, s, ws);
  EvaluateConstraints(m, s, ws);
  EvaluateForces(m, s, ws, true);
  AddMassTangents(m, s, a, ws);
  AssembleIterationMatrix(m, s, ws, MatrixCoefficients{1.0, 0.0, 0.0, false});
  L.M = LinearizationTopLeft(ws, nv);
  AssembleIterationMatrix(m, s, ws, MatrixCoefficients{0.0, 1.0, 0.0, false});
  L.C = LinearizationTopLeft(ws, nv);
  AssembleIterationMatrix(m, s, ws, MatrixCoefficients{0.0, 0.0, 1.0, true});
  L.K = LinearizationTopLeft(ws, nv);
  L.B = MatX(ws.B);
  if (!L.M.allFinite() || !L.C.allFinite() || !L.K.allFinite() || !L.B.allFinite())
    throw NumericalError("linearization: the mass, damping or stiffness matrix is not finite at this state");

  // null space of B: the last columns of Q in B^T P = Q R
  if (L.B.rows() == 0) {
    L.N = MatX::Identity(nv, nv);
  } else {
    Eigen::ColPivHouseholderQR<MatX> qr(L.B.transpose());
    qr.setThreshold(std::max(1e-12, m.solver.redundancy_tol));
    L.constraint_rank = static_cast<int>(qr.rank());
    const MatX Q = qr.householderQ() * MatX::Identity(nv, nv);
    L.N = Q.rightCols(nv - L.constraint_rank);
  }
  if (L.N.cols() == 0)
    throw InputError("the model has no degrees of freedom: the joints and drivers fix every body (" +
                     std::to_string(nv) + " velocity coordinates, constraint rank " +
                     std::to_string(L.constraint_rank) + ")");
  ReduceWithBasis(L, MatX(L.N));
  const Eigen::LLT<MatX> llt(L.Mr);
  const double mscale = L.Mr.diagonal().cwiseAbs().maxCoeff();
  bool ok = llt.info() == Eigen::Success;
  if (ok) {
    // a Cholesky factor with a tiny pivot: singular in practice
    const VecX d = MatX(llt.matrixL()).diagonal();
    ok = d.minCoeff() > 1e-7 * std::sqrt(mscale);
  }
  if (!ok) {
    const std::string who = LinearizationMasslessBody(m, ws);
    throw NumericalError("singular mass matrix: " +
                         (who.empty() ? std::string("a free motion of the constrained system carries no mass")
                                      : who + " (a massless body)") +
                         "; give it mass and inertia or constrain its free motion");
  }
  return L;
}

}  // namespace flexmb
