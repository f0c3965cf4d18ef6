#pragma once
/// \file flexible_sensors.h
/// Sensors of floating-frame flexible bodies (bodies/flexible_body.h):
/// modal coordinates, elastic displacement of a node relative to the
/// floating frame, elastic strain energy.

#include <string>
#include <vector>

#include "flexmb/sensors/sensor.h"

namespace flexmb {

class FlexibleBody;

/// Modal coordinates w_1 .. w_n of a flexible body (units of the body file's
/// modes); components "w1", "w2", ...
class ModalCoordinatesSensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies holding `flexible`.
  ModalCoordinatesSensor(std::string name, int body, const FlexibleBody& flexible);
  const char* type() const override { return "modal_coordinates"; }
  std::vector<std::string> Components() const override;
  void Evaluate(const Model& model, const State& state, const Workspace& ws, double* out) const override;

 private:
  int body_, n_;
};

/// Elastic displacement H_k^t w of node k relative to the floating frame,
/// in body axes [m]; components "ux", "uy", "uz".
class NodeDisplacementSensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies (a FlexibleBody), `node` a node
  /// index of its mesh.
  NodeDisplacementSensor(std::string name, int body, int node)
      : Sensor(std::move(name)), body_(body), node_(node) {}
  const char* type() const override { return "node_displacement"; }
  std::vector<std::string> Components() const override { return {"ux", "uy", "uz"}; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws, double* out) const override;

 private:
  int body_, node_;
};

/// Elastic strain energy 1/2 w^T K w of a flexible body [J]; component
/// "strain".
class StrainEnergySensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies (a FlexibleBody).
  StrainEnergySensor(std::string name, int body) : Sensor(std::move(name)), body_(body) {}
  const char* type() const override { return "strain_energy"; }
  std::vector<std::string> Components() const override { return {"strain"}; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws, double* out) const override;

 private:
  int body_;
};

}  // namespace flexmb
