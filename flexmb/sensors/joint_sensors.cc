#include "flexmb/sensors/joint_sensors.h"

#include "flexmb/common/error.h"
#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

JointCoordinateSensor::JointCoordinateSensor(std::string name, int joint, const Joint& joint_ref,
                                             int coordinate)
    : Sensor(std::move(name)), joint_(joint), coordinate_(coordinate) {
  if (coordinate < 0 || coordinate >= joint_ref.NumCoordinates())
    throw InputError("joint '" + joint_ref.name() + "' (" + joint_ref.type() + ") has no coordinate " +
                         std::to_string(coordinate),
                     {"", 0, "sensor '" + this->name() + "'"});
  is_angle_ = joint_ref.CoordinateIsAngle(coordinate);
}

void JointCoordinateSensor::Evaluate(const Model& model, const State&, const Workspace& ws,
                                     double* out) const {
  const Joint& j = *model.joints[joint_];
  const MarkerState& mi = ws.markers[j.marker_i];
  const MarkerState& mj = ws.markers[j.marker_j];
  Vec12 dq;
  out[0] = j.Coordinate(coordinate_, mi, mj, &dq);
  // rate = dq . (v_i, w_i, v_j, w_j)
  out[1] = dq.segment<3>(0).dot(mi.v_WM) + dq.segment<3>(3).dot(mi.w_WM) +
           dq.segment<3>(6).dot(mj.v_WM) + dq.segment<3>(9).dot(mj.w_WM);
}

void JointReactionSensor::Evaluate(const Model& model, const State& state, const Workspace& ws,
                                   double* out) const {
  const Joint& j = *model.joints[joint_];
  const JointEval& e = ws.joints[joint_];
  // wrench on marker j: -(D^T lambda) in its j columns
  Vec3 f = Vec3::Zero(), m = Vec3::Zero();
  for (int q = 0; q < j.NumEquations(); ++q) {
    const double lam = state.lambda(j.lambda_offset + q);
    f -= lam * e.D.block<1, 3>(q, 6).transpose();
    m -= lam * e.D.block<1, 3>(q, 9).transpose();
  }
  if (!world_) {
    const Mat3& R = ws.markers[j.marker_i].R_WM;
    f = R.transpose() * f;
    m = R.transpose() * m;
  }
  for (int k = 0; k < 3; ++k) out[k] = f(k), out[3 + k] = m(k);
}

}  // namespace flexmb
