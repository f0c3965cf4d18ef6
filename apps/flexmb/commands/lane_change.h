#pragma once
/// \file lane_change.h
/// The lane-change test ("perestavka") of a truck: reads a lane-change file
/// (examples/truck_lane_change/truck.yaml), builds the truck, drives it
/// through the course with the closed-loop driver, watches the corridor and
/// wheel lift-off, and writes results.csv, summary.json and, when asked,
/// the ParaView animation (animation/anim.pvd, truck_animation.h).

#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/model/state.h"
#include "flexmb/solver/statics.h"
#include "flexmb/vehicle/driver.h"
#include "flexmb/vehicle/truck.h"

namespace flexmb::vehicle {

/// Settings of the static equilibrium of the standing truck that its tests
/// roll off from and its modes are taken about (SolveStatics with
/// hold_always: nothing but the tires' slip damping holds the truck's
/// position, heading and wheel spins at rest). Stops at a force residual
/// of 1e-7 of the largest force; a contact patch's weight along its slide
/// on a slightly tilted carrier, balanced by the carcass spring whose
/// torque spins the free wheel, leaves a residual of about 1e-8 of it that
/// no displacement removes (StaticsResult::creep).
StaticsSettings TruckStaticsSettings();

/// What a lane-change run should do.
struct LaneChangeOptions {
  std::string file;                   ///< lane-change YAML file
  std::string out_dir;                ///< output directory; empty: write nothing
  std::optional<double> speed_kmh;    ///< entry speed [km/h], overrides the file
  std::optional<std::string> frame;   ///< "rigid" or "elastic", overrides the file
  std::optional<double> dt;           ///< step size [s], overrides the file
  bool stop_on_failure = false;       ///< end the run at the first corridor exit or lift-off
  std::FILE* info = nullptr;          ///< one-line report (nullptr: silent)
  /// Elastic frame only: a reduced frame to use instead of reducing the
  /// file's frame (ReduceTruckFrame of the same file's truck and modes; a
  /// bisection or a benchmark reduces once). Not written to frame.h5.
  std::shared_ptr<const reduction::ReducedBody> frame_body;
  /// End the run when the front axle has travelled this far from the start
  /// of section 1 [m] (a shorter
  /// run for tests); the run counts as completed when it gets there.
  std::optional<double> stop_distance;
  /// Driver settings set after the file is read, in its order: numeric keys
  /// of the file's driver section in its units (SetDriverSetting).
  std::vector<std::pair<std::string, double>> driver_settings;
  /// Time [s] at the entry speed on straight road before section 1 (the
  /// settling of the start: frame sag, suspension, tire patches, speed
  /// control; not monitored), overrides the file's `run_up_time` (1 s).
  std::optional<double> run_up_time;
  /// Write the ParaView animation to out_dir/animation (anim.pvd and
  /// frames/): overrides the file's `animation` (default off).
  std::optional<bool> animation;
  /// Animation frames per second of simulated time, overrides the file's
  /// `animation_fps` (default 25); setting it turns the animation on.
  std::optional<double> animation_fps;
  /// Called after every animation frame is written, with the model and the
  /// state the frame shows (tests and tools; empty: nothing).
  std::function<void(const Model&, const State&)> on_animation_frame;
};

/// Outcome of a lane-change run (also written as summary.json).
struct LaneChangeResult {
  bool completed = false;             ///< reached the end of the test distance (or 10 s)
  bool passed = false;                ///< completed, no corridor exit, no lift-off
  bool rolled_over = false;           ///< the run ended because |roll| exceeded 45 deg
  std::string message;                ///< error message if the simulation failed
  double entry_speed_kmh = 0.0;       ///< [km/h]
  double distance = 0.0;              ///< front-axle travel reached from the start of section 1 [m]
  double run_up = 0.0;                ///< straight road before section 1, run_up_time * entry speed [m]
  double t_end = 0.0;                 ///< simulated time [s]
  double corridor_exit_time = -1.0;   ///< first time a gauge point left the corridor [s], -1: never
  double lift_off_time = -1.0;        ///< first time a tire lost contact [s], -1: never
  double min_corridor_margin = 0.0;   ///< smallest margin of any gauge point [m] (negative: outside)
  double max_lateral_acceleration = 0.0;  ///< max |a_y| of the frame's centre of mass [m/s^2]
  double max_roll_deg = 0.0;          ///< max |roll| of the frame [deg]
  double max_steering_wheel_deg = 0.0;  ///< max |steering-wheel angle| [deg]
  double max_yaw_rate_deg = 0.0;      ///< max |yaw rate| [deg/s]
  std::vector<std::string> axle_names;  ///< the truck's axles, front to rear (AxleData::name)
  std::vector<double> min_axle_load;   ///< smallest load of each axle [N]
  /// Largest |load-transfer ratio| of each axle [-]: LTR =
  /// (Fz_left - Fz_right) / (Fz_left + Fz_right) of the axle's tire loads;
  /// 1 when one side's wheels lift off (rollover margin: 1 - the largest).
  std::vector<double> max_abs_ltr;
  std::vector<double> static_axle_load;  ///< static axle loads (StaticAxleLoads) [N]
  long steps = 0;                     ///< accepted steps
  long newton_iterations = 0;         ///< Newton iterations of all step attempts
  long factorizations = 0;            ///< LU factorizations of the iteration matrix
  double cpu_time_s = 0.0;            ///< CPU time of the integration (process clock) [s]
  double wall_time_s = 0.0;           ///< wall time of the integration [s]
  double real_time_factor = 0.0;      ///< simulated time / wall time
  std::string frame = "rigid";        ///< frame model, "rigid" or "elastic"
  /// Elastic frame: largest elastic displacement of a frame node relative to
  /// the floating frame (|H_k^t w|) over the run [m], the node's id, its
  /// undeformed position (vehicle frame) [m] and the time [s].
  double max_frame_displacement = 0.0;
  int max_displacement_node = -1;
  Vec3 max_displacement_position = Vec3::Zero();
  double max_displacement_time = 0.0;
  /// Elastic frame: largest von Mises stress of the shell stress modes
  /// (element surfaces) over the run [Pa], the element's id, its centroid
  /// (vehicle frame) [m] and the time [s].
  double max_frame_stress = 0.0;
  int max_stress_element = -1;
  Vec3 max_stress_position = Vec3::Zero();
  double max_stress_time = 0.0;
  int frame_modal_coordinates = 0;    ///< elastic frame: modal coordinates of the body
  double reduction_wall_time_s = 0.0; ///< elastic frame: generation, reduction and body file [s]
  int animation_frames = 0;           ///< ParaView frames written (0: animation off)
  double animation_wall_time_s = 0.0; ///< wall time spent writing them (included in wall_time_s) [s]
};

/// True if the YAML file at `path` is a lane-change file (top-level key
/// `lane_change_test`). False for unreadable files (the normal loader then
/// reports the fault).
bool IsLaneChangeFile(const std::string& path);

/// Sets the driver's `key`, a numeric key of the lane-change file's driver
/// section (preview_time, lag_time, understeer_gradient_deg,
/// reaction_delay, ...), to `value` in the file's units. Throws InputError
/// naming the valid keys for an unknown one, or for a value not finite
/// (the Driver checks the ranges).
void SetDriverSetting(DriverData& d, const std::string& key, double value);

/// The value of the driver's `key` in the file's units (SetDriverSetting).
double GetDriverSetting(const DriverData& d, const std::string& key);

/// Runs the test. Throws InputError for a bad file or option; a numerical
/// failure of the simulation or a rollover (|roll| > 45 deg) ends the run
/// with completed = false and the message set (results up to then are kept).
LaneChangeResult RunLaneChange(const LaneChangeOptions& options);

/// `flexmb check` of a lane-change file: reads and checks the file (and the
/// options' overrides: speed, frame; the elastic frame is reduced), builds
/// the truck, makes its initial state consistent and prints the model
/// report of ReportModel (bodies, joints, degrees of freedom, redundant
/// equations) and the test's set-up (speed, run-up, course, static axle
/// loads, driver, solver) to `out`. Simulates nothing, writes no file.
/// Throws InputError / NumericalError as RunLaneChange.
void CheckLaneChange(const LaneChangeOptions& options, std::FILE* out);

/// Highest entry speed [km/h] in [low, high] at which the test is passed,
/// by bisection to `tol` [km/h] (each trial stops at the first failure).
/// Returns low - 0 if even `low` fails (passed flag in `*at_low`).
double MaxPassSpeed(const LaneChangeOptions& base, double low, double high, double tol, std::FILE* log,
                    bool* low_passed);

/// The truck's parameters of a lane-change file (tire files resolved
/// relative to it); throws InputError like RunLaneChange.
TruckData LoadLaneChangeTruck(const std::string& file);

/// Settings of the elastic frame's reduction (lane_change_test keys
/// frame_modes, frame_damping, frame_keep_modes).
struct FrameReductionData {
  int normal_modes = 10;           ///< fixed-interface normal modes (seed: 10)
  double damping_ratio = 0.02;     ///< modal damping ratio of every mode
  int keep = -1;                   ///< keep the lowest N flexible modes (-1: all, as the seed)
  /// add the acceleration modes (ReductionOptions::acceleration_modes): the
  /// frame's sag under its own distributed mass in the basis
  bool acceleration_modes = false;
};

/// The truck's elastic frame: the user's body file (d.frame_body, as it
/// is; `r` does not apply), or the Craig-Bampton reduction of the generated
/// frame (BuildGeneratedFrameModel: the interface nodes nearest to
/// FrameAttachments(d, g), each with a rigid spider of radius
/// d.ladder.spider_radius, the arm pivots' brackets reaching both rails),
/// all their static modes and the fixed-interface normal modes of `r`.
std::shared_ptr<const reduction::ReducedBody> ReduceTruckFrame(const TruckData& d, const FrameReductionData& r,
                                                               double g = 9.81);

/// The elastic frame's reduction settings of a lane-change file.
FrameReductionData LaneChangeFrameReduction(const std::string& file);

/// The result as a JSON object.
std::string LaneChangeJson(const LaneChangeResult& r);

/// The settings of a lane-change file that other manoeuvres of its truck
/// share (the straight run, straight_run.h): the file's values as read,
/// the course aside.
struct TruckFileSettings {
  double speed_kmh = 55.0;          ///< entry_speed_kmh [km/h]
  double run_up_time = 1.0;         ///< run_up_time [s]
  std::string frame = "rigid";      ///< frame: "rigid" or "elastic"
  FrameReductionData reduction;     ///< the elastic frame's reduction
  double mu = 0.8;                  ///< road_mu [-]
  DriverData driver;                ///< driver gains (steering ratio from the truck)
  SolverSettings solver;            ///< the solver section (dt_min as read)
  bool dt_min_given = false;        ///< the solver section gives dt_min (else use 1e-6 dt)
  double output_interval = 0.01;    ///< solver.output_interval [s]
  TruckData truck;                  ///< the truck
};

/// Reads the shared settings of a lane-change file; throws InputError
/// naming the file and key like RunLaneChange.
TruckFileSettings LoadTruckFileSettings(const std::string& file);

}  // namespace flexmb::vehicle
