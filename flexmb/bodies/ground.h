#pragma once
/// \file ground.h
/// The ground: the world frame, a body without coordinates.

#include "flexmb/bodies/body.h"

namespace flexmb {

/// The fixed world frame. Markers on the ground are fixed world frames.
class Ground final : public Body {
 public:
  Ground() : Body("ground") {}
  int nq() const override { return 0; }
  int nv() const override { return 0; }
  void InitialCoordinates(double*, double*) const override {}
  void Retract(const double*, const double*, double*) const override {}
  void MassMatrix(const double*, MatX& M) const override { M.resize(0, 0); }
  void AddForces(const double*, const double*, const Vec3&, Eigen::Ref<VecX>, Eigen::Ref<MatX>,
                 Eigen::Ref<MatX>) const override {}
  void EvaluateMarker(const double*, const double*, const Marker& m, MarkerState& out) const override;
  Vec6 MarkerAccelerationBias(const double*, const double*, const Marker&) const override {
    return Vec6::Zero();
  }
  void AddMarkerWrenchTangent(const double*, const Marker&, const Vec6&,
                              Eigen::Ref<MatX>) const override {}
  void MarkerTwistTangent(const double*, const double*, const Marker&, Eigen::Ref<MatX>) const override {}
  double KineticEnergy(const double*, const double*) const override { return 0.0; }
  double GravityPotential(const double*, const Vec3&) const override { return 0.0; }
  Vec6 Momentum(const double*, const double*) const override { return Vec6::Zero(); }
  void BodyFramePose(const double*, Vec3& p_WB, Mat3& R_WB) const override {
    p_WB.setZero();
    R_WB.setIdentity();
  }
};

}  // namespace flexmb
