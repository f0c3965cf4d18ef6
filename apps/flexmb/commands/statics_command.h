#pragma once
/// \file statics_command.h
/// `flexmb statics MODEL.yaml --out DIR` (and `flexmb run` of a model file
/// with solver.analysis: statics): the static equilibrium under gravity and
/// the applied loads, drivers held at their values at time `time`, by
/// SolveStatics with automatic load stepping. Writes DIR/results.csv (one
/// row per converged load step: load_factor, iterations, residual, then the
/// sensor columns), DIR/summary.json and, with the animation, one frame per
/// load step (its time is the load factor).

#include <cstdio>
#include <optional>
#include <string>

namespace flexmb::cli {

/// What the statics command should do.
struct StaticsCommandOptions {
  std::string model_path;          ///< YAML model file
  std::string out_dir;             ///< output directory (created if missing)
  double time = 0.0;               ///< time at which drivers and loads are evaluated [s]
  bool animation = false;          ///< write anim.pvd (as output.animation)
  std::FILE* info = nullptr;       ///< result lines (nullptr: silent)
  std::FILE* err = nullptr;        ///< warnings and errors (nullptr: silent)
};

/// Runs the static solve; returns the exit code (0 ok, 2 input error, 1
/// no equilibrium or other error). Never throws for faults of the model:
/// summary.json says "status": "failed" with the message naming the body
/// or joint and the load factor reached.
int StaticsCommand(const StaticsCommandOptions& options);

/// True if the model file asks for a static solve (solver.analysis:
/// statics); false also when it cannot be loaded.
bool ModelAsksForStatics(const std::string& model_path);

}  // namespace flexmb::cli
