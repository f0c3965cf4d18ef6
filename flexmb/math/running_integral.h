#pragma once
/// \file running_integral.h
/// The integral from 0 to t of a function of time, for time-stepping
/// callers that ask at (mostly) increasing t: e.g. a winch's paid-out
/// length from its hoisting speed.

#include <memory>

#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// I(t) = int_0^t f as a sum of 5-point Gauss-Legendre panels of fixed
/// width in time (exact for f polynomial of degree <= 9 on each panel). The
/// partial sums are cached, but the result does not depend on the order of
/// calls (a call behind the cache sums again from 0), so one object must
/// not be evaluated from two threads at once.
class RunningIntegral {
 public:
  /// Panel width of the winch's paid-out length (Rope, WinchDriver) [s].
  static constexpr double kWinchPanel = 0.01;
  /// f must not be null; panel [s] > 0.
  RunningIntegral(std::shared_ptr<const ScalarFunction> f, double panel);
  /// int_0^t f (negative for t < 0).
  double operator()(double t) const;
  /// The integrand.
  const ScalarFunction& function() const { return *f_; }

 private:
  double Panel(long k) const;

  std::shared_ptr<const ScalarFunction> f_;
  double panel_;
  mutable long reached_ = 0;       // panels 0..reached_-1 summed
  mutable double sum_ = 0.0;       // their integral
};

}  // namespace flexmb
