#include "flexmb/forces/spring_damper.h"

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/forces/line_force.h"

namespace flexmb {
SpringDamper::SpringDamper(std::string name, SpringDamperLaw law)
    : ForceElement(std::move(name)), law_(std::move(law)) {
  const ErrorContext ctx{"", 0, "force '" + this->name() + "'"};
  auto check = [&](double x, const char* what) {
    if (!std::isfinite(x) || x < 0.0)
      throw InputError(std::string(what) + " must be finite and >= 0, got " + std::to_string(x), ctx);
  };
  check(law_.free_length, "free_length");
  check(law_.stiffness, "stiffness");
  check(law_.damping, "damping");
  if (!std::isfinite(law_.preload)) throw InputError("preload must be finite", ctx);
}

void SpringDamper::Evaluate(const MarkerState& mi, const MarkerState& mj, double, ForceEval& e) const {
  const Vec3 d = mj.p_WM - mi.p_WM;
  const double l = d.norm();
  if (!(l > 1e-12 * std::max(1.0, law_.free_length)))
    throw NumericalError("the marker origins coincide: the spring direction is undefined",
                         {"", 0, "force '" + name() + "'"});
  const Vec3 u = d / l;
  const Vec3 vrel = mj.v_WM - mi.v_WM;
  const double x = l - law_.free_length, ldot = u.dot(vrel);
  // tension and its derivatives with respect to the deflection and the rate
  double F = law_.preload, dFdx, dFdv;
  if (law_.force_deflection) {
    F += law_.force_deflection->Value(x);
    dFdx = law_.force_deflection->Derivative(x);
  } else {
    F += law_.stiffness * x;
    dFdx = law_.stiffness;
  }
  if (law_.force_velocity) {
    F += law_.force_velocity->Value(ldot);
    dFdv = law_.force_velocity->Derivative(ldot);
  } else {
    F += law_.damping * ldot;
    dFdv = law_.damping;
  }
  SetLineForce(u, l, vrel, F, dFdx, dFdv, e);
}

double SpringDamper::PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double) const {
  const double x = (mj.p_WM - mi.p_WM).norm() - law_.free_length;
  const double spring = law_.force_deflection ? law_.force_deflection->IntegralFromZero(x)
                                              : 0.5 * law_.stiffness * x * x;
  return spring + law_.preload * x;
}

}  // namespace flexmb
