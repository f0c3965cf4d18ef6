#pragma once
/// \file running_integral.h
/// The integral from 0 to t of a function of time, for time-stepping
/// callers that ask at (mostly) increasing t: e.g. a winch's paid-out
/// length from its hoisting speed.

#include <memory>
#include <optional>
#include <utility>

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

/// Free length L(t) of a rope paid out by a winch, and its rate: a given
/// function of time, else the length at t = 0 minus the integral of the
/// hoisting speed (hauled in positive; RunningIntegral on panels of
/// kWinchPanel), else constant. Shared by the rope force and the winch
/// driver; not thread-safe (the integral's cache).
class PaidOutLength {
 public:
  /// From a law with the fields free_length, free_length_function and
  /// hoist_speed (RopeLaw, WinchLaw).
  template <class Law>
  explicit PaidOutLength(const Law& law) : free_length_(law.free_length), function_(law.free_length_function) {
    if (law.hoist_speed) hoisted_.emplace(law.hoist_speed, RunningIntegral::kWinchPanel);
  }
  /// L(t) [m] and dL/dt [m/s], unchecked.
  void operator()(double t, double& L, double& Ldot) const {
    if (function_) {
      L = function_->Value(t);
      Ldot = function_->Derivative(t);
    } else if (hoisted_) {
      L = free_length_ - (*hoisted_)(t);
      Ldot = -hoisted_->function().Value(t);
    } else {
      L = free_length_;
      Ldot = 0.0;
    }
  }

 private:
  double free_length_;
  std::shared_ptr<const ScalarFunction> function_;
  std::optional<RunningIntegral> hoisted_;
};

}  // namespace flexmb
