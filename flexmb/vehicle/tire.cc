#include "flexmb/vehicle/tire.h"

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/vehicle/road_surface.h"

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
  return Compute(p, R, v, w, nullptr, nullptr, contact).head<6>();
}

Vec12 Tire::RelaxedWrench(const Vec3& p, const Mat3& R, const Vec3& v, const Vec3& w, const Vec3& p_j,
                          const Vec3& v_j, TireContact* contact) const {
  if (!relaxed())
    throw InputError("RelaxedWrench needs relaxation_length > 0", {"", 0, "tire '" + name() + "'"});
  return Compute(p, R, v, w, &p_j, &v_j, contact);
}

Vec12 Tire::Compute(const Vec3& p, const Mat3& R, const Vec3& v, const Vec3& w, const Vec3* p_j, const Vec3* v_j,
                    TireContact* contact) const {
  Vec12 out = Vec12::Zero();
  if (contact) *contact = TireContact{};
  const TireData& d = data_;
  // carcass spring between the wheel centre and the contact patch
  Vec3 spring = p_j ? Vec3(k_carcass_ * (*p_j - p)) : Vec3::Zero();
  out.segment<3>(0) = spring;
  out.segment<3>(6) = -spring;
  // road plane under the centre: height h, normal n (flat road: z = 0, +z)
  double h = 0.0, slope = 0.0;
  if (road_) road_->Evaluate(p.x(), &h, &slope);
  const Vec3 n = road_ ? Vec3(Vec3(-slope, 0, 1).normalized()) : Vec3(0, 0, 1);
  const Vec3 a = R.col(2);
  const Vec3 axn = a.cross(n);
  const double s = axn.norm();
  // wheel lying flat: no defined rolling direction, no force
  if (s < 1e-6) return out;
  const Vec3 xt = axn / s;
  const Vec3 yt = n.cross(xt);
  // upward unit vector in the wheel plane; cos(gamma) = r . n = s
  const Vec3 r = xt.cross(a);
  const double rho = road_ ? (p.z() - h) * n.z() / s : p.z() / s;
  const double defl = d.unloaded_radius - rho;
  const Vec3 c = p - rho * r;
  // longitudinally relaxed: the spring is stiffer along x_t and acts on both
  // bodies at the patch's contact point c + u
  const bool along = p_j && k_long_ > 0;
  if (along) {
    const Vec3 u = *p_j - p;
    spring += (k_long_ - k_carcass_) * u.dot(xt) * xt;
    out.segment<3>(0) = spring;
    out.segment<3>(3) = (c - p + u).cross(spring);
    out.segment<3>(6) = -spring;
    out.segment<3>(9) = -(c - p).cross(spring);
  }
  if (contact) {
    contact->deflection = defl;
    contact->contact_W = c;
    contact->fy_wheel = spring.dot(yt);
    contact->fx_wheel = along ? spring.dot(xt) : 0.0;
  }
  if (defl <= 0) return out;
  const double n_t = d.count;
  // deflection rate: the centre's velocity along the road normal
  const double vn = road_ ? (v.z() - slope * v.x()) * n.z() : v.z();
  const double fz = std::max(0.0, n_t * (d.vertical_stiffness * defl - d.vertical_damping * vn / s));
  if (fz <= 0) return out;

  // slip
  const double vx = v.dot(xt);
  const Vec3 vc = v + w.cross(c - p);
  const double re = d.unloaded_radius - d.rolling_radius_factor * defl;
  const double omega = w.dot(a);
  // the longitudinally relaxed tire slips with the patch as well
  const double vsx = vx - re * omega + (along ? (*v_j - v).dot(xt) : 0.0);
  // the relaxed tire slips with the patch, which slides relative to the centre
  const double vsy = vc.dot(yt) + (v_j ? (*v_j - v).dot(yt) : 0.0);
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
    const double ky = CorneringStiffness(fz1);
    fy0 = -MagicFormula(alpha, ky / (d.pcy1 * dy), d.pcy1, dy, d.pey1);
  }
  // combined slip by cosine weighting
  const double fx = n_t * fx0 * std::cos(std::atan(d.rbx1 * alpha));
  const double fy = n_t * fy0 * std::cos(std::atan(d.rby1 * kappa));
  // rolling resistance: a moment against the spin, f_r Fz times the lever rho
  const Vec3 my = -d.rolling_resistance * fz * rho * std::tanh(vx / 0.5) * a;
  const Vec3 fw = fx * xt + fz * n;
  const Vec3 fl = fy * yt;
  const double trail = d.trail * std::cos(std::atan(d.trail_decay * alpha));
  const Vec3 mz = -trail * fy * std::tanh(vx / 0.5) * n;
  if (along) {
    // slip forces and aligning moment on the patch, Fz on the wheel
    const Vec3 fz_n = fz * n;
    const Vec3 fs = fx * xt + fl;
    out.segment<3>(0) += fz_n;
    out.segment<3>(3) += (c - p).cross(fz_n) + my;
    out.segment<3>(6) += fs;
    out.segment<3>(9) += (c - p).cross(fs) + mz;
  } else if (p_j) {
    // lateral force and aligning moment on the patch (arm c - p from its marker)
    out.segment<3>(0) += fw;
    out.segment<3>(3) = (c - p).cross(fw) + my;
    out.segment<3>(6) += fl;
    out.segment<3>(9) = (c - p).cross(fl) + mz;
  } else {
    out.segment<3>(0) = fw + fl;
    out.segment<3>(3) = (c - p).cross(fw + fl) + mz + my;
  }
  if (contact) {
    contact->fz = fz;
    contact->fx = fx;
    contact->fy = fy;
    if (!p_j) contact->fy_wheel = fy;
    if (!along) contact->fx_wheel = fx;
    contact->kappa = kappa;
    contact->alpha = alpha;
  }
  return out;
}

void Tire::Evaluate(const MarkerState& mi, const MarkerState& mj, double, ForceEval& e) const {
  const bool patch = marker_j >= 0;
  if (relaxed() != patch)
    throw InputError(relaxed() ? "a tire with relaxation_length > 0 needs a contact-patch marker j"
                               : "a tire without relaxation length takes one marker",
                     {"", 0, "tire '" + name() + "'"});
  // the patch's pose (dp, dtheta) and twist (v, w) variations: only p_j and
  // v_j enter, so its rotation columns stay zero
  const int n_var = patch ? 12 : 6;
  Vec3 pi = mi.p_WM, vi = mi.v_WM, wi = mi.w_WM, pj = mj.p_WM, vj = mj.v_WM;
  Mat3 Ri = mi.R_WM;
  auto eval = [&]() { return Compute(pi, Ri, vi, wi, patch ? &pj : nullptr, patch ? &vj : nullptr, nullptr); };
  e.wrench = eval();
  // the tangents cost 24 (with patch: 36) more evaluations: only when asked
  if (!e.tangents) return;
  e.K.setZero();
  e.C.setZero();
  Vec12 fp, fm;
  // forces at var = base +- step into fp, fm; var restored to base
  auto central = [&](Vec3& var, const Vec3& base, const Vec3& step) {
    var = base + step;
    fp = eval();
    var = base - step;
    fm = eval();
    var = base;
  };
  // central differences: pose (dp, dtheta with dR = skew(dtheta) R), then twist
  for (int k = 0; k < n_var; ++k) {
    if (k >= 9) continue;
    const int a = k % 3;
    Vec3 step = Vec3::Zero();
    step[a] = kStepPose;
    if (k < 3) {
      central(pi, mi.p_WM, step);
    } else if (k < 6) {
      Ri = ExpSO3(step) * mi.R_WM;
      fp = eval();
      Ri = ExpSO3(-step) * mi.R_WM;
      fm = eval();
      Ri = mi.R_WM;
    } else {
      central(pj, mj.p_WM, step);
    }
    e.K.col(k) = (fp - fm) / (2 * kStepPose);
    step[a] = kStepRate;
    if (k < 3)
      central(vi, mi.v_WM, step);
    else if (k < 6)
      central(wi, mi.w_WM, step);
    else
      central(vj, mj.v_WM, step);
    e.C.col(k) = (fp - fm) / (2 * kStepRate);
  }
}

}  // namespace flexmb::vehicle
