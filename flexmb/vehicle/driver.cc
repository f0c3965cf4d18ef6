#include "flexmb/vehicle/driver.h"

#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb::vehicle {

Driver::Driver(const DriverData& d, const LaneChangeCourse& course, double target_speed)
    : data_(d),
      course_(course),
      v_target_(target_speed),
      delta_sw_(std::make_shared<double>(0.0)),
      torque_(std::make_shared<double>(0.0)) {
  const ErrorContext ctx{"", 0, "driver"};
  if (!(d.steering_ratio > 0) || !(d.preview_time > 0) || !(d.min_preview > 0) || !(d.max_wheel_angle > 0) ||
      !(d.max_wheel_rate > 0) || !(d.max_drive_torque >= 0) || !(d.speed_kp >= 0) || !(d.speed_ki >= 0))
    throw InputError("steering ratio, preview, limits must be positive and gains >= 0", ctx);
  if (!std::isfinite(target_speed) || target_speed < 0) throw InputError("target speed must be >= 0", ctx);
}

void Driver::Update(const VehicleView& v) {
  const double dt = started_ ? v.t - t_last_ : 0.0;
  started_ = true;
  t_last_ = v.t;

  // steering: pure pursuit from the rear-axle centre to a preview point on
  // the centre line; active from the front axle entering section 2
  double target_sw = 0.0;
  const int section = course_.Section(v.x_front);
  const bool active = section == 2 || (section == 3 && !data_.neutral_in_section3);
  if (active) {
    const double ld = std::max(data_.min_preview, data_.preview_time * std::abs(v.speed));
    const double xp = v.x_rear + ld;
    const double dx = xp - v.x_rear, dy = course_.CentreLine(xp) - v.y_rear;
    const double c = std::cos(v.yaw), s = std::sin(v.yaw);
    const double xl = c * dx + s * dy, yl = -s * dx + c * dy;
    const double road = std::atan(2.0 * v.wheelbase * yl / (xl * xl + yl * yl));
    target_sw = data_.steering_ratio * road;
  }
  target_sw = std::clamp(target_sw, -data_.max_wheel_angle, data_.max_wheel_angle);
  if (dt > 0) {
    const double step = data_.max_wheel_rate * dt;
    *delta_sw_ = std::clamp(target_sw, *delta_sw_ - step, *delta_sw_ + step);
  } else {
    *delta_sw_ = 0.0;
  }

  // speed: PI on the forward speed, anti-windup by clamping
  if (!data_.hold_speed) {
    *torque_ = 0.0;
    return;
  }
  const double err = v_target_ - v.speed;
  const double tau_p = data_.speed_kp * err;
  if (dt > 0) integral_ += err * dt;
  double tau = tau_p + data_.speed_ki * integral_;
  if (std::abs(tau) > data_.max_drive_torque && data_.speed_ki > 0) {
    tau = std::clamp(tau, -data_.max_drive_torque, data_.max_drive_torque);
    integral_ = (tau - tau_p) / data_.speed_ki;
  }
  *torque_ = tau;
}

}  // namespace flexmb::vehicle
