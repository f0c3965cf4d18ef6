#pragma once
/// \file modes_command.h
/// `flexmb modes MODEL.yaml [--at statics|initial|time] [--time T]
/// [--count N] --out DIR`: the modes of the whole machine linearized about
/// a state (solver/linearization.h, solver/system_modes.h). Writes
/// DIR/modes.csv (one row per mode), DIR/modes.json (frequencies, damping
/// ratios, eigenvalues, kinds and shapes in the velocity coordinates, with
/// the coordinates' names), DIR/summary.json and, unless switched off, one
/// ParaView animation per vibration mode, DIR/mode_<k>/anim.pvd, over one
/// period. A lane-change file (examples/truck_lane_change/truck.yaml) gives
/// the modes of the truck standing on its tires, named (truck_modes.h).

#include <cstdio>
#include <string>
#include <vector>

#include "apps/flexmb/commands/analysis_support.h"
#include "apps/flexmb/commands/truck_modes.h"
#include "flexmb/solver/system_modes.h"

namespace flexmb::cli {

/// What the modes command should do.
struct ModesCommandOptions {
  std::string model_path;       ///< YAML model file (with model_text: its name in messages)
  std::string model_text;       ///< the model-file text itself (empty: read model_path)
  std::string out_dir;          ///< output directory (created if missing; empty: no files)
  std::string at = "statics";   ///< state: "statics", "initial", "time" or, with `source`, "current"
  double time = 0.0;            ///< with at == "statics"/"initial": time of the loads; "time": time simulated to [s]
  int count = 10;               ///< vibration (non-rigid) modes reported, lowest first; rigid modes always
  bool animation = true;        ///< write the mode animations
  int frames = 24;              ///< animation frames per period
  double amplitude = 0.1;       ///< animation amplitude: largest entry of the shape [m or rad]
  const AnalysisSource* source = nullptr;  ///< a model in simulation (at "current"), else the model file
  /// Lane-change (truck) files only: the frame model, "rigid" or "elastic"
  /// (empty: the file's); the truck stands on its tires (truck_modes.h).
  std::string frame;
  std::FILE* info = nullptr;    ///< the frequency table (nullptr: silent)
  std::FILE* err = nullptr;     ///< warnings and errors (nullptr: silent)
};

/// The modes of ModesAnalysis, as written to modes.json.
struct ModesResult : AnalysisOutcome {
  std::string model_name;                ///< the model's name
  double time = 0.0;                     ///< time of the state [s]
  int dof = 0;                           ///< degrees of freedom of the linearized system
  int rigid = 0;                         ///< rigid-body (zero) modes among them
  std::vector<std::string> coordinates;  ///< names of the velocity coordinates (rows of the shapes)
  std::vector<SystemMode> modes;         ///< the reported modes: rigid ones, then `count` vibration modes
  /// Lane-change (truck) files: the name of each reported mode by its
  /// dominant motion (NameTruckModes); empty for other models.
  std::vector<TruckModeName> names;
  /// Lane-change files with the elastic frame: the frame's free-free
  /// flexible modes (FrameFreeModes), for comparison with the modes in the
  /// vehicle; empty otherwise.
  std::vector<FrameFreeMode> frame_free_modes;
};

/// The modal analysis of `flexmb modes`: the result, and the files of the
/// command in options.out_dir unless it is empty. Faults of the model end
/// up in the result's code and message, never as exceptions.
ModesResult ModesAnalysis(const ModesCommandOptions& options);

/// Runs the modal analysis; returns the exit code (0 ok, 2 input error, 1
/// numerical or other error); summary.json is written in every case in
/// which the output directory can be created.
int ModesCommand(const ModesCommandOptions& options);

}  // namespace flexmb::cli
