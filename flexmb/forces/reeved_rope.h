#pragma once
/// \file reeved_rope.h
/// Hoisting rope reeved from a winch over sheaves to the hook block: one
/// tension along a path of markers, its free length paid out by a winch drum
/// that turns in a revolute joint (drum inertia, drive torque and brake come
/// from the drum's body, its joint and a joint motor on it).

#include "flexmb/forces/rope.h"

namespace flexmb {

/// Winch drum of a ReevedRope: a joint whose first coordinate (an angle) is
/// the drum's rotation, marker i on the winch frame, marker j on the drum.
struct RopeDrum {
  const Joint* joint = nullptr;  ///< revolute (or cylindrical) joint of the drum; null: no drum
  double radius = 0.0;           ///< winding radius to the rope's centre line [m], > 0
};

/// The hanging span of a reeved rope as an ANCF body of changing length
/// (ancf/ancf_hoist_rope_body.h, without its own drum): the rope's path then
/// ends at the boom-head sheave, and the span's free length L (its payout
/// marker's x) is fed from this rope.
struct RopeSpan {
  bool present = false;
  double free_length = 0.0;  ///< L of the span at the start [m]
};

/// Tension-only rope along the path of markers P_0 .. P_m (m >= 1): P_0 where
/// the rope leaves the winch, P_1 .. P_{m-1} sheaves (the rope passes through
/// the marker origins: wrap length and sheave friction are not modelled),
/// P_m the hook block, hanging on `falls` = n parts of line from P_{m-1}.
/// With the segment lengths l_s = |P_{s+1} - P_s| and c_s = 1 (c_{m-1} = n),
/// the rope's stretched length is l = sum c_s l_s, its strain
/// eps = (l - L0) / L0 and the tension T = EA eps + beta EA d(eps)/dt when
/// eps > 0 and T > 0 (else the rope is slack: no force). Each segment pulls
/// its two markers together with c_s T.
///
/// Free length: without a drum L0(t) as Rope::FreeLength (constant, given
/// function or hoisting speed). With a drum turned by theta (the joint's
/// angle, positive paying out) L0 = free_length + R theta, and the rope
/// turns the drum with the generalized force (torque about the joint axis)
///   Q = R (EA eps (1 + eps / 2) + beta EA d(eps)/dt (1 + eps)),
/// derived from the rope's elastic energy V = EA L0 eps^2 / 2 and dissipation
/// function D = beta EA L0 (d eps/dt)^2 / 2 (so the model conserves energy
/// exactly: Q differs from T R by the strain, < 1 %). theta is unwrapped
/// from the joint angle by continuity between evaluations: the drum must turn
/// less than half a turn between two evaluations, and one ReevedRope with a
/// drum must not be evaluated from two threads at once. The rope has no mass.
/// Markers: P_0 .. P_m, then the drum joint's markers i and j. K and C are
/// exact on each side of the slack switch.
///
/// With a span (RopeSpan), P_m is the sheave the span hangs from, every path
/// segment counts once, and the n falls are the span's (an ANCF body whose
/// section is the n falls together): the rope is conserved between drum,
/// path and span, so the path's free length is
///   L0 = free_length + R theta - n (L - L_span(0)),
/// L the span's free length (the x of its payout marker, the last marker).
/// The path's tension then pulls the span's payout marker with the
/// generalized force -n EA eps (1 + eps / 2) - ... (the same as the drum's,
/// with -n for R): at rest the span's top tension (all falls) is n T. Paying
/// out more than the path holds (L0 <= 0) is an error naming the rope. With
/// L0 = free_length + psi, psi = R theta - n (L - L_span(0)), every tangent
/// below is taken through psi.
class ReevedRope final : public ForceElement {
 public:
  /// `path_markers` = m + 1 >= 2. `law` as for Rope; with a drum, free_length
  /// is L0 at theta = 0 and a hoisting speed or free-length function is an
  /// error. Throws InputError naming the rope for bad values, a drum radius
  /// <= 0 or a drum joint without an angle coordinate.
  ReevedRope(std::string name, RopeLaw law, int path_markers, RopeDrum drum = {}, RopeSpan span = {});
  const char* type() const override { return "rope"; }
  /// Not used: a ReevedRope acts on more than two markers.
  void Evaluate(const MarkerState&, const MarkerState&, double, ForceEval&) const override;
  void EvaluateMarkers(const MarkerState* const* m, double t, ForceEval& e) const override;
  /// Elastic energy EA L0 eps^2 / 2 when stretched, 0 when slack [J].
  double PotentialEnergyMarkers(const MarkerState* const* m, double t) const override;
  /// Number of path markers m + 1.
  int path_markers() const { return path_; }
  /// The drum (joint null without one).
  const RopeDrum& drum() const { return drum_; }
  /// The rope's properties (free_length: the path's at drum angle 0).
  const RopeLaw& law() const { return law_.law(); }
  /// The span (present false without one).
  const RopeSpan& span() const { return span_; }

 private:
  /// Free length L0 [m] and its rate [m/s]; with a drum also the drum axis
  /// a (world) and the relative angular velocity w_j - w_i of its markers.
  void FreeLength(const MarkerState* const* m, double t, double& L0, double& L0dot, Vec3& a, Vec3& wrel) const;
  /// Coefficient of path segment s in the stretched length.
  double SegmentFactor(int s) const { return s == path_ - 2 && !span_.present ? law_.law().falls : 1.0; }
  /// Index of the span's payout marker.
  int PayoutMarker() const { return path_ + (drum_.joint ? 2 : 0); }

  Rope law_;  // the rope's properties and, without a drum, its winch
  int path_;
  RopeDrum drum_;
  RopeSpan span_;
  mutable double theta_last_ = 0.0;  // unwrapped drum angle of the last evaluation
  mutable bool theta_set_ = false;
};

}  // namespace flexmb
