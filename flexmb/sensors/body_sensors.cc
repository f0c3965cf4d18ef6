#include "flexmb/sensors/body_sensors.h"

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

void BodyPositionSensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                  double* out) const {
  const Body& b = *model.bodies[body_];
  Vec3 p;
  Mat3 R;
  b.BodyFramePose(state.q.data() + b.q_offset, p, R);
  const Vec3 rpy = RollPitchYaw(R);
  for (int k = 0; k < 3; ++k) out[k] = p(k), out[3 + k] = rpy(k);
}

void BodyEnergySensor::Evaluate(const Model& model, const State& state, const Workspace&,
                                double* out) const {
  const Body& b = *model.bodies[body_];
  const double* q = state.q.data() + b.q_offset;
  out[0] = b.KineticEnergy(q, state.v.data() + b.v_offset);
  out[1] = b.GravityPotential(q, model.gravity_W);
}

void SystemEnergySensor::Evaluate(const Model& model, const State& state, const Workspace& ws,
                                  double* out) const {
  double kinetic = 0.0, potential = 0.0;
  // bodies: kinetic energy and gravity
  for (const auto& b : model.bodies) {
    const double* q = state.q.data() + b->q_offset;
    kinetic += b->KineticEnergy(q, state.v.data() + b->v_offset);
    potential += b->GravityPotential(q, model.gravity_W);
    potential += b->ElasticEnergy(q);
  }
  // force elements: stored energy
  static const MarkerState kNoMarker{};
  const MarkerState* more[kMaxForceMarkers] = {nullptr};
  for (const auto& f : model.forces) {
    if (f->NumMarkers() > 2) {
      for (int a = 0; a < f->NumMarkers(); ++a) more[a] = &ws.markers[f->MarkerAt(a)];
      potential += f->PotentialEnergyMarkers(more, state.t);
      continue;
    }
    const MarkerState& mi = ws.markers[f->marker_i];
    const MarkerState& mj = f->marker_j >= 0 ? ws.markers[f->marker_j] : kNoMarker;
    potential += f->PotentialEnergy(mi, mj, state.t);
  }
  out[0] = kinetic;
  out[1] = potential;
  out[2] = kinetic + potential;
}

}  // namespace flexmb
