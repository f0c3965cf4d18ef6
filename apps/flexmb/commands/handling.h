#pragma once
/// \file handling.h
/// `flexmb truck handling`: the heavy-vehicle handling tests of a
/// lane-change file's truck with open-loop steering and the speed held by
/// the file's driver gains, each writing results.csv and summary.json:
///  - step-steer (ISO 14793, lateral transient response, step input): a
///    steering-wheel step at constant speed; steady-state gains, response
///    and peak response times and overshoots of yaw rate and lateral
///    acceleration;
///  - constant-steer (ISO 14792, steady-state circular driving, constant
///    steering-wheel angle): the speed rises slowly at a held angle; the
///    understeer, roll and side-slip gradients from the quasi-steady states;
///  - braking (straight-line braking, ECE R13 type-0 measures): a brake
///    torque step at speed; stopping distance, mean fully developed
///    deceleration, pitch, dynamic axle loads, path and heading deviation;
///  - sine-steer (ISO 14793 / ISO 7401, sinusoidal input): a continuous
///    sinusoidal steering-wheel angle at constant speed; gain and phase lag
///    of yaw rate and lateral acceleration at the input frequency (least
///    squares fit over the periods after the first), beside the dynamic
///    single-track model's;
///  - brake-in-turn (after ISO 14794): braking from a steady turn at a held
///    steering-wheel angle; the yaw-rate and lateral-acceleration ratios and
///    the heading deviation 1 s after the brake onset, besides the braking
///    measures.
/// summary.json holds the linear single-track model's values beside the
/// truck's (single_track.h). docs/cli.md, "truck handling".

#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace flexmb::vehicle {

/// Options of a handling test.
struct HandlingOptions {
  std::string file;                   ///< lane-change file (the truck, road_mu, driver gains, solver)
  std::string out_dir;                ///< results.csv and summary.json ("": none)
  std::string test = "step-steer";    ///< "step-steer", "sine-steer", "constant-steer", "braking" or "brake-in-turn"
  /// Step steer: the speed; constant steer: the start speed [km/h]
  /// (default: the file's entry speed; constant steer: 10).
  std::optional<double> speed_kmh;
  /// Steering-wheel angle [deg] (default: the single-track model's angle
  /// for `target_ay` at the speed (step steer; sine steer: the amplitude),
  /// for `radius` (constant steer)).
  std::optional<double> steer_deg;
  double target_ay = 2.0;             ///< step steer: default angle's steady lateral acceleration [m/s^2]
  double radius = 50.0;               ///< constant steer: default angle's kinematic radius L / delta [m]
  double step_time = 2.0;             ///< start of the steering input [s] (after the start settles)
  double rise_time = 0.15;            ///< step steer: ramp of the steering input [s]
  double hold_time = 6.0;             ///< step steer: time after the step [s]
  double frequency = 0.5;             ///< sine steer: input frequency [Hz]
  int periods = 4;                    ///< sine steer: periods of the input (the first is not fitted), >= 2
  double speed_rate_kmh_s = 1.0;      ///< constant steer: rise of the speed [km/h per s]
  double max_ay = 3.0;                ///< constant steer: end at this lateral acceleration [m/s^2]
  double max_speed_kmh = 90.0;        ///< constant steer: or at this speed [km/h]
  /// Braking: total brake torque of all wheels [N m] (default: the torque
  /// for `decel` on the unloaded tire radius, rotating inertia left out).
  std::optional<double> brake_torque;
  double decel = 3.0;                 ///< braking: default torque's deceleration [m/s^2]
  double brake_rise_time = 0.2;       ///< braking: ramp of the brake torque [s]
  std::optional<std::string> frame;   ///< "rigid" or "elastic" (default: the file's)
  std::optional<double> dt;           ///< step size override [s]
  std::FILE* info = nullptr;          ///< one summary line (nullptr: none)
};

/// Outcome of a handling test: named metrics (SI units unless the name
/// says deg), in the order summary.json lists them.
struct HandlingResult {
  std::string test;                   ///< the test run
  std::string frame;                  ///< "rigid" or "elastic"
  bool completed = false;
  std::string message;                ///< why the run stopped early
  std::vector<std::pair<std::string, double>> metrics;
  /// The metric `name` (NaN if absent).
  double Metric(const std::string& name) const;
};

/// Runs the handling test of `opt`. Throws InputError for bad options or
/// a bad file; a numerical failure ends the run with completed false and
/// the rows so far kept.
HandlingResult RunHandlingTest(const HandlingOptions& opt);

/// summary.json of a handling test: test, status, message, frame and the
/// metrics (NaN as null).
std::string HandlingJson(const HandlingResult& r);

}  // namespace flexmb::vehicle
