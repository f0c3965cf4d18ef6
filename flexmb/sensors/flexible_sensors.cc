#include "flexmb/sensors/flexible_sensors.h"

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/model/model.h"

namespace flexmb {
namespace {

// the body, known to be flexible when the sensor was made
const FlexibleBody& Flexible(const Model& model, int body) {
  return static_cast<const FlexibleBody&>(*model.bodies[body]);
}

}  // namespace

ModalCoordinatesSensor::ModalCoordinatesSensor(std::string name, int body, const FlexibleBody& flexible)
    : Sensor(std::move(name)), body_(body), n_(flexible.modes()) {}

std::vector<std::string> ModalCoordinatesSensor::Components() const {
  std::vector<std::string> c;
  for (int i = 0; i < n_; ++i) c.push_back("w" + std::to_string(i + 1));
  return c;
}

void ModalCoordinatesSensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                      double* out) const {
  const Body& b = *model.bodies[body_];
  for (int i = 0; i < n_; ++i) out[i] = state.q(b.q_offset + 7 + i);
}

void NodeDisplacementSensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                      double* out) const {
  const FlexibleBody& b = Flexible(model, body_);
  const Vec3 u = b.NodeDisplacement(state.q.data() + b.q_offset, node_);
  for (int k = 0; k < 3; ++k) out[k] = u(k);
}

void StrainEnergySensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                  double* out) const {
  const FlexibleBody& b = Flexible(model, body_);
  out[0] = b.StrainEnergy(state.q.data() + b.q_offset);
}

}  // namespace flexmb
