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
#include "flexmb/bodies/body.h"

namespace flexmb::ancf {

/// Specification of a 3D ANCF beam body. The reference shape starts at
/// start_W with tangent direction_W; it is straight (radius 0) or an arc of
/// the given radius turning about the normal (towards y0 = z0 x t0).
struct AncfBeam3dData {
  double length = 0.0;               ///< undeformed length (arc length) [m], > 0
  int elements = 0;                  ///< number of elements N, > 0
  Beam3dSection section;             ///< section, material and damping
  QuadratureOrder order;             ///< quadrature of the elastic forces
  Vec3 start_W = Vec3::Zero();       ///< position of node 0 [m]
  Vec3 direction_W = Vec3::UnitX();  ///< tangent t0 at node 0 (normalized on use)
  /// Section z axis z0 at node 0 (its part normal to direction_W); a zero
  /// vector picks world z, or world x if direction_W is along z.
  Vec3 normal_W = Vec3::Zero();
  double radius = 0.0;                    ///< radius of the reference arc [m]; 0: straight
  Vec3 load_per_length_W = Vec3::Zero();  ///< constant distributed load [N/m]
};

/// 3D ANCF beam body with torsion; see the file comment.
class AncfBeam3dBody final : public Body {
 public:
  /// Throws InputError (naming the body) on a non-positive length, element
  /// count or section value, a negative radius, an arc turning by 180 degrees
  /// or more, a zero direction, or a normal parallel to it.
  AncfBeam3dBody(std::string name, const AncfBeam3dData& data);

  int nq() const override { return 7 * (n_el_ + 1); }
  int nv() const override { return 7 * (n_el_ + 1); }
  void InitialCoordinates(double* q, double* v) const override;
  void Retract(const double* q, const double* dx, double* q_out) const override;
  void MassMatrix(const double* q, MatX& M) const override;
  bool HasConstantMass() const override { return true; }
  void AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                 Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const override;
  /// Element-wise coupling: 14x14 blocks overlapping at the shared nodes.
  bool BlockPattern(std::vector<std::pair<int, int>>& entries) const override;
  /// The 7 velocities of the marker's node.
  std::pair<int, int> MarkerColumns(const Marker& m) const override { return {7 * NodeOf(m), 7}; }
  void EvaluateMarker(const double* q, const double* v, const Marker& m,
                      MarkerState& out) const override;
  Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const override;
  void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                              Eigen::Ref<MatX> dQdq) const override;
  void MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                          Eigen::Ref<MatX> out) const override;
  double KineticEnergy(const double* q, const double* v) const override;
  double GravityPotential(const double* q, const Vec3& g_W) const override;
  /// Strain energy of the whole beam [J].
  double ElasticEnergy(const double* q) const override;
  /// Momentum of the centre line (the twist rotary inertia is left out).
  Vec6 Momentum(const double* q, const double* v) const override;
  /// The reference frame: origin start_W, axes R_0 = [t0, y0, z0].
  void BodyFramePose(const double* q, Vec3& p_WB, Mat3& R_WB) const override;

  /// Number of elements N.
  int elements() const { return n_el_; }
  /// Number of nodes N + 1.
  int nodes() const { return n_el_ + 1; }
  /// Element i (0..N-1).
  const AncfBeam3d& element(int i) const { return elements_[i]; }
  /// Reference frame R_0 = [t0, y0, z0] in world.
  const Mat3& R_W0() const { return R_W0_; }
  /// Total undeformed length [m].
  double length() const { return data_.length; }
  /// World position [m] of the centre line at reference arc length s in [0, L].
  Vec3 PositionAt(const double* q, double s) const;
  /// Section frame [t, d2, d3] of node k (the node frame of its markers).
  Mat3 NodeFrame(const double* q, int k) const;

 private:
  // checks the marker's node index
  int NodeOf(const Marker& m) const;
  // node frame of marker m, with a NumericalError naming it at a singular slope
  Mat3 MarkerFrame(const double* q, const Marker& m) const;

  AncfBeam3dData data_;
  int n_el_;
  Mat3 R_W0_;
  std::vector<AncfBeam3d> elements_;
  VecX q0_;
  MatX mass_;
};

}  // namespace flexmb::ancf
