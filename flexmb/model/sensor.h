#pragma once
/// \file sensor.h
/// The interface of a sensor: named scalar components computed from the state.

#include <string>
#include <vector>

namespace flexmb {

class Model;
struct State;
struct Workspace;

/// A sensor yields one or more scalar components, written to results as
/// columns "<sensor>.<component>".
class Sensor {
 public:
  virtual ~Sensor() = default;
  /// Unique name.
  const std::string& name() const { return name_; }
  /// Type name as in the model file.
  virtual const char* type() const = 0;
  /// Component names, e.g. {"x", "y", "z"}.
  virtual std::vector<std::string> Components() const = 0;
  /// True if component k is an angle [rad] that may wrap at +-pi, so that a
  /// results writer can unwrap it over several turns.
  virtual bool ComponentIsAngle(int k) const { return false; }
  /// Writes the components to out. The workspace holds the marker states,
  /// joint evaluations and accelerations of `state` (Workspace::Update done).
  virtual void Evaluate(const Model& model, const State& state, const Workspace& ws,
                        double* out) const = 0;

 protected:
  explicit Sensor(std::string name) : name_(std::move(name)) {}

 private:
  std::string name_;
};

}  // namespace flexmb
