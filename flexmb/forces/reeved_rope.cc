#include "flexmb/forces/reeved_rope.h"

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb {
namespace {

/// Vector over the pose variations of a force element's markers, stored in
/// place (no allocation per evaluation).
using ReevedRopeVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6 * kMaxForceMarkers, 1>;

}  // namespace

ReevedRope::ReevedRope(std::string name, RopeLaw law, int path_markers, RopeDrum drum, RopeSpan span)
    : ForceElement(name), law_(name, std::move(law)), path_(path_markers), drum_(drum), span_(span) {
  const ErrorContext ctx{"", 0, "force '" + this->name() + "'"};
  if (path_ < 2) throw InputError("a rope path needs at least two markers, got " + std::to_string(path_), ctx);
  if (span_.present && (law_.law().hoist_speed || law_.law().free_length_function))
    throw InputError("with a span the rope is paid out by its drum: give neither hoist_speed nor a free-length "
                     "function",
                     ctx);
  if (span_.present && !(span_.free_length > 0.0))
    throw InputError(fmt::format("the span's free length must be > 0, got {:g} m", span_.free_length), ctx);
  if (!drum_.joint) return;
  if (!(drum_.radius > 0.0) || !std::isfinite(drum_.radius))
    throw InputError(fmt::format("the drum radius must be finite and > 0, got {:g} m", drum_.radius), ctx);
  if (drum_.joint->NumCoordinates() < 1 || !drum_.joint->CoordinateIsAngle(0))
    throw InputError(std::string("the drum joint '") + drum_.joint->name() + "' (" + drum_.joint->type() +
                         "): its first coordinate is not an angle; the drum turns in a revolute joint",
                     ctx);
  if (law_.law().hoist_speed || law_.law().free_length_function)
    throw InputError("with a drum the winch is the drum: give neither hoist_speed nor a free-length function",
                     ctx);
}

void ReevedRope::Evaluate(const MarkerState&, const MarkerState&, double, ForceEval&) const {
  throw InputError("a reeved rope acts on " + std::to_string(NumMarkers()) + " markers", {"", 0, "force '" + name() + "'"});
}

void ReevedRope::FreeLength(const MarkerState* const* m, double t, double& L0, double& L0dot, Vec3& a,
                            Vec3& wrel) const {
  double theta = 0.0;
  if (!drum_.joint) {
    if (span_.present) {
      L0 = law_.law().free_length;
      L0dot = 0.0;
    } else {
      law_.FreeLength(t, L0, L0dot);
      return;
    }
  } else {
    const MarkerState& di = *m[path_];
    const MarkerState& dj = *m[path_ + 1];
    const double wrapped = drum_.joint->Coordinate(0, di, dj, nullptr);
    theta = wrapped;
    if (theta_set_) theta += 2.0 * M_PI * std::round((theta_last_ - wrapped) / (2.0 * M_PI));
    theta_last_ = theta;
    theta_set_ = true;
    a = drum_.joint->CoordinateAxis(0, di);
    wrel = dj.w_WM - di.w_WM;
    L0 = law_.law().free_length + drum_.radius * theta;
    L0dot = drum_.radius * a.dot(wrel);
  }
  if (span_.present) {
    const MarkerState& p = *m[PayoutMarker()];
    L0 -= law_.law().falls * (p.p_WM.x() - span_.free_length);
    L0dot -= law_.law().falls * p.v_WM.x();
  }
  if (!(L0 > 0.0)) {
    char what[240];
    std::snprintf(what, sizeof what, "the free length of the rope is %.6g m at t = %.6g s (drum angle %.6g rad%s); "
                  "it must stay > 0 (the drum would be empty)", L0, t, theta,
                  span_.present ? ", after what the span took" : "");
    throw InputError(what, {"", 0, "force '" + name() + "'"});
  }
}

void ReevedRope::EvaluateMarkers(const MarkerState* const* m, double t, ForceEval& e) const {
  // the markers, also before the model sets them
  const int n6 = 6 * (path_ + (drum_.joint ? 2 : 0) + (span_.present ? 1 : 0));
  e.wrench_n.setZero();
  if (e.tangents) {
    e.K_n.setZero();
    e.C_n.setZero();
  }
  double L0, L0dot;
  Vec3 a = Vec3::Zero(), wrel = Vec3::Zero();
  FreeLength(m, t, L0, L0dot, a, wrel);
  const RopeLaw& law = law_.law();
  // stretched length, its rate and its gradient g_l over the path positions
  double l = 0.0, ldot = 0.0;
  Eigen::Ref<VecX> w = e.wrench_n;
  for (int s = 0; s + 1 < path_; ++s) {
    const Vec3 d = m[s + 1]->p_WM - m[s]->p_WM;
    const double ls = d.norm();
    if (!(ls > 1e-12 * L0))
      throw NumericalError("the path markers " + std::to_string(s) + " and " + std::to_string(s + 1) +
                               " coincide: the rope direction is undefined",
                           {"", 0, "force '" + name() + "'"});
    const double c = SegmentFactor(s);
    l += c * ls;
    ldot += c * (d / ls).dot(m[s + 1]->v_WM - m[s]->v_WM);
  }
  const double eps = l / L0 - 1.0;
  if (!(eps > 0.0)) return;  // slack
  const double EA = law.axial_stiffness, beta = law.damping_time;
  const double eps_dot = ldot / L0 - l * L0dot / (L0 * L0);
  const double T = EA * (eps + beta * eps_dot);
  if (!(T > 0.0)) return;  // the damping may relieve the rope, never push
  // generalized force on psi (L0 = free_length + psi), from the elastic
  // energy and the dissipation function
  const double Qpsi = EA * (eps * (1.0 + 0.5 * eps) + beta * eps_dot * (1.0 + eps));
  const double R = drum_.joint ? drum_.radius : 0.0;

  // g_l = dl/dx (positions of the path), g_psi = dpsi/dx (drum rotations,
  // the span's payout)
  VecX& gl = e.wrench_n;  // built in place, then scaled
  for (int s = 0; s + 1 < path_; ++s) {
    const Vec3 u = (m[s + 1]->p_WM - m[s]->p_WM).normalized();
    const double c = SegmentFactor(s);
    gl.segment<3>(6 * (s + 1)) += c * u;
    gl.segment<3>(6 * s) -= c * u;
  }
  const int di = 6 * path_, dj = 6 * (path_ + 1), dp = 6 * PayoutMarker();
  const double n_span = span_.present ? law.falls : 0.0;
  if (!e.tangents) {
    gl *= -T;
    if (R > 0.0) {
      w.segment<3>(di + 3) = -R * Qpsi * a;
      w.segment<3>(dj + 3) = R * Qpsi * a;
    }
    if (span_.present) w(dp) = -n_span * Qpsi;
    return;
  }
  ReevedRopeVec gpsi = ReevedRopeVec::Zero(n6);
  if (R > 0.0) {
    gpsi.segment<3>(di + 3) = -R * a;
    gpsi.segment<3>(dj + 3) = R * a;
  }
  if (span_.present) gpsi(dp) = -n_span;
  // partial derivatives of eps and d(eps)/dt by l, L0, ldot, L0dot
  const double e_l = 1.0 / L0, e_L = -l / (L0 * L0);
  const double ed_l = -L0dot / (L0 * L0), ed_L = -ldot / (L0 * L0) + 2.0 * l * L0dot / (L0 * L0 * L0);
  const double ed_ld = 1.0 / L0, ed_Ld = -l / (L0 * L0);
  // T and Q_psi by l, psi, ldot, psidot
  const double T_l = EA * (e_l + beta * ed_l), T_psi = EA * (e_L + beta * ed_L);
  const double T_ld = EA * beta * ed_ld, T_psid = EA * beta * ed_Ld;
  const auto q_of = [&](double ex, double edx) {
    return EA * (ex * (1.0 + eps) + beta * (edx * (1.0 + eps) + eps_dot * ex));
  };
  const double Q_l = q_of(e_l, ed_l), Q_psi = q_of(e_L, ed_L);
  const double Q_ld = q_of(0.0, ed_ld), Q_psid = q_of(0.0, ed_Ld);

  // d(ldot)/dx and d(psidot)/dx at fixed twists (the payout marker's
  // Jacobian is constant); the Hessian of l
  ReevedRopeVec dld = ReevedRopeVec::Zero(n6), dpsid = ReevedRopeVec::Zero(n6);
  for (int s = 0; s + 1 < path_; ++s) {
    const Vec3 d = m[s + 1]->p_WM - m[s]->p_WM;
    const double ls = d.norm();
    const Vec3 u = d / ls;
    const double c = SegmentFactor(s);
    const Mat3 P = c * (Mat3::Identity() - u * u.transpose()) / ls;
    const Vec3 pv = P * (m[s + 1]->v_WM - m[s]->v_WM);
    dld.segment<3>(6 * (s + 1)) += pv;
    dld.segment<3>(6 * s) -= pv;
    // -T d(g_l)/dx
    const int i0 = 6 * s, j0 = 6 * (s + 1);
    e.K_n.block<3, 3>(j0, j0) -= T * P;
    e.K_n.block<3, 3>(i0, i0) -= T * P;
    e.K_n.block<3, 3>(j0, i0) += T * P;
    e.K_n.block<3, 3>(i0, j0) += T * P;
  }
  if (R > 0.0) {
    dpsid.segment<3>(di + 3) = R * a.cross(wrel);
    // Q_psi d(g_psi)/dx: the axis a turns with marker i (da = -skew(a) dth_i)
    const Mat3 Sa = Skew(a);
    e.K_n.block<3, 3>(dj + 3, di + 3) -= R * Qpsi * Sa;
    e.K_n.block<3, 3>(di + 3, di + 3) += R * Qpsi * Sa;
  }
  const ReevedRopeVec g = gl;
  const ReevedRopeVec dT = T_l * g + T_psi * gpsi + T_ld * dld + T_psid * dpsid;
  const ReevedRopeVec dQ = Q_l * g + Q_psi * gpsi + Q_ld * dld + Q_psid * dpsid;
  const ReevedRopeVec cT = T_ld * g + T_psid * gpsi;
  const ReevedRopeVec cQ = Q_ld * g + Q_psid * gpsi;
  e.K_n.noalias() -= g * dT.transpose();
  e.K_n.noalias() += gpsi * dQ.transpose();
  e.C_n.noalias() -= g * cT.transpose();
  e.C_n.noalias() += gpsi * cQ.transpose();
  // the wrench last (gl is its storage)
  gl *= -T;
  w += Qpsi * gpsi;
}

double ReevedRope::PotentialEnergyMarkers(const MarkerState* const* m, double t) const {
  double L0, L0dot;
  Vec3 a, wrel;
  FreeLength(m, t, L0, L0dot, a, wrel);
  double l = 0.0;
  for (int s = 0; s + 1 < path_; ++s)
    l += SegmentFactor(s) * (m[s + 1]->p_WM - m[s]->p_WM).norm();
  const double eps = l / L0 - 1.0;
  return eps > 0.0 ? 0.5 * law_.law().axial_stiffness * L0 * eps * eps : 0.0;
}

}  // namespace flexmb
