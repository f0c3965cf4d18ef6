#include <cmath>
#include <numbers>
#include <string>

#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/common/error.h"

// The truck tests' settings that are not the file's reading: the static
// equilibrium they start from, the driver's numeric keys by name.
namespace flexmb::vehicle {
namespace {
constexpr double kDriverKeyDeg = 180.0 / std::numbers::pi;
}  // namespace

StaticsSettings TruckStaticsSettings() {
  StaticsSettings s;
  s.hold_always = true;
  s.residual_tol = 1e-7;
  return s;
}

namespace {

// a numeric key of the driver section: its member and the factor from the
// file's units to DriverData's
struct LaneChangeDriverKey {
  const char* name;
  double DriverData::*member;
  double scale;
};

const LaneChangeDriverKey& FindDriverKey(const std::string& key) {
  static const LaneChangeDriverKey keys[] = {
      {"preview_time", &DriverData::preview_time, 1.0},
      {"min_preview", &DriverData::min_preview, 1.0},
      {"lag_time", &DriverData::lag_time, 1.0},
      {"understeer_gradient_deg", &DriverData::understeer_gradient, 1.0 / kDriverKeyDeg},
      {"max_wheel_angle_deg", &DriverData::max_wheel_angle, 1.0 / kDriverKeyDeg},
      {"max_wheel_rate_deg", &DriverData::max_wheel_rate, 1.0 / kDriverKeyDeg},
      {"speed_kp", &DriverData::speed_kp, 1.0},
      {"speed_ki", &DriverData::speed_ki, 1.0},
      {"max_drive_torque", &DriverData::max_drive_torque, 1.0},
      {"reaction_delay", &DriverData::reaction_delay, 1.0},
      {"neuromuscular_lag", &DriverData::neuromuscular_lag, 1.0}};
  std::string names;
  for (const LaneChangeDriverKey& k : keys) {
    if (key == k.name) return k;
    names += std::string(names.empty() ? "" : ", ") + k.name;
  }
  throw InputError("unknown driver setting '" + key + "'; the driver's numeric keys are " + names);
}

}  // namespace

void SetDriverSetting(DriverData& d, const std::string& key, double value) {
  const LaneChangeDriverKey& k = FindDriverKey(key);
  if (!std::isfinite(value)) throw InputError("driver setting '" + key + "' must be a finite number");
  d.*(k.member) = value * k.scale;
}

double GetDriverSetting(const DriverData& d, const std::string& key) {
  const LaneChangeDriverKey& k = FindDriverKey(key);
  return d.*(k.member) / k.scale;
}

}  // namespace flexmb::vehicle
