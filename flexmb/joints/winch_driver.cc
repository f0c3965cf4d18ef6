#include "flexmb/joints/winch_driver.h"

#include <cmath>
#include <cstdio>

#include "flexmb/common/error.h"

namespace flexmb {

WinchDriver::WinchDriver(std::string name, WinchLaw law)
    : Joint(std::move(name)), law_(std::move(law)), payout_(law_) {
  const ErrorContext ctx{"", 0, "driver '" + this->name() + "'"};
  if (law_.hoist_speed && law_.free_length_function)
    throw InputError("give the free length as a function of time or a hoisting speed, not both", ctx);
  double L, Ld;
  try {
    FreeLength(0.0, L, Ld);
  } catch (const NumericalError& e) {
    throw InputError(e.message(), ctx);
  }
}

std::string WinchDriver::EquationName(int) const { return "free length of the rope = L(t)"; }

void WinchDriver::FreeLength(double t, double& L, double& Ldot) const {
  payout_(t, L, Ldot);
  if (!(L > 0.0) || !std::isfinite(Ldot)) {
    char what[160];
    std::snprintf(what, sizeof what,
                  "the winch's free length is %.6g m at t = %.6g s; it must stay > 0 (the winch hauled in "
                  "more rope than hangs)",
                  L, t);
    throw NumericalError(what, {"", 0, "driver '" + name() + "'"});
  }
}

void WinchDriver::Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const {
  double L, Ld;
  FreeLength(t, L, Ld);
  e.phi(0) = mi.p_WM.x() - mj.p_WM.x() - L;
  e.phi_t(0) = -Ld;
  e.D.row(0).setZero();
  e.D(0, 0) = 1.0;
  e.D(0, 6) = -1.0;
}

}  // namespace flexmb
