#include "flexmb/reduction/rigid_modes.h"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "flexmb/common/error.h"

namespace flexmb::reduction {

namespace {

// rows: `numbering` (free or full) of every node and component; n rows
Eigen::MatrixXd RigidVectors(const fe::Mesh& mesh, const std::vector<std::array<int, 6>>& numbering, int n_rows,
                             const fe::Vec3& origin) {
  if (numbering.size() != mesh.nodes.size()) {
    throw InputError("rigid-body vectors: the DOF map has " + std::to_string(numbering.size()) +
                     " nodes, the mesh " + std::to_string(mesh.nodes.size()));
  }
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(n_rows, 6);
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    const fe::Vec3 x = mesh.nodes[n].x - origin;
    for (int c = 0; c < 6; ++c) {
      const int f = numbering[n][static_cast<size_t>(c)];
      if (f < 0) continue;
      r(f, c) = 1.0;
      if (c < 3) {
        // (theta x x)_c = theta_j x_k - theta_k x_j
        const int j = (c + 1) % 3, k = (c + 2) % 3;
        r(f, 3 + j) = x[k];
        r(f, 3 + k) = -x[j];
      }
    }
  }
  return r;
}

}  // namespace

Eigen::MatrixXd RigidBodyVectors(const fe::Mesh& mesh, const fe::DofMap& dofs, const fe::Vec3& origin) {
  return RigidVectors(mesh, dofs.free, dofs.n_free, origin);
}

Eigen::MatrixXd RigidBodyVectorsFull(const fe::Mesh& mesh, const fe::DofMap& dofs, const fe::Vec3& origin) {
  return RigidVectors(mesh, dofs.full, dofs.n_full, origin);
}

RigidSplit SplitRigidMotions(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness,
                             const Eigen::MatrixXd& candidates, double stiffness_scale) {
  const Eigen::Index m = mass.rows();
  if (mass.cols() != m || stiffness.rows() != m || stiffness.cols() != m || candidates.rows() != m) {
    throw InputError("rigid motions: the reduced matrices and the candidates differ in size");
  }
  RigidSplit out;
  // unit M-norm candidates, zero ones dropped
  Eigen::MatrixXd c(m, candidates.cols());
  Eigen::Index kc = 0;
  for (Eigen::Index j = 0; j < candidates.cols(); ++j) {
    const double norm2 = candidates.col(j).dot(mass * candidates.col(j));
    if (norm2 > 0.0 && std::isfinite(norm2)) c.col(kc++) = candidates.col(j) / std::sqrt(norm2);
  }
  c.conservativeResize(m, kc);
  out.dependent = static_cast<int>(candidates.cols() - kc);

  // M-orthonormal basis of their span, dependent directions dropped
  Eigen::MatrixXd qn(m, 0);
  if (kc > 0) {
    Eigen::MatrixXd g = c.transpose() * mass * c;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ge(0.5 * (g + g.transpose()));
    const double gmax = ge.eigenvalues().maxCoeff();
    Eigen::Index kept = 0;
    qn.resize(m, kc);
    for (Eigen::Index j = 0; j < kc; ++j) {
      const double gj = ge.eigenvalues()[j];
      if (gj > 1e-10 * gmax) qn.col(kept++) = c * ge.eigenvectors().col(j) / std::sqrt(gj);
    }
    qn.conservativeResize(m, kept);
    out.dependent += static_cast<int>(kc - kept);
  }
  const Eigen::Index k = qn.cols();

  // eigenvalues of the whole reduced problem
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> all(0.5 * (stiffness + stiffness.transpose()),
                                                                0.5 * (mass + mass.transpose()),
                                                                Eigen::EigenvaluesOnly | Eigen::Ax_lBx);
  if (all.info() != Eigen::Success) {
    throw NumericalError("rigid motions: the reduced mass matrix is not positive definite");
  }
  const Eigen::VectorXd& nu = all.eigenvalues();

  // candidate directions ordered by strain energy
  Eigen::MatrixXd rotated(m, k);
  out.rayleigh.resize(k);
  if (k > 0) {
    const Eigen::MatrixXd a = qn.transpose() * stiffness * qn;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ae(0.5 * (a + a.transpose()));
    out.rayleigh = ae.eigenvalues();
    rotated = qn * ae.eigenvectors();
  }
  for (Eigen::Index j = k; j >= 1; --j) {
    const double mu = out.rayleigh[j - 1];
    const bool rigid = j < m ? mu <= 1e-6 * nu[j] : mu <= 1e-10 * stiffness_scale;
    if (rigid) {
      out.count = static_cast<int>(j);
      break;
    }
  }
  out.rigid = rotated.leftCols(out.count);

  // complement: orthogonal to M * rigid in the Euclidean sense
  if (out.count == 0) {
    out.complement = Eigen::MatrixXd::Identity(m, m);
  } else {
    const Eigen::MatrixXd b = mass * out.rigid;
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(b);
    const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(m, m);
    out.complement = q.rightCols(m - out.count);
  }
  return out;
}

}  // namespace flexmb::reduction
