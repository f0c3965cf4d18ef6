#pragma once
/// \file rainflow.h
/// Rainflow cycle counting after ASTM E1049-85 (reapproved 2017),
/// section 5.4.4: the signal is reduced to its peaks and valleys
/// (reversals), then ranges are counted with the three-point rule and a
/// moving starting point; what is left at the end (the residue) is counted
/// as half cycles, range by range, as step 6 of the standard says.

#include <cstddef>
#include <vector>

namespace flexmb::durability {

/// One counted range: a full cycle (count 1) or a half cycle (count 0.5).
struct RainflowCycle {
  double range = 0.0;  ///< |peak - valley| (units of the signal)
  double mean = 0.0;   ///< (peak + valley) / 2
  double count = 0.0;  ///< 1 or 0.5
};

/// Peaks and valleys of x[0..n): the first and last point and every point
/// where the signal turns; plateaus (equal consecutive values) count once.
/// `out` is cleared first; a constant signal gives one point.
void ExtractReversals(const double* x, int n, std::vector<double>& out);

/// Calls f(range, mean, count) for every cycle and half cycle of the
/// reversals r[0..n) (ExtractReversals), in the order of ASTM E1049-85
/// 5.4.4; `stack` is scratch (no allocation once it has grown).
template <class F>
void ForEachRainflowCycle(const double* r, int n, std::vector<double>& stack, F&& f) {
  stack.clear();
  for (int i = 0; i < n; ++i) {
    stack.push_back(r[i]);
    // step 2 to 5: compare the most recent range X with the previous Y
    while (stack.size() >= 3) {
      const std::size_t top = stack.size() - 1;
      const double x = stack[top] > stack[top - 1] ? stack[top] - stack[top - 1] : stack[top - 1] - stack[top];
      const double a = stack[top - 1], b = stack[top - 2];
      const double y = a > b ? a - b : b - a;
      if (x < y) break;
      if (stack.size() == 3) {
        // Y holds the starting point: half cycle, the start moves on
        f(y, 0.5 * (a + b), 0.5);
        stack.erase(stack.begin());
      } else {
        f(y, 0.5 * (a + b), 1.0);
        stack[top - 2] = stack[top];
        stack.resize(top - 1);
      }
    }
  }
  // step 6: the residue as half cycles
  for (std::size_t i = 1; i < stack.size(); ++i) {
    const double a = stack[i], b = stack[i - 1];
    f(a > b ? a - b : b - a, 0.5 * (a + b), 0.5);
  }
}

/// All cycles of the signal x[0..n) (reversals, then ForEachRainflowCycle),
/// in counting order, appended to `cycles` after clearing it.
void CountRainflow(const double* x, int n, std::vector<RainflowCycle>& cycles);

}  // namespace flexmb::durability
