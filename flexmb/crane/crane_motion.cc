#include "flexmb/crane/crane_motion.h"

#include <fmt/format.h>

#include <cmath>

namespace flexmb::crane {

std::string Num(double x) { return fmt::format("{}", x); }

double TrapezoidMove::CruiseEnd() const {
  if (until >= 0) return until;
  const double cruise = distance / std::abs(speed) - 0.5 * (ramp + stop_ramp);
  return start + ramp + cruise;
}

double TrapezoidMove::Total() const { return At(End()); }

double TrapezoidMove::At(double t) const {
  const double t1 = start + ramp, t2 = CruiseEnd(), t3 = t2 + stop_ramp;
  const double tt = std::min(t, t3);
  if (tt <= start) return 0.0;
  if (tt < t1) return 0.5 * speed / ramp * (tt - start) * (tt - start);
  const double s1 = 0.5 * speed * ramp;
  if (tt < t2) return s1 + speed * (tt - t1);
  const double s2 = s1 + speed * (t2 - t1);
  return s2 + speed * (tt - t2) - 0.5 * speed / stop_ramp * (tt - t2) * (tt - t2);
}

std::string TrapezoidMove::Expression() const {
  const double t1 = start + ramp, t2 = CruiseEnd(), t3 = t2 + stop_ramp;
  const double s1 = 0.5 * speed * ramp, s2 = s1 + speed * (t2 - t1);
  return fmt::format("(t < {0} ? 0 : (t < {1} ? {2}*(t-{0})^2 : (t < {3} ? {4} + {5}*(t-{1}) : "
                     "(t < {6} ? {7} + {5}*(t-{3}) - {8}*(t-{3})^2 : {9}))))",
                     Num(start), Num(t1), Num(0.5 * speed / ramp), Num(t2), Num(s1), Num(speed), Num(t3), Num(s2),
                     Num(0.5 * speed / stop_ramp), Num(Total()));
}

std::string CheckMove(const TrapezoidMove& m) {
  if (!(m.ramp > 0) || !(m.stop_ramp > 0)) return "the ramps must be positive [s] (a speed step is an infinite acceleration)";
  if (!(std::abs(m.speed) > 0)) return "'speed' must not be zero";
  if ((m.distance >= 0) == (m.until >= 0)) return "give either 'distance' or 'until'";
  if (m.distance >= 0 && !(m.distance > 0)) return "'distance' must be positive";
  if (m.CruiseEnd() < m.start + m.ramp - 1e-12)
    return m.distance >= 0 ? fmt::format("'distance' {} is shorter than the ramps take ({})", Num(m.distance),
                                         Num(0.5 * std::abs(m.speed) * (m.ramp + m.stop_ramp)))
                           : "'until' comes before the end of the ramp up";
  return "";
}

std::string SumExpression(const std::vector<TrapezoidMove>& moves, double factor) {
  if (moves.empty()) return "0";
  std::string s;
  for (const TrapezoidMove& m : moves) s += (s.empty() ? "" : " + ") + m.Expression();
  return factor == 1.0 ? s : Num(factor) + "*(" + s + ")";
}

std::string CosineRamp::Expression() const {
  const double h = 0.5 * (to - from);
  return fmt::format("(t < {0} ? 0 : (t < {1} ? {2}*(1-cos(pi*(t-{0})/{3})) : {4}))", Num(start),
                     Num(start + duration), Num(h), Num(duration), Num(to - from));
}

}  // namespace flexmb::crane
