#pragma once
/// \file straight_run.h
/// The straight run of a truck over a rough road ("flexmb truck
/// straight-run", issue 22): the truck of a lane-change file
/// (examples/truck_lane_change/truck.yaml) drives straight ahead at a
/// constant speed (the driver's speed controller holds it, its steering
/// holds the line y = 0) over a road profile (ISO 8608 generated, a CSV of
/// measured elevations, or the flat road), the tires following the left
/// and right tracks (Tire::SetRoad). Writes results.csv (tire vertical
/// forces and the forces of the frame's mounts and suspension springs on
/// the frame), summary.json (distance driven, force statistics) and, for
/// the elastic frame, the modal history that "flexmb post" turns into
/// stress histories and fatigue damage. docs/cli.md, "truck straight-run".

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flexmb/reduction/reduced_body.h"
#include "flexmb/vehicle/road_profile.h"

namespace flexmb::vehicle {

/// What a straight run should do.
struct StraightRunOptions {
  std::string file;                  ///< lane-change YAML file (truck, driver, solver, frame reduction)
  std::string out_dir;               ///< output directory; empty: write nothing
  std::optional<double> speed_kmh;   ///< speed [km/h], > 0; default: the file's entry speed
  std::optional<std::string> frame;  ///< "rigid" or "elastic"; default: the file's
  std::optional<double> dt;          ///< step size [s]; default: the file's
  /// Road: "flat" (z = 0 under every wheel, the tires' default road),
  /// "iso8608" (generated, road_class / road_length / seed) or "csv"
  /// (road_csv).
  std::string road = "iso8608";
  std::string road_class = "B";      ///< ISO 8608 class, one letter A to H
  double road_length = 300.0;        ///< generated road's length [m] (the flat road's too)
  unsigned seed = 1;                 ///< random seed of the generated road
  std::string road_csv;              ///< CSV of x, z_left, z_right [m] (ReadRoadCsv)
  /// Distance the front axle drives on the road, from the road's start [m];
  /// default: the whole road (its length; a CSV's last x minus its first).
  /// Longer than the road: InputError.
  std::optional<double> distance;
  /// Time at the speed on the flat before the road [s], >= 0 (not
  /// recorded): the start settles (frame sag, suspension, tire patches,
  /// speed control); the elastic frame's modes at 2 % damping need a few
  /// seconds to ring down below the stress noise of the flat road.
  double run_up_time = 3.0;
  /// Length of the road's fade-in [m], >= 0: the elevations are multiplied
  /// by (1 - cos(pi x / fade_in)) / 2 over the first fade_in metres, so the
  /// road starts level with the run-up.
  double fade_in = 5.0;
  /// Elastic frame only: a reduced frame to use instead of reducing the
  /// file's frame (tests reduce once). Not written to frame.h5.
  std::shared_ptr<const reduction::ReducedBody> frame_body;
  std::FILE* info = nullptr;         ///< one-line report (nullptr: silent)
};

/// Mean, standard deviation and extremes of one force over the recorded
/// rows [N].
struct ForceStatistics {
  std::string name;    ///< tire or mount name
  double mean = 0.0;   ///< [N]
  double std = 0.0;    ///< standard deviation (population) [N]
  double min = 0.0;    ///< [N]
  double max = 0.0;    ///< [N]
};

/// Outcome of a straight run (also written as summary.json).
struct StraightRunResult {
  bool completed = false;            ///< the front axle drove the whole distance
  std::string message;               ///< why not, if not
  std::string frame = "rigid";       ///< "rigid" or "elastic"
  double speed_kmh = 0.0;            ///< target speed [km/h]
  std::string road;                  ///< "flat", "iso8608 class B, seed 1" or the CSV path
  double road_length = 0.0;          ///< road length [m]
  double run_up = 0.0;               ///< flat run-up before the road, run_up_time * speed [m]
  double distance = 0.0;             ///< front-axle travel on the road (recorded) [m]
  double t_end = 0.0;                ///< simulated time [s]
  int rows = 0;                      ///< recorded rows (results.csv, modal history)
  double mean_speed_kmh = 0.0;       ///< mean forward speed over the recorded rows [km/h]
  /// Vertical tire forces of the sets FL, FR, RL, RR (TireContact::fz).
  std::vector<ForceStatistics> tires;
  /// Vertical (world z) force of every mount and suspension spring on the
  /// frame, named as the force element, preload included [N].
  std::vector<ForceStatistics> mounts;
  long steps = 0;                    ///< accepted steps
  double cpu_time_s = 0.0;           ///< CPU time of the integration [s]
  double wall_time_s = 0.0;          ///< wall time of the integration [s]
  double reduction_wall_time_s = 0.0;  ///< elastic frame: generation and reduction [s]
};

/// The road profile of the options, as the tires see it: x from 0 at the
/// road's start (a CSV's x shifted by its first x), the fade-in applied.
/// Throws InputError naming the option or the file and line (bad class,
/// non-positive length, a CSV with NaN or non-increasing x, ...).
RoadProfile StraightRunRoad(const StraightRunOptions& options, double track_width);

/// Runs the straight run. Throws InputError for a bad file or option; a
/// numerical failure ends the run with completed = false and the message.
StraightRunResult RunStraight(const StraightRunOptions& options);

/// The result as a JSON object.
std::string StraightRunJson(const StraightRunResult& r);

}  // namespace flexmb::vehicle
