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
      !(d.max_wheel_rate > 0) || !(d.max_drive_torque >= 0) || !(d.max_brake_torque >= 0) ||
      !(d.speed_kp >= 0) || !(d.speed_ki >= 0))
    throw InputError("steering ratio, preview, limits must be positive and gains >= 0", ctx);
  if (!std::isfinite(target_speed) || target_speed < 0) throw InputError("target speed must be >= 0", ctx);
  if (!(d.lag_time >= 0) || !std::isfinite(d.understeer_gradient))
    throw InputError("lag_time must be >= 0 and the understeer gradient finite", ctx);
}

void Driver::Update(const VehicleView& v) {
  const double dt = started_ ? v.t - t_last_ : 0.0;
  started_ = true;
  t_last_ = v.t;

  double target_sw = 0.0;
  const int section = course_.Section(v.x_front);
  const double ld = std::max(data_.min_preview, data_.preview_time * std::abs(v.speed));
  if (data_.steering_law == SteeringLaw::kPurePursuit) {
    // pure pursuit from the rear-axle centre to a preview point on the
    // centre line; active from the front axle entering section 2
    const bool active = section == 2 || (section == 3 && !data_.neutral_in_section3);
    if (active) {
      const double xp = v.x_rear + ld;
      const double dx = xp - v.x_rear, dy = course_.CentreLine(xp) - v.y_rear;
      const double c = std::cos(v.yaw), s = std::sin(v.yaw);
      const double xl = c * dx + s * dy, yl = -s * dx + c * dy;
      const double road = std::atan(2.0 * v.wheelbase * yl / (xl * xl + yl * yl));
      target_sw = data_.steering_ratio * road;
    }
  } else {
    const bool active = (section == 1 && data_.steer_in_section1) || section == 2 ||
                        (section == 3 && !data_.neutral_in_section3);
    if (active) {
      // the vehicle's pose lag_time ahead along its current arc
      const double tau = data_.lag_time, speed = std::abs(v.speed);
      const double yaw = v.yaw + v.yaw_rate * tau, mid = v.yaw + 0.5 * v.yaw_rate * tau;
      const double xr = v.x_rear + speed * tau * std::cos(mid), yr = v.y_rear + speed * tau * std::sin(mid);
      const double c = std::cos(yaw), s = std::sin(yaw);
      // the preview point on the centre line ahead of the predicted front axle
      const double xp = xr + (v.wheelbase + ld) * c;
      const double dx = xp - xr, dy = course_.CentreLine(xp) - yr;
      const double xl = c * dx + s * dy, yl = -s * dx + c * dy;
      const double kappa = 2.0 * yl / (xl * xl + yl * yl);
      const double road = std::atan((v.wheelbase + data_.understeer_gradient * speed * speed / 9.81) * kappa);
      target_sw = data_.steering_ratio * road;
    }
  }
  target_sw = std::clamp(target_sw, -data_.max_wheel_angle, data_.max_wheel_angle);
  if (dt > 0) {
    const double step = data_.max_wheel_rate * dt;
    *delta_sw_ = std::clamp(target_sw, *delta_sw_ - step, *delta_sw_ + step);
  } else {
    *delta_sw_ = 0.0;
  }

  // speed: PI on the forward speed, anti-windup by clamping; a negative
  // output brakes
  if (!data_.hold_speed) {
    *torque_ = 0.0;
    *brake_ = 0.0;
    return;
  }
  const double err = v_target_ - v.speed;
  const double tau_p = data_.speed_kp * err;
  if (dt > 0) integral_ += err * dt;
  double tau = tau_p + data_.speed_ki * integral_;
  if (tau > data_.max_drive_torque || tau < -data_.max_brake_torque) {
    tau = std::clamp(tau, -data_.max_brake_torque, data_.max_drive_torque);
    if (data_.speed_ki > 0) integral_ = (tau - tau_p) / data_.speed_ki;
  }
  *torque_ = std::max(tau, 0.0);
  *brake_ = std::max(-tau, 0.0);
}

}  // namespace flexmb::vehicle
