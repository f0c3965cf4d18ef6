#pragma once
/// \file sn_curve.h
/// S-N curves in stress RANGES (as EN 1993-1-9 gives them) and the
/// mean-stress corrections of a rainflow cycle. A curve is a Basquin line
/// N = N_ref (S_ref / S)^m1 with an optional knee at N_knee, below which
/// either the slope is m2 (to a cut-off at N_cut, below which cycles do no
/// damage) or there is an endurance limit (no damage below the knee), or a
/// table of (N, S) points interpolated linearly in log-log space (no damage
/// below the last point's range, the first segment extended above).

#include <string>
#include <vector>

#include "flexmb/common/error.h"

namespace flexmb::durability {

/// How the cycles' mean stress changes the range that enters the S-N curve.
enum class MeanStressCorrection {
  kNone,     ///< the range as counted
  kGoodman,  ///< S_a,eq = S_a / (1 - S_m / S_u) for S_m > 0; S_a for S_m <= 0
  kFkm,      ///< FKM guideline, four regions with the mean-stress sensitivity M
};

/// An S-N curve (see the file comment). Ranges in Pa (model stress units).
class SnCurve {
 public:
  /// Basquin curve through (n_ref, s_ref) with slope m1 (> 0); knee at
  /// n_knee (0: no knee, one slope to the cut-off); m2 > 0 the slope below
  /// the knee, m2 = 0 an endurance limit at the knee; cut-off at n_cut (0:
  /// none; with m2 > 0 it must exceed n_knee). Throws InputError naming
  /// `context` for a non-positive or non-finite value or n_cut <= n_knee.
  static SnCurve Basquin(double s_ref, double n_ref, double m1, double n_knee, double m2, double n_cut,
                         const ErrorContext& context = {});

  /// The EN 1993-1-9 curve of detail category `category` (the range at 2e6
  /// cycles in MPa: 160, 140, 125, 112, 100, 90, 80, 71, 63, 56, 50, 45, 40,
  /// 36): m1 = 3 to N_D = 5e6, m2 = 5 to the cut-off N_L = 1e8 (direct
  /// stress ranges, partial factors 1). Throws InputError for another
  /// category.
  static SnCurve Eurocode(int category);

  /// A named preset: "en1993-NNN" (Eurocode(NNN)). Throws InputError
  /// naming the preset and listing the valid names otherwise.
  static SnCurve Preset(const std::string& name);

  /// A table of points (cycles N_i, range S_i) with N strictly increasing
  /// and S strictly decreasing (a monotonic curve), at least two points.
  /// Throws InputError for a point that breaks this, naming context.file and
  /// the line lines[i] of the point (lines may be empty: point numbers).
  static SnCurve Table(const std::vector<double>& cycles, const std::vector<double>& ranges,
                       const ErrorContext& context = {}, const std::vector<int>& lines = {});

  /// Reads a table from a CSV file of lines "N, range_Pa" ('#' comments and
  /// a header line of text allowed) and checks it as Table. Throws
  /// InputError naming the file and line.
  static SnCurve ReadCsv(const std::string& path);

  /// Cycles to failure at the range s [Pa]: +infinity below the cut-off or
  /// endurance limit (and for s <= 0).
  double Cycles(double s) const;
  /// 1 / Cycles(s): the damage of one cycle of range s.
  double Damage(double s) const;
  /// Description for reports, e.g. "EN 1993-1-9 detail category 71".
  const std::string& name() const { return name_; }

 private:
  // log-log segments: for S in [s_lo, s_hi): N = n_at_hi * (s_hi / S)^m
  struct Segment {
    double s_lo, s_hi, n_at_hi, m;
  };
  std::vector<Segment> segments_;  // descending ranges; the first has s_hi = +inf
  std::string name_;
};

/// Mean-stress correction settings.
struct MeanStress {
  MeanStressCorrection method = MeanStressCorrection::kNone;
  double ultimate = 0.0;     ///< Goodman: ultimate tensile strength S_u [Pa]
  double sensitivity = 0.0;  ///< FKM: mean-stress sensitivity M (e.g. 0.35e-3 Rm[MPa] - 0.1 for steel)
};

/// The range of the fully reversed cycle (R = -1) equivalent to a cycle of
/// range `range` and mean `mean` [Pa]: 2 S_a,eq with S_a = range / 2.
/// Goodman: S_a / (1 - S_m / S_u) for S_m > 0 (+infinity for S_m >= S_u),
/// S_a for S_m <= 0. FKM (Forschungskuratorium Maschinenbau guideline,
/// with R = (S_m - S_a) / (S_m + S_a)): region I (R > 1) S_a (1 - M);
/// region II (R <= 0) S_a + M S_m; region III (0 < R < 0.5)
/// (S_a + M S_m / 3) (1 + M) / (1 + M / 3); region IV (R >= 0.5) 3 S_a (1 +
/// M)^2 / (3 + M).
double EquivalentRange(double range, double mean, const MeanStress& correction);

/// Checks the settings: Goodman needs S_u > 0, FKM 0 <= M < 1. Throws
/// InputError naming `what`.
void CheckMeanStress(const MeanStress& correction, const std::string& what);

}  // namespace flexmb::durability
