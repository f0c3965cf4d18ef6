#pragma once
/// \file marker_sensors.h
/// Sensors that read the kinematic state of one marker: position, velocity,
/// acceleration and orientation.

#include "flexmb/model/sensor.h"

namespace flexmb {

/// Position of marker M's origin [m]: components (x, y, z) in world, or, with
/// a reference marker R, R_WR^T (p_WM - p_WR), the position in R's frame.
class MarkerPositionSensor final : public Sensor {
 public:
  /// `marker` and `relative_to` are indices into Model::markers; -1 = world.
  MarkerPositionSensor(std::string name, int marker, int relative_to = -1)
      : Sensor(std::move(name)), marker_(marker), relative_to_(relative_to) {}
  const char* type() const override { return "marker_position"; }
  std::vector<std::string> Components() const override { return {"x", "y", "z"}; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int marker_, relative_to_;
};

/// Velocity of marker M's origin in world, (x, y, z) [m/s], and optionally its
/// angular velocity in world, (wx, wy, wz) [rad/s].
class MarkerVelocitySensor final : public Sensor {
 public:
  /// `marker` is an index into Model::markers.
  MarkerVelocitySensor(std::string name, int marker, bool angular)
      : Sensor(std::move(name)), marker_(marker), angular_(angular) {}
  const char* type() const override { return "marker_velocity"; }
  std::vector<std::string> Components() const override;
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int marker_;
  bool angular_;
};

/// Acceleration of marker M's origin in world, (x, y, z) [m/s^2], and
/// optionally its angular acceleration in world, (ax, ay, az) [rad/s^2]:
/// J vdot + bias, with vdot the accelerations of the last solved step
/// (Workspace::vdot) and the bias from Body::MarkerAccelerationBias.
class MarkerAccelerationSensor final : public Sensor {
 public:
  /// `marker` is an index into Model::markers.
  MarkerAccelerationSensor(std::string name, int marker, bool angular)
      : Sensor(std::move(name)), marker_(marker), angular_(angular) {}
  const char* type() const override { return "marker_acceleration"; }
  std::vector<std::string> Components() const override;
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int marker_;
  bool angular_;
};

/// Orientation of marker M in world (or, with a reference marker R, of
/// R_RM = R_WR^T R_WM): roll, pitch, yaw [rad] (R = Rz(yaw) Ry(pitch) Rx(roll),
/// see RollPitchYaw), and optionally the unit quaternion (qw, qx, qy, qz) with
/// qw >= 0.
class MarkerOrientationSensor final : public Sensor {
 public:
  /// `marker` and `relative_to` are indices into Model::markers; -1 = world.
  MarkerOrientationSensor(std::string name, int marker, int relative_to, bool quaternion)
      : Sensor(std::move(name)), marker_(marker), relative_to_(relative_to), quaternion_(quaternion) {}
  const char* type() const override { return "marker_orientation"; }
  std::vector<std::string> Components() const override;
  /// Roll and yaw wrap at +-pi; pitch stays in [-pi/2, pi/2].
  bool ComponentIsAngle(int k) const override { return k == 0 || k == 2; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int marker_, relative_to_;
  bool quaternion_;
};

}  // namespace flexmb
