#pragma once
/// \file linearize_command.h
/// `flexmb linearize MODEL.yaml --inputs F[,F...] [--outputs S[,S...]]
/// [--at statics|initial] --out DIR`: a state-space model
///   x' = A x + B u,  y = C x + D u
/// of the model file linearized about a state (solver/linearization.h).
/// The state x = (z, z') holds the increments of the independent velocity
/// coordinates (coordinate partitioning of the constraint Jacobian: each
/// state is a named body coordinate, rigid bodies' rotations as rotation
/// increments about body axes) and their rates. Inputs u are extra loads of
/// force elements: a point_force gives 3 inputs (world force components
/// [N]), a point_torque 3 (world moment components [N m]), a spring_damper
/// 1 (extra tension [N]). Outputs y are the sensors' components, as
/// deviations from their values at the state. Writes DIR/A.mtx, B.mtx,
/// C.mtx, D.mtx (Matrix Market, dense "array" format), DIR/statespace.json
/// (the names of states, inputs and outputs, and the operating point) and
/// DIR/summary.json.

#include <cstdio>
#include <string>
#include <vector>

namespace flexmb::cli {

/// What the linearize command should do.
struct LinearizeCommandOptions {
  std::string model_path;            ///< YAML model file
  std::string out_dir;               ///< output directory (created if missing)
  std::string at = "statics";        ///< state: "statics" or "initial"
  double time = 0.0;                 ///< time of the loads and drivers [s]
  std::vector<std::string> inputs;   ///< force element names
  std::vector<std::string> outputs;  ///< sensor names (empty: all sensors)
  std::FILE* info = nullptr;         ///< a summary line (nullptr: silent)
  std::FILE* err = nullptr;          ///< warnings and errors (nullptr: silent)
};

/// Runs the linearization; returns the exit code (0 ok, 2 input error, 1
/// numerical or other error); summary.json is written in every case in
/// which the output directory can be created.
int LinearizeCommand(const LinearizeCommandOptions& options);

}  // namespace flexmb::cli
