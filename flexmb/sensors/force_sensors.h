#pragma once
/// \file force_sensors.h
/// Sensors that read a force element: the wrench it applies.

#include "flexmb/model/sensor.h"

namespace flexmb {

/// The force (fx, fy, fz) [N] and moment (mx, my, mz) [N m] that a force
/// element applies to its marker i (moment about the marker's origin),
/// world components, and the magnitude of the force "f" [N]: a rope's
/// load on its boom-head marker, a contact's force on the load, a spring's
/// tension (f, with the sign lost: read fx..fz for the direction).
class ForceElementSensor final : public Sensor {
 public:
  /// `force` is an index into Model::forces.
  ForceElementSensor(std::string name, int force) : Sensor(std::move(name)), force_(force) {}
  const char* type() const override { return "force_element"; }
  std::vector<std::string> Components() const override {
    return {"fx", "fy", "fz", "mx", "my", "mz", "f"};
  }
  void Evaluate(const Model& model, const State& state, const Workspace& ws,
                double* out) const override;

 private:
  int force_;
};

}  // namespace flexmb
