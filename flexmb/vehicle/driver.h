#pragma once
/// \file driver.h
/// Closed-loop driver of the lane-change test: a preview (pure-pursuit)
/// steering controller following the course centre line and a PI speed
/// controller acting by a drive torque on the rear axle. Sampled at every
/// accepted time step (zero-order hold, docs/design.md "Vehicle: driver").

#include <memory>

#include "flexmb/vehicle/lane_change_course.h"

namespace flexmb::vehicle {

/// Gains and limits of the Driver.
struct DriverData {
  double steering_ratio = 20.0;       ///< steering-wheel angle / road-wheel angle [-]
  double preview_time = 1.0;          ///< look-ahead time [s]
  double min_preview = 8.0;           ///< shortest look-ahead distance [m]
  double max_wheel_angle = 12.566;    ///< steering-wheel angle limit [rad] (2 turns)
  double max_wheel_rate = 12.0;       ///< steering-wheel rate limit [rad/s]
  bool neutral_in_section3 = false;   ///< hold the wheel straight in section 3 (the seed's text)
  double speed_kp = 8000.0;           ///< drive torque per speed error [N m s/m]
  double speed_ki = 2000.0;           ///< drive torque per integrated speed error [N m/m]
  double max_drive_torque = 20000.0;  ///< |drive torque| limit on the axle [N m]
  bool hold_speed = true;             ///< run the speed controller
};

/// What the driver sees of the vehicle at a sampling instant (world, road plane).
struct VehicleView {
  double t = 0.0;             ///< time [s]
  double x_front = 0.0;       ///< x of the front-axle centre [m]
  double x_rear = 0.0;        ///< x of the rear-axle centre [m]
  double y_rear = 0.0;        ///< y of the rear-axle centre [m]
  double yaw = 0.0;           ///< heading of the vehicle's x axis [rad]
  double speed = 0.0;         ///< forward speed [m/s]
  double wheelbase = 4.0;     ///< [m]
};

/// The driver. Its outputs live in shared values read by CommandSignal
/// functions: the steering-wheel angle [rad] and the drive torque on the
/// rear axle [N m].
class Driver {
 public:
  /// Target speed [m/s]; throws InputError for non-positive ratios or
  /// preview parameters.
  Driver(const DriverData& data, const LaneChangeCourse& course, double target_speed);
  /// Samples the controllers: updates the steering-wheel angle and the drive
  /// torque from the vehicle's state, with the time since the last sample
  /// (the first call only sets the clock).
  void Update(const VehicleView& v);
  /// Shared outputs.
  std::shared_ptr<const double> steering_wheel_angle() const { return delta_sw_; }
  std::shared_ptr<const double> drive_torque() const { return torque_; }
  /// Road-wheel angle commanded [rad] (steering-wheel angle / ratio).
  double road_wheel_angle() const { return *delta_sw_ / data_.steering_ratio; }
  /// The driver's data.
  const DriverData& data() const { return data_; }

 private:
  DriverData data_;
  const LaneChangeCourse& course_;
  double v_target_;
  std::shared_ptr<double> delta_sw_, torque_;
  double integral_ = 0.0;
  double t_last_ = 0.0;
  bool started_ = false;
};

}  // namespace flexmb::vehicle
