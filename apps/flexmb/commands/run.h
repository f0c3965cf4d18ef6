#pragma once
/// \file run.h
/// The "run" and "check" workflows of the command line, as library calls so
/// that other front ends (Python) can reuse them: load a model file, make
/// the initial state consistent, integrate, and write results.csv,
/// summary.json and (optionally) the animation to an output directory.

#include <csignal>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace flexmb {

/// What a run should do.
struct RunOptions {
  std::string model_path;        ///< YAML model file
  std::string out_dir;           ///< output directory (created if missing)
  std::optional<double> t_end;   ///< overrides solver.t_end [s]
  std::optional<double> dt;      ///< overrides solver.dt [s]
  std::string manoeuvre;         ///< the file's manoeuvre to run ("": the file's `manoeuvre`, or none)
  bool animation = false;        ///< write the animation even if output.animation is off
  bool progress = false;         ///< draw a progress bar on `err`
  std::FILE* info = nullptr;     ///< DOF count and file names (nullptr: silent)
  std::FILE* err = nullptr;      ///< warnings and the progress bar (nullptr: silent)
  /// If set, the run stops at the next output time once *interrupt != 0,
  /// which a signal handler sets to the signal's number: SIGTERM ends the
  /// run as "terminated" (exit 143), any other value (SIGINT, Ctrl-C) as
  /// "interrupted" (exit 130).
  const volatile std::sig_atomic_t* interrupt = nullptr;
};

/// How a run ended.
enum class RunStatus { kOk, kInputError, kNumericalError, kInterrupted, kOtherError, kTerminated };

/// Outcome and statistics of a run, also written as summary.json.
struct RunSummary {
  RunStatus status = RunStatus::kOk;
  std::string message;            ///< error message with context (empty if ok)
  std::string model;              ///< model file path
  std::string model_name;         ///< Model::name ("" if not loaded)
  std::string manoeuvre;          ///< the manoeuvre run ("" if none)
  double t_end_requested = 0.0;   ///< end time asked for [s]
  double t_end = 0.0;             ///< simulated time reached [s]
  long steps = 0;                 ///< accepted steps
  long rejected_steps = 0;        ///< rejected step attempts
  long newton_iterations = 0;     ///< Newton iterations of all attempts
  long factorizations = 0;        ///< numeric LU factorizations
  long chord_checks = 0;          ///< full Newton convergence checks with the previous factorization
  long chord_steps = 0;           ///< of these, corrections above the tolerance taken without a new matrix
  double wall_time_s = 0.0;       ///< wall time of the whole run, loading included [s]
  double integration_time_s = 0.0;  ///< wall time of initialization and time integration [s]
  double max_constraint_violation = 0.0;  ///< max |Phi| over accepted steps [m or rad]
  int dof = 0;                    ///< degrees of freedom
  int constraint_equations = 0;   ///< all constraint equations
  int redundant_constraints = 0;  ///< equations removed as redundant
  double steps_per_second = 0.0;  ///< steps / integration_time_s
  long rows = 0;                  ///< rows written to results.csv
  int frames = 0;                 ///< animation frames written
  std::vector<std::string> warnings;  ///< warnings issued during initialization and the run
  /// The element with the largest share of the scaled Newton residual when
  /// the run failed ("force element 'k'"; "" if none was named).
  std::string culprit;
  double culprit_share = 0.0;     ///< its share, in [0, 1]
  /// Largest local error estimate of a fixed-step run (1 = the tolerance;
  /// 0 for adaptive runs).
  double max_error_estimate = 0.0;
  /// Step size that would meet the tolerance [s]; 0 if it was met.
  double dt_needed = 0.0;
};

/// "ok", "failed", "interrupted" or "terminated".
const char* StatusName(RunStatus status);

/// Process exit code of a run: 0 ok, 2 input error, 130 interrupted
/// (SIGINT), 143 terminated (SIGTERM), 1 otherwise.
int ExitCode(RunStatus status);

/// Runs the model file as described by `options`. Rows of results.csv are
/// written every output.interval (0: every step) and animation frames every
/// output.animation_interval; the integrator stops exactly on the finer of
/// the two grids, and each output goes to the first stop at or after its
/// own grid time (exactly on it when one interval is a multiple of the
/// other), plus a last row and frame at the end time. Never throws for faults of
/// the model or the solve: they end up in the summary (status, message), and
/// results.csv keeps the rows written before the fault. summary.json is
/// written in every case in which the output directory can be created.
RunSummary RunModel(const RunOptions& options);

/// The summary as a JSON object (keys as in RunSummary, "status" as
/// StatusName; non-finite numbers as null).
std::string SummaryJson(const RunSummary& summary);

/// Loads the model file, makes its initial state consistent and prints a
/// report to `out`: counts of bodies, joints (with equations), forces and
/// sensors, "degrees of freedom: N", "constraint equations: M (R redundant)"
/// and the redundancy warnings; with `manoeuvre`, of the model with that
/// entry of the file's `manoeuvres` applied (as `flexmb run --manoeuvre`
/// does). Throws InputError / NumericalError.
void CheckModel(const std::string& model_path, std::FILE* out, const std::string& manoeuvre = "");

class Model;

/// The report of CheckModel for a model built in code (e.g. the truck of a
/// lane-change file): bodies, joints with their equations, forces, sensors,
/// then the constraint analysis of the initialization (degrees of freedom,
/// redundant equations, warnings). `model_path` names the file in the
/// report and in errors without a file of their own.
void ReportModel(const Model& model, const std::string& model_path, std::FILE* out);

}  // namespace flexmb
