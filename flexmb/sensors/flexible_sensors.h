#pragma once
/// \file flexible_sensors.h
/// Sensors of floating-frame flexible bodies (bodies/flexible_body.h):
/// modal coordinates, elastic displacement of a node relative to the
/// floating frame, absolute position and velocity of a node, stress at an
/// element or a node from the stress modes, elastic strain energy.

#include <string>
#include <vector>

#include "flexmb/model/sensor.h"

namespace flexmb::reduction {
struct StressTable;
}  // namespace flexmb::reduction

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

/// World position of node k, r + R (rho_k + H_k^t w) [m]; components "x",
/// "y", "z".
class NodePositionSensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies (a FlexibleBody), `node` a node
  /// index of its mesh.
  NodePositionSensor(std::string name, int body, int node)
      : Sensor(std::move(name)), body_(body), node_(node) {}
  const char* type() const override { return "node_position"; }
  std::vector<std::string> Components() const override { return {"x", "y", "z"}; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws, double* out) const override;

 private:
  int body_, node_;
};

/// World velocity of node k, v_W + R (om x u_k + H_k^t wd) [m/s];
/// components "vx", "vy", "vz".
class NodeVelocitySensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies (a FlexibleBody), `node` a node
  /// index of its mesh.
  NodeVelocitySensor(std::string name, int body, int node)
      : Sensor(std::move(name)), body_(body), node_(node) {}
  const char* type() const override { return "node_velocity"; }
  std::vector<std::string> Components() const override { return {"vx", "vy", "vz"}; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws, double* out) const override;

 private:
  int body_, node_;
};

/// Stress of one element from the body's stress modes (StressModes in
/// reduction/reduced_body.h), values = modes * w, as stored: for every
/// recovery point ("bottom", "top" of shells; "end_a", "end_b" of beams;
/// "centroid" of solids) its components in the element's stress frame
/// (shells: sxx syy sxy in the element frame [Pa]; beams: section forces N
/// Vy Vz [N], T My Mz [N m] in the element frame; solids: sxx .. szx in
/// body axes [Pa]), then for shells and solids its von Mises stress [Pa]
/// (beams have none: the section's shape is not stored). Component names
/// "<point>_<component>", e.g. "top_sxx", "top_von_mises", "end_a_My".
class ElementStressSensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies holding `flexible`, `element` an
  /// index into its mesh's elements. Throws InputError naming the body if
  /// the element is in none of its stress tables.
  ElementStressSensor(std::string name, int body, const FlexibleBody& flexible, int element);
  const char* type() const override { return "element_stress"; }
  std::vector<std::string> Components() const override { return names_; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws, double* out) const override;

 private:
  int body_;
  const reduction::StressTable* table_;  // owned by the body's reduced body
  int k_ = 0;                            // position in table_->elements
  bool von_mises_ = false;
  std::vector<std::string> names_;
};

/// Stress at a node, averaged over the elements around it: over its shell
/// elements if it has any, else over its solid elements (beams: use
/// ElementStressSensor). Each element's stress tensor at a recovery point
/// is turned to body axes (shells: plane stress in the element frame), the
/// tensors are averaged per recovery point ("bottom", "top" for shells,
/// "centroid" for solids), and the von Mises stress is that of the average.
/// Components "<point>_sxx", "_syy", "_szz", "_sxy", "_syz", "_szx" (body
/// axes) and "<point>_von_mises" [Pa].
class NodeStressSensor final : public Sensor {
 public:
  /// `body` is an index into Model::bodies holding `flexible`, `node` a node
  /// index of its mesh. Throws InputError naming the body and node if no
  /// shell or solid element with stress modes has the node.
  NodeStressSensor(std::string name, int body, const FlexibleBody& flexible, int node);
  const char* type() const override { return "node_stress"; }
  std::vector<std::string> Components() const override { return names_; }
  void Evaluate(const Model& model, const State& state, const Workspace& ws, double* out) const override;

 private:
  int body_;
  const reduction::StressTable* table_;  // owned by the body's reduced body
  std::vector<int> ks_;                  // positions in table_->elements
  bool shell_ = false;
  std::vector<std::string> names_;
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
