#pragma once
/// \file joint_sensors.h
/// Sensors that read a joint: its coordinate and its reaction.

#include "flexmb/model/sensor.h"

namespace flexmb {

class Joint;

/// Joint coordinate k of a joint (Joint::Coordinate): components "value"
/// [rad or m] (angles in (-pi, pi]) and "rate" [rad/s or m/s], the derivative
/// dq (12) applied to the marker twists (v_i, w_i, v_j, w_j).
class JointCoordinateSensor final : public Sensor {
 public:
  /// `joint` is an index into Model::joints, `coordinate` a valid coordinate
  /// of `joint_ref` (the same joint; its type decides angle or length).
  JointCoordinateSensor(std::string name, int joint, const Joint& joint_ref, int coordinate);
  const char* type() const override { return "joint_coordinate"; }
  std::vector<std::string> Components() const override { return {"value", "rate"}; }
  /// The value is an angle if the joint coordinate is one.
  bool ComponentIsAngle(int k) const override { return k == 0 && is_angle_; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int joint_, coordinate_;
  bool is_angle_;
};

/// Force (fx, fy, fz) [N] and moment (mx, my, mz) [N m] that a joint applies
/// to its marker j, moment about marker j's origin, components in marker i's
/// frame (default) or in world. The reaction on the markers is -D^T lambda
/// with the joint's multipliers from State::lambda; equations removed as
/// redundant have lambda = 0, so for redundant joint sets the values are one
/// valid distribution of the reactions.
class JointReactionSensor final : public Sensor {
 public:
  /// `joint` is an index into Model::joints; `world` selects world components.
  JointReactionSensor(std::string name, int joint, bool world)
      : Sensor(std::move(name)), joint_(joint), world_(world) {}
  const char* type() const override { return "joint_reaction"; }
  std::vector<std::string> Components() const override {
    return {"fx", "fy", "fz", "mx", "my", "mz"};
  }
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int joint_;
  bool world_;
};

}  // namespace flexmb
