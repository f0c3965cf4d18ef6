#include "flexmb/vehicle/driver.h"

#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb::vehicle {
namespace {

// the wheelbase of the steering law (VehicleView::steering_wheelbase)
double SteeringWheelbase(const VehicleView& v) { return v.steering_wheelbase > 0 ? v.steering_wheelbase : v.wheelbase; }

}  // namespace

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
  if (!(d.reaction_delay >= 0) || !std::isfinite(d.reaction_delay) || !(d.neuromuscular_lag >= 0) ||
      !std::isfinite(d.neuromuscular_lag))
    throw InputError("reaction_delay and neuromuscular_lag must be finite and >= 0 s", ctx);
  if (d.reaction_delay > 0) {
    hist_t_.assign(64, 0.0);
    hist_u_.assign(64, 0.0);
  }
}

void Driver::PushTarget(double t, double u) {
  const size_t cap = hist_t_.size();
  if (count_ == cap) {
    // grow: unroll the ring into twice the room
    std::vector<double> nt(2 * cap), nu(2 * cap);
    for (size_t k = 0; k < count_; ++k) {
      nt[k] = hist_t_[(head_ + k) % cap];
      nu[k] = hist_u_[(head_ + k) % cap];
    }
    hist_t_.swap(nt);
    hist_u_.swap(nu);
    head_ = 0;
  }
  const size_t at = (head_ + count_) % hist_t_.size();
  hist_t_[at] = t;
  hist_u_[at] = u;
  ++count_;
}

double Driver::DelayedTarget(double t) {
  const double seen = t - data_.reaction_delay;
  const size_t cap = hist_t_.size();
  // drop the samples superseded before `seen`
  while (count_ >= 2 && hist_t_[(head_ + 1) % cap] <= seen) {
    head_ = (head_ + 1) % cap;
    --count_;
  }
  return count_ >= 1 && hist_t_[head_] <= seen ? hist_u_[head_] : 0.0;
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
      const double road = std::atan(2.0 * SteeringWheelbase(v) * yl / (xl * xl + yl * yl));
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
      const double road =
          std::atan((SteeringWheelbase(v) + data_.understeer_gradient * speed * speed / 9.81) * kappa);
      target_sw = data_.steering_ratio * road;
    }
  }
  target_sw = std::clamp(target_sw, -data_.max_wheel_angle, data_.max_wheel_angle);
  // reaction delay: the target the driver decided on reaction_delay ago
  if (data_.reaction_delay > 0) {
    PushTarget(v.t, target_sw);
    target_sw = DelayedTarget(v.t);
  }
  // neuromuscular lag: the arms moved over the last interval towards the
  // target held in it (exact first-order response), then aim at the new one
  if (data_.neuromuscular_lag > 0) {
    if (dt > 0) arm_ = held_target_ + (arm_ - held_target_) * std::exp(-dt / data_.neuromuscular_lag);
    held_target_ = target_sw;
    target_sw = arm_;
  }
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
