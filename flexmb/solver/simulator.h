#pragma once
/// \file simulator.h
/// Runs a model in time: consistent initial conditions, generalized-alpha
/// steps with step-size control (local error estimate; step cutting on Newton
/// failure), and a callback at each output time.

#include <functional>

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/generalized_alpha.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/statics.h"

namespace flexmb {

/// Called at t0 and at every output time with the state and an up-to-date
/// workspace (markers, constraints, forces and accelerations of that state).
using Observer = std::function<void(const State&, const Workspace&)>;

/// Simulation of one model.
class Simulator {
 public:
  /// Finalizes nothing: `model` must be finalized and outlive the simulator.
  explicit Simulator(const Model& model);

  /// Consistent initial conditions from the model's initial state.
  const ConstraintReport& Initialize();

  /// Integrates to t_end [s], calling `observer` at t0 (if at the start) and
  /// every `output_interval` [s] (0: every step). Throws NumericalError naming
  /// the joint or body at fault when the step size falls below dt_min.
  void Run(double t_end, double output_interval, const Observer& observer);

  /// Moves the (initialized) current state to its static equilibrium at its
  /// time (SolveStatics, velocities zero) and restarts the integrator from
  /// there (accelerations and multipliers of the new state). Throws
  /// NumericalError as SolveStatics; the state is then unchanged in time.
  StaticsResult SettleStatics(const StaticsSettings& settings = {});

  /// Evaluates the workspace at the current state (markers, constraints,
  /// forces) so that sensors can read it.
  void RefreshWorkspace();

  State& state() { return state_; }
  const Workspace& workspace() const { return ws_; }
  const IntegratorStats& stats() const { return integrator_.stats; }
  const ConstraintReport& constraints() const { return report_; }
  /// Current step size [s].
  double step_size() const { return h_; }

 private:
  const Model& model_;
  State state_;
  Workspace ws_;
  ConstraintReport report_;
  GeneralizedAlpha integrator_;
  double h_;
  bool initialized_ = false;
};

}  // namespace flexmb
