#pragma once
/// \file element_fatigue.h
/// Per-element results of a run over all instants and recovery points
/// (durability/stress_recovery.h): extremes of von Mises, signed von Mises
/// and the principal stresses with where and when, the range of the
/// counted stress measure, and the Palmgren-Miner damage of its rainflow
/// cycles (durability/rainflow.h) on an S-N curve (durability/sn_curve.h).
/// The element's damage is the largest over its recovery points.

#include <optional>
#include <vector>

#include "flexmb/durability/sn_curve.h"
#include "flexmb/durability/stress_recovery.h"

namespace flexmb::durability {

/// What to count and how.
struct FatigueOptions {
  /// The counted stress measure (docs/design.md, "Durability": the
  /// principal stress of largest magnitude, with its sign, by default).
  StressMeasure measure = StressMeasure::kMaxAbsPrincipal;
  std::optional<SnCurve> curve;  ///< no curve: no damage (extremes only)
  MeanStress mean_stress;        ///< mean-stress correction of each cycle
  int block = 64;                ///< elements per recovery batch
};

/// Results per element, index k as in the table's `elements`.
struct ElementResults {
  std::vector<double> max_von_mises;         ///< [Pa]
  std::vector<int> max_von_mises_instant;    ///< instant of max_von_mises
  std::vector<int> max_von_mises_point;      ///< recovery point of max_von_mises
  std::vector<double> min_signed_von_mises;  ///< [Pa]
  std::vector<double> max_signed_von_mises;  ///< [Pa]
  std::vector<double> max_principal;         ///< largest max principal over the run [Pa]
  std::vector<double> min_principal;         ///< smallest min principal over the run [Pa]
  std::vector<double> range;                 ///< max - min of the counted measure, largest over the points [Pa]
  std::vector<double> damage;                ///< Miner sum of the run, largest over the points (0 without curve)
  std::vector<int> damage_point;             ///< recovery point of `damage`
};

/// Analyses every element of `recovery`'s table in batches of
/// options.block elements. Throws InputError if block < 1 or the
/// mean-stress settings are invalid.
ElementResults AnalyzeElements(StressRecovery& recovery, const FatigueOptions& options);

/// Palmgren-Miner damage of the signal x[0..n): sum of count / N(S_eq)
/// over its rainflow cycles, S_eq the mean-stress corrected range.
/// `reversals` and `stack` are scratch.
double MinerDamage(const double* x, int n, const SnCurve& curve, const MeanStress& mean_stress,
                   std::vector<double>& reversals, std::vector<double>& stack);

}  // namespace flexmb::durability
