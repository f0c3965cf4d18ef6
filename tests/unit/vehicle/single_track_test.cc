// The dynamic single-track model's frequency response (single_track.h)
// against its limits: at f -> 0 the steady-state yaw-rate gain v / (L + K
// v^2 / g) / ratio with K from the same model (trail included); a_y = v r
// there; without relaxation and trail the classical second-order response
// (Mitschke and Wallentowitz, ch. 30: the characteristic polynomial
// m I v s^2 + (m (a^2 C_f + b^2 C_r) + I (C_f + C_r)) s + ..., checked here by
// the yaw rate's transfer function evaluated by hand).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "flexmb/vehicle/single_track.h"

namespace flexmb::vehicle {
namespace {

SingleTrack SingleTrackExample() {
  SingleTrack s;
  s.wheelbase = 4.2;
  s.axle_load[0] = 39000.0;
  s.axle_load[1] = 78000.0;
  s.cornering_stiffness[0] = 3.0e5;
  s.cornering_stiffness[1] = 9.0e5;
  s.trail[0] = 0.045;
  s.trail[1] = 0.045;
  s.steering_ratio = 20.0;
  s.mass = 117000.0 / 9.81;
  s.yaw_inertia = 58000.0;
  s.relaxation_length[0] = 0.55;
  s.relaxation_length[1] = 0.5;
  const double W = 117000.0, a = 4.2 * 78000.0 / W, b = 4.2 * 39000.0 / W, arm = 4.2;
  s.understeer_gradient = W * (b + 0.045) / arm / 3.0e5 - W * (a - 0.045) / arm / 9.0e5;
  return s;
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
  s.relaxation_length[0] = s.relaxation_length[1] = 0.0;
  s.trail[0] = s.trail[1] = 0.0;
  const double m = s.mass, I = s.yaw_inertia, cf = s.cornering_stiffness[0], cr = s.cornering_stiffness[1];
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

}  // namespace
}  // namespace flexmb::vehicle
