#pragma once
/// \file marker.h
/// Markers: frames attached to bodies. Joints, force elements and sensors
/// connect markers, never bodies, so that every joint works on every body type.

#include <Eigen/Core>
#include <string>

#include "flexmb/math/rotation.h"

namespace flexmb {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
using Mat6X = Eigen::Matrix<double, 6, Eigen::Dynamic>;

/// A frame M fixed on a body B. For a rigid body the offset is from the body's
/// internal frame (its centre of mass, axes of the user's body frame); for a
/// node-based body `node` names the node and the offset is from that node.
struct Marker {
  std::string name;      ///< "body.marker", unique in the model
  int body = 0;          ///< index into Model::bodies (0 = ground)
  int node = -1;         ///< node index on node-based bodies, -1 otherwise
  Vec3 p_BM = Vec3::Zero();          ///< origin of M in the body's internal frame [m]
  Mat3 R_BM = Mat3::Identity();      ///< orientation of M relative to the body frame
};

/// The kinematic state of a marker, evaluated from the body's coordinates.
/// Variations of the pose are (dp_W, dtheta_W): displacement of the origin and
/// small rotation, both in world components, with dR_WM = skew(dtheta_W) R_WM.
/// J maps the body's velocity coordinates (and equally its tangent increments)
/// to the marker twist: [v_WM; w_WM] = J * v_body.
struct MarkerState {
  Vec3 p_WM = Vec3::Zero();      ///< origin position in world [m]
  Mat3 R_WM = Mat3::Identity();  ///< orientation in world
  Vec3 v_WM = Vec3::Zero();      ///< origin velocity in world [m/s]
  Vec3 w_WM = Vec3::Zero();      ///< angular velocity in world [rad/s]
  Mat6X J;                       ///< 6 x nv(body) twist Jacobian
  int v_offset = 0;              ///< offset of the body's velocity coordinates
  int nv = 0;                    ///< number of velocity coordinates of the body
};

}  // namespace flexmb
