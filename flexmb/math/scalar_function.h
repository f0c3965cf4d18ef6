#pragma once
/// \file scalar_function.h
/// Scalar functions of one variable, used for drivers (functions of time t [s])
/// and for tabulated force laws (functions of a deflection [m] or a rate
/// [m/s]). Every function gives its value and first two derivatives.

#include <memory>
#include <string>
#include <vector>

namespace flexmb {

/// A scalar function f(x) with derivatives. Implementations are immutable and
/// safe to evaluate from const code.
class ScalarFunction {
 public:
  virtual ~ScalarFunction() = default;
  /// f(x).
  virtual double Value(double x) const = 0;
  /// df/dx.
  virtual double Derivative(double x) const = 0;
  /// d2f/dx2.
  virtual double SecondDerivative(double x) const = 0;
  /// Integral of f from 0 to x (the potential of a tabulated force law), by
  /// composite Simpson's rule on 64 intervals; exact for polynomials up to
  /// cubic pieces that the 64 intervals resolve.
  virtual double IntegralFromZero(double x) const;
};

/// f(x) = c.
class ConstantFunction final : public ScalarFunction {
 public:
  explicit ConstantFunction(double c) : c_(c) {}
  double Value(double) const override { return c_; }
  double Derivative(double) const override { return 0.0; }
  double SecondDerivative(double) const override { return 0.0; }

 private:
  double c_;
};

/// f(x) = c x + F tanh(x / s): a viscous damper c in parallel with Coulomb
/// friction of force F, smoothed over the rate s (a rate of s gives 0.76 F);
/// e.g. the inter-leaf friction of a leaf spring as a force of its rate.
class ViscousCoulombFunction final : public ScalarFunction {
 public:
  /// Throws InputError unless c >= 0, F >= 0 and s > 0 (all finite).
  ViscousCoulombFunction(double viscous, double friction, double smoothing);
  double Value(double x) const override;
  double Derivative(double x) const override;
  double SecondDerivative(double x) const override;

 private:
  double c_, f_, s_;
};

/// Interpolated table (x_i, y_i) with strictly increasing x. Linear or natural
/// cubic spline interpolation; outside the table the end value is held
/// (`extrapolate` = false) or the end slope continued (`extrapolate` = true).
class TableFunction final : public ScalarFunction {
 public:
  enum class Interpolation { kLinear, kCubicSpline };
  /// Throws InputError if x is not strictly increasing, sizes differ, or
  /// there are fewer than 2 points.
  TableFunction(std::vector<double> x, std::vector<double> y, Interpolation interpolation,
                bool extrapolate);
  double Value(double x) const override;
  double Derivative(double x) const override;
  double SecondDerivative(double x) const override;

 private:
  int Segment(double x) const;
  std::vector<double> x_, y_, m2_;  // m2_: spline second derivatives
  Interpolation interpolation_;
  bool extrapolate_;
};

/// An expression in the variable `t` (or another name), parsed by muparser:
/// e.g. "2*pi*t", "0.1*sin(2*pi*t)", "t<1 ? t : 1". Derivatives by central
/// differences of step 1e-5 (scaled with |t|), accurate to about 1e-8.
class ExpressionFunction final : public ScalarFunction {
 public:
  /// Throws InputError with the parser's message if `expression` is invalid.
  ExpressionFunction(const std::string& expression, const std::string& variable = "t");
  ~ExpressionFunction() override;
  double Value(double x) const override;
  double Derivative(double x) const override;
  double SecondDerivative(double x) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace flexmb
