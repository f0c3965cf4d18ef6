#include "flexmb/vehicle/tire.h"

#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb::vehicle {
namespace {

// magic formula y = D sin(C atan(B x - E (B x - atan(B x))))
double MagicFormula(double x, double B, double C, double D, double E) {
  const double bx = B * x;
  return D * std::sin(C * std::atan(bx - E * (bx - std::atan(bx))));
}

// finite-difference steps: position [m], rotation [rad], velocities [m/s, rad/s]
constexpr double kStepPose = 1e-6;
constexpr double kStepRate = 1e-5;

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
}

Vec6 Tire::Wrench(const Vec3& p, const Mat3& R, const Vec3& v, const Vec3& w, TireContact* contact) const {
  Vec6 out = Vec6::Zero();
  if (contact) *contact = TireContact{};
  const TireData& d = data_;
  const Vec3 n(0, 0, 1);
  const Vec3 a = R.col(2);
  const Vec3 axn = a.cross(n);
  const double s = axn.norm();
  // wheel lying flat: no defined rolling direction, no force
  if (s < 1e-6) return out;
  const Vec3 xt = axn / s;
  const Vec3 yt = n.cross(xt);
  // upward unit vector in the wheel plane; cos(gamma) = r . n = s
  const Vec3 r = xt.cross(a);
  const double rho = p.z() / s;
  const double defl = d.unloaded_radius - rho;
  const Vec3 c = p - rho * r;
  if (contact) {
    contact->deflection = defl;
    contact->contact_W = c;
  }
  if (defl <= 0) return out;
  const double n_t = d.count;
  const double fz = std::max(0.0, n_t * (d.vertical_stiffness * defl - d.vertical_damping * v.z() / s));
  if (fz <= 0) return out;

  // slip
  const double vx = v.dot(xt);
  const Vec3 vc = v + w.cross(c - p);
  const double re = d.unloaded_radius - d.rolling_radius_factor * defl;
  const double omega = w.dot(a);
  const double vsx = vx - re * omega;
  const double vsy = vc.dot(yt);
  const double vref = std::sqrt(vx * vx + d.low_speed * d.low_speed);
  const double kappa = -vsx / vref;
  const double alpha = std::atan(vsy / vref);

  // pure slip per tire
  const double fz1 = fz / n_t;
  const double dfz = (fz1 - d.nominal_load) / d.nominal_load;
  const double dx = mu_ * d.pdx1 * std::max(0.0, 1.0 + d.pdx2 * dfz) * fz1;
  const double dy = mu_ * d.pdy1 * std::max(0.0, 1.0 + d.pdy2 * dfz) * fz1;
  double fx0 = 0.0, fy0 = 0.0;
  if (dx > 0) fx0 = MagicFormula(kappa, d.pkx1 * fz1 / (d.pcx1 * dx), d.pcx1, dx, d.pex1);
  if (dy > 0) {
    const double ky = d.pky1 * d.nominal_load * std::sin(2.0 * std::atan(fz1 / (d.pky2 * d.nominal_load)));
    fy0 = -MagicFormula(alpha, ky / (d.pcy1 * dy), d.pcy1, dy, d.pey1);
  }
  // combined slip by cosine weighting
  const double fx = n_t * fx0 * std::cos(std::atan(d.rbx1 * alpha));
  const double fy = n_t * fy0 * std::cos(std::atan(d.rby1 * kappa));
  const double frr = -d.rolling_resistance * fz * std::tanh(vx / 0.5);
  const Vec3 f = (fx + frr) * xt + fy * yt + fz * n;
  const double trail = d.trail * std::cos(std::atan(d.trail_decay * alpha));
  const Vec3 mz = -trail * fy * std::tanh(vx / 0.5) * n;
  out.head<3>() = f;
  out.tail<3>() = (c - p).cross(f) + mz;
  if (contact) {
    contact->fz = fz;
    contact->fx = fx + frr;
    contact->fy = fy;
    contact->kappa = kappa;
    contact->alpha = alpha;
  }
  return out;
}

void Tire::Evaluate(const MarkerState& mi, const MarkerState&, double, ForceEval& e) const {
  e.wrench.setZero();
  e.K.setZero();
  e.C.setZero();
  e.wrench.head<6>() = Wrench(mi.p_WM, mi.R_WM, mi.v_WM, mi.w_WM, nullptr);
  // central differences: pose (dp, dtheta with dR = skew(dtheta) R), then twist
  for (int k = 0; k < 3; ++k) {
    Vec3 dp = Vec3::Zero();
    dp[k] = kStepPose;
    const Vec6 fp = Wrench(mi.p_WM + dp, mi.R_WM, mi.v_WM, mi.w_WM, nullptr);
    const Vec6 fm = Wrench(mi.p_WM - dp, mi.R_WM, mi.v_WM, mi.w_WM, nullptr);
    e.K.block<6, 1>(0, k) = (fp - fm) / (2 * kStepPose);
    const Vec6 rp = Wrench(mi.p_WM, ExpSO3(dp) * mi.R_WM, mi.v_WM, mi.w_WM, nullptr);
    const Vec6 rm = Wrench(mi.p_WM, ExpSO3(-dp) * mi.R_WM, mi.v_WM, mi.w_WM, nullptr);
    e.K.block<6, 1>(0, 3 + k) = (rp - rm) / (2 * kStepPose);
    Vec3 dv = Vec3::Zero();
    dv[k] = kStepRate;
    const Vec6 vp = Wrench(mi.p_WM, mi.R_WM, mi.v_WM + dv, mi.w_WM, nullptr);
    const Vec6 vm = Wrench(mi.p_WM, mi.R_WM, mi.v_WM - dv, mi.w_WM, nullptr);
    e.C.block<6, 1>(0, k) = (vp - vm) / (2 * kStepRate);
    const Vec6 wp = Wrench(mi.p_WM, mi.R_WM, mi.v_WM, mi.w_WM + dv, nullptr);
    const Vec6 wm = Wrench(mi.p_WM, mi.R_WM, mi.v_WM, mi.w_WM - dv, nullptr);
    e.C.block<6, 1>(0, 3 + k) = (wp - wm) / (2 * kStepRate);
  }
}

}  // namespace flexmb::vehicle
