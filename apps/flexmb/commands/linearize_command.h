#pragma once
/// \file linearize_command.h
/// `flexmb linearize MODEL.yaml --inputs F[,F...] [--outputs S[,S...]]
/// [--at statics|initial|time] [--time T] --out DIR`: a state-space model
///   x' = A x + B u,  y = C x + D u
/// of the model file linearized about a state (solver/linearization.h).
/// The state x = (z, z') holds the increments of the independent velocity
/// coordinates (coordinate partitioning of the constraint Jacobian: each
/// state is a named body coordinate, rigid bodies' rotations as rotation
/// increments about body axes) and their rates. Inputs u are extra loads of
/// force elements: a point_force gives 3 inputs (world force components
/// [N]), a point_torque 3 (world moment components [N m]), a spring_damper
/// 1 (extra tension [N]), a joint_motor 1 (its torque [N m] or force [N]),
/// a motion driver 1 (its acceleration [rad/s^2 or m/s^2]; its value and
/// rate are then appended to the state, linearize_drivers.h).
/// Outputs y are the sensors' components, as deviations from their values
/// at the state. Writes DIR/A.mtx, B.mtx,
/// C.mtx, D.mtx (Matrix Market, dense "array" format), DIR/statespace.json
/// (the names of states, inputs and outputs, and the operating point) and
/// DIR/summary.json.

#include <cstdio>
#include <string>
#include <vector>

#include "apps/flexmb/commands/analysis_support.h"

namespace flexmb::cli {

/// What the linearize command should do.
struct LinearizeCommandOptions {
  std::string model_path;            ///< YAML model file (with model_text: its name in messages)
  std::string model_text;            ///< the model-file text itself (empty: read model_path)
  std::string out_dir;               ///< output directory (created if missing; empty: no files)
  std::string at = "statics";        ///< state: "statics", "initial", "time" or, with `source`, "current"
  double time = 0.0;                 ///< "statics"/"initial": time of the loads and drivers; "time": time simulated to [s]
  std::vector<std::string> inputs;   ///< force element and motion driver names
  std::vector<std::string> outputs;  ///< sensor names (empty: all sensors)
  const AnalysisSource* source = nullptr;  ///< a model in simulation (at "current"), else the model file
  std::FILE* info = nullptr;         ///< a summary line (nullptr: silent)
  std::FILE* err = nullptr;          ///< warnings and errors (nullptr: silent)
};

/// The state-space model of LinearizeAnalysis, as written to the files.
struct LinearizeResult : AnalysisOutcome {
  MatX A, B, C, D;                   ///< x' = A x + B u, y = C x + D u
  /// names of x ("dx COORDINATE", then "v COORDINATE", then "driver
  /// NAME.position" and "driver NAME.velocity" of the driver inputs)
  std::vector<std::string> states;
  std::vector<std::string> inputs;   ///< names of u ("FORCE.fx", ..., "SPRING.tension", "DRIVER.acceleration")
  std::vector<std::string> outputs;  ///< names of y ("SENSOR.COMPONENT")
  VecX output_values;                ///< the outputs' values at the state (y is the deviation from them)
  double time = 0.0;                 ///< time of the state [s]
};

/// The linearization of `flexmb linearize`: the result, and the files of
/// the command in options.out_dir unless it is empty. Faults of the model
/// end up in the result's code and message, never as exceptions.
LinearizeResult LinearizeAnalysis(const LinearizeCommandOptions& options);

/// Runs the linearization; returns the exit code (0 ok, 2 input error, 1
/// numerical or other error); summary.json is written in every case in
/// which the output directory can be created.
int LinearizeCommand(const LinearizeCommandOptions& options);

}  // namespace flexmb::cli
