#include "flexmb/math/scalar_function.h"

#include <muParser.h>

#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb {

double ScalarFunction::IntegralFromZero(double x) const {
  const int n = 64;
  const double h = x / n;
  double s = Value(0.0) + Value(x);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4.0 : 2.0) * Value(k * h);
  return s * h / 3.0;
}

ViscousCoulombFunction::ViscousCoulombFunction(double viscous, double friction, double smoothing)
    : c_(viscous), f_(friction), s_(smoothing) {
  if (!(c_ >= 0) || !(f_ >= 0) || !(s_ > 0) || !std::isfinite(c_) || !std::isfinite(f_) || !std::isfinite(s_))
    throw InputError("a damper with friction needs damping >= 0, friction force >= 0 and a smoothing rate > 0");
}

double ViscousCoulombFunction::Value(double x) const { return c_ * x + f_ * std::tanh(x / s_); }

double ViscousCoulombFunction::Derivative(double x) const {
  const double t = std::tanh(x / s_);
  return c_ + f_ / s_ * (1.0 - t * t);
}

double ViscousCoulombFunction::SecondDerivative(double x) const {
  const double t = std::tanh(x / s_);
  return -2.0 * f_ / (s_ * s_) * t * (1.0 - t * t);
}

TableFunction::TableFunction(std::vector<double> x, std::vector<double> y,
                             Interpolation interpolation, bool extrapolate)
    : x_(std::move(x)), y_(std::move(y)), interpolation_(interpolation), extrapolate_(extrapolate) {
  if (x_.size() != y_.size()) throw InputError("table columns have different lengths");
  if (x_.size() < 2) throw InputError("table needs at least 2 rows");
  for (size_t i = 0; i < x_.size(); ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      throw InputError("table row " + std::to_string(i + 1) + " is not a finite number");
    if (i > 0 && !(x_[i] > x_[i - 1]))
      throw InputError("table abscissae must increase strictly (row " + std::to_string(i + 1) + ")");
  }
  const size_t n = x_.size();
  m2_.assign(n, 0.0);
  if (interpolation_ == Interpolation::kCubicSpline && n > 2) {
    // natural spline: tridiagonal system for the second derivatives (Thomas)
    std::vector<double> c(n, 0.0), d(n, 0.0);
    for (size_t i = 1; i + 1 < n; ++i) {
      const double h0 = x_[i] - x_[i - 1], h1 = x_[i + 1] - x_[i];
      const double a = h0 / 6.0, b = (h0 + h1) / 3.0, cc = h1 / 6.0;
      const double r = (y_[i + 1] - y_[i]) / h1 - (y_[i] - y_[i - 1]) / h0;
      const double denom = b - a * c[i - 1];
      c[i] = cc / denom;
      d[i] = (r - a * d[i - 1]) / denom;
    }
    for (size_t i = n - 2; i >= 1; --i) m2_[i] = d[i] - c[i] * m2_[i + 1];
  }
}

int TableFunction::Segment(double x) const {
  auto it = std::upper_bound(x_.begin(), x_.end(), x);
  int i = static_cast<int>(it - x_.begin()) - 1;
  return std::clamp(i, 0, static_cast<int>(x_.size()) - 2);
}

double TableFunction::Value(double x) const {
  const int n = static_cast<int>(x_.size());
  if (x <= x_.front() || x >= x_.back()) {
    const bool low = x <= x_.front();
    const double xe = low ? x_.front() : x_.back();
    const double ye = low ? y_.front() : y_.back();
    if (!extrapolate_) return ye;
    return ye + Derivative(low ? x_.front() : x_[n - 1]) * (x - xe);
  }
  const int i = Segment(x);
  const double h = x_[i + 1] - x_[i];
  const double a = (x_[i + 1] - x) / h, b = (x - x_[i]) / h;
  double v = a * y_[i] + b * y_[i + 1];
  if (interpolation_ == Interpolation::kCubicSpline)
    v += ((a * a * a - a) * m2_[i] + (b * b * b - b) * m2_[i + 1]) * h * h / 6.0;
  return v;
}

double TableFunction::Derivative(double x) const {
  if (!extrapolate_ && (x < x_.front() || x > x_.back())) return 0.0;
  const int i = Segment(x);
  const double xc = std::clamp(x, x_.front(), x_.back());
  const double h = x_[i + 1] - x_[i];
  double d = (y_[i + 1] - y_[i]) / h;
  if (interpolation_ == Interpolation::kCubicSpline) {
    const double a = (x_[i + 1] - xc) / h, b = (xc - x_[i]) / h;
    d += (-(3 * a * a - 1) * m2_[i] + (3 * b * b - 1) * m2_[i + 1]) * h / 6.0;
  }
  return d;
}

double TableFunction::SecondDerivative(double x) const {
  if (interpolation_ == Interpolation::kLinear) return 0.0;
  if (x < x_.front() || x > x_.back()) return 0.0;
  const int i = Segment(x);
  const double h = x_[i + 1] - x_[i];
  const double a = (x_[i + 1] - x) / h, b = (x - x_[i]) / h;
  return a * m2_[i] + b * m2_[i + 1];
}

struct ExpressionFunction::Impl {
  mu::Parser parser;
  mutable double var = 0.0;
  double Eval(double x) const {
    var = x;
    return const_cast<mu::Parser&>(parser).Eval();
  }
};

ExpressionFunction::ExpressionFunction(const std::string& expression, const std::string& variable)
    : impl_(std::make_unique<Impl>()) {
  try {
    impl_->parser.DefineVar(variable, &impl_->var);
    impl_->parser.DefineConst("pi", M_PI);
    impl_->parser.SetExpr(expression);
    impl_->Eval(0.0);  // parse now so errors surface at load time
  } catch (const mu::Parser::exception_type& e) {
    throw InputError("invalid expression '" + expression + "': " + e.GetMsg());
  }
}

ExpressionFunction::~ExpressionFunction() = default;

double ExpressionFunction::Value(double x) const { return impl_->Eval(x); }

double ExpressionFunction::Derivative(double x) const {
  const double h = 1e-5 * std::max(1.0, std::abs(x));
  return (impl_->Eval(x + h) - impl_->Eval(x - h)) / (2 * h);
}

double ExpressionFunction::SecondDerivative(double x) const {
  const double h = 1e-4 * std::max(1.0, std::abs(x));
  return (impl_->Eval(x + h) - 2 * impl_->Eval(x) + impl_->Eval(x - h)) / (h * h);
}

}  // namespace flexmb
