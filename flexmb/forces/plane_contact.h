#pragma once
/// \file plane_contact.h
/// Unilateral contact of a point (a marker's origin) with a plane fixed in
/// the world: a load standing on the ground, an outrigger pad, a wheel-less
/// support. Penalty normal force with damping, regularized Coulomb friction.

#include "flexmb/forces/force_element.h"

namespace flexmb {

/// Parameters of a PlaneContact (SI units).
struct PlaneContactLaw {
  Vec3 point_W = Vec3::Zero();           ///< a point of the plane, world [m]
  Vec3 normal_W = Vec3::UnitZ();         ///< plane normal, world, towards the free side (normalized by the element)
  double stiffness = 0.0;                ///< normal contact stiffness k [N/m], > 0
  double damping = 0.0;                  ///< normal contact damping c [N s/m], >= 0
  double friction = 0.0;                 ///< Coulomb friction coefficient mu, >= 0
  double slip_velocity = 1e-3;           ///< regularization velocity of the friction v_s [m/s], > 0
};

/// Contact of the origin of marker i with the plane {x : n.(x - p0) = 0}
/// (marker_j = -1). With the penetration g = -n.(p_i - p0) and its rate
/// gdot = -n.v_i, the normal force is F_n = max(0, k g + c gdot) while
/// g > 0, else 0: the contact pushes and never pulls (the damper lets go
/// as the point leaves the plane). Friction acts against the sliding
/// velocity v_t = v_i - (n.v_i) n with F_t = -mu F_n v_t / sqrt(|v_t|^2 + v_s^2)
/// (Coulomb, regularized below v_s: a standing load creeps at v_s times the
/// ratio of the tangential load to mu F_n). The force F_n n + F_t acts at the
/// marker origin (no moment about it).
class PlaneContact final : public ForceElement {
 public:
  /// Throws InputError naming the element for a non-positive stiffness or
  /// slip velocity, negative damping or friction, a zero normal, or
  /// non-finite values.
  PlaneContact(std::string name, PlaneContactLaw law);
  const char* type() const override { return "plane_contact"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// Elastic energy 1/2 k g^2 while the point penetrates, else 0 [J].
  double PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double t) const override;
  /// Penetration g [m] of the marker origin p_W (positive: in contact).
  double Penetration(const Vec3& p_W) const { return -law_.normal_W.dot(p_W - law_.point_W); }
  /// The law, with the normal normalized.
  const PlaneContactLaw& law() const { return law_; }

 private:
  PlaneContactLaw law_;
};

}  // namespace flexmb
