#pragma once
/// \file modes_command.h
/// `flexmb modes MODEL.yaml [--at statics|initial|time] [--time T]
/// [--count N] --out DIR`: the modes of the whole machine linearized about
/// a state (solver/linearization.h, solver/system_modes.h). Writes
/// DIR/modes.csv (one row per mode), DIR/modes.json (frequencies, damping
/// ratios, eigenvalues, kinds and shapes in the velocity coordinates, with
/// the coordinates' names), DIR/summary.json and, unless switched off, one
/// ParaView animation per vibration mode, DIR/mode_<k>/anim.pvd, over one
/// period.

#include <cstdio>
#include <string>

namespace flexmb::cli {

/// What the modes command should do.
struct ModesCommandOptions {
  std::string model_path;       ///< YAML model file
  std::string out_dir;          ///< output directory (created if missing)
  std::string at = "statics";   ///< state: "statics", "initial" or "time"
  double time = 0.0;            ///< with at == "statics"/"initial": time of the loads; "time": time simulated to [s]
  int count = 10;               ///< vibration (non-rigid) modes reported, lowest first; rigid modes always
  bool animation = true;        ///< write the mode animations
  int frames = 24;              ///< animation frames per period
  double amplitude = 0.1;       ///< animation amplitude: largest entry of the shape [m or rad]
  std::FILE* info = nullptr;    ///< the frequency table (nullptr: silent)
  std::FILE* err = nullptr;     ///< warnings and errors (nullptr: silent)
};

/// Runs the modal analysis; returns the exit code (0 ok, 2 input error, 1
/// numerical or other error); summary.json is written in every case in
/// which the output directory can be created.
int ModesCommand(const ModesCommandOptions& options);

}  // namespace flexmb::cli
