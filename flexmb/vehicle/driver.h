#pragma once
/// \file driver.h
/// Closed-loop driver of the lane-change test: a preview (pure-pursuit)
/// steering controller following the course centre line and a PI speed
/// controller acting by a drive torque on the rear axle and, above the
/// target speed, by the brakes. Sampled at every
/// accepted time step (zero-order hold, docs/design.md "Vehicle: driver").
///
/// Steering laws (DriverData::steering_law):
/// - kPreview (default): the driver predicts the vehicle's pose `lag_time`
///   ahead along its current arc (heading + yaw rate x lag_time, rear-axle
///   centre advanced by V lag_time along the mean heading), looks at the
///   course centre-line point a distance L_p = max(min_preview,
///   preview_time V) ahead of the predicted front-axle centre, and steers
///   the curvature of the arc from the predicted rear-axle centre, tangent
///   to the predicted heading, through that point (pure pursuit from the
///   predicted pose: kappa = 2 y_l / (x_l^2 + y_l^2), x_l, y_l the point in
///   predicted vehicle axes), converted to a road-wheel angle with the
///   steady-state understeer: delta = atan((L + K V^2 / g) kappa), K the
///   understeer gradient. The prediction feeds the yaw rate back (it damps
///   the yaw response and compensates the truck's steering-to-yaw lag);
///   measuring the preview from the front axle keeps the look-ahead on the
///   course ahead of the vehicle's actual position. Active in every
///   section (steer_in_section1: the driver sees the lane change coming).
/// - kPurePursuit (the first version): pure pursuit from the actual
///   rear-axle centre to the centre-line point max(min_preview,
///   preview_time V) ahead of it (in x), no understeer compensation, active
///   from the front axle entering section 2.

#include <memory>
#include <vector>

#include "flexmb/vehicle/lane_change_course.h"

namespace flexmb::vehicle {

/// Steering law of the Driver (driver.h).
enum class SteeringLaw { kPreview, kPurePursuit };

/// Gains and limits of the Driver.
struct DriverData {
  SteeringLaw steering_law = SteeringLaw::kPreview;  ///< steering controller (file key steering_law: preview, pure_pursuit)
  double steering_ratio = 20.0;       ///< steering-wheel angle / road-wheel angle [-]
  /// Look-ahead time [s] (kPreview: from the predicted front axle; the
  /// first version's pure pursuit used 1.0 s and 8 m from the rear axle).
  double preview_time = 0.3;
  double min_preview = 3.0;           ///< shortest look-ahead distance [m]
  double lag_time = 0.3;              ///< kPreview: prediction horizon of the vehicle's pose [s], >= 0
  /// kPreview: understeer gradient K [rad per g of lateral acceleration];
  /// 0.0128 rad/g = 0.73 deg/g, measured by truck_cornering_test.
  double understeer_gradient = 0.0128;
  bool steer_in_section1 = true;      ///< kPreview: steer from the start (false: from the front axle entering section 2)
  double max_wheel_angle = 12.566;    ///< steering-wheel angle limit [rad] (2 turns)
  double max_wheel_rate = 12.0;       ///< steering-wheel rate limit [rad/s]
  bool neutral_in_section3 = false;   ///< hold the wheel straight in section 3 (the seed's text)
  double speed_kp = 8000.0;           ///< drive torque per speed error [N m s/m]
  double speed_ki = 2000.0;           ///< drive torque per integrated speed error [N m/m]
  double max_drive_torque = 20000.0;  ///< drive torque limit on the axle [N m]
  /// Brake torque limit, sum over all wheels [N m], >= 0: when the speed
  /// is above the target the controller's negative output is a brake torque.
  double max_brake_torque = 40000.0;
  bool hold_speed = true;             ///< run the speed controller
  /// Reaction delay [s], >= 0: the driver acts on what the steering law
  /// computed this long ago (a transport delay of perception and decision;
  /// zero-order hold of the sampled targets). 0: none.
  double reaction_delay = 0.0;
  /// Neuromuscular lag [s], >= 0: the time constant of the first-order lag
  /// by which the arms follow the (delayed) target angle, integrated exactly
  /// over each sampling interval with the target held; the rate limit
  /// max_wheel_rate acts after it. 0: none.
  double neuromuscular_lag = 0.0;
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
  double y_front = 0.0;       ///< y of the front-axle centre [m]
  double yaw_rate = 0.0;      ///< yaw rate of the vehicle [rad/s]
  /// Wheelbase of the steering law, delta = (L + K v^2 / g) kappa [m]: a
  /// truck with more than two axles turns as if its wheelbase were the
  /// single-track model's equivalent one (DriverWheelbase); 0: `wheelbase`.
  double steering_wheelbase = 0.0;
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
  /// Brake torque, sum over all wheels [N m], >= 0.
  std::shared_ptr<const double> brake_torque() const { return brake_; }
  /// Road-wheel angle commanded [rad] (steering-wheel angle / ratio).
  double road_wheel_angle() const { return *delta_sw_ / data_.steering_ratio; }
  /// The driver's data.
  const DriverData& data() const { return data_; }

 private:
  DriverData data_;
  const LaneChangeCourse& course_;
  double v_target_;
  std::shared_ptr<double> delta_sw_, torque_;
  std::shared_ptr<double> brake_ = std::make_shared<double>(0.0);
  double integral_ = 0.0;
  double t_last_ = 0.0;
  bool started_ = false;
  // reaction delay: ring buffer of the sampled targets (time, angle),
  // oldest at head_; grows by doubling, so a run allocates only while its
  // delay window first fills
  std::vector<double> hist_t_, hist_u_;
  size_t head_ = 0, count_ = 0;
  double held_target_ = 0.0;  // neuromuscular lag: the target held over the last interval
  double arm_ = 0.0;          // neuromuscular lag: the arms' angle [rad]
  void PushTarget(double t, double u);
  double DelayedTarget(double t);
};

}  // namespace flexmb::vehicle
