#pragma once
/// \file craig_bampton_basis.h
/// Steps 1 to 4 of the Craig-Bampton reduction (THEORY section 2) on an
/// assembled model: boundary/interior split, one sparse Cholesky
/// factorization of K_ii, static modes for all boundary DOF in one
/// multi-right-hand-side solve, fixed-interface normal modes by block
/// shift-invert Lanczos on the same factor (shift 0: K_ii is positive
/// definite whenever the static modes exist, and one factor then serves
/// both), and the reduced matrices M_CB = H^T M H,
/// K_CB = H^T K H (see `stiffness`). ReduceCraigBampton (craig_bampton.h) builds on it; tests
/// use it to look at the basis before orthonormalization.

#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"
#include "flexmb/fe/modal.h"
#include "flexmb/reduction/craig_bampton.h"

namespace flexmb::reduction {

/// The Craig-Bampton basis H = [[I, 0], [Psi, Phi]] (rows: boundary, then
/// interior DOF; columns: the reduced coordinates q = (u_b, eta), boundary
/// displacements first, then the modal amplitudes of the normal modes).
struct CraigBamptonBasis {
  std::vector<int> boundary;     ///< free DOF of the boundary, ascending: coordinate k of q is u at boundary[k]
  std::vector<int> interior;     ///< free DOF of the interior, ascending
  /// n_i x n_b static (constraint) modes, -K_ii^{-1} K_ib. For a free body
  /// (K r = 0 for the six geometric rigid-body vectors r) the solve's
  /// round-off along the rigid directions is removed, Psi r_b = r_i exactly.
  Eigen::MatrixXd psi;
  /// n_i x n_f fixed-interface normal modes, Phi^T M_ii Phi = I; with
  /// ReductionOptions::acceleration_modes the acceleration modes follow
  /// (M_ii-orthonormal to them and each other, not eigenvectors)
  Eigen::MatrixXd phi;
  /// their frequencies [Hz]: the normal modes' ascending, then the
  /// acceleration modes' Rayleigh quotients
  Eigen::VectorXd fixed_interface_hz;
  int acceleration_modes = 0;    ///< how many of phi's last columns are acceleration modes
  Eigen::MatrixXd mass;          ///< M_CB = H^T M H, m x m, m = n_b + n_f
  /// K_CB = H^T K H, m x m. BuildCraigBamptonBasis forms it without a
  /// product over the interior: with K_ii Psi = -K_ib the static block is
  /// the Schur complement K_bb + K_bi Psi, the static-normal coupling is
  /// zero and the normal block is Phi^T K_ii Phi; equal to the literal
  /// product up to the static solve's residual (a relative 1e-13 or so on
  /// the reduced frequencies, measured in reduction_cb_test). An imported
  /// basis (body_file/modes_file.h) gets the literal product, as its static modes
  /// need not solve our K_ii.
  Eigen::MatrixXd stiffness;
  /// Median over the free DOF of K_kk / M_kk [rad^2/s^2 in SI]: the scale of
  /// the FE model's eigenvalues, for relative tests.
  double stiffness_scale = 0.0;

  int static_modes() const { return static_cast<int>(boundary.size()); }
  int normal_modes() const { return static_cast<int>(phi.cols()); }
  int size() const { return static_modes() + normal_modes(); }
  /// H q for a block of reduced coordinates (m x k): n_free x k, free numbering.
  Eigen::MatrixXd Expand(const Eigen::MatrixXd& q) const;
};

/// Step 1 of the reduction: the free DOF split into boundary and interior.
struct InterfaceSplit {
  std::vector<char> is_b;        ///< per free DOF: 1 on the boundary
  std::vector<int> local;        ///< per free DOF: its index in `boundary` or `interior`
  std::vector<int> boundary;     ///< free DOF of the boundary, ascending
  std::vector<int> interior;     ///< free DOF of the interior, ascending
  int normal_modes = 0;          ///< fixed-interface modes to solve for first (more with a cut-off)
};

/// The boundary DOF are every free DOF the interface nodes' motion depends
/// on (rows of model.T; only the DOF map and T of `model` are used, so a
/// partial assembly serves). Throws InputError for an interface node that
/// does not exist or has no DOF, an empty interior, or more normal modes
/// than the interior has (without a cut-off).
InterfaceSplit SplitInterface(const fe::Mesh& mesh, const fe::AssembledModel& model, const ReductionOptions& options);

/// For a free body (K r = 0 for its rigid-body vectors r, rows rb at the
/// boundary and ri at the interior, 6 columns): makes Psi r_b = r_i exact,
/// removing the static solve's round-off along the six rigid directions
/// (psi += (ri - psi rb) (rb^T rb)^-1 rb^T), so that the basis holds the
/// rigid motions exactly. `ri` and `psi` may be any same rows of the
/// interior (a process's share). Nothing if rb^T rb is singular.
void ProjectRigidMotions(const Eigen::MatrixXd& rb, const Eigen::MatrixXd& ri, Eigen::MatrixXd& psi);

/// Throws NumericalError (naming the model file `source`) unless the
/// largest diagonal entry of M_ii is positive: without mass there are no
/// fixed-interface modes.
void RequireInteriorMass(double largest_diagonal, const std::string& source);

/// The lowest `count` modes by solve(count) (a fe::ModalResult, whose
/// modes may be any rows of the mode vectors); with a cut-off, the count is
/// grown until a mode above it is found (or the interior of n_i DOF is
/// exhausted) and only the modes below it are returned.
template <class Solve>
fe::ModalResult SolveUpToCutoff(int count, int ni, double cutoff_hz, const Solve& solve) {
  fe::ModalResult r = solve(count);
  while (cutoff_hz > 0.0 && r.frequencies_hz[count - 1] < cutoff_hz && count < ni - 1) {
    count = std::min(ni - 1, 2 * count);
    r = solve(count);
  }
  int keep = count;
  if (cutoff_hz > 0.0) {
    keep = 0;
    while (keep < count && r.frequencies_hz[keep] < cutoff_hz) ++keep;
  }
  fe::ModalResult out;
  out.modes = r.modes.leftCols(keep);
  out.frequencies_hz = r.frequencies_hz.head(keep);
  return out;
}

/// Median over the DOF of K_kk / M_kk (both positive), 1 if there is none:
/// CraigBamptonBasis::stiffness_scale.
double StiffnessScale(const fe::SparseMat& k, const fe::SparseMat& m);

/// Builds the basis for `model` assembled from `mesh` (node ids and
/// positions; the mesh's node list must match the DOF map). Uses
/// options.interface_nodes, normal_modes and cutoff_hz; fills the factorize,
/// static_modes, normal_modes and orthonormalize (reduced matrices) timings.
/// The boundary DOF are every free DOF the interface nodes' motion depends
/// on: a node's own free DOF and, for a node made dependent by a rigid link,
/// the independent node's DOF it follows (so a dependent node can be an
/// interface node, and its motion stays exact). Throws InputError for an
/// interface node that does not exist or has no DOF, or more normal modes
/// than the interior has; NumericalError naming the node and component where
/// K_ii is singular (a mechanism with the interface held).
CraigBamptonBasis BuildCraigBamptonBasis(const fe::Mesh& mesh, const fe::AssembledModel& model,
                                         const ReductionOptions& options, ReductionTimings* timings = nullptr);

}  // namespace flexmb::reduction
