#pragma once
/// \file ancf_cable3d_body.h
/// A 3D ANCF cable as one Body: a chain of N AncfCable3d elements of equal
/// length sharing nodes. Coordinates q = v = (r_k, r'_k), k = 0..N, in world
/// components [m, -] (6 per node); tangent increments add to q (Retract is
/// q + dx). Mass matrix constant; forces: elastic (axial and bending),
/// structural damping, gravity and an optional constant load per length.
///
/// Markers sit at nodes (Marker::node). The cable has no torsion, so the
/// slope r'_k fixes only the x axis of the node frame N; the rule for the two
/// other axes is the minimal rotation from the reference frame: R_WN =
/// Rmin(t0 -> t) R_0, where t = r'_k / |r'_k|, t0 is the initial direction of
/// the cable (`direction`), R_0 = [t0, y0, z0] the reference node frame (z0
/// the part of `normal` normal to t0, y0 = z0 x t0), and Rmin(t0 -> t) the
/// rotation by the smallest angle about t0 x t that takes t0 into t
/// (quaternion proportional to (1 + t0.t, t0 x t)). Its angular velocity is
/// w = 2 vec(pdot p*) / |p|^2 with p = (1 + t0.t, t0 x t): it has no free
/// spin about t, so a marker's twist Jacobian has rank 5 and the body reports
/// MarkerJacobianFullRank() false. The rule is singular when the slope turns
/// to -t0 (NumericalError naming the marker when t0.t < -1 + 1e-8).
/// A marker's offset and orientation (Marker::p_BM, R_BM) are given in N.

#include <utility>
#include <vector>

#include "flexmb/ancf/ancf_cable3d.h"
#include "flexmb/ancf/ancf_line_body.h"

namespace flexmb::ancf {

/// Specification of a 3D ANCF cable body. The initial shape is straight from
/// start_W along direction_W, moving as a rigid body with angular velocity
/// angular_velocity_W about start_W.
struct AncfCable3dData : AncfLineData {
  BeamSection section;  ///< section, material and damping
  /// Reference z axis of the node frames (its part normal to direction_W);
  /// a zero vector picks world z, or world x if direction_W is along z.
  Vec3 normal_W = Vec3::Zero();
  Vec3 angular_velocity_W = Vec3::Zero();  ///< initial rigid rotation rate about start_W [rad/s]
};

/// 3D ANCF cable body; see the file comment.
class AncfCable3dBody final : public AncfLineBody<AncfCable3dBody, AncfCable3d, 6> {
 public:
  /// Throws InputError (naming the body) on a non-positive length, element
  /// count or section value, a zero direction, or a normal parallel to it.
  AncfCable3dBody(std::string name, const AncfCable3dData& data);

  void InitialCoordinates(double* q, double* v) const override;
  bool MarkerJacobianFullRank() const override { return false; }
  void EvaluateMarker(const double* q, const double* v, const Marker& m,
                      MarkerState& out) const override;
  Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const override;
  void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                              Eigen::Ref<MatX> dQdq) const override;
  void MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                          Eigen::Ref<MatX> out) const override;
  /// Momentum of the centre line (mass m (x) I3 per element).
  Vec6 Momentum(const double* q, const double* v) const override;

  /// The (identical) element.
  const AncfCable3d& element() const { return element_; }
  /// Reference node frame R_0 = [t0, y0, z0] in world.
  const Mat3& R_W0() const { return R_W0_; }
  /// Rotation R_WN of the node frame for the slope a (see the file comment);
  /// throws NumericalError naming the marker `marker` at the singular slope -t0.
  Mat3 NodeFrame(const Vec3& a, const std::string& marker) const;

 private:
  using Base = AncfLineBody<AncfCable3dBody, AncfCable3d, 6>;
  friend Base;
  static constexpr const char* kLineKind = "cable";
  // hooks of the shared element loops (see ancf_line_body.h)
  const AncfCable3d& ElementAt(int) const { return element_; }
  const Mat3& FrameAxes() const { return R_W0_; }
  // node frame angular velocity w = G(a) adot: G (3 x 3)
  Mat3 RateMatrix(const Vec3& a, const Marker& m) const;
  // d(G(a) u)/da at fixed u (3 x 3)
  Mat3 RateDerivative(const Vec3& a, const Vec3& u) const;
  // d(G(a)^T y)/da at fixed y (3 x 3)
  Mat3 RateTransposeDerivative(const Vec3& a, const Vec3& y) const;

  AncfCable3dData data_;
  AncfCable3d element_;
  Vec3 t0_;
  Mat3 R_W0_;
};

}  // namespace flexmb::ancf
