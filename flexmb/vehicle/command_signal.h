#pragma once
/// \file command_signal.h
/// A controller output held constant over each time step (zero-order hold),
/// seen by force elements as a function of time.

#include <memory>

#include "flexmb/math/scalar_function.h"

namespace flexmb::vehicle {

/// f(t) = the value last set by the controller, scaled by `gain`. The value
/// is shared (std::shared_ptr) between the controller, which writes it
/// between accepted time steps, and the force elements, which read it;
/// within a step (all Newton iterations) it is constant, so the iteration
/// sees a smooth problem. Derivatives are zero (a held value).
class CommandSignal final : public ScalarFunction {
 public:
  /// `value` must not be null.
  CommandSignal(std::shared_ptr<const double> value, double gain) : value_(std::move(value)), gain_(gain) {}
  double Value(double) const override { return gain_ * *value_; }
  double Derivative(double) const override { return 0.0; }
  double SecondDerivative(double) const override { return 0.0; }

 private:
  std::shared_ptr<const double> value_;
  double gain_;
};

/// f(t) = gain * g(t) for a truck input g given as a function of time
/// (model-file vehicles: TruckInputs), its derivatives scaled alike.
class ScaledSignal final : public ScalarFunction {
 public:
  /// `f` must not be null.
  ScaledSignal(std::shared_ptr<const ScalarFunction> f, double gain) : f_(std::move(f)), gain_(gain) {}
  double Value(double t) const override { return gain_ * f_->Value(t); }
  double Derivative(double t) const override { return gain_ * f_->Derivative(t); }
  double SecondDerivative(double t) const override { return gain_ * f_->SecondDerivative(t); }

 private:
  std::shared_ptr<const ScalarFunction> f_;
  double gain_;
};

}  // namespace flexmb::vehicle
