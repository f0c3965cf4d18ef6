#pragma once
/// \file rigid_modes.h
/// Rigid-body motions of a reduced body (THEORY section 2, step 6): the
/// geometric rigid-body vectors of an FE model and their detection and
/// removal in a reduced (Craig-Bampton) space. A rigid motion is recognized
/// by its geometry and its (zero) strain energy, not by a frequency
/// threshold alone, so that a clamped or partly supported body keeps every
/// flexible mode and a free body loses exactly its rigid motions.

#include <Eigen/Core>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::reduction {

/// Geometric rigid-body vectors of the free DOF of an assembled model,
/// n_free x 6: columns 0-2 translate by 1 (model length unit) along basic x,
/// y, z; columns 3-5 rotate by 1 rad about basic x, y, z through `origin`
/// (u_k = theta x (x_k - origin), rotation DOF = theta). Because rigid links
/// move their dependent nodes rigidly, T times a column is the same rigid
/// motion of every active DOF.
Eigen::MatrixXd RigidBodyVectors(const fe::Mesh& mesh, const fe::DofMap& dofs, const fe::Vec3& origin);

/// The same on the full numbering (DofMap::full, n_full x 6): every active
/// DOF, those of dependent (rigid-link) and constrained nodes included, for
/// loads through AssembledModel::M_full.
Eigen::MatrixXd RigidBodyVectorsFull(const fe::Mesh& mesh, const fe::DofMap& dofs, const fe::Vec3& origin);

/// The rigid motions found in a reduced space of dimension m with symmetric
/// mass and stiffness matrices (mass positive definite).
struct RigidSplit {
  int count = 0;                 ///< rigid motions admitted (zero strain energy)
  /// m x count: M-orthonormal reduced coordinates of the rigid motions
  Eigen::MatrixXd rigid;
  /// m x (m - count): orthonormal (Euclidean) columns, each M-orthogonal to
  /// every column of `rigid` to round-off; the identity when count = 0
  Eigen::MatrixXd complement;
  /// Rayleigh quotients x^T K x / x^T M x of the M-orthonormalized candidate
  /// directions, ascending [rad^2/s^2 in SI]; the first `count` are rigid.
  Eigen::VectorXd rayleigh;
  /// Candidate directions dropped because the candidates were linearly
  /// dependent in the M-norm (e.g. rigid vectors that vanish on the reduced
  /// coordinates of a clamped body).
  int dependent = 0;
};

/// Splits the reduced space into rigid motions and their M-orthogonal
/// complement. `candidates` (m x k, k <= 6) are the reduced coordinates of
/// the geometric rigid-body vectors. They are M-orthonormalized (directions
/// dependent to 1e-10 dropped) and rotated to the eigenvectors of their
/// stiffness, Rayleigh quotients mu_1 <= ... <= mu_k. The first r are rigid,
/// r the largest j with mu_j <= 1e-6 nu_{j+1}, nu_1 <= nu_2 <= ... the
/// eigenvalues of the whole reduced problem: a rigid direction has zero
/// strain energy to round-off, the body's next mode lies at least a
/// frequency ratio of 1000 above it. When j = m (no next mode: the reduced
/// space is itself rigid) the test is mu_m <= 1e-10 `stiffness_scale`, a
/// typical eigenvalue of the FE model (e.g. the median of K_kk / M_kk). By the
/// min-max principle nu_j <= mu_j, so a supported body is given j rigid
/// motions only if it has j modes a frequency ratio of 1000 below the next
/// (quasi-rigid motions on very soft supports); a clamped body has none.
RigidSplit SplitRigidMotions(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness,
                             const Eigen::MatrixXd& candidates, double stiffness_scale);

}  // namespace flexmb::reduction
