#pragma once
/// \file rigid_body.h
/// Rigid body with six degrees of freedom on R3 x SO(3).
///
/// Coordinates: q = (p_WC [m], quaternion of R_WB (w, x, y, z)), the position of
/// the centre of mass C in world and the orientation of the body axes.
/// Velocities: v = (v_WC [m/s] in world, w_WB_B [rad/s] in body axes). With C as
/// the internal reference point the mass matrix is constant,
/// M = diag(m I, J_C), and the only velocity term is the gyroscopic moment.
/// Tangent increments dx = (dp_W, dtheta_B): p += dp, R <- R exp(dtheta).

#include "flexmb/bodies/body.h"

namespace flexmb {

/// Inertia tensor about the centre of mass in body axes, from the inertia
/// I_F [kg m^2] given about the origin of a frame F (position p_BF, axes R_BF in
/// the user's body frame B), for mass m [kg] with centre of mass c_B [m].
Mat3 InertiaAboutCom(double mass, const Mat3& I_F, const Vec3& p_BF, const Mat3& R_BF,
                     const Vec3& c_B);

/// Physical and initial data of a rigid body, all in the user's body frame B.
struct RigidBodyData {
  double mass = 0.0;                  ///< [kg], > 0
  Mat3 inertia_C = Mat3::Zero();      ///< about the centre of mass, body axes [kg m^2], SPD
  Vec3 c_B = Vec3::Zero();            ///< centre of mass in body frame [m]
  Vec3 p_WB = Vec3::Zero();           ///< initial position of the body frame origin [m]
  Mat3 R_WB = Mat3::Identity();       ///< initial orientation
  Vec3 v_WB = Vec3::Zero();           ///< initial velocity of the body frame origin, world [m/s]
  Vec3 w_WB = Vec3::Zero();           ///< initial angular velocity, world [rad/s]
};

/// Rigid body; see the file comment for its coordinates.
class RigidBody final : public Body {
 public:
  /// Throws InputError if the mass is not positive or the inertia is not
  /// symmetric positive definite (or violates the triangle inequality).
  RigidBody(std::string name, const RigidBodyData& data);

  int nq() const override { return 7; }
  int nv() const override { return 6; }
  void InitialCoordinates(double* q, double* v) const override;
  void Retract(const double* q, const double* dx, double* q_out) const override;
  void MassMatrix(const double* q, MatX& M) const override;
  void AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                 Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const override;
  void EvaluateMarker(const double* q, const double* v, const Marker& m,
                      MarkerState& out) const override;
  Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const override;
  void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                              Eigen::Ref<MatX> dQdq) const override;
  void MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                          Eigen::Ref<MatX> out) const override;
  double KineticEnergy(const double* q, const double* v) const override;
  double GravityPotential(const double* q, const Vec3& g_W) const override;
  Vec6 Momentum(const double* q, const double* v) const override;
  void BodyFramePose(const double* q, Vec3& p_WB, Mat3& R_WB) const override;
  Vec3 InternalPosition(const Vec3& p_B) const override { return p_B - data_.c_B; }

  /// Mass [kg].
  double mass() const { return data_.mass; }
  /// Inertia about the centre of mass in body axes [kg m^2].
  const Mat3& inertia_C() const { return data_.inertia_C; }
  /// Centre of mass in the user's body frame [m]; markers given in the body
  /// frame are stored relative to it.
  const Vec3& com_B() const { return data_.c_B; }

 private:
  RigidBodyData data_;
};

}  // namespace flexmb
