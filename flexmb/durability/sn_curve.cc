#include "flexmb/durability/sn_curve.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "flexmb/common/number_table.h"

namespace flexmb::durability {
namespace {

constexpr int kSnEurocodeCategories[] = {160, 140, 125, 112, 100, 90, 80, 71, 63, 56, 50, 45, 40, 36};

bool SnPositive(double v) { return std::isfinite(v) && v > 0; }

std::string SnNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

SnCurve SnCurve::Basquin(double s_ref, double n_ref, double m1, double n_knee, double m2, double n_cut,
                         const ErrorContext& context) {
  if (!SnPositive(s_ref) || !SnPositive(n_ref) || !SnPositive(m1))
    throw InputError("S-N curve: reference range, reference cycles and slope m1 must be positive numbers", context);
  if (!(std::isfinite(n_knee) && n_knee >= 0) || !(std::isfinite(m2) && m2 >= 0) ||
      !(std::isfinite(n_cut) && n_cut >= 0))
    throw InputError("S-N curve: knee cycles, slope m2 and cut-off cycles must be numbers >= 0", context);
  SnCurve c;
  c.name_ = "Basquin S_ref " + SnNumber(s_ref) + " at N " + SnNumber(n_ref) + ", m1 " + SnNumber(m1);
  const auto range_at = [&](double n) { return s_ref * std::pow(n_ref / n, 1.0 / m1); };
  if (n_knee == 0) {
    c.segments_.push_back({n_cut > 0 ? range_at(n_cut) : 0.0, s_ref, n_ref, m1});
    return c;
  }
  const double s_knee = range_at(n_knee);
  c.segments_.push_back({s_knee, s_ref, n_ref, m1});
  if (m2 == 0) return c;
  if (n_cut > 0 && n_cut <= n_knee)
    throw InputError("S-N curve: cut-off cycles " + SnNumber(n_cut) + " not above the knee " + SnNumber(n_knee),
                     context);
  const double s_cut = n_cut > 0 ? s_knee * std::pow(n_knee / n_cut, 1.0 / m2) : 0.0;
  c.segments_.push_back({s_cut, s_knee, n_knee, m2});
  return c;
}

SnCurve SnCurve::Eurocode(int category) {
  for (int k : kSnEurocodeCategories) {
    if (k != category) continue;
    SnCurve c = Basquin(k * 1e6, 2e6, 3.0, 5e6, 5.0, 1e8);
    c.name_ = "EN 1993-1-9 detail category " + std::to_string(k);
    return c;
  }
  throw InputError("EN 1993-1-9 has no detail category " + std::to_string(category) +
                   " (160 140 125 112 100 90 80 71 63 56 50 45 40 36)");
}

SnCurve SnCurve::Preset(const std::string& name) {
  const std::string prefix = "en1993-";
  if (name.compare(0, prefix.size(), prefix) == 0) {
    const std::string number = name.substr(prefix.size());
    char* end = nullptr;
    const long k = std::strtol(number.c_str(), &end, 10);
    if (!number.empty() && *end == '\0') {
      for (int c : kSnEurocodeCategories)
        if (c == k) return Eurocode(c);
    }
  }
  throw InputError("unknown S-N curve preset '" + name +
                   "' (presets: en1993-160 en1993-140 en1993-125 en1993-112 en1993-100 en1993-90 en1993-80 "
                   "en1993-71 en1993-63 en1993-56 en1993-50 en1993-45 en1993-40 en1993-36)");
}

SnCurve SnCurve::Table(const std::vector<double>& cycles, const std::vector<double>& ranges,
                       const ErrorContext& context, const std::vector<int>& lines) {
  const auto where = [&](size_t i) {
    ErrorContext c = context;
    if (i < lines.size()) c.line = lines[i];
    else c.entity = "S-N point " + std::to_string(i + 1);
    return c;
  };
  if (cycles.size() != ranges.size() || cycles.size() < 2)
    throw InputError("S-N table needs at least two points (cycles, range)", context);
  for (size_t i = 0; i < cycles.size(); ++i) {
    if (!SnPositive(cycles[i]) || !SnPositive(ranges[i]))
      throw InputError("S-N point: cycles and range must be positive numbers", where(i));
    if (i > 0 && !(cycles[i] > cycles[i - 1]))
      throw InputError("S-N curve not monotonic: cycles " + SnNumber(cycles[i]) + " not above the previous point's " +
                           SnNumber(cycles[i - 1]), where(i));
    if (i > 0 && !(ranges[i] < ranges[i - 1]))
      throw InputError("S-N curve not monotonic: range " + SnNumber(ranges[i]) + " not below the previous point's " +
                           SnNumber(ranges[i - 1]) + " at more cycles", where(i));
  }
  SnCurve c;
  c.name_ = "S-N table of " + std::to_string(cycles.size()) + " points";
  if (!context.file.empty()) c.name_ += " (" + context.file + ")";
  for (size_t i = 0; i + 1 < cycles.size(); ++i) {
    const double m = std::log(cycles[i + 1] / cycles[i]) / std::log(ranges[i] / ranges[i + 1]);
    c.segments_.push_back({ranges[i + 1], ranges[i], cycles[i], m});
  }
  return c;
}

SnCurve SnCurve::ReadCsv(const std::string& path) {
  const NumberTable table = ReadNumberTable(path, 2, "S-N file", "cycles, range");
  std::vector<double> n, s;
  for (const std::vector<double>& row : table.rows) {
    n.push_back(row[0]);
    s.push_back(row[1]);
  }
  return Table(n, s, {path, 0, ""}, table.lines);
}

double SnCurve::Cycles(double s) const {
  if (!(s > 0)) return std::numeric_limits<double>::infinity();
  for (const Segment& g : segments_)
    if (s >= g.s_lo) return g.n_at_hi * std::pow(g.s_hi / s, g.m);
  return std::numeric_limits<double>::infinity();
}

double SnCurve::Damage(double s) const {
  if (!(s > 0)) return 0.0;
  for (const Segment& g : segments_)
    if (s >= g.s_lo) return std::pow(s / g.s_hi, g.m) / g.n_at_hi;
  return 0.0;
}

double EquivalentRange(double range, double mean, const MeanStress& c) {
  const double sa = 0.5 * range;
  switch (c.method) {
    case MeanStressCorrection::kNone: return range;
    case MeanStressCorrection::kGoodman:
      if (mean <= 0) return range;
      if (mean >= c.ultimate) return std::numeric_limits<double>::infinity();
      return 2.0 * sa / (1.0 - mean / c.ultimate);
    case MeanStressCorrection::kFkm: {
      const double m = c.sensitivity;
      if (mean <= -sa) return 2.0 * sa * (1.0 - m);           // region I: R > 1 (or -inf)
      if (mean <= sa) return 2.0 * (sa + m * mean);           // region II: R <= 0
      if (mean < 3.0 * sa) return 2.0 * (sa + m * mean / 3.0) * (1.0 + m) / (1.0 + m / 3.0);  // III
      return 2.0 * 3.0 * sa * (1.0 + m) * (1.0 + m) / (3.0 + m);  // region IV: R >= 0.5
    }
  }
  return range;
}

void CheckMeanStress(const MeanStress& c, const std::string& what) {
  if (c.method == MeanStressCorrection::kGoodman && !SnPositive(c.ultimate))
    throw InputError("Goodman mean-stress correction needs an ultimate strength > 0", {"", 0, what});
  if (c.method == MeanStressCorrection::kFkm && !(std::isfinite(c.sensitivity) && c.sensitivity >= 0 && c.sensitivity < 1))
    throw InputError("FKM mean-stress correction needs a sensitivity M in [0, 1)", {"", 0, what});
}

}  // namespace flexmb::durability
