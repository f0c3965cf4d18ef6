#include "flexmb/durability/element_fatigue.h"

#include <algorithm>
#include <limits>

#include "flexmb/durability/rainflow.h"

namespace flexmb::durability {

double MinerDamage(const double* x, int n, const SnCurve& curve, const MeanStress& mean_stress,
                   std::vector<double>& reversals, std::vector<double>& stack) {
  ExtractReversals(x, n, reversals);
  double damage = 0.0;
  const bool plain = mean_stress.method == MeanStressCorrection::kNone;
  ForEachRainflowCycle(reversals.data(), static_cast<int>(reversals.size()), stack,
                       [&](double range, double mean, double count) {
                         const double s = plain ? range : EquivalentRange(range, mean, mean_stress);
                         damage += count * curve.Damage(s);
                       });
  return damage;
}

ElementResults AnalyzeElements(StressRecovery& rec, const FatigueOptions& opt) {
  if (opt.block < 1) throw InputError("element block size must be at least 1");
  CheckMeanStress(opt.mean_stress, "mean-stress correction");
  const int ne = rec.Elements(), np = rec.Points(), nt = rec.Instants();
  const double inf = std::numeric_limits<double>::infinity();
  ElementResults out;
  out.max_von_mises.assign(ne, 0.0);
  out.max_von_mises_instant.assign(ne, 0);
  out.max_von_mises_point.assign(ne, 0);
  out.min_signed_von_mises.assign(ne, inf);
  out.max_signed_von_mises.assign(ne, -inf);
  out.max_principal.assign(ne, -inf);
  out.min_principal.assign(ne, inf);
  out.range.assign(ne, 0.0);
  out.damage.assign(ne, 0.0);
  out.damage_point.assign(ne, 0);
  std::vector<double> reversals, stack;
  PointHistory h;
  for (int k0 = 0; k0 < ne; k0 += opt.block) {
    const int count = std::min(opt.block, ne - k0);
    rec.Recover(k0, count);
    for (int k = k0; k < k0 + count; ++k) {
      for (int p = 0; p < np; ++p) {
        // all measures over the instants, then their extremes
        rec.Histories(k, p, h);
        if (nt == 0) continue;
        Eigen::Index at = 0;
        const double vm = h.von_mises.maxCoeff(&at);
        if (vm > out.max_von_mises[k]) {
          out.max_von_mises[k] = vm;
          out.max_von_mises_instant[k] = static_cast<int>(at);
          out.max_von_mises_point[k] = p;
        }
        out.min_signed_von_mises[k] = std::min(out.min_signed_von_mises[k], h.signed_von_mises.minCoeff());
        out.max_signed_von_mises[k] = std::max(out.max_signed_von_mises[k], h.signed_von_mises.maxCoeff());
        out.max_principal[k] = std::max(out.max_principal[k], h.max_principal.maxCoeff());
        out.min_principal[k] = std::min(out.min_principal[k], h.min_principal.minCoeff());
        const Eigen::ArrayXd& counted = h.Get(opt.measure);
        out.range[k] = std::max(out.range[k], counted.maxCoeff() - counted.minCoeff());
        if (!opt.curve) continue;
        const double d = MinerDamage(h.Get(opt.measure).data(), nt, *opt.curve, opt.mean_stress, reversals, stack);
        if (d > out.damage[k]) {
          out.damage[k] = d;
          out.damage_point[k] = p;
        }
      }
    }
  }
  if (nt == 0)
    for (int k = 0; k < ne; ++k) {
      out.min_signed_von_mises[k] = out.max_signed_von_mises[k] = 0.0;
      out.max_principal[k] = out.min_principal[k] = 0.0;
    }
  return out;
}

}  // namespace flexmb::durability
