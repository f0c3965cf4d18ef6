#pragma once
/// \file simulator.h
/// Runs a model in time: consistent initial conditions, generalized-alpha
/// steps with step-size control (local error estimate; step cutting on Newton
/// failure), and a callback at each output time.

#include <functional>
#include <string>

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/generalized_alpha.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/statics.h"

namespace flexmb {

/// Called at t0 and at every output time with the state and an up-to-date
/// workspace (markers, constraints, forces and accelerations of that state).
using Observer = std::function<void(const State&, const Workspace&)>;

/// A run stops as a runaway when it has rejected more than this many times
/// as many step attempts as it accepted ...
inline constexpr double kRunawayRatio = 1000.0;
/// ... and at least this many.
inline constexpr long kRunawayMinRejected = 1000;

/// Whether `rejected` step attempts for `accepted` steps make a runaway
/// (kRunawayRatio, kRunawayMinRejected).
bool IsRunaway(long rejected, long accepted);

/// A fixed-step run warns when its local error estimate (1 = the tolerance
/// of SolverSettings rtol, atol) exceeds this.
inline constexpr double kFarAboveTolerance = 100.0;

/// The local error estimate of a fixed-step run against its tolerance.
struct AccuracyReport {
  double max_error = 0.0;  ///< largest error estimate of an accepted step (1 = tolerance)
  double t = 0.0;          ///< time at the end of that step [s]
  double dt_needed = 0.0;  ///< step that would meet the tolerance everywhere [s] (0: met)
  std::string warning;     ///< the warning issued ("" if none)
};

/// Simulation of one model.
class Simulator {
 public:
  /// Finalizes nothing: `model` must be finalized and outlive the simulator.
  explicit Simulator(const Model& model);

  /// Consistent initial conditions from the model's initial state.
  const ConstraintReport& Initialize();

  /// Integrates to t_end [s], calling `observer` at t0 (if at the start) and
  /// every `output_interval` [s] (0: every step). A fixed-step run whose
  /// Newton iteration fails cuts that step into pieces (halved on failure,
  /// doubled again on success, up to the step) that end on the step's own
  /// time, so the observer is called at every output time whatever path the
  /// step took. Throws NumericalError naming the joint or body at fault
  /// when the step size falls below dt_min, or when the run is a runaway
  /// (IsRunaway: far more rejected attempts than accepted steps).
  void Run(double t_end, double output_interval, const Observer& observer);

  /// Moves the (initialized) current state to its static equilibrium at its
  /// time (SolveStatics, velocities zero) and restarts the integrator from
  /// there (accelerations and multipliers of the new state). Throws
  /// NumericalError as SolveStatics; the state is then unchanged in time.
  /// With `keep_velocities` the velocities of before are given back to the
  /// settled state, projected onto its velocity constraints: a vehicle
  /// rolling off from the equilibrium of its standing self (the forward
  /// speed and wheel spins kept, the sag of springs, tires and an elastic
  /// frame already there).
  StaticsResult SettleStatics(const StaticsSettings& settings = {}, bool keep_velocities = false);

  /// Evaluates the workspace at the current state (markers, constraints,
  /// forces) so that sensors can read it.
  void RefreshWorkspace();

  State& state() { return state_; }
  const Workspace& workspace() const { return ws_; }
  const IntegratorStats& stats() const { return integrator_.stats; }
  const ConstraintReport& constraints() const { return report_; }
  /// Current step size [s].
  double step_size() const { return h_; }
  /// The local error estimate of the steps of a fixed-step run (all zero
  /// for an adaptive run, whose error control meets the tolerance). At the
  /// end of Run, a fixed-step run whose estimate went above
  /// kFarAboveTolerance issues a warning (LogWarning, also kept here) with
  /// the step size that would be needed: 0.5 h err^(-1/3), the smallest
  /// over the steps (the local error of generalized-alpha is third order in
  /// h once the step resolves the motion; the factor 0.5 covers coarse steps
  /// that do not, where the estimate grows more slowly).
  const AccuracyReport& accuracy() const { return accuracy_; }
  /// The elements named by the last failure: largest share of the scaled
  /// Newton residual first, or, when the error control cut the step below
  /// dt_min (the last attempt converged), the bodies with the largest
  /// shares of the local error estimate; empty if the run has not failed.
  const std::vector<ResidualShare>& failure_shares() const { return failure_shares_; }

 private:
  // fixed step: integrates from the current time to t_target in pieces
  // (the first h / 2); throws through Fail below dt_min
  void CutStep(double t_target, double h, double eps, const std::function<void()>& check_runaway);
  /// Lets go of the joints whose release time is reached (up to eps [s]) and
  /// restarts the integrator from the current state with them released:
  /// accelerations and multipliers consistent again, as the acceleration
  /// jumps at a release (Joint::release_time).
  void ReleaseJoints(double eps);
  // throws NumericalError: `what`, the integrator's failure hint and the
  // elements with the largest shares of the residual (entity: the largest)
  [[noreturn]] void Fail(const std::string& what);

  const Model& model_;
  State state_;
  Workspace ws_;
  ConstraintReport report_;
  GeneralizedAlpha integrator_;
  double h_;
  bool initialized_ = false;
  std::vector<ResidualShare> failure_shares_;
  AccuracyReport accuracy_;
  // records the error estimate of an accepted fixed step of size h
  void NoteAccuracy(double h);
};

}  // namespace flexmb
