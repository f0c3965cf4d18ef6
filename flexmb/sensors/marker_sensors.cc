#include "flexmb/sensors/marker_sensors.h"

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

void MarkerPositionSensor::Evaluate(const Model&, const State&, const Workspace& ws,
                                    double* out) const {
  const MarkerState& m = ws.markers[marker_];
  Vec3 p = m.p_WM;
  // express in the reference marker's frame
  if (relative_to_ >= 0) {
    const MarkerState& r = ws.markers[relative_to_];
    p = r.R_WM.transpose() * (m.p_WM - r.p_WM);
  }
  for (int k = 0; k < 3; ++k) out[k] = p(k);
}

std::vector<std::string> MarkerVelocitySensor::Components() const {
  if (angular_) return {"x", "y", "z", "wx", "wy", "wz"};
  return {"x", "y", "z"};
}

void MarkerVelocitySensor::Evaluate(const Model&, const State&, const Workspace& ws,
                                    double* out) const {
  const MarkerState& m = ws.markers[marker_];
  for (int k = 0; k < 3; ++k) out[k] = m.v_WM(k);
  if (angular_)
    for (int k = 0; k < 3; ++k) out[3 + k] = m.w_WM(k);
}

std::vector<std::string> MarkerAccelerationSensor::Components() const {
  if (angular_) return {"x", "y", "z", "ax", "ay", "az"};
  return {"x", "y", "z"};
}

void MarkerAccelerationSensor::Evaluate(const Model& model, const State& state, const Workspace& ws,
                                        double* out) const {
  const MarkerState& ms = ws.markers[marker_];
  const Marker& marker = model.markers[marker_];
  const Body& body = *model.bodies[marker.body];
  Vec6 a = Vec6::Zero();
  // a = J vdot + velocity-product bias
  if (ms.nv > 0) {
    a.noalias() = ms.J * ws.vdot.segment(ms.v_offset, ms.nv);
    a += body.MarkerAccelerationBias(state.q.data() + body.q_offset,
                                     state.v.data() + body.v_offset, marker);
  }
  const int n = angular_ ? 6 : 3;
  for (int k = 0; k < n; ++k) out[k] = a(k);
}

std::vector<std::string> MarkerOrientationSensor::Components() const {
  if (quaternion_) return {"roll", "pitch", "yaw", "qw", "qx", "qy", "qz"};
  return {"roll", "pitch", "yaw"};
}

void MarkerOrientationSensor::Evaluate(const Model&, const State&, const Workspace& ws,
                                       double* out) const {
  Mat3 R = ws.markers[marker_].R_WM;
  if (relative_to_ >= 0) R = ws.markers[relative_to_].R_WM.transpose() * R;
  const Vec3 rpy = RollPitchYaw(R);
  for (int k = 0; k < 3; ++k) out[k] = rpy(k);
  if (!quaternion_) return;
  // canonical sign: qw >= 0
  Quat q(R);
  q.normalize();
  const double s = q.w() < 0.0 ? -1.0 : 1.0;
  out[3] = s * q.w(), out[4] = s * q.x(), out[5] = s * q.y(), out[6] = s * q.z();
}

}  // namespace flexmb
