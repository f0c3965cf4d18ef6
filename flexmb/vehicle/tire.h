#pragma once
/// \file tire.h
/// Tire force element on a flat road (or on a RoadSurface, road_surface.h): a Magic Formula-type (Pacejka 2002
/// simplified) longitudinal and lateral force with combined slip and load
/// sensitivity, a vertical spring-damper with lift-off, an effective rolling
/// radius, a pneumatic-trail aligning moment and rolling resistance.

#include <memory>
#include <string>

#include "flexmb/forces/force_element.h"

namespace flexmb::vehicle {

class RoadSurface;

/// Coefficients of one tire (or of each tire of an identical twin set),
/// following the naming of Pacejka, "Tire and Vehicle Dynamics", 3rd ed.,
/// ch. 4.3.2 (MF 2002), with lambda scale factors 1 and without camber,
/// turn slip and the shift terms.
struct TireData {
  int count = 1;                 ///< tires in the set (2: twin tires sharing the load equally)
  double unloaded_radius = 0.5;  ///< R0 [m], > 0
  double vertical_stiffness = 8e5;  ///< per tire [N/m], > 0
  double vertical_damping = 1e3;    ///< per tire [N s/m], >= 0
  double rolling_radius_factor = 1.0 / 3.0;  ///< Re = R0 - f * deflection, in [0, 1]
  double nominal_load = 25e3;    ///< Fz0 per tire [N], > 0
  double pcx1 = 1.65;            ///< longitudinal shape factor C_x
  double pdx1 = 0.8;             ///< longitudinal peak friction at Fz0 (times the road mu)
  double pdx2 = -0.1;            ///< load dependence of the longitudinal peak friction
  double pex1 = 0.0;             ///< longitudinal curvature factor E_x, <= 1
  double pkx1 = 15.0;            ///< longitudinal slip stiffness K_x / Fz [-]
  double pcy1 = 1.3;             ///< lateral shape factor C_y
  double pdy1 = 0.8;             ///< lateral peak friction at Fz0 (times the road mu)
  double pdy2 = -0.1;            ///< load dependence of the lateral peak friction
  double pey1 = -0.5;            ///< lateral curvature factor E_y, <= 1
  double pky1 = 8.0;             ///< max cornering stiffness / Fz0 [1/rad]
  double pky2 = 2.0;             ///< load (in Fz0) at which the cornering stiffness peaks, /2
  double rbx1 = 12.0;            ///< combined slip: Fx reduction by slip angle, Gxa = cos(atan(rbx1 alpha))
  double rby1 = 10.0;            ///< combined slip: Fy reduction by slip ratio, Gyk = cos(atan(rby1 kappa))
  double trail = 0.04;           ///< pneumatic trail at zero slip angle [m]
  double trail_decay = 8.0;      ///< trail t = trail * cos(atan(trail_decay alpha)) [1/rad]
  double rolling_resistance = 0.007;  ///< rolling resistance coefficient f_r [-]
  double low_speed = 1.0;        ///< v_low in the slip denominator sqrt(Vx^2 + v_low^2) [m/s], > 0
  /// Lateral relaxation length sigma0 at the nominal load [m], >= 0; 0: no
  /// relaxation (stateless tire). With sigma0 > 0 the lateral slip force acts
  /// on a contact-patch body tied to the wheel by the lateral carcass
  /// stiffness k_y = Ky(Fz0) / sigma0 per tire, so that
  /// sigma(Fz) = Ky(Fz) / k_y (Pacejka, 3rd ed., sec. 7.2.1).
  double relaxation_length = 0.0;
  /// Mass of the contact-patch body per tire [kg], > 0 (used with
  /// relaxation_length > 0; small against Ky / V * sigma / V).
  double patch_mass = 0.5;
  /// Longitudinal relaxation length sigma_kappa0 at the nominal load [m],
  /// >= 0; 0: no longitudinal relaxation (the slip ratio is the wheel's).
  /// With sigma_kappa0 > 0 (needs relaxation_length > 0: the patch body) the
  /// patch also slides along x_t, tied to the wheel by the longitudinal
  /// carcass stiffness k_x = Kx(Fz0) / sigma_kappa0 per tire, so that
  /// sigma_kappa(Fz) = Kx(Fz) / k_x (Pacejka, 3rd ed., sec. 7.2.1, the
  /// single-contact-point model in the longitudinal direction).
  double longitudinal_relaxation_length = 0.0;
};

/// Contact quantities of one evaluation of a Tire (for sensors and tests).
struct TireContact {
  double deflection = 0.0;  ///< R0 minus the centre height along the wheel plane [m]
  double fz = 0.0;          ///< vertical force of the set [N] (0 when lifted off)
  double fx = 0.0;          ///< longitudinal slip force of the set [N] (on the contact patch when longitudinally relaxed)
  double fy = 0.0;          ///< lateral slip force of the set [N] (on the contact patch when relaxed)
  /// Lateral force of the set passed to the wheel along y_t [N]: the carcass
  /// spring's force when relaxed, fy otherwise.
  double fy_wheel = 0.0;
  /// Longitudinal force of the set passed to the wheel along x_t [N]: the
  /// longitudinal carcass spring's force when longitudinally relaxed, fx
  /// otherwise.
  double fx_wheel = 0.0;
  double kappa = 0.0;       ///< longitudinal slip ratio [-] (the patch's when longitudinally relaxed)
  double alpha = 0.0;       ///< slip angle [rad] (the patch's when relaxed)
  Vec3 contact_W = Vec3::Zero();  ///< contact point on the road [m]
};

/// Tire on the road plane z = 0 (normal +z of the world), acting on one marker
/// (marker_j = -1) at the wheel centre whose z axis is the spin axis (the
/// axis of the wheel's revolute joint; its sign is free, the road frame
/// follows it). Road frame: x_t = normalize(a x n) (forward for a wheel whose
/// a points to the vehicle's left), y_t = n x x_t. With p the centre,
/// gamma the inclination of the wheel plane, the loaded radius
/// rho = p_z / cos(gamma) and contact point c = p - rho r (r the unit
/// upward direction in the wheel plane):
///   deflection d = R0 - rho, Fz = max(0, n (k d - c p'_z / cos(gamma))) (no pull),
///   Vx = v . x_t, slip velocity Vsx = Vx - Re Omega (Omega = w . a signed
///   so that forward rolling is positive, Re = R0 - f d), Vsy = v_c . y_t
///   with v_c the velocity of the wheel material at c,
///   kappa = -Vsx / V, alpha = atan(Vsy / V), V = sqrt(Vx^2 + v_low^2).
/// Per tire (Fz1 = Fz / n, dfz = (Fz1 - Fz0)/Fz0):
///   Fx0 = Dx sin(Cx atan(Bx k - Ex (Bx k - atan(Bx k)))), Dx = mu pdx1 (1 + pdx2 dfz) Fz1,
///   Kx = pkx1 Fz1, Bx = Kx / (Cx Dx); Fy0 likewise in alpha with
///   Ky = pky1 Fz0 sin(2 atan(Fz1 / (pky2 Fz0))), and Fy0 opposes Vsy;
///   combined: Fx = Fx0 cos(atan(rbx1 alpha)), Fy = Fy0 cos(atan(rby1 kappa)).
/// The set's force n (Fx x_t + Fy y_t) + Fz n acts at c; the aligning
/// moment -t n Fy s (s = tanh(Vx / 0.5 m/s), the trail lies behind the
/// contact in the direction of travel) with t = trail cos(atan(trail_decay
/// alpha)); the rolling resistance is the moment -f_r Fz rho s a against the
/// spin (a moment, not a force at c: a force at the contact would be
/// cancelled by the slip force of a free-rolling wheel, leaving no net
/// resistance), so a free-rolling wheel is retarded by f_r Fz.
/// Wrench about the wheel centre.
/// Relaxation length (relaxation_length > 0): marker j is a contact-patch
/// marker at the wheel centre on a light body that slides along the spin
/// axis on the wheel carrier (a prismatic joint, built by the truck). The
/// element then applies the carcass spring -k_y (p_j - p) on the patch (and
/// the reaction on the wheel), and the lateral slip force Fy and the aligning
/// moment on the patch, from the patch's slip velocity
/// Vsy' = Vsy + (v_j - v) . y_t, with the moment arm c - p; Fz, Fx and the
/// rolling resistance stay on the wheel. In the linear range and with the
/// patch mass neglected, Fy lags its steady value by
/// sigma dFy/dx + Fy = Fy_ss (x the travelled distance), sigma = Ky / k_y
/// (docs/design.md "Vehicle: tire relaxation length").
/// Longitudinal relaxation (longitudinal_relaxation_length > 0 as well): the
/// patch slides in the plane of the spin axis and the carrier's forward axis
/// (a ContactPatchJoint, built by the truck); the carcass spring becomes
/// S = k_y u + (k_x - k_y) (u . x_t) x_t with u = p_j - p, and acts with
/// opposite signs on wheel and patch at one point, the patch's contact point
/// c + u (so its x_t part turns the wheel about the spin axis with the lever
/// rho, as the slip force did); the longitudinal slip force Fx acts on the
/// patch, from its slip Vsx' = Vsx + (v_j - v) . x_t, kappa = -Vsx' / V; Fz
/// and the rolling resistance stay on the wheel. Linear range, massless
/// patch: sigma_kappa dFx/dx + Fx = Fx_ss, sigma_kappa = Kx / k_x.
/// K and C are the exact derivatives of the wrench, computed with it in one
/// forward-mode evaluation (Eigen's AutoDiff; docs/design.md "Vehicle: tire
/// tangent").
/// Road surface (SetRoad): the road under the wheel is the plane through
/// (p_x, p_y, h(p_x)) with the normal n = (-h', 0, 1) / sqrt(1 + h'^2)
/// (h, h' = dh/dx of the RoadSurface at the centre's x) in place of z = 0
/// and +z: rho = (p_z - h) n_z / cos(gamma), the deflection rate in the
/// damper is the centre's velocity along n, (v_z - h' v_x) n_z (the road's
/// curvature neglected), and the slip frame x_t = normalize(a x n) follows
/// the road's slope. The vertical road input thus acts through the radial
/// stiffness and damping; the tangents see h(p_x) and h' (h'' = 0 of the
/// piecewise linear profile).
/// Without a road (the default) the flat road z = 0 is evaluated exactly as
/// before.
class Tire final : public ForceElement {
 public:
  /// Throws InputError naming the element for a coefficient out of range
  /// or a friction coefficient mu <= 0.
  Tire(std::string name, const TireData& data, double mu);
  const char* type() const override { return "tire"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// Wrench (f, m) about the centre [N, N m] and the contact quantities for
  /// a wheel centre at p with spin axis a = R.col(2), velocity v and
  /// angular velocity w (world).
  Vec6 Wrench(const Vec3& p, const Mat3& R, const Vec3& v, const Vec3& w, TireContact* contact) const;
  /// Wrenches (wheel marker: f, m about p; patch marker: f, m about p_j)
  /// [N, N m] of the relaxed tire for a wheel centre (p, R, v, w) and a
  /// contact-patch marker at p_j with velocity v_j (world); requires
  /// relaxation_length > 0.
  Vec12 RelaxedWrench(const Vec3& p, const Mat3& R, const Vec3& v, const Vec3& w, const Vec3& p_j, const Vec3& v_j,
                      TireContact* contact) const;
  /// True when the tire has a relaxation length (needs a patch marker j).
  bool relaxed() const { return data_.relaxation_length > 0; }
  /// True when the tire also relaxes longitudinally (its patch slides along x_t).
  bool longitudinally_relaxed() const { return data_.longitudinal_relaxation_length > 0; }
  /// Lateral carcass stiffness of the set, count * Ky(Fz0) / sigma0 [N/m]
  /// (0 without relaxation).
  double carcass_stiffness() const { return k_carcass_; }
  /// Longitudinal carcass stiffness of the set, count * Kx(Fz0) /
  /// sigma_kappa0 with Kx(Fz0) = pkx1 Fz0 [N/m] (0 without longitudinal
  /// relaxation).
  double longitudinal_carcass_stiffness() const { return k_long_; }
  /// Cornering stiffness per tire Ky(Fz1) = pky1 Fz0 sin(2 atan(Fz1 / (pky2 Fz0))) [N/rad].
  double CorneringStiffness(double fz1) const;
  /// The tire's coefficients.
  const TireData& data() const { return data_; }
  /// Road friction coefficient [-].
  double mu() const { return mu_; }
  /// Rolls the tire on `road` (nullptr: the flat road z = 0, the default).
  /// Set before the simulation starts; the surface is shared, not copied.
  void SetRoad(std::shared_ptr<const RoadSurface> road) { road_ = std::move(road); }
  /// The road surface (nullptr: flat road z = 0).
  const RoadSurface* road() const { return road_.get(); }

 private:
  template <class S>
  using V3 = Eigen::Matrix<S, 3, 1>;
  // wheel wrench (head) and patch wrench (tail) for the spin axis a; no
  // patch when p_j is null. S: double, or an AD scalar for the tangents
  // (tire.cc, instantiated there only)
  template <class S>
  Eigen::Matrix<S, 12, 1> Compute(const V3<S>& p, const V3<S>& a, const V3<S>& v, const V3<S>& w, const V3<S>* p_j,
                                  const V3<S>* v_j, TireContact* contact) const;
  TireData data_;
  double mu_;
  double k_carcass_ = 0.0;
  double k_long_ = 0.0;
  std::shared_ptr<const RoadSurface> road_;
};

}  // namespace flexmb::vehicle
