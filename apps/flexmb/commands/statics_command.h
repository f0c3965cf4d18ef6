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
#include <vector>

#include "apps/flexmb/commands/analysis_support.h"
#include "flexmb/solver/statics.h"

namespace flexmb::cli {

/// What the statics command should do.
struct StaticsCommandOptions {
  std::string model_path;          ///< YAML model file (with model_text: its name in messages)
  std::string model_text;          ///< the model-file text itself (empty: read model_path)
  std::string out_dir;             ///< output directory (created if missing; empty: no files)
  double time = 0.0;               ///< time at which drivers and loads are evaluated [s]
  std::string manoeuvre;           ///< entry of the file's `manoeuvres` (--manoeuvre; empty: the file's)
  bool animation = false;          ///< write anim.pvd (as output.animation)
  std::FILE* info = nullptr;       ///< result lines (nullptr: silent)
  std::FILE* err = nullptr;        ///< warnings and errors (nullptr: silent)
};

/// The equilibrium of StaticsAnalysis, as written to the files.
struct StaticsOutcome : AnalysisOutcome {
  std::string model_name;                ///< the model's name
  double load_factor = 0.0;              ///< load factor reached (1: the full load)
  StaticsResult solve;                   ///< Newton iterations, residual [N, N m], load steps, cuts
  std::vector<std::string> columns;      ///< the columns of results.csv
  std::vector<std::vector<double>> rows; ///< its rows, one per converged load step
  VecX q;                                ///< position coordinates at the equilibrium (the last one reached)
  VecX lambda;                           ///< constraint multipliers there
  std::vector<std::string> bodies;       ///< body names
  std::vector<int> body_q_offset;        ///< each body's first entry in q
  std::vector<int> body_nq;              ///< each body's number of position coordinates
  int dof = 0;                           ///< degrees of freedom of the model
  int constraint_equations = 0;          ///< constraint equations
};

/// The static solve of `flexmb statics`: the result, and the files of the
/// command in options.out_dir unless it is empty. Faults of the model end
/// up in the result's code and message, never as exceptions.
StaticsOutcome StaticsAnalysis(const StaticsCommandOptions& options);

/// Runs the static solve; returns the exit code (0 ok, 2 input error, 1
/// no equilibrium or other error). Never throws for faults of the model:
/// summary.json says "status": "failed" with the message naming the body
/// or joint and the load factor reached.
int StaticsCommand(const StaticsCommandOptions& options);

/// True if the model file, with its `manoeuvres` entry `manoeuvre` (empty:
/// the file's own choice), asks for a static solve (solver.analysis:
/// statics); false also when it cannot be loaded.
bool ModelAsksForStatics(const std::string& model_path, const std::string& manoeuvre = "");

}  // namespace flexmb::cli
