#pragma once
// Comparison of sampled trajectories in the validation tests (the ANCF
// pendulum's tip path against a finer run or another strain measure).

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace flexmb::testing {

/// Largest distance between two paths sampled at the same instants [m];
/// NaN if a sample of either is missing (NaN).
inline double SampledPathDistance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double e = 0.0;
  for (size_t k = 0; k < a.size(); ++k) {
    const double d = (a[k] - b[k]).norm();
    if (!std::isfinite(d)) return NAN;
    e = std::max(e, d);
  }
  return e;
}

}  // namespace flexmb::testing
