#include "flexmb/durability/rainflow.h"

namespace flexmb::durability {

void ExtractReversals(const double* x, int n, std::vector<double>& out) {
  out.clear();
  if (n <= 0) return;
  out.push_back(x[0]);
  int direction = 0;  // +1 rising, -1 falling, 0 not yet known
  for (int i = 1; i < n; ++i) {
    const double last = out.back();
    if (x[i] == last) continue;
    const int d = x[i] > last ? 1 : -1;
    if (d == direction) {
      out.back() = x[i];  // the same slope goes on: the candidate moves
    } else {
      out.push_back(x[i]);  // a turn: the previous point is a reversal
      direction = d;
    }
  }
}

void CountRainflow(const double* x, int n, std::vector<RainflowCycle>& cycles) {
  cycles.clear();
  std::vector<double> reversals, stack;
  ExtractReversals(x, n, reversals);
  ForEachRainflowCycle(reversals.data(), static_cast<int>(reversals.size()), stack,
                       [&cycles](double range, double mean, double count) {
                         cycles.push_back({range, mean, count});
                       });
}

}  // namespace flexmb::durability
