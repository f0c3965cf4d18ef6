#pragma once
/// \file settings.h
/// Solver and output settings of a model, and the one set of rules they obey
/// whoever sets them (model file, lane-change file, command line, code).

#include <optional>
#include <string>

namespace flexmb {

/// What `flexmb run` does with a model (model file: solver.analysis).
enum class Analysis {
  kDynamics,              ///< time integration from the initial state
  kStatics,               ///< static equilibrium only (as `flexmb statics`)
  kStaticsThenDynamics,   ///< static equilibrium, then time integration from it
};

/// Settings of the time integrator and the nonlinear solvers.
struct SolverSettings {
  double t_end = 1.0;          ///< end time [s]
  double dt = 1e-3;            ///< (initial) step size [s]
  double dt_min = 1e-10;       ///< smallest step before giving up [s]
  double dt_max = 0.0;         ///< largest step with step-size control [s]; 0 = 100 dt
  double rho_inf = 0.8;        ///< spectral radius at infinity of generalized-alpha, in [0, 1]
  bool adaptive = false;       ///< step-size control by the local error estimate
  double rtol = 1e-4;          ///< relative tolerance of the error estimate
  double atol = 1e-6;          ///< absolute tolerance of the error estimate [m, rad]
  double newton_tol = 1e-10;   ///< Newton tolerance on the scaled correction and constraints
  int max_newton = 12;         ///< Newton iterations before the step is cut
  bool geometric_stiffness = true;  ///< include d(B^T lambda)/dq in the iteration matrix
  /// Modified Newton: keep the factorized iteration matrix over Newton
  /// iterations and steps while the iteration contracts fast (rate <=
  /// jacobian_reuse_rate); a fresh matrix when it does not, when the step size
  /// changes, or when an attempt fails (which is then repeated with full
  /// Newton). Same convergence test (newton_tol) as full Newton.
  bool jacobian_reuse = false;
  /// Largest contraction ||dx_k|| / ||dx_k-1|| accepted with a reused
  /// iteration matrix, in (0, 1); above it the matrix is refreshed.
  double jacobian_reuse_rate = 0.2;
  double assembly_tol = 1e-10; ///< position assembly tolerance on ||Phi|| [m]
  double redundancy_tol = 1e-8; ///< relative rank tolerance for redundant constraints
  Analysis analysis = Analysis::kDynamics;  ///< what `flexmb run` does (solver.analysis)
  /// Static equilibrium (analysis statics / statics_then_dynamics, `flexmb
  /// statics`, `modes --at statics`): hold the directions without stiffness
  /// by the damping from the first iteration (solver.statics_hold: always;
  /// StaticsSettings::hold_always), as a vehicle on its tires needs; false
  /// (singular, the default): only once the tangent is found singular.
  bool statics_hold_always = false;
  /// Force residual of the static equilibrium relative to the largest
  /// applied force (solver.statics_residual_tol), > 0.
  double statics_residual_tol = 1e-8;
};

/// A broken rule of the solver settings: the model-file key it is about and
/// the message ("'dt_min' must not exceed 'dt'").
struct SettingsProblem {
  const char* key;
  std::string message;
};

/// The first rule of `s` that is broken (ranges of each setting and the
/// rules tying them together: dt_min <= dt, dt_max = 0 or >= dt), or none.
/// Every writer of SolverSettings checks through this one function.
std::optional<SettingsProblem> FindSolverSettingsProblem(const SolverSettings& s);

/// Values that replace the model file's, e.g. from the command line.
struct SolverOverrides {
  std::optional<double> t_end;  ///< end time [s] (--t-end)
  std::optional<double> dt;     ///< (initial) step size [s] (--dt)
  /// Entry of the model file's `manoeuvres` to run (--manoeuvre); empty:
  /// the file's `manoeuvre`, or the file as written.
  std::string manoeuvre;
};

/// Applies `o` to `s`, then checks `s` by FindSolverSettingsProblem; throws
/// InputError naming the option ("--dt 0.5: 'dt_min' must not exceed 'dt'").
/// Called before the model is finalized, so an override is checked like the
/// file's value.
void ApplySolverOverrides(const SolverOverrides& o, SolverSettings& s);

/// Settings of the result output.
struct OutputSettings {
  double interval = 0.0;             ///< time between result rows [s]; 0 = every step
  bool animation = false;            ///< write anim.pvd and .vtu frames
  double animation_interval = 0.02;  ///< time between animation frames [s]
  /// Factor on the elastic displacement of flexible bodies' FE meshes in the
  /// animation (1 = true scale, 0 = undeformed), >= 0.
  double deformation_scale = 1.0;
};

}  // namespace flexmb
