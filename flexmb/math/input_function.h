#pragma once
/// \file input_function.h
/// Inputs set by a script between steps: a function whose value is held in
/// a shared cell that a controller (the Python module) writes, e.g. a motor
/// target or an applied force closing a loop. In the model file an input is
/// {input: NAME, initial: VALUE}; a command-line run keeps it at its initial
/// value.

#include <map>
#include <memory>
#include <string>

#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// The value of one named input [the unit of the quantity it drives].
struct InputSignal {
  double value = 0.0;  ///< current value, held constant until set again
};

/// f(t) = signal value, derivatives zero (a step when the value is set).
class InputFunction final : public ScalarFunction {
 public:
  /// Throws InputError if `signal` is null.
  explicit InputFunction(std::shared_ptr<InputSignal> signal);
  double Value(double) const override { return signal_->value; }
  double Derivative(double) const override { return 0.0; }
  double SecondDerivative(double) const override { return 0.0; }

 private:
  std::shared_ptr<InputSignal> signal_;
};

/// The inputs of one model by name (several functions may share an input).
using InputTable = std::map<std::string, std::shared_ptr<InputSignal>>;

/// While alive, the inputs that model files create on this thread are
/// registered in `table` (RegisterInput); scopes nest, the innermost wins.
class InputScope {
 public:
  explicit InputScope(InputTable& table);
  ~InputScope();
  InputScope(const InputScope&) = delete;
  InputScope& operator=(const InputScope&) = delete;

 private:
  InputTable* previous_;
};

/// The signal named `name`: the one already in the current scope's table
/// (its value unchanged), else a new one with value `initial`, registered
/// in the current scope's table if there is one.
std::shared_ptr<InputSignal> RegisterInput(const std::string& name, double initial);

}  // namespace flexmb
