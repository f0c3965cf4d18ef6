#pragma once
/// \file crane_motion.h
/// The crane's drive motions as driver functions of time (muparser
/// expressions in t, docs/model-file.md "Functions"): hoisting and slewing
/// as trapezoidal speed profiles (constant acceleration, constant speed,
/// constant deceleration), luffing as cosine ramps of the cylinder length.

#include <string>
#include <vector>

namespace flexmb::crane {

/// Radians per degree.
inline constexpr double kRadPerDeg = 0.017453292519943295;

/// One move of a drive: from `start` [s] the speed ramps in `ramp` [s] to
/// `speed` (signed, [m/s] of rope or [rad/s] of slew), holds it and ramps
/// down in `stop_ramp` [s]; it ends after `distance` (> 0, [m] or [rad]
/// covered in all) or starts ramping down at `until` [s] (< 0: not given).
struct TrapezoidMove {
  double start = 0, speed = 0, ramp = 0, stop_ramp = 0, distance = -1, until = -1;
  /// Time the speed starts to ramp down [s].
  double CruiseEnd() const;
  /// Signed distance covered at the end [m or rad].
  double Total() const;
  /// Signed distance covered at time t.
  double At(double t) const;
  /// Time the move ends [s].
  double End() const { return CruiseEnd() + stop_ramp; }
  /// The covered distance as a muparser expression in t.
  std::string Expression() const;
};

/// Checks a move: ramps > 0, speed != 0, the cruise not shorter than 0
/// (a distance long enough for the ramps); returns "" or the reason.
std::string CheckMove(const TrapezoidMove& m);

/// The sum of the moves' distances as an expression ("0" for none), scaled by `factor`.
std::string SumExpression(const std::vector<TrapezoidMove>& moves, double factor);

/// One luffing move: from `start` [s], in `duration` [s], the cylinder
/// length goes from `from` to `to` [m] along a cosine ramp.
struct CosineRamp {
  double start = 0, duration = 0, from = 0, to = 0;
  /// The change of length as a muparser expression in t (0 before, to - from after).
  std::string Expression() const;
};

/// A number as the shortest text that reads back to the same double.
std::string Num(double x);

}  // namespace flexmb::crane
