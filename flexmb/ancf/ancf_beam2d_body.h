#pragma once
/// \file ancf_beam2d_body.h
/// A planar ANCF beam as one Body: a chain of N AncfBeam2d elements of equal
/// length sharing nodes, moving in a plane P fixed in world (origin O_W, axes
/// R_WP = [u, w, n], n the plane normal).
///
/// Coordinates q = v = (x_k, y_k, x'_k, y'_k), k = 0..N, in plane axes [m, -];
/// the position of the centre line at reference arc length s is
/// p_W(s) = O_W + R_WP (r(s), 0). Tangent increments add to q (Retract is
/// q + dx). Mass matrix constant; forces: elastic, structural damping,
/// gravity (its in-plane part) and an optional constant load per length.
///
/// Markers sit at nodes (Marker::node). The node frame N has its x axis along
/// the slope r'_k, its z axis along the plane normal n; a marker's offset and
/// orientation (Marker::p_BM, R_BM) are given in N. Its angular velocity is
/// n dtheta/dt with theta = atan2(y'_k, x'_k). Marker Jacobians have rank 3
/// (planar motion): the body reports MarkerJacobianFullRank() false so that
/// the out-of-plane equations of joints on it are found redundant.

#include <vector>

#include "flexmb/ancf/ancf_beam2d.h"
#include "flexmb/ancf/ancf_line_body.h"

namespace flexmb::ancf {

/// Specification of a planar ANCF beam body; start_W is the plane origin
/// O_W, direction_W the initial direction of the beam at node 0, and only
/// the in-plane part of load_per_length_W acts.
struct AncfBeam2dData : AncfLineData {
  BeamSection section;            ///< section, material and damping
  double curvature0 = 0.0;        ///< stress-free curvature [1/m] (0: straight)
  Vec3 normal_W = Vec3::UnitZ();  ///< plane normal n; must not be parallel to direction
};

/// Planar ANCF beam body; see the file comment.
class AncfBeam2dBody final : public AncfLineBody<AncfBeam2dBody, AncfBeam2d, 4> {
 public:
  /// Throws InputError (naming the body) on a non-positive length, element
  /// count or section value, or a direction parallel to the normal. The
  /// initial shape is straight, or for curvature0 != 0 the circular arc of
  /// that curvature (nodes on the arc, slopes tangent to it; between nodes
  /// the cubic deviates from the arc by O((kappa0 L / N)^4)).
  AncfBeam2dBody(std::string name, const AncfBeam2dData& data);

  void InitialCoordinates(double* q, double* v) const override;
  bool MarkerJacobianFullRank() const override { return false; }
  void EvaluateMarker(const double* q, const double* v, const Marker& m,
                      MarkerState& out) const override;
  Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const override;
  void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                              Eigen::Ref<MatX> dQdq) const override;
  void MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                          Eigen::Ref<MatX> out) const override;
  Vec6 Momentum(const double* q, const double* v) const override;

  /// The (identical) element.
  const AncfBeam2d& element() const { return element_; }
  /// Plane axes [u, w, n] in world.
  const Mat3& R_WP() const { return R_WP_; }
  /// Strain energy of the whole beam [J] (ElasticEnergy).
  double StrainEnergy(const double* q) const { return ElasticEnergy(q); }

 private:
  using Base = AncfLineBody<AncfBeam2dBody, AncfBeam2d, 4>;
  friend Base;
  static constexpr const char* kLineKind = "beam";
  // hooks of the shared element loops (see ancf_line_body.h)
  const AncfBeam2d& ElementAt(int) const { return element_; }
  const Mat3& FrameAxes() const { return R_WP_; }
  // in-plane part of a world force per length
  Eigen::Vector2d LoadArg(const Vec3& f_W) const { return {R_WP_.col(0).dot(f_W), R_WP_.col(1).dot(f_W)}; }
  Vec3 PointToWorld(const Eigen::Vector2d& r) const { return data_.start_W + R_WP_.leftCols<2>() * r; }
  // potential of the plane origin: the coordinates are relative to it
  double GravityPotentialOffset(double rhoA, const Vec3& g_W) const {
    return -rhoA * data_.length * g_W.dot(data_.start_W);
  }

  AncfBeam2dData data_;
  AncfBeam2d element_;
  Mat3 R_WP_;
};

}  // namespace flexmb::ancf
