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
#include "flexmb/bodies/body.h"

namespace flexmb::ancf {

/// Specification of a planar ANCF beam body.
struct AncfBeam2dData {
  double length = 0.0;            ///< undeformed length [m], > 0
  int elements = 0;               ///< number of elements N, > 0
  BeamSection section;            ///< section, material and damping
  double curvature0 = 0.0;        ///< stress-free curvature [1/m] (0: straight)
  QuadratureOrder order;          ///< quadrature of the elastic forces
  Vec3 start_W = Vec3::Zero();    ///< initial position of node 0, plane origin O_W [m]
  Vec3 direction_W = Vec3::UnitX();  ///< initial direction of the beam at node 0 (unit after normalization)
  Vec3 normal_W = Vec3::UnitZ();  ///< plane normal n; must not be parallel to direction
  Vec3 load_per_length_W = Vec3::Zero();  ///< constant distributed load [N/m] (its in-plane part acts)
};

/// Planar ANCF beam body; see the file comment.
class AncfBeam2dBody final : public Body {
 public:
  /// Throws InputError (naming the body) on a non-positive length, element
  /// count or section value, or a direction parallel to the normal. The
  /// initial shape is straight, or for curvature0 != 0 the circular arc of
  /// that curvature (nodes on the arc, slopes tangent to it; between nodes
  /// the cubic deviates from the arc by O((kappa0 L / N)^4)).
  AncfBeam2dBody(std::string name, const AncfBeam2dData& data);

  int nq() const override { return 4 * (n_el_ + 1); }
  int nv() const override { return 4 * (n_el_ + 1); }
  void InitialCoordinates(double* q, double* v) const override;
  void Retract(const double* q, const double* dx, double* q_out) const override;
  void MassMatrix(const double* q, MatX& M) const override;
  bool HasConstantMass() const override { return true; }
  bool MarkerJacobianFullRank() const override { return false; }
  void AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                 Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const override;
  /// Element-wise coupling: the 8x8 blocks of the elements, overlapping
  /// at the shared nodes (banded, half bandwidth 7).
  bool BlockPattern(std::vector<std::pair<int, int>>& entries) const override;
  /// The 4 velocities of the marker's node.
  std::pair<int, int> MarkerColumns(const Marker& m) const override { return {4 * NodeOf(m), 4}; }
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
  /// The strain energy of the whole beam [J] (StrainEnergy).
  double ElasticEnergy(const double* q) const override { return StrainEnergy(q); }
  /// The plane frame: origin O_W, axes R_WP.
  void BodyFramePose(const double* q, Vec3& p_WB, Mat3& R_WB) const override;

  /// Number of elements N.
  int elements() const { return n_el_; }
  /// Number of nodes N + 1.
  int nodes() const { return n_el_ + 1; }
  /// The (identical) element.
  const AncfBeam2d& element() const { return element_; }
  /// Plane axes [u, w, n] in world.
  const Mat3& R_WP() const { return R_WP_; }
  /// Strain energy of the whole beam [J].
  double StrainEnergy(const double* q) const;
  /// World position [m] of the centre line at reference arc length s in [0, L].
  Vec3 PositionAt(const double* q, double s) const;

 private:
  // checks the marker's node index
  int NodeOf(const Marker& m) const;

  AncfBeam2dData data_;
  int n_el_;
  AncfBeam2d element_;
  Mat3 R_WP_;
  MatX mass_;
};

}  // namespace flexmb::ancf
