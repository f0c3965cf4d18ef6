#pragma once
/// \file flexible_body.h
/// Floating-frame (FFR) flexible body: a Craig-Bampton reduced body
/// (reduction/reduced_body.h) in large motion, THEORY sections 3 to 6.
///
/// Coordinates: q = (r_W [m], quaternion of R_WB (w, x, y, z), w [modal]),
/// the position of the body frame origin (the FE model's basic origin) in
/// world, the orientation of the body frame, and the n modal coordinates;
/// nq = 7 + n.
/// Velocities: v = (v_W [m/s] velocity of the frame origin in world,
/// om_B [rad/s] angular velocity in body axes, wd modal velocities); nv =
/// 6 + n. This is the rigid body's choice (world translation, body rotation)
/// with the frame origin as the reference point; THEORY's nu = (R^T v_W, om,
/// wd). Tangent increments dx = (dp_W, dtheta_B, dw): r += dp,
/// R <- R exp(dtheta), w += dw.
///
/// Node k of the FE mesh is at u_k = rho_k + H_k^t w in the body frame and
/// turned by the small rotation H_k^r w. A marker on node k with offset d
/// (Marker::p_BM, body axes) is the point s = rho_k + d + (H_k^t - skew(d)
/// H_k^r) w (the offset turns with the node to first order, so the point is
/// linear in w) with orientation R exp(skew(H_k^r w)) R_BM. Its twist is
/// J v with J = [[I, -R skew(s), R (H_k^t - skew(d) H_k^r)], [0, R, R H_k^r]]
/// (THEORY section 6): exact for the position; for the rotation it is the
/// derivative of the exponential to first order in the elastic rotation, as
/// in the linear FE model. A marker without a node (node = -1) is fixed on
/// the floating frame at p_BM.
///
/// Forces: inertial and gravity forces from the inertia invariants
/// (flexible_inertia.h), elastic -K w and damping -D wd with the reduced
/// stiffness and damping of the body (or a damping override), and, if the
/// body file has it and FlexibleBodyData::geometric_stiffening allows, the
/// centrifugal geometric stiffening -G(om) w (geometric_stiffening.h) and
/// the stiffening by the body's own deformation -G(w) w
/// (deformation_stiffening.h).

#include <memory>

#include "flexmb/bodies/body.h"
#include "flexmb/bodies/flexible_inertia.h"
#include "flexmb/bodies/flexible_mass_tangent.h"
#include "flexmb/bodies/deformation_stiffening.h"
#include "flexmb/bodies/geometric_stiffening.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb {

/// Data of a flexible body: the reduced body and the initial state.
struct FlexibleBodyData {
  std::shared_ptr<const reduction::ReducedBody> reduced;  ///< body file contents, required
  Vec3 p_WB = Vec3::Zero();      ///< initial position of the frame origin [m]
  Mat3 R_WB = Mat3::Identity();  ///< initial orientation
  Vec3 v_WB = Vec3::Zero();      ///< initial velocity of the frame origin, world [m/s]
  Vec3 w_WB = Vec3::Zero();      ///< initial angular velocity, world [rad/s]
  VecX w0;                       ///< initial modal coordinates (empty = zero)
  VecX wd0;                      ///< initial modal velocities (empty = zero)
  /// Damping override, n x n (empty = the reduced body's damping).
  MatX damping;
  /// Geometric stiffening from the body file's centrifugal geometric
  /// stiffness (bodies/geometric_stiffening.h): by default used if present.
  GeometricStiffening geometric_stiffening = GeometricStiffening::kAuto;
  /// Stiffening by the body's own deformation from the body file's
  /// deformation stiffness (bodies/deformation_stiffening.h): by default
  /// used if present.
  GeometricStiffening deformation_stiffening = GeometricStiffening::kAuto;
};

/// Floating-frame flexible body; see the file comment.
class FlexibleBody final : public Body {
 public:
  /// Throws InputError naming the body if the reduced body is missing or its
  /// sizes are inconsistent (invariants, modes, matrices, initial values).
  FlexibleBody(std::string name, FlexibleBodyData data);
  /// Not copyable or movable: the mass tangent refers to this body's inertia.
  FlexibleBody(const FlexibleBody&) = delete;
  FlexibleBody& operator=(const FlexibleBody&) = delete;

  int nq() const override { return 7 + n_; }
  int nv() const override { return 6 + n_; }
  void InitialCoordinates(double* q, double* v) const override;
  void Retract(const double* q, const double* dx, double* q_out) const override;
  void MassMatrix(const double* q, MatX& M) const override;
  bool HasConstantMass() const override { return false; }
  void AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                 Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const override;
  /// The forces of AddForces without their derivatives (no O(n^2) tangent
  /// work); returns true.
  bool AddForceVector(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q) const override;
  /// d(M(q) a)/dq by FlexibleMassTangent (analytic, O(n^2)).
  void AddMassTangent(const double* q, const double* a, double scale, Eigen::Ref<MatX> K) const override;
  void EvaluateMarker(const double* q, const double* v, const Marker& m,
                      MarkerState& out) const override;
  Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const override;
  void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                              Eigen::Ref<MatX> dQdq) const override;
  void MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                          Eigen::Ref<MatX> out) const override;
  /// 1/2 nu^T M(w) nu [J].
  double KineticEnergy(const double* q, const double* v) const override;
  /// -g . (m r + R (S0 + M_vw w)), S0 the first moment about the frame origin [J].
  double GravityPotential(const double* q, const Vec3& g_W) const override;
  Vec6 Momentum(const double* q, const double* v) const override;
  /// The strain energy 1/2 w^T K w [J] (StrainEnergy).
  double ElasticEnergy(const double* q) const override { return StrainEnergy(q); }
  void BodyFramePose(const double* q, Vec3& p_WB, Mat3& R_WB) const override;

  /// Elastic strain energy 1/2 w^T K w [J] (the stiffening forces have no
  /// potential; docs/design.md, "Geometric stiffening").
  double StrainEnergy(const double* q) const;
  /// Elastic displacement of node `node` (index) relative to the floating
  /// frame, H_k^t w, body axes [m].
  Vec3 NodeDisplacement(const double* q, int node) const;
  /// World position of node `node` (index), r + R (rho_k + H_k^t w) [m].
  Vec3 NodePosition(const double* q, int node) const;
  /// World velocity of node `node` (index), v_W + R (om x u_k + H_k^t wd)
  /// with u_k = rho_k + H_k^t w [m/s].
  Vec3 NodeVelocity(const double* q, const double* v, int node) const;
  /// Copies the mode rows of the marker nodes into one small matrix
  /// (marker_modes_): in the column-major mode matrix one row's entries of
  /// successive modes are 8 x 6 x nodes bytes apart, so every marker
  /// evaluation touched one page per mode.
  void UseMarkerNodes(const std::vector<int>& nodes) override;
  /// Number of modal coordinates.
  int modes() const { return n_; }
  /// The reduced body.
  const reduction::ReducedBody& reduced() const { return *data_.reduced; }
  /// True if `node` (index) moves exactly as the FE model's node: an
  /// interface node of the reduction, or a node clamped in it (`reduce
  /// --fix`: no modal motion, the node is fixed to the floating frame).
  bool IsInterfaceNode(int node) const;
  /// Reduced damping matrix in use (n x n).
  const MatX& damping() const { return damping_; }
  /// True if the body adds the geometric stiffening force.
  bool HasGeometricStiffening() const { return stiffening_ != nullptr; }
  /// True if the body adds the deformation stiffening force.
  bool HasDeformationStiffening() const { return deformation_stiffening_ != nullptr; }

 private:
  // Q_w -= K w + D wd
  void AddElasticAndDamping(const double* w, const double* wd, Eigen::Ref<VecX> Q) const;
  // H^t (3 x n), H^r (3 x n) of the marker's node and its offset point
  void MarkerGeometry(const Marker& m, const double* w, Vec3& s, Vec3& theta) const;
  // body-axes twist of the marker at point s (after MarkerGeometry, which
  // sets Hm_): v_rel = om x s + Hm wd (velocity relative to the frame
  // origin's), w_B = om + H^r wd
  void MarkerBodyTwist(const double* v, const Marker& m, const Vec3& s, Vec3& v_rel, Vec3& w_B) const;
  // throws InputError naming the body if `node` is not a node index
  void CheckNode(int node) const;
  // rows first .. first + 2 of the node's 6 mode rows (marker_modes_ when
  // the node carries a marker)
  Eigen::Block<const MatX, 3, Eigen::Dynamic> ModeRows(int node, int first) const;
  Eigen::Block<const MatX, 3, Eigen::Dynamic> Ht(int node) const;
  Eigen::Block<const MatX, 3, Eigen::Dynamic> Hr(int node) const;

  FlexibleBodyData data_;
  int n_ = 0;
  // the 6 mode rows (H^t, H^r) of each marker node, node after node, and
  // each node's place in it (-1: read the full mode matrix); UseMarkerNodes
  MatX marker_modes_;
  std::vector<int> marker_slot_;
  MatX damping_;
  // diagonals of K and D when they are exactly diagonal (empty otherwise):
  // K w and D wd then cost O(n)
  VecX stiffness_diag_, damping_diag_;
  FlexibleInertia inertia_;
  FlexibleMassTangent mass_tangent_;
  Vec3 first_moment_ = Vec3::Zero();  // S0 = m c0 in body axes [kg m]
  mutable Eigen::Matrix3Xd Hm_;       // scratch: marker modal translation H^t - skew(d) H^r
  mutable MatX mass_rows_;            // scratch: 3 x nv
  mutable MatX mass_cols_;            // scratch: nv x 3
  mutable MatX mass_body_;            // scratch: nv x nv
  mutable FlexibleInertia::MatN3 theta_cols_;  // scratch: nv x 3
  mutable VecX nu_;                   // scratch: nv
  std::unique_ptr<GeometricStiffeningForce> stiffening_;  // null: no geometric stiffening
  std::unique_ptr<DeformationStiffeningForce> deformation_stiffening_;  // null: none
};

}  // namespace flexmb
