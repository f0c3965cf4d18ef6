#include "flexmb/math/running_integral.h"

#include <cmath>
#include <utility>

namespace flexmb {
namespace {

// 5-point Gauss-Legendre nodes and weights on [-1, 1]
constexpr double kGaussX[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                               0.9061798459386640};
constexpr double kGaussW[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                               0.2369268850561891};

// integral of f over [a, b]
double Gauss5(const ScalarFunction& f, double a, double b) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double s = 0.0;
  for (int k = 0; k < 5; ++k) s += kGaussW[k] * f.Value(c + h * kGaussX[k]);
  return h * s;
}

}  // namespace

RunningIntegral::RunningIntegral(std::shared_ptr<const ScalarFunction> f, double panel)
    : f_(std::move(f)), panel_(panel) {}

double RunningIntegral::Panel(long k) const {
  return Gauss5(*f_, static_cast<double>(k) * panel_, static_cast<double>(k + 1) * panel_);
}

double RunningIntegral::operator()(double t) const {
  const long k = static_cast<long>(std::floor(t / panel_));
  if (k < 0) {
    // before t = 0: the panels between t and 0, summed downwards
    double s = 0.0;
    for (long p = -1; p > k; --p) s -= Panel(p);
    return s - Gauss5(*f_, t, static_cast<double>(k + 1) * panel_);
  }
  if (k < reached_) {
    // behind the cache (a rejected step): the same sum again from 0
    reached_ = 0;
    sum_ = 0.0;
  }
  for (; reached_ < k; ++reached_) sum_ += Panel(reached_);
  const double a = static_cast<double>(k) * panel_;
  return sum_ + (t > a ? Gauss5(*f_, a, t) : 0.0);
}

}  // namespace flexmb
