#pragma once
/// \file ancf_hoist_rope_body.h
/// Hoisting rope of changing free length: the hanging span of a crane rope
/// as 3D ANCF cable elements whose common reference length follows a winch,
/// with the rope stored on the drum and the drum's spin inertia in the same
/// body, so that rope mass moves between drum and span inside one closed
/// Lagrangian system (docs/design.md "Hoisting rope of changing length").
///
/// Mesh and material. The span hangs from node 0 (where the rope leaves the
/// boom-head sheave, a mesh point that stays there) to node N (the rope's end
/// on the hook, a material point). With the free (unstretched) length L(t)
/// as a coordinate, every element has the reference length h = L / N and the
/// mesh coordinate eta in [0, N] (element e: eta = e + xi, xi in [0, 1]).
/// The material arc length from the hook end is sigma = (N - eta) h, so a
/// material point moves through the mesh with eta' = (N - eta) L' / L, and
/// its velocity is
///   v = S(xi) qdot_e + S_xi(xi) q_e (N - eta) L' / L.
/// Node coordinates are r_k and the mesh slope d_k = dr/deta = h dr/dsigma
/// (so the shape functions are the cubic Hermite ones on the unit interval,
/// independent of L): q = (r_0, d_0, ..., r_N, d_N, L), 6 (N + 1) + 1
/// entries, q = v (Retract is q + dx).
///
/// Kinetic energy. T = 1/2 L qdot^T Mb qdot + L' qdot^T Cb q
///   + 1/2 L'^2 (q^T Db q / L + m_s(L)), with the constant matrices
///   Mb = rho A / N sum_e int S^T S, Cb = rho A / N sum_e int w S^T S_xi,
///   Db = rho A / N sum_e int w^2 S_xi^T S_xi  (w = N - eta),
/// and m_s(L) = rho A (L_total - L) + J / R^2 the mass of the stored rope
/// (on the drum and in the lead span, moving with the rope speed L') plus
/// the drum's spin inertia J about its axis reduced to the rope line at the
/// winding radius R. The mass matrix and the velocity terms are Lagrange's
/// equations of this T (exact tangents; the mass depends on q).
///
/// Strain energy. Per element, with a = S_xi q_e, b = S_xixi q_e:
///   axial  lambda = |a| N / L, eps = lambda - 1 or (lambda^2 - 1) / 2,
///          W = 1/2 EA int eps^2 dsigma (5 Gauss points, full integration:
///          a rope's bending is too soft for membrane locking to matter).
///          The span carries compression like the other ANCF bodies: with
///          a tension-only law the line can fold onto itself at no cost and
///          the runs went wrong (docs/design.md); a rope that goes slack
///          and snaps taut is the massless `rope` force element's case;
///   bending kappa = (a x b) / (|a|^2 h), W = 1/2 EI int |kappa|^2 dsigma.
/// Damping: Kelvin-Voigt with time beta on the rates of the same strains at
/// fixed mesh points (a Rayleigh dissipation function, so energy only
/// leaves; the convective part eps_eta eta' of the material rate is left
/// out, zero for a uniform strain).
///
/// Gravity acts on the span and on the stored rope, the latter at the drum
/// centre (its potential -rho A (L_total - L) g . p_drum; the lead span's
/// shape is taken as fixed, so its own potential is a constant).
///
/// Markers: `node` 0..N are points on the centre line (position only, no
/// offset; the orientation is the reference frame, fixed: the twist
/// Jacobian has rank 3, MarkerJacobianFullRank() is false), for spherical
/// joints to the sheave and the hook. Node N + 1 (PayoutNode()) is the
/// payout marker: a point at (L, 0, 0) in world, i.e. the free length as a
/// displacement along world x, on which a winch driver (WinchDriver)
/// prescribes L(t) or a point force along x applies the drum torque / R.
///
/// Without the drum in the body (HoistRopeData::drum_in_body false) the
/// stored rope and drum terms above are left out (m_s = 0, no stored weight;
/// the rope enters at node 0's height instead: Q_L gets -rho A g . r_0, so
/// that at rest the feeding pull is the axial force at the top of the span.
/// This term is not conservative: the lead span is massless, so the rope's
/// mass appears at the sheave. GravityPotential gives the span's weight
/// relative to node 0, the potential of the applied forces while node 0
/// stays where it is; when the sheave moves, the energy balance misses the
/// work of the span's weight carried with it):
/// a `rope` force element with a `span` (forces/reeved_rope.h) is then the
/// lead span from the drum to the sheave, whose tension pulls the payout
/// marker; the L coordinate's inertia is the span's own transport term.
///
/// Not modelled (with the drum in the body): the lead span's own stretch and
/// its pull on the boom head (see the previous paragraph), the rope's
/// wrap on the sheave, torsion, and the drum's rotation with its carrier
/// (the slewing platform's turn adds nothing to the drum spin).

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "flexmb/ancf/line_element.h"
#include "flexmb/bodies/body.h"

namespace flexmb::ancf {

/// Specification of an AncfHoistRopeBody.
struct HoistRopeData {
  double free_length = 0.0;    ///< L(0), free (unstretched) length of the span [m], > 0
  double stored_length = 0.0;  ///< rope on the drum and in the lead span at t = 0 [m], >= 0
  int elements = 0;            ///< N, > 0
  BeamSection section;         ///< section, material, damping and axial strain measure
  Vec3 start_W = Vec3::Zero();          ///< node 0 (leaves the sheave) [m]
  Vec3 direction_W = -Vec3::UnitZ();    ///< initial straight direction of the span
  Vec3 drum_W = Vec3::Zero();           ///< drum centre: where the stored rope's weight acts [m]
  double drum_radius = 0.0;             ///< winding radius R [m], > 0
  double drum_inertia = 0.0;            ///< drum spin inertia J about its axis [kg m^2], >= 0
  double payout_speed = 0.0;            ///< L'(0) [m/s] (positive pays out)
  /// true: the span is fed straight from the drum, whose spin inertia and
  /// stored rope (mass, weight at drum_W) belong to the body. false: the span
  /// is fed over the boom-head sheave by a `rope` force element (the lead
  /// span, with the drum) that couples to the payout marker
  /// (forces/reeved_rope.h), or paid out by a winch driver; the body then
  /// has neither drum nor stored rope mass, and stored_length only bounds
  /// how much can be paid out.
  bool drum_in_body = true;
  /// Length the span covers at t = 0 from start_W along direction_W [m]
  /// (the nodes are spaced evenly on it): 0 for free_length (unstretched);
  /// longer starts the span stretched (a hanging load's static strain).
  double initial_length = 0.0;
};

/// Hoisting rope of changing free length; see the file comment.
class AncfHoistRopeBody final : public Body {
 public:
  /// Throws InputError naming the body for a non-positive free length,
  /// element count, section value or drum radius, a negative stored length,
  /// drum inertia or damping, or a zero direction.
  AncfHoistRopeBody(std::string name, const HoistRopeData& data);

  int nq() const override { return nL_ + 1; }
  int nv() const override { return nL_ + 1; }
  void InitialCoordinates(double* q, double* v) const override;
  void Retract(const double* q, const double* dx, double* q_out) const override;
  void MassMatrix(const double* q, MatX& M) const override;
  bool HasConstantMass() const override { return false; }
  bool MarkerJacobianFullRank() const override { return false; }
  void AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                 Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const override;
  /// The forces of AddForces without their tangents (kept iteration matrix).
  bool AddForceVector(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q) const override;
  void AddMassTangent(const double* q, const double* a, double scale, Eigen::Ref<MatX> K) const override;
  /// The element blocks and the full row and column of L.
  bool BlockPattern(std::vector<std::pair<int, int>>& entries) const override;
  std::pair<int, int> MarkerColumns(const Marker& m) const override;
  void EvaluateMarker(const double* q, const double* v, const Marker& m, MarkerState& out) const override;
  /// Zero: the marker Jacobians are constant.
  Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const override;
  /// Nothing to add: the marker Jacobians are constant.
  void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                              Eigen::Ref<MatX> dQdq) const override;
  void MarkerTwistTangent(const double* q, const double* v, const Marker& m, Eigen::Ref<MatX> out) const override;
  /// 1/2 v^T M(q) v: span, stored rope and drum [J].
  double KineticEnergy(const double* q, const double* v) const override;
  /// Span and stored rope (at the drum centre) [J].
  double GravityPotential(const double* q, const Vec3& g_W) const override;
  double ElasticEnergy(const double* q) const override;
  /// Linear and angular momentum of the hanging span (the stored rope and
  /// the drum turn about the drum axis, which the body does not know).
  Vec6 Momentum(const double* q, const double* v) const override;
  /// Centre line: kLinePointsPerElement points per element and node N.
  int CentreLinePoints() const override { return kLinePointsPerElement * n_el_ + 1; }
  /// Point k at mesh coordinate eta = k / kLinePointsPerElement.
  Vec3 CentreLinePoint(const double* q, int k) const override;
  /// Frame at node 0's reference position with the reference axes.
  void BodyFramePose(const double* q, Vec3& p_WB, Mat3& R_WB) const override;

  /// Number of elements N.
  int elements() const { return n_el_; }
  /// Node index of the payout marker, N + 1.
  int PayoutNode() const { return n_el_ + 1; }
  /// Index of L in q and v.
  int LengthIndex() const { return nL_; }
  /// Free length L [m] at q.
  double FreeLength(const double* q) const { return q[nL_]; }
  /// Mass of the hanging span rho A L and of the stored rope
  /// rho A (L_total - L) [kg] at q: they always add up to rho A L_total.
  /// Without the drum in the body the stored rope is not the body's: 0.
  std::pair<double, double> RopeMasses(const double* q) const;
  /// World position [m] of the material point at arc length sigma [m] from
  /// the hook end (clamped to the span).
  Vec3 MaterialPoint(const double* q, double sigma) const;
  /// Axial force [N] at the centre of element e (0..N-1): EA eps deps/dlambda.
  double AxialForce(const double* q, int e) const;
  /// The specification.
  const HoistRopeData& data() const { return data_; }

 private:
  using Vec12 = Eigen::Matrix<double, 12, 1>;
  using Mat12 = Eigen::Matrix<double, 12, 12>;
  using Vec13 = Eigen::Matrix<double, 13, 1>;
  using Mat13 = Eigen::Matrix<double, 13, 13>;
  using Shape = Eigen::Matrix<double, 3, 12>;

  // cubic Hermite shape matrices on the unit element (mesh slopes: the line
  // element of length 1) and their derivatives in xi
  Shape S0(double xi) const { return unit_.Shape(xi); }
  Shape S1(double xi) const { return unit_.ShapeSlope(xi); }
  Shape S2(double xi) const { return unit_.ShapeCurvature(xi); }
  // y = A x for a block-banded matrix given by element blocks B_e
  template <class BlockOf>
  void ApplyBanded(BlockOf&& block, const double* x, VecX& y) const;
  // forces, and with dQdq, dQdv their tangents
  void Forces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q, Eigen::Ref<MatX>* dQdq,
              Eigen::Ref<MatX>* dQdv) const;
  // axial and bending strain terms of element e at the extended
  // coordinates (q_e, L): energy, with Q != nullptr also the forces, and
  // with K, C != nullptr their tangents
  double ElementStrain(int e, const Vec13& y, const Vec13& ydot, Vec13* Q, Mat13* K, Mat13* C) const;
  // check a marker's node; throws InputError naming it
  int NodeOf(const Marker& m) const;

  HoistRopeData data_;
  int n_el_;
  int nL_;          // 6 (N + 1): index of L
  double rhoA_;
  double L_total_;  // free + stored length at t = 0 [m]
  double m_drum_;   // J / R^2 [kg] (0 without the drum in the body)
  double rhoS_;     // mass per length of the stored rope counted in the body (rho A, or 0)
  Mat3 R_W0_;       // reference frame: x along the initial direction
  // element integrals (unit element, rho A included): M0 = int S^T S,
  // Ca = int S^T S', Cb = int xi S^T S', Da = int S'^T S', Db = int xi S'^T S',
  // Dc = int xi^2 S'^T S'
  Mat12 M0_, Ca_, Cb_, Da_, Db_, Dc_;
  // the same as 4 x 4 factors X of X (x) I3 (the shape matrices are [s_i I3])
  Eigen::Matrix4d m0_, ca_, cb_, da_, db_, dc_;
  // the line element of length 1, for its shape functions only (its section
  // is a placeholder)
  LineElement<3> unit_{1.0, [] {
    BeamSection unit;
    unit.E = unit.A = unit.I = unit.rho = 1.0;
    return unit;
  }()};
  // scratch of AddForces / MassMatrix (sized once; one thread per body)
  mutable VecX t1_, t2_, t3_, t4_, t5_, t6_;
};

}  // namespace flexmb::ancf
