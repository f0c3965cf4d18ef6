#pragma once
/// \file body_sensors.h
/// Sensors that read bodies: the pose of a body frame and energies.

#include "flexmb/model/sensor.h"

namespace flexmb {

/// Pose of a body's user frame (Body::BodyFramePose): position (x, y, z) of
/// its origin in world [m] and roll, pitch, yaw [rad] of its orientation
/// (R_WB = Rz(yaw) Ry(pitch) Rx(roll), see RollPitchYaw).
class BodyPositionSensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies.
  BodyPositionSensor(std::string name, int body) : Sensor(std::move(name)), body_(body) {}
  const char* type() const override { return "body_position"; }
  std::vector<std::string> Components() const override {
    return {"x", "y", "z", "roll", "pitch", "yaw"};
  }
  /// Roll and yaw wrap at +-pi.
  bool ComponentIsAngle(int k) const override { return k == 3 || k == 5; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int body_;
};

/// Energies of one body [J]: "kinetic" and "potential" (of gravity, zero at
/// the world origin).
class BodyEnergySensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies.
  BodyEnergySensor(std::string name, int body) : Sensor(std::move(name)), body_(body) {}
  const char* type() const override { return "body_energy"; }
  std::vector<std::string> Components() const override { return {"kinetic", "potential"}; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int body_;
};

/// Energies of the whole model [J]: "kinetic" (all bodies), "potential"
/// (gravity of all bodies, the force elements' PotentialEnergy and the
/// elastic energy of deformable bodies, Body::ElasticEnergy) and
/// "total" = kinetic + potential.
class SystemEnergySensor final : public Sensor {
 public:
  explicit SystemEnergySensor(std::string name) : Sensor(std::move(name)) {}
  const char* type() const override { return "system_energy"; }
  std::vector<std::string> Components() const override { return {"kinetic", "potential", "total"}; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;
};

}  // namespace flexmb
