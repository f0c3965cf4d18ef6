#pragma once
/// \file ancf_beam3d_body.h
/// A 3D ANCF beam with torsion as one Body: a chain of N AncfBeam3d elements
/// of equal length sharing nodes. Coordinates q = v = (r_k, r'_k, phi_k),
/// k = 0..N (7 per node; world components [m, -, rad]); increments add to q
/// (Retract is q + dx). Mass matrix constant; forces: elastic (axial,
/// bending about both section axes, torsion), structural damping, gravity
/// and an optional constant load per length. The reference shape is straight
/// or a circular arc (initial curvature, stress-free).
///
/// Markers sit at nodes (Marker::node). The node frame N is the section
/// frame of the beam there: R_WN = Rmin(t0 -> t) R_0 Rx(phi_k), x along the
/// slope t = r'_k / |r'_k|, y and z the section axes (see ancf_beam3d.h),
/// R_0 = [t0, y0, z0] the frame at node 0 in the reference state. Its angular
/// velocity is w = G(r'_k) r'dot_k + phidot_k t, so the marker Jacobian has
/// full rank 6 (a fixed joint clamps position, slope and twist). The frame
/// rule is singular when a slope turns to -t0 (NumericalError).
/// A marker's offset and orientation (Marker::p_BM, R_BM) are given in N.

#include <utility>
#include <vector>

#include "flexmb/ancf/ancf_beam3d.h"
#include "flexmb/ancf/ancf_line_body.h"

namespace flexmb::ancf {

/// Specification of a 3D ANCF beam body. The reference shape starts at
/// start_W with tangent direction_W; it is straight (radius 0) or an arc of
/// the given radius turning about the normal (towards y0 = z0 x t0).
struct AncfBeam3dData : AncfLineData {
  Beam3dSection section;  ///< section, material and damping (of every element unless element_sections)
  /// Sections of the elements 0..N-1 in order (a stepped or tapered beam);
  /// empty: every element has `section`. Lengths stay equal.
  std::vector<Beam3dSection> element_sections;
  /// Section z axis z0 at node 0 (its part normal to direction_W); a zero
  /// vector picks world z, or world x if direction_W is along z.
  Vec3 normal_W = Vec3::Zero();
  double radius = 0.0;  ///< radius of the reference arc [m]; 0: straight
};

/// 3D ANCF beam body with torsion; see the file comment.
class AncfBeam3dBody final : public AncfLineBody<AncfBeam3dBody, AncfBeam3d, 7> {
 public:
  /// Throws InputError (naming the body) on a non-positive length, element
  /// count or section value, element_sections not one per element, a negative radius, an arc turning by 180 degrees
  /// or more, a zero direction, or a normal parallel to it.
  AncfBeam3dBody(std::string name, const AncfBeam3dData& data);

  void InitialCoordinates(double* q, double* v) const override;
  void EvaluateMarker(const double* q, const double* v, const Marker& m,
                      MarkerState& out) const override;
  Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const override;
  void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                              Eigen::Ref<MatX> dQdq) const override;
  void MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                          Eigen::Ref<MatX> out) const override;
  /// Momentum of the centre line (the twist rotary inertia is left out).
  Vec6 Momentum(const double* q, const double* v) const override;

  /// Element i (0..N-1).
  const AncfBeam3d& element(int i) const { return elements_[i]; }
  /// Reference frame R_0 = [t0, y0, z0] in world.
  const Mat3& R_W0() const { return R_W0_; }
  /// Total undeformed length [m].
  double length() const { return data_.length; }
  /// Section frame [t, d2, d3] of node k (the node frame of its markers).
  Mat3 NodeFrame(const double* q, int k) const;

 private:
  using Base = AncfLineBody<AncfBeam3dBody, AncfBeam3d, 7>;
  friend Base;
  static constexpr const char* kLineKind = "beam";
  // hooks of the shared element loops (see ancf_line_body.h)
  const AncfBeam3d& ElementAt(int i) const { return elements_[i]; }
  const Mat3& FrameAxes() const { return R_W0_; }
  // node frame of marker m, with a NumericalError naming it at a singular slope
  Mat3 MarkerFrame(const double* q, const Marker& m) const;

  AncfBeam3dData data_;
  Mat3 R_W0_;
  std::vector<AncfBeam3d> elements_;
  VecX q0_;
};

}  // namespace flexmb::ancf
