#pragma once
/// \file bushing.h
/// Six-component linear bushing between two markers.

#include "flexmb/forces/force_element.h"

namespace flexmb {

/// Diagonal stiffness, damping and preload of a Bushing, all in the axes of
/// marker i.
struct BushingData {
  Vec3 translational_stiffness = Vec3::Zero();  ///< [N/m], each >= 0
  Vec3 rotational_stiffness = Vec3::Zero();     ///< [N m/rad], each >= 0
  Vec3 translational_damping = Vec3::Zero();    ///< [N s/m], each >= 0
  Vec3 rotational_damping = Vec3::Zero();       ///< [N m s/rad], each >= 0
  Vec3 preload_force = Vec3::Zero();            ///< force on j at zero deflection [N]
  Vec3 preload_torque = Vec3::Zero();           ///< moment on j at zero deflection [N m]
};

/// Linear bushing. In the axes of marker i, with d = p_j - p_i:
///   displacement  d_i = R_i^T d, its rate d_i' = R_i^T (v_j - v_i - w_i x d),
///   rotation      phi = Log(R_i^T R_j) (rotation vector [rad], |phi| <= pi),
///   angular rate  w_rel = R_i^T (w_j - w_i);
/// force on j  f_j = R_i (F0 - Kt d_i - Ct d_i'),
/// moment on j m_j = R_i (T0 - Kr phi - Cr w_rel) (about p_j),
/// reactions on i: f_i = -f_j, m_i = -m_j - d x f_j (about p_i), so the
/// element satisfies Newton's third law exactly. For small rotations phi
/// equals the three small angles about the axes of i.
class Bushing final : public ForceElement {
 public:
  /// Throws InputError naming the element for a negative or non-finite
  /// stiffness or damping entry or a non-finite preload.
  Bushing(std::string name, const BushingData& data);
  const char* type() const override { return "bushing"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// 0.5 d_i.Kt d_i + 0.5 phi.Kr phi - F0.d_i - T0.phi [J]. The translational
  /// part is an exact potential of the forces; the rotational part is exact
  /// when Kr is isotropic and T0 = 0 (otherwise the moment law, like Adams',
  /// is not derived from a potential and this is an approximation).
  double PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double t) const override;
  /// The bushing's coefficients.
  const BushingData& data() const { return data_; }

 private:
  BushingData data_;
};

}  // namespace flexmb
