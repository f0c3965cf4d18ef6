#include "flexmb/forces/plane_contact.h"

#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb {

PlaneContact::PlaneContact(std::string name, PlaneContactLaw law)
    : ForceElement(std::move(name)), law_(std::move(law)) {
  const ErrorContext ctx{"", 0, "force '" + this->name() + "'"};
  auto finite = [&](double x, const char* what) {
    if (!std::isfinite(x)) throw InputError(std::string(what) + " must be finite", ctx);
  };
  for (int k = 0; k < 3; ++k) finite(law_.point_W(k), "point"), finite(law_.normal_W(k), "normal");
  finite(law_.stiffness, "stiffness");
  finite(law_.damping, "damping");
  finite(law_.friction, "friction");
  finite(law_.slip_velocity, "slip_velocity");
  if (!(law_.stiffness > 0.0)) throw InputError("stiffness must be > 0", ctx);
  if (law_.damping < 0.0) throw InputError("damping must be >= 0", ctx);
  if (law_.friction < 0.0) throw InputError("friction must be >= 0", ctx);
  if (!(law_.slip_velocity > 0.0)) throw InputError("slip_velocity must be > 0", ctx);
  const double n = law_.normal_W.norm();
  if (!(n > 0.0)) throw InputError("normal must not be the zero vector", ctx);
  law_.normal_W /= n;
}

void PlaneContact::Evaluate(const MarkerState& mi, const MarkerState&, double, ForceEval& e) const {
  e.wrench.setZero();
  e.K.setZero();
  e.C.setZero();
  const Vec3& n = law_.normal_W;
  const double g = Penetration(mi.p_WM);
  if (!(g > 0.0)) return;
  const double gdot = -n.dot(mi.v_WM);
  const double Fn = law_.stiffness * g + law_.damping * gdot;
  if (!(Fn > 0.0)) return;
  // normal force and its derivatives: dFn/dp = -k n^T, dFn/dv = -c n^T
  const Mat3 nn = n * n.transpose();
  Vec3 f = Fn * n;
  Mat3 dfdp = -law_.stiffness * nn, dfdv = -law_.damping * nn;
  if (law_.friction > 0.0) {
    const Vec3 vt = mi.v_WM - n.dot(mi.v_WM) * n;
    const double s = std::sqrt(vt.squaredNorm() + law_.slip_velocity * law_.slip_velocity);
    const Vec3 dir = vt / s;  // |dir| < 1: the regularized direction
    const double mu = law_.friction;
    f -= mu * Fn * dir;
    dfdp += mu * law_.stiffness * dir * n.transpose();
    dfdv += mu * law_.damping * dir * n.transpose();
    // d(vt / s)/dv = (P - dir dir^T) / s with P = I - n n^T
    dfdv -= (mu * Fn / s) * (Mat3::Identity() - nn - dir * dir.transpose());
  }
  e.wrench.segment<3>(0) = f;
  e.K.block<3, 3>(0, 0) = dfdp;
  e.C.block<3, 3>(0, 0) = dfdv;
}

double PlaneContact::PotentialEnergy(const MarkerState& mi, const MarkerState&, double) const {
  const double g = Penetration(mi.p_WM);
  return g > 0.0 ? 0.5 * law_.stiffness * g * g : 0.0;
}

}  // namespace flexmb
