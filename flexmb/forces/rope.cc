#include "flexmb/forces/rope.h"

#include <cmath>
#include <cstdio>

#include "flexmb/common/error.h"
#include "flexmb/forces/line_force.h"

namespace flexmb {
Rope::Rope(std::string name, RopeLaw law)
    : ForceElement(std::move(name)), law_(std::move(law)), payout_(law_) {
  const ErrorContext ctx{"", 0, "force '" + this->name() + "'"};
  if (!std::isfinite(law_.axial_stiffness) || law_.axial_stiffness <= 0.0)
    throw InputError("axial_stiffness (EA) must be finite and > 0, got " +
                         std::to_string(law_.axial_stiffness), ctx);
  if (law_.falls < 1) throw InputError("falls must be >= 1, got " + std::to_string(law_.falls), ctx);
  if (!std::isfinite(law_.damping_time) || law_.damping_time < 0.0)
    throw InputError("damping_time must be finite and >= 0, got " + std::to_string(law_.damping_time), ctx);
  if (law_.free_length_function && law_.hoist_speed)
    throw InputError("give the free length as a function of time or a hoisting speed, not both", ctx);
  if (!std::isfinite(law_.free_length))
    throw InputError("free_length must be finite", ctx);
  double L0, L0dot;
  FreeLength(0.0, L0, L0dot);  // throws for L0(0) <= 0
}

void Rope::FreeLength(double t, double& L0, double& L0dot) const {
  payout_(t, L0, L0dot);
  if (!(L0 > 0.0) || !std::isfinite(L0dot)) {
    char what[160];
    std::snprintf(what, sizeof what, "the free length of the rope is %.6g m at t = %.6g s; it must stay > 0 "
                  "(the winch would be empty)", L0, t);
    throw InputError(what, {"", 0, "force '" + name() + "'"});
  }
}

void Rope::Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const {
  double L0, L0dot;
  FreeLength(t, L0, L0dot);
  const Vec3 d = mj.p_WM - mi.p_WM;
  const double l = d.norm();
  if (!(l > 1e-12 * L0))
    throw NumericalError("the marker origins coincide: the rope direction is undefined",
                         {"", 0, "force '" + name() + "'"});
  e.wrench.setZero();
  e.K.setZero();
  e.C.setZero();
  const double n = law_.falls, EA = law_.axial_stiffness, beta = law_.damping_time;
  const Vec3 u = d / l;
  const Vec3 vrel = mj.v_WM - mi.v_WM;
  const double ldot = u.dot(vrel);
  const double eps = n * l / L0 - 1.0;
  if (!(eps > 0.0)) return;  // slack: no force
  const double eps_dot = n * ldot / L0 - n * l * L0dot / (L0 * L0);
  const double T = EA * (eps + beta * eps_dot);
  if (!(T > 0.0)) return;  // the damping may relieve the rope, never push
  // F = n T and its derivatives with respect to l and ldot
  const double F = n * T;
  const double dFdl = n * EA * (n / L0 - beta * n * L0dot / (L0 * L0));
  const double dFdv = n * beta * EA * n / L0;
  SetLineForce(u, l, vrel, F, dFdl, dFdv, e);
}

double Rope::PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double t) const {
  double L0, L0dot;
  FreeLength(t, L0, L0dot);
  const double eps = law_.falls * (mj.p_WM - mi.p_WM).norm() / L0 - 1.0;
  return eps > 0.0 ? 0.5 * law_.axial_stiffness * L0 * eps * eps : 0.0;
}

}  // namespace flexmb
