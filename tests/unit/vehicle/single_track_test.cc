// The dynamic single-track model's frequency response (single_track.h)
// against its limits: at f -> 0 the steady-state yaw-rate gain v / (L + K
// v^2 / g) / ratio with K from the same model (trail included); a_y = v r
// there; without relaxation and trail the classical second-order response
// (Mitschke and Wallentowitz, ch. 30: the characteristic polynomial
// m I v s^2 + (m (a^2 C_f + b^2 C_r) + I (C_f + C_r)) s + ..., checked here by
// the yaw rate's transfer function evaluated by hand); the steady state of
// two axles against the classical formulas and of a tandem (three axles)
// against its equivalent wheelbase and a direct solve of the two balances.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include <Eigen/Dense>

#include "flexmb/vehicle/single_track.h"

namespace flexmb::vehicle {
namespace {

SingleTrack SingleTrackExample() {
  SingleTrack s;
  s.axles = {{0.0, 39000.0, 3.0e5, 0.045, 0.55, 1.0}, {-4.2, 78000.0, 9.0e5, 0.045, 0.5, 0.0}};
  s.steering_ratio = 20.0;
  s.mass = 117000.0 / 9.81;
  s.yaw_inertia = 58000.0;
  s.SetSteadyState(9.81);
  return s;
}

TEST(SingleTrack, TwoAxlesTheClassicalWheelbaseAndUndersteerGradient) {
  const SingleTrack s = SingleTrackExample();
  // the forces balance about the points t behind the axles: F_f (a - t) = F_r (b + t)
  const double W = 117000.0, a = 4.2 * 78000.0 / W, b = 4.2 * 39000.0 / W, arm = 4.2;
  const double K = W * (b + 0.045) / arm / 3.0e5 - W * (a - 0.045) / arm / 9.0e5;
  EXPECT_NEAR(s.wheelbase, 4.2, 1e-14);
  EXPECT_NEAR(s.understeer_gradient, K, 1e-14);
  EXPECT_NEAR(s.CentreOfMassX(), -a, 1e-14);
}

// A tandem (6x4): three axles, no trail. At low speed the turn needs the
// equivalent wheelbase L_eq = L + (1 + C_t / C_1) C_2 C_3 d^2 / (C_t^2 L)
// (L to the rear axles' stiffness-weighted centre, d their spacing, C_t =
// C_2 + C_3: the tandem scrubs and resists the turn; derived from the two
// balances at m v^2 / R -> 0, docs/validation.md); at speed the steady
// state of the two balances solved as a 2 x 2 system here.
TEST(SingleTrack, TandemEquivalentWheelbaseAndSteadyTurn) {
  SingleTrack s;
  const double c1 = 3.0e5, c2 = 5.0e5, c3 = 4.0e5, x2 = -3.6, x3 = -4.9;
  s.axles = {{0.0, 60000.0, c1, 0.0, 0.0, 1.0}, {x2, 85000.0, c2, 0.0, 0.0, 0.0}, {x3, 80000.0, c3, 0.0, 0.0, 0.0}};
  s.mass = 225000.0 / 9.81;
  s.steering_ratio = 20.0;
  s.SetSteadyState(9.81);
  const double ct = c2 + c3, L = -(c2 * x2 + c3 * x3) / ct, d = x2 - x3;
  EXPECT_NEAR(s.wheelbase, L + (1 + ct / c1) * c2 * c3 * d * d / (ct * ct * L), 1e-12);
  EXPECT_GT(s.wheelbase, L + 0.1);
  for (const double v : {5.0, 15.0, 25.0}) {
    // unknowns (beta, rho = 1 / R) for delta = 1: sum F = m v^2 rho, sum F p = 0
    const double xc = s.CentreOfMassX();
    Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
    Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
    for (const SingleTrack::Axle& ax : s.axles) {
      const double p = ax.x - xc, c = ax.cornering_stiffness, delta = ax.steer;
      // F = c (delta - beta - p rho)
      A(0, 0) += c;
      A(0, 1) += c * p;
      rhs(0) += c * delta;
      A(1, 0) += c * p;
      A(1, 1) += c * p * p;
      rhs(1) += c * p * delta;
    }
    A(0, 1) += s.mass * v * v;
    const Eigen::Vector2d x = A.partialPivLu().solve(rhs);
    const double gain = v * x(1) / s.steering_ratio;  // yaw rate per steering-wheel angle
    EXPECT_NEAR(s.YawRateGain(v), gain, 1e-12 * gain) << v;
    EXPECT_NEAR(s.FrequencyResponse(1e-7, v, 0.0).yaw_rate.real(), gain, 1e-9 * gain) << v;
  }
}

TEST(SingleTrack, FrequencyResponseTendsToTheSteadyGain) {
  const SingleTrack s = SingleTrackExample();
  for (const double v : {10.0, 15.0, 25.0}) {
    const SingleTrack::Response r = s.FrequencyResponse(1e-7, v, -1.0);
    EXPECT_NEAR(r.yaw_rate.real(), s.YawRateGain(v), 1e-9 * s.YawRateGain(v)) << v;
    EXPECT_NEAR(std::arg(r.yaw_rate), 0.0, 1e-5);
    EXPECT_NEAR(std::abs(r.lateral_acceleration), v * s.YawRateGain(v), 1e-6 * v * s.YawRateGain(v));
  }
}

TEST(SingleTrack, WithoutLagAndTrailTheClassicalTransferFunction) {
  SingleTrack s = SingleTrackExample();
  for (SingleTrack::Axle& a : s.axles) a.relaxation_length = a.trail = 0.0;
  const double m = s.mass, I = s.yaw_inertia, cf = s.axles[0].cornering_stiffness, cr = s.axles[1].cornering_stiffness;
  const double a = 4.2 * 78000.0 / 117000.0, b = 4.2 - a, v = 15.0, L = 4.2;
  for (const double f : {0.1, 0.5, 1.0, 2.0}) {
    const std::complex<double> sj(0.0, 2 * M_PI * f);
    // r / delta = C_f (m a v s + C_r L) / (m I v s^2 + (m (a^2 C_f + b^2 C_r) + I (C_f + C_r)) s
    //             + (C_f C_r L^2 / v - m v (a C_f - b C_r)))
    const std::complex<double> num = cf * (m * a * v * sj + cr * L);
    const std::complex<double> den = m * I * v * sj * sj + (m * (a * a * cf + b * b * cr) + I * (cf + cr)) * sj +
                                     (cf * cr * L * L / v - m * v * (a * cf - b * cr));
    const std::complex<double> ref = num / den / s.steering_ratio;
    const std::complex<double> got = s.FrequencyResponse(f, v, 0.0).yaw_rate;
    EXPECT_NEAR(std::abs(got - ref), 0.0, 1e-12 * std::abs(ref)) << f;
  }
}

// Two steered axles (8x4 front) and one rear axle: with the second axle's
// steer ratio of the Ackermann geometry, r = (x_2 - x_3) / (x_1 - x_3), every
// axle rolls without slip at low speed about a centre on the rear axle's
// line, so the equivalent wheelbase is the distance to the rear axle.
TEST(SingleTrack, AckermannSecondSteeredAxleTurnsAboutTheRearAxle) {
  SingleTrack s;
  const double x2 = -1.9, x3 = -6.0;
  s.axles = {{0.0, 60000.0, 3.0e5, 0.0, 0.0, 1.0},
             {x2, 60000.0, 3.2e5, 0.0, 0.0, (x2 - x3) / (0.0 - x3)},
             {x3, 150000.0, 8.0e5, 0.0, 0.0, 0.0}};
  s.mass = 270000.0 / 9.81;
  s.steering_ratio = 20.0;
  s.SetSteadyState(9.81);
  EXPECT_NEAR(s.wheelbase, -x3, 1e-12);
  // without the second axle's steering it would turn wider
  s.axles[1].steer = 0.0;
  s.SetSteadyState(9.81);
  EXPECT_GT(s.wheelbase, -x3 + 0.3);
}

}  // namespace
}  // namespace flexmb::vehicle
