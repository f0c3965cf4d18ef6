#pragma once
/// \file generalized_alpha.h
/// Generalized-alpha integrator for the index-3 DAE
///   M(q) vdot + B^T lambda = Q(q, v, t),  Phi(q, t) = 0
/// in the Lie-group form of Arnold & Bruls (2007) and Bruls, Cardona &
/// Arnold (2012): coordinates are advanced by q_{n+1} = q_n (+) h dq_n with the
/// bodies' exponential maps, so rotations have no singularity at any angle.
/// Newton iterates on the tangent correction with the sparse iteration matrix
///   [[M + (gamma'/beta') C_t + K_t / beta', B^T], [B, 0]]
/// (scaled so that its blocks are O(1) for any h; Bottasso et al. 2008).
/// With SolverSettings::jacobian_reuse the factorized matrix is kept over
/// iterations and steps (modified Newton) while ||dx_k|| / ||dx_k-1|| stays
/// at or below SolverSettings::jacobian_reuse_rate; iterations with a kept
/// matrix evaluate no force derivatives. The convergence test is the same
/// (||dx|| <= newton_tol), and with a kept matrix an iterate is accepted only
/// after at least two iterations of the step, with the last contraction
/// rate within jacobian_reuse_rate and the correction itself within
/// kKeptMatrixErrorFraction newton_tol. An attempt that fails with a kept
/// matrix is repeated at once with full Newton.

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/residual_share.h"
#include "flexmb/solver/sparse_lu.h"

namespace flexmb {

/// Counters of an integration.
struct IntegratorStats {
  long steps = 0;              ///< accepted steps
  long rejected = 0;           ///< steps rejected (error or Newton failure)
  long newton_iterations = 0;  ///< Newton iterations of all attempts
  long factorizations = 0;     ///< numeric LU factorizations
  long chord_checks = 0;       ///< full Newton's convergence checks with the previous factorization
  long chord_steps = 0;        ///< of these, corrections above the tolerance taken without a new matrix (kChordKeepRate)
  double max_constraint_violation = 0.0;  ///< max |Phi| over accepted steps
};

/// Result of one step attempt.
enum class StepStatus { kConverged, kNewtonFailed };

/// One generalized-alpha integrator bound to a model and its workspace.
class GeneralizedAlpha {
 public:
  /// With a kept matrix an iterate is accepted when, besides ||dx|| <=
  /// newton_tol, its estimated remaining error rate / (1 - rate) ||dx|| is at
  /// most this fraction of newton_tol (full Newton's remaining error is
  /// quadratic in ||dx||, far below the tolerance).
  static constexpr double kKeptMatrixErrorFraction = 0.01;

  /// Full Newton accepts a chord correction (the previous iterate's
  /// factorization applied to this iterate's residual) as the step's last
  /// when it is within this fraction of newton_tol; else it refreshes the
  /// matrix at this iterate. The chord correction differs from the Newton
  /// correction by O(|dx_prev|) relatively, and the error left after it is
  /// O(|dx_prev| |dx|).
  static constexpr double kChordAcceptFraction = 1.0;

  /// ... and when it is at most this fraction of the previous correction
  /// (Newton contracts quadratically near the solution; a chord correction
  /// that does not shrink means the previous matrix no longer fits).
  static constexpr double kChordMaxRate = 0.5;

  /// A chord correction above the tolerance that is at most this fraction
  /// of the previous correction is taken as it is, and the next iteration
  /// checks again with the current factorization; a weaker contraction
  /// refreshes the matrix at the iterate. After such a step the check that
  /// ends the step must show this contraction too (instead of
  /// kChordMaxRate), so that the error left is at most about this fraction
  /// of the tolerance, as with a kept matrix (docs/design.md "Convergence
  /// check by a chord step").
  static constexpr double kChordKeepRate = 0.01;

  /// Full Newton tries its first chord check of a step at the iteration
  /// where the last step's was accepted (or after the last that failed);
  /// every this many steps it tries from the second iteration again.
  static constexpr int kChordRelearnSteps = 16;

  /// rho_inf in [0, 1]: spectral radius at infinite frequency (1 = no
  /// numerical damping).
  GeneralizedAlpha(const Model& model, Workspace& ws, double rho_inf);

  /// Starts from a consistent state whose accelerations are in ws.vdot.
  void Start(const State& s);

  /// Attempts a step of size h from `s` (left unchanged). On kConverged the
  /// trial state is kept for Accept() and error_estimate() gives the local
  /// error norm (<= 1 is within tolerance).
  StepStatus TryStep(const State& s, double h);

  /// Weighted RMS norm of the local error estimate of the last converged step,
  /// (beta - 1/6) h^2 (a_{n+1} - a_n), scaled by atol + rtol |h v|.
  double error_estimate() const { return error_; }

  /// Accepts the last converged trial: writes it to `s` (and its
  /// accelerations to ws.vdot) and makes it the start of the next step. The
  /// workspace then holds markers and constraints evaluated at `s`.
  void Accept(State& s);

  /// Equation or body with the largest residual in the last failed attempt.
  const std::string& failure_hint() const { return hint_; }

  /// Whether the last attempt failed (Newton); false when it converged.
  bool last_failed() const { return last_failed_; }

  /// The bodies, joints and force elements with the largest shares of the
  /// scaled Newton residual of the last failed attempt, largest first
  /// (LargestResidualShares; at most `count`). Empty if the last attempt
  /// converged. Allocates: for failed runs only.
  std::vector<ResidualShare> FailureShares(int count) const;

  /// The bodies with the largest shares of the local error estimate of the
  /// last attempt, which converged (the sum over each body's coordinates of
  /// the squared scaled errors, as a fraction of the whole), largest first,
  /// at most `count`, none below 1 %. Empty if the last attempt failed.
  std::vector<ResidualShare> ErrorShares(int count) const;

  IntegratorStats stats;

 private:
  // one attempt; reuse: modified Newton (SolverSettings::jacobian_reuse)
  StepStatus Attempt(const State& s, double h, bool reuse);
  // assembles the iteration matrix at the trial state and factorizes it;
  // false (with the hint set) if it is singular
  bool FactorizeIterationMatrix(const MatrixCoefficients& coef, double h);

  const Model& model_;
  Workspace& ws_;
  SparseLu lu_;
  double am_, af_, gamma_, beta_;
  double error_ = 0.0;
  std::string hint_;
  bool last_failed_ = false;
  double last_bp_ = 1.0;  // d vdot / d dx of the last attempt
  double last_h_ = 0.0;   // step size of the last attempt
  // factorization in lu_ usable for steps of size matrix_h_ (modified Newton)
  bool have_matrix_ = false;
  double matrix_h_ = 0.0;
  bool used_kept_ = false;  // the last attempt iterated with a kept matrix
  double rate_ = 1.0;       // last contraction rate with the kept matrix
  // accepted state of the integrator: a (pseudo-acceleration), vdot
  VecX a_, vdot_;
  // trial values
  VecX a1_, vdot1_, q1_, v1_, lam1_, dq_, res_, dx_;
  VecX rhs_probe_;  // right-hand side of a chord check, kept for the Newton solve
  int probe_from_ = 1;    // first iteration of a step with a chord check (full Newton)
  long probe_steps_ = 0;  // converged full Newton steps, for kChordRelearnSteps
  State trial_;
};

}  // namespace flexmb
