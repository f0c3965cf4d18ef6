#include "flexmb/vehicle/tire.h"

#include <cmath>

#include <unsupported/Eigen/AutoDiff>

#include "flexmb/common/error.h"
#include "flexmb/vehicle/road_surface.h"

namespace flexmb::vehicle {
namespace {

// forward-mode derivative of the tire's wrench: value and derivatives by
// the 18 variations (dp, dtheta, dp_j, v, w, v_j), Eigen's AutoDiff
using Ad = Eigen::AutoDiffScalar<Eigen::Matrix<double, 18, 1>>;
constexpr int kVarPose = 0, kVarTwist = 9;  // first pose (dp, dtheta, dp_j) and twist (v, w, v_j) variation

double Val(double x) { return x; }
double Val(const Ad& x) { return x.value(); }
Vec3 Vals(const Vec3& x) { return x; }
Vec3 Vals(const Eigen::Matrix<Ad, 3, 1>& x) { return Vec3(x.x().value(), x.y().value(), x.z().value()); }
// Eigen 3.4's AutoDiff has no atan
double Atan(double x) { return std::atan(x); }
Ad Atan(const Ad& x) { return Ad(std::atan(x.value()), x.derivatives() / (1.0 + x.value() * x.value())); }

// magic formula y = D sin(C atan(B x - E (B x - atan(B x))))
template <class S>
S MagicFormula(const S& x, const S& B, double C, const S& D, double E) {
  using std::sin;
  const S bx = B * x;
  return D * sin(C * Atan(S(bx - E * (bx - Atan(bx)))));
}

// a vector of AD scalars with value x and derivative e_k along variable
// first + k (k = 0, 1, 2)
Eigen::Matrix<Ad, 3, 1> Variable(const Vec3& x, int first) {
  Eigen::Matrix<Ad, 3, 1> out;
  for (int k = 0; k < 3; ++k) out(k) = Ad(x(k), 18, first + k);
  return out;
}

}  // namespace

Tire::Tire(std::string name, const TireData& d, double mu) : ForceElement(std::move(name)), data_(d), mu_(mu) {
  const ErrorContext ctx{"", 0, "tire '" + this->name() + "'"};
  auto positive = [&](double v, const char* what) {
    if (!(v > 0) || !std::isfinite(v)) throw InputError(std::string(what) + " must be a positive number", ctx);
  };
  auto finite = [&](double v, const char* what) {
    if (!std::isfinite(v)) throw InputError(std::string(what) + " must be finite", ctx);
  };
  if (d.count < 1) throw InputError("count must be at least 1", ctx);
  positive(d.unloaded_radius, "unloaded_radius");
  positive(d.vertical_stiffness, "vertical_stiffness");
  positive(d.nominal_load, "nominal_load");
  positive(d.pcx1, "pcx1");
  positive(d.pdx1, "pdx1");
  positive(d.pkx1, "pkx1");
  positive(d.pcy1, "pcy1");
  positive(d.pdy1, "pdy1");
  positive(d.pky1, "pky1");
  positive(d.pky2, "pky2");
  positive(d.low_speed, "low_speed");
  positive(mu, "road friction coefficient mu");
  for (double v : {d.pdx2, d.pdy2, d.rbx1, d.rby1, d.trail, d.trail_decay, d.rolling_resistance})
    finite(v, "a tire coefficient");
  if (!(d.vertical_damping >= 0)) throw InputError("vertical_damping must be >= 0", ctx);
  if (!(d.rolling_radius_factor >= 0 && d.rolling_radius_factor <= 1))
    throw InputError("rolling_radius_factor must lie in [0, 1]", ctx);
  if (!(d.pex1 <= 1) || !(d.pey1 <= 1)) throw InputError("pex1 and pey1 must be <= 1", ctx);
  if (!(d.relaxation_length >= 0) || !std::isfinite(d.relaxation_length))
    throw InputError("relaxation_length must be >= 0", ctx);
  if (d.relaxation_length > 0) {
    positive(d.patch_mass, "patch_mass");
    k_carcass_ = d.count * CorneringStiffness(d.nominal_load) / d.relaxation_length;
  }
  if (!(d.longitudinal_relaxation_length >= 0) || !std::isfinite(d.longitudinal_relaxation_length))
    throw InputError("longitudinal_relaxation_length must be >= 0", ctx);
  if (d.longitudinal_relaxation_length > 0) {
    if (!(d.relaxation_length > 0))
      throw InputError("longitudinal_relaxation_length > 0 needs relaxation_length > 0 (the contact-patch body)", ctx);
    k_long_ = d.count * d.pkx1 * d.nominal_load / d.longitudinal_relaxation_length;
  }
}

double Tire::CorneringStiffness(double fz1) const {
  const TireData& d = data_;
  return d.pky1 * d.nominal_load * std::sin(2.0 * std::atan(fz1 / (d.pky2 * d.nominal_load)));
}

Vec6 Tire::Wrench(const Vec3& p, const Mat3& R, const Vec3& v, const Vec3& w, TireContact* contact) const {
  const Vec3 a = R.col(2);
  return Compute<double>(p, a, v, w, nullptr, nullptr, contact).head<6>();
}

Vec12 Tire::RelaxedWrench(const Vec3& p, const Mat3& R, const Vec3& v, const Vec3& w, const Vec3& p_j,
                          const Vec3& v_j, TireContact* contact) const {
  if (!relaxed())
    throw InputError("RelaxedWrench needs relaxation_length > 0", {"", 0, "tire '" + name() + "'"});
  const Vec3 a = R.col(2);
  return Compute<double>(p, a, v, w, &p_j, &v_j, contact);
}

template <class S>
Eigen::Matrix<S, 12, 1> Tire::Compute(const V3<S>& p, const V3<S>& a, const V3<S>& v, const V3<S>& w, const V3<S>* p_j,
                                      const V3<S>* v_j, TireContact* contact) const {
  using std::cos;
  using std::sin;
  using std::sqrt;
  using std::tanh;
  using V = V3<S>;
  Eigen::Matrix<S, 12, 1> out = Eigen::Matrix<S, 12, 1>::Zero();
  if (contact) *contact = TireContact{};
  const TireData& d = data_;
  // carcass spring between the wheel centre and the contact patch
  V spring = p_j ? V(k_carcass_ * (*p_j - p)) : V(V::Zero());
  out.template segment<3>(0) = spring;
  out.template segment<3>(6) = -spring;
  // road plane under the centre: height h, normal n (flat road: z = 0, +z)
  // (piecewise linear: h' = slope, the slope's own derivative is 0)
  double h0 = 0.0, slope = 0.0;
  if (road_) road_->Evaluate(Val(p.x()), &h0, &slope);
  const S h = h0 + slope * (p.x() - Val(p.x()));
  const V n = (road_ ? Vec3(Vec3(-slope, 0, 1).normalized()) : Vec3(0, 0, 1)).cast<S>();
  const V axn = a.cross(n);
  const S s = axn.norm();
  // wheel lying flat: no defined rolling direction, no force
  if (Val(s) < 1e-6) return out;
  const V xt = axn / s;
  const V yt = n.cross(xt);
  // upward unit vector in the wheel plane; cos(gamma) = r . n = s
  const V r = xt.cross(a);
  const S rho = road_ ? S((p.z() - h) * n.z() / s) : S(p.z() / s);
  const S defl = d.unloaded_radius - rho;
  const V c = p - rho * r;
  // longitudinally relaxed: the spring is stiffer along x_t and acts on both
  // bodies at the patch's contact point c + u
  const bool along = p_j && k_long_ > 0;
  if (along) {
    const V u = *p_j - p;
    spring += (k_long_ - k_carcass_) * u.dot(xt) * xt;
    out.template segment<3>(0) = spring;
    out.template segment<3>(3) = (c - p + u).cross(spring);
    out.template segment<3>(6) = -spring;
    out.template segment<3>(9) = -(c - p).cross(spring);
  }
  if (contact) {
    contact->deflection = Val(defl);
    contact->contact_W = Vals(c);
    contact->fy_wheel = Val(spring.dot(yt));
    contact->fx_wheel = along ? Val(spring.dot(xt)) : 0.0;
  }
  if (Val(defl) <= 0) return out;
  const double n_t = d.count;
  // deflection rate: the centre's velocity along the road normal
  const S vn = road_ ? S((v.z() - slope * v.x()) * n.z()) : v.z();
  const S fz = n_t * (d.vertical_stiffness * defl - d.vertical_damping * vn / s);
  if (Val(fz) <= 0) return out;

  // slip
  const S vx = v.dot(xt);
  const V vc = v + w.cross(c - p);
  const S re = d.unloaded_radius - d.rolling_radius_factor * defl;
  const S omega = w.dot(a);
  // the longitudinally relaxed tire slips with the patch as well
  S vsx = vx - re * omega;
  if (along) vsx += (*v_j - v).dot(xt);
  // the relaxed tire slips with the patch, which slides relative to the centre
  S vsy = vc.dot(yt);
  if (v_j) vsy += (*v_j - v).dot(yt);
  const S vref = sqrt(vx * vx + d.low_speed * d.low_speed);
  const S kappa = -vsx / vref;
  const S alpha = Atan(S(vsy / vref));

  // pure slip per tire
  const S fz1 = fz / n_t;
  const S dfz = (fz1 - d.nominal_load) / d.nominal_load;
  // load sensitivity of the peak, max(0, 1 + p dfz)
  const S gx = 1.0 + d.pdx2 * dfz, gy = 1.0 + d.pdy2 * dfz;
  const S dx = Val(gx) > 0 ? S(mu_ * d.pdx1 * gx * fz1) : S(0.0);
  const S dy = Val(gy) > 0 ? S(mu_ * d.pdy1 * gy * fz1) : S(0.0);
  S fx0 = 0.0, fy0 = 0.0;
  if (Val(dx) > 0) fx0 = MagicFormula<S>(kappa, d.pkx1 * fz1 / (d.pcx1 * dx), d.pcx1, dx, d.pex1);
  if (Val(dy) > 0) {
    // Ky(Fz1), CorneringStiffness
    const S ky = d.pky1 * d.nominal_load * sin(2.0 * Atan(S(fz1 / (d.pky2 * d.nominal_load))));
    fy0 = -MagicFormula<S>(alpha, ky / (d.pcy1 * dy), d.pcy1, dy, d.pey1);
  }
  // combined slip by cosine weighting
  const S fx = n_t * fx0 * cos(Atan(S(d.rbx1 * alpha)));
  const S fy = n_t * fy0 * cos(Atan(S(d.rby1 * kappa)));
  // rolling resistance: a moment against the spin, f_r Fz times the lever rho
  const S roll_sign = tanh(vx / 0.5);
  const V my = (-d.rolling_resistance * fz * rho * roll_sign) * a;
  const V fw = fx * xt + fz * n;
  const V fl = fy * yt;
  const S trail = d.trail * cos(Atan(S(d.trail_decay * alpha)));
  const V mz = (-trail * fy * roll_sign) * n;
  if (along) {
    // slip forces and aligning moment on the patch, Fz on the wheel
    const V fz_n = fz * n;
    const V fs = fx * xt + fl;
    out.template segment<3>(0) += fz_n;
    out.template segment<3>(3) += (c - p).cross(fz_n) + my;
    out.template segment<3>(6) += fs;
    out.template segment<3>(9) += (c - p).cross(fs) + mz;
  } else if (p_j) {
    // lateral force and aligning moment on the patch (arm c - p from its marker)
    out.template segment<3>(0) += fw;
    out.template segment<3>(3) = (c - p).cross(fw) + my;
    out.template segment<3>(6) += fl;
    out.template segment<3>(9) = (c - p).cross(fl) + mz;
  } else {
    out.template segment<3>(0) = fw + fl;
    out.template segment<3>(3) = (c - p).cross(fw + fl) + mz + my;
  }
  if (contact) {
    contact->fz = Val(fz);
    contact->fx = Val(fx);
    contact->fy = Val(fy);
    if (!p_j) contact->fy_wheel = Val(fy);
    if (!along) contact->fx_wheel = Val(fx);
    contact->kappa = Val(kappa);
    contact->alpha = Val(alpha);
  }
  return out;
}

void Tire::Evaluate(const MarkerState& mi, const MarkerState& mj, double, ForceEval& e) const {
  const bool patch = marker_j >= 0;
  if (relaxed() != patch)
    throw InputError(relaxed() ? "a tire with relaxation_length > 0 needs a contact-patch marker j"
                               : "a tire without relaxation length takes one marker",
                     {"", 0, "tire '" + name() + "'"});
  const Vec3 a0 = mi.R_WM.col(2);
  // the wrench in doubles whether or not tangents are asked, so that a
  // residual does not depend on it (the AD evaluation's values may differ
  // in the last bit)
  e.wrench = Compute<double>(mi.p_WM, a0, mi.v_WM, mi.w_WM, patch ? &mj.p_WM : nullptr,
                             patch ? &mj.v_WM : nullptr, nullptr);
  if (!e.tangents) return;
  // one evaluation in AD scalars gives the exact derivatives of the wrench
  // by the pose (dp, dtheta with dR = skew(dtheta) R, dp_j) and the twist
  // (v, w, v_j) of the markers; the patch's rotation does not enter
  const Eigen::Matrix<Ad, 3, 1> p = Variable(mi.p_WM, kVarPose), v = Variable(mi.v_WM, kVarTwist),
                                w = Variable(mi.w_WM, kVarTwist + 3), pj = Variable(mj.p_WM, kVarPose + 6),
                                vj = Variable(mj.v_WM, kVarTwist + 6);
  // spin axis a = R e_z: d a / d theta_k = e_k x a
  Eigen::Matrix<Ad, 3, 1> a;
  for (int i = 0; i < 3; ++i) {
    a(i) = Ad(a0(i), Eigen::Matrix<double, 18, 1>::Zero());
    for (int k = 0; k < 3; ++k) a(i).derivatives()(kVarPose + 3 + k) = Vec3::Unit(k).cross(a0)(i);
  }
  const Eigen::Matrix<Ad, 12, 1> f = Compute<Ad>(p, a, v, w, patch ? &pj : nullptr, patch ? &vj : nullptr, nullptr);
  const int n_var = patch ? 9 : 6;
  e.K.setZero();
  e.C.setZero();
  for (int r = 0; r < 12; ++r) {
    const auto& g = f(r).derivatives();
    for (int k = 0; k < n_var; ++k) {
      e.K(r, k) = g(kVarPose + k);
      e.C(r, k) = g(kVarTwist + k);
    }
  }
}

}  // namespace flexmb::vehicle
