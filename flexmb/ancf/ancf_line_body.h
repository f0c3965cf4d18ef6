#pragma once
/// \file ancf_line_body.h
/// The part shared by the ANCF line bodies (AncfBeam2dBody, AncfCable3dBody,
/// AncfBeam3dBody): a chain of N elements of equal length sharing nodes, with
/// kNodeDof coordinates per node, q = v (Retract is q + dx), a constant mass
/// matrix assembled from the element blocks, and the element loops of the
/// forces, energies, block pattern and centre-line positions. A CRTP base
/// (not a virtual middle class, see docs/design.md "ANCF line bodies"): the
/// loops call the derived body's element access inline.
///
/// The derived body provides (private, with `friend Base`):
///   - `const Element& ElementAt(int i) const`: element i (0..N-1);
///   - `static constexpr const char* kLineKind`: "beam" or "cable" (messages);
///   - `data_`: its specification (an AncfLineData);
///   - `const Mat3& FrameAxes() const`: axes of the body frame in world;
/// and may hide the defaults below (they fit coordinates in world axes):
///   - `LoadArg(f_W)`: a world force per length as the element's load argument;
///   - `PointToWorld(r)`: an element position r as a world point [m];
///   - `GravityPotentialOffset(rhoA, g_W)`: potential [J] not carried by q.

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/ancf/line_element.h"
#include "flexmb/bodies/body.h"
#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb::ancf {

/// The part of an ANCF line body's specification that all of them share.
struct AncfLineData {
  double length = 0.0;                    ///< undeformed length (arc length) [m], > 0
  int elements = 0;                       ///< number of elements N, > 0
  QuadratureOrder order;                  ///< quadrature of the elastic forces
  Vec3 start_W = Vec3::Zero();            ///< position of node 0 in the reference state [m]
  Vec3 direction_W = Vec3::UnitX();       ///< direction (tangent) at node 0 (normalized on use)
  Vec3 load_per_length_W = Vec3::Zero();  ///< constant distributed load [N/m]
};

/// CRTP base of the ANCF line bodies; Element is the element class (the same
/// interface as LineElement: Vec, Mat, kDof, length, section, MassMatrix,
/// DistributedLoad, AddInternalForces, StrainEnergy, Position).
template <class Derived, class Element, int kNodeDof>
class AncfLineBody : public Body {
 public:
  /// Coordinates of one element (two nodes).
  static constexpr int kElementDof = 2 * kNodeDof;
  static_assert(Element::kDof == kElementDof, "an element spans two nodes");
  /// Element coordinate vector and matrix.
  using ElVec = typename Element::Vec;
  using ElMat = typename Element::Mat;

  int nq() const override { return kNodeDof * (n_el_ + 1); }
  int nv() const override { return kNodeDof * (n_el_ + 1); }
  /// q_out = q + dx (the coordinates form a vector space).
  void Retract(const double* q, const double* dx, double* q_out) const override {
    for (int j = 0; j < nq(); ++j) q_out[j] = q[j] + dx[j];
  }
  /// The constant mass matrix assembled at construction.
  void MassMatrix(const double*, MatX& M) const override { M = mass_; }
  bool HasConstantMass() const override { return true; }
  /// Elastic and damping forces of the elements, gravity (rho A g) and the
  /// constant load per length, with their element-block tangents.
  void AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                 Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const override {
    ForEachElementLoad(q, v, g_W, [&](int i, const auto& e, const auto& edot, ElVec& Qe) {
      ElMat K = ElMat::Zero(), C = ElMat::Zero();
      self().ElementAt(i).AddInternalForces(e, edot, Qe, K, C);
      Q.template segment<kElementDof>(kNodeDof * i) += Qe;
      dQdq.template block<kElementDof, kElementDof>(kNodeDof * i, kNodeDof * i) += K;
      dQdv.template block<kElementDof, kElementDof>(kNodeDof * i, kNodeDof * i) += C;
    });
  }
  /// The forces of AddForces without their tangents, for Newton iterations
  /// that keep an earlier iteration matrix; false (the caller uses
  /// AddForces) for an element without AddInternalForceVector.
  bool AddForceVector(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q) const override {
    if constexpr (requires(const Element& el, const ElVec& e, ElVec& Qe) { el.AddInternalForceVector(e, e, Qe); }) {
      ForEachElementLoad(q, v, g_W, [&](int i, const auto& e, const auto& edot, ElVec& Qe) {
        self().ElementAt(i).AddInternalForceVector(e, edot, Qe);
        Q.template segment<kElementDof>(kNodeDof * i) += Qe;
      });
      return true;
    } else {
      return false;
    }
  }
  /// Element-wise coupling: the element blocks, overlapping at the shared
  /// nodes (banded, half bandwidth kElementDof - 1).
  bool BlockPattern(std::vector<std::pair<int, int>>& entries) const override {
    for (int e = 0; e < n_el_; ++e)
      for (int j = 0; j < kElementDof; ++j)
        for (int i = 0; i < kElementDof; ++i) entries.emplace_back(kNodeDof * e + i, kNodeDof * e + j);
    return true;
  }
  /// The kNodeDof velocities of the marker's node.
  std::pair<int, int> MarkerColumns(const Marker& m) const override { return {kNodeDof * NodeOf(m), kNodeDof}; }
  double KineticEnergy(const double*, const double* v) const override {
    double T = 0.0;
    for (int i = 0; i < n_el_; ++i) {
      const Eigen::Map<const ElVec> ve(v + kNodeDof * i);
      T += 0.5 * ve.dot(self().ElementAt(i).MassMatrix() * ve);
    }
    return T;
  }
  double GravityPotential(const double* q, const Vec3& g_W) const override {
    // per element: the offset is linear in rho A and the length (1/N of the line's)
    double V = 0.0;
    for (int i = 0; i < n_el_; ++i) {
      const auto& sec = self().ElementAt(i).section();
      const double rhoA = sec.rho * sec.A;
      const ElVec Qg = self().ElementAt(i).DistributedLoad(rhoA * self().LoadArg(g_W));
      V += self().GravityPotentialOffset(rhoA, g_W) / n_el_ - Eigen::Map<const ElVec>(q + kNodeDof * i).dot(Qg);
    }
    return V;
  }
  /// Strain energy of the whole line [J].
  double ElasticEnergy(const double* q) const override {
    double W = 0.0;
    for (int i = 0; i < n_el_; ++i) W += self().ElementAt(i).StrainEnergy(Eigen::Map<const ElVec>(q + kNodeDof * i));
    return W;
  }
  /// The body frame: origin start_W, axes FrameAxes() (fixed in world).
  void BodyFramePose(const double*, Vec3& p_WB, Mat3& R_WB) const override {
    p_WB = self().data_.start_W;
    R_WB = self().FrameAxes();
  }

  /// Centre line for animations: kLinePointsPerElement points per element
  /// and the last node.
  int CentreLinePoints() const override { return kLinePointsPerElement * n_el_ + 1; }
  /// Point k at reference arc length s = k h / kLinePointsPerElement.
  Vec3 CentreLinePoint(const double* q, int k) const override {
    return PositionAt(q, k * self().ElementAt(0).length() / kLinePointsPerElement);
  }

  /// Number of elements N.
  int elements() const { return n_el_; }
  /// Number of nodes N + 1.
  int nodes() const { return n_el_ + 1; }
  /// World position [m] of the centre line at reference arc length s in [0, L].
  Vec3 PositionAt(const double* q, double s) const {
    int i = 0;
    double xi = 0.0;
    LocateOnAncfLine(s, self().ElementAt(0).length(), n_el_, i, xi);
    return self().PointToWorld(self().ElementAt(i).Position(Eigen::Map<const ElVec>(q + kNodeDof * i), xi));
  }

 protected:
  /// Body `name` of n_el elements over the undeformed length [m]; throws
  /// InputError (naming the body) unless both are positive. The derived
  /// constructor calls AssembleMass once its elements exist.
  AncfLineBody(std::string name, double length, int n_el) : Body(std::move(name)), n_el_(n_el) {
    const std::string kind = std::string("ANCF ") + Derived::kLineKind;
    if (!(length > 0.0) || !std::isfinite(length))
      throw InputError(kind + " length must be positive, got " + std::to_string(length), BodyContext());
    if (n_el <= 0)
      throw InputError(kind + " element count must be positive, got " + std::to_string(n_el), BodyContext());
  }

  /// Error context naming this body.
  ErrorContext BodyContext() const { return {"", 0, "body '" + name() + "'"}; }
  /// Returns make(), rethrowing an InputError of it with this body named in
  /// the context (for the element constructors).
  template <class F>
  decltype(auto) NamingBody(F&& make) const {
    try {
      return make();
    } catch (const InputError& e) {
      throw InputError(e.message(), BodyContext());
    }
  }

  /// Assembles the constant mass matrix from the element blocks.
  void AssembleMass() {
    mass_.setZero(nv(), nv());
    for (int i = 0; i < n_el_; ++i)
      mass_.template block<kElementDof, kElementDof>(kNodeDof * i, kNodeDof * i) += self().ElementAt(i).MassMatrix();
  }
  /// The marker's node index; throws InputError (naming the marker) if it is
  /// not one of 0..N.
  int NodeOf(const Marker& m) const {
    if (m.node < 0 || m.node > n_el_)
      throw InputError("marker on node " + std::to_string(m.node) + ", but the " + Derived::kLineKind +
                           " has nodes 0.." + std::to_string(n_el_),
                       {"", 0, "marker '" + m.name + "'"});
    return m.node;
  }
  /// Linear momentum [kg m/s] and angular momentum about the world origin
  /// [kg m^2/s] of the centre line, for position vectors in world axes at the
  /// element coordinate slots `slot` (see AddAncfElementMomentum).
  Vec6 CentreLineMomentum(const double* q, const double* v, const int (&slot)[4]) const {
    Vec3 p = Vec3::Zero(), L = Vec3::Zero();
    for (int i = 0; i < n_el_; ++i)
      AddAncfElementMomentum(self().ElementAt(i).MassMatrix(), q + kNodeDof * i, v + kNodeDof * i, slot, p, L);
    Vec6 out;
    out << p, L;
    return out;
  }

  /// Fills out for a marker at node k of a body whose node coordinates start
  /// with (r, r') in world axes: node frame R_WN, its angular velocity w
  /// [rad/s] and dw/dr'dot = G; J gets the columns of r and r' (others zero).
  /// Returns the marker offset s = R_WN p_BM [m, world].
  Vec3 FillNodeMarker(const double* q, const double* v, int k, const Mat3& R_WN, const Mat3& G, const Vec3& w,
                      const Marker& m, MarkerState& out) const {
    const Eigen::Map<const Vec3> r(q + kNodeDof * k), rd(v + kNodeDof * k);
    const Vec3 s = R_WN * m.p_BM;
    out.p_WM = r + s;
    out.R_WM = R_WN * m.R_BM;
    out.v_WM = rd + w.cross(s);
    out.w_WM = w;
    out.J.setZero(6, nv());
    out.J.template block<3, 3>(0, kNodeDof * k).setIdentity();
    out.J.template block<3, 3>(0, kNodeDof * k + 3) = -Skew(s) * G;
    out.J.template block<3, 3>(3, kNodeDof * k + 3) = G;
    out.v_offset = v_offset;
    out.nv = nv();
    return s;
  }
  /// Acceleration bias (a_M, alpha_M) of a marker at offset s [m, world] from
  /// its node, for a node frame with angular velocity w [rad/s] and angular
  /// acceleration bias alpha [rad/s^2]: (alpha x s + w x (w x s), alpha).
  static Vec6 OffsetMarkerBias(const Vec3& alpha, const Vec3& w, const Vec3& s) {
    Vec6 b;
    b.head<3>() = alpha.cross(s) + w.cross(w.cross(s));
    b.tail<3>() = alpha;
    return b;
  }

  /// Calls f(i, e, edot, Qe) for every element i with its coordinates,
  /// velocities and the load vector of its weight (rho A g_W) and the load
  /// per length in Qe; the load vector is evaluated again only where rho A
  /// changes along the line (the elements have equal lengths).
  template <class F>
  void ForEachElementLoad(const double* q, const double* v, const Vec3& g_W, F&& f) const {
    double rhoA_of_Qf = -1.0;
    ElVec Qf;
    for (int i = 0; i < n_el_; ++i) {
      const auto& sec = self().ElementAt(i).section();
      if (sec.rho * sec.A != rhoA_of_Qf) {
        rhoA_of_Qf = sec.rho * sec.A;
        Qf = self().ElementAt(i).DistributedLoad(self().LoadArg(rhoA_of_Qf * g_W + self().data_.load_per_length_W));
      }
      const Eigen::Map<const ElVec> e(q + kNodeDof * i), edot(v + kNodeDof * i);
      ElVec Qe = Qf;
      f(i, e, edot, Qe);
    }
  }

  /// Default: the element takes world force vectors.
  static const Vec3& LoadArg(const Vec3& f_W) { return f_W; }
  /// Default: element positions are world points.
  static Vec3 PointToWorld(const Vec3& r) { return r; }
  /// Default: the coordinates carry the whole potential.
  static double GravityPotentialOffset(double, const Vec3&) { return 0.0; }

  /// Number of elements N.
  int n_el_;
  /// Constant mass matrix (nv x nv).
  MatX mass_;

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace flexmb::ancf
