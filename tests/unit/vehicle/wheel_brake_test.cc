// Wheel brake: analytic torque (dry friction smoothed by tanh), its K and C
// against central finite differences, Newton's third law.
#include "flexmb/vehicle/wheel_brake.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flexmb/math/scalar_function.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb::vehicle {
namespace {

TEST(WheelBrake, TorqueOpposesRelativeSpin) {
  const WheelBrake b("b", std::make_shared<ConstantFunction>(3000.0), 0.5);
  MarkerState mi, mj;
  mi.R_WM = ExpSO3(Vec3(0.3, -0.2, 0.1));
  mj.R_WM = mi.R_WM;
  const Vec3 a = mi.R_WM.col(2);
  mi.w_WM = Vec3(0.1, 0.2, -0.3);
  mj.w_WM = mi.w_WM + 0.4 * a + Vec3(0.05, 0, 0).cross(a);
  const double omega = a.dot(mj.w_WM - mi.w_WM);
  const Vec12 w = testing::Wrench(b, mi, mj, 0.0);
  EXPECT_LT((w.segment<3>(9) + 3000.0 * std::tanh(omega / 0.5) * a).norm(), 1e-9);
  EXPECT_EQ(w.segment<3>(0).norm() + w.segment<3>(6).norm(), 0.0);
  // far above omega_s the full torque, at zero spin none
  mj.w_WM = mi.w_WM + 20.0 * a;
  EXPECT_NEAR(testing::Wrench(b, mi, mj, 0.0).segment<3>(9).dot(a), -3000.0, 1e-6);
  mj.w_WM = mi.w_WM;
  EXPECT_EQ(testing::Wrench(b, mi, mj, 0.0).norm(), 0.0);
  // a negative command does not drive
  const WheelBrake neg("n", std::make_shared<ConstantFunction>(-100.0), 0.5);
  mj.w_WM = mi.w_WM + 2.0 * a;
  EXPECT_EQ(testing::Wrench(neg, mi, mj, 0.0).norm(), 0.0);
  EXPECT_THROW(WheelBrake("x", nullptr, 0.5), InputError);
  EXPECT_THROW(WheelBrake("x", std::make_shared<ConstantFunction>(1.0), 0.0), InputError);
}

TEST(WheelBrake, TangentsMatchFiniteDifferences) {
  std::mt19937 rng(35);
  const WheelBrake b("b", std::make_shared<ConstantFunction>(2500.0), 0.7);
  for (int trial = 0; trial < 5; ++trial) {
    const MarkerState mi = testing::RandomMarker(rng), mj = testing::RandomMarker(rng);
    testing::ExpectTangents(b, mi, mj, 0.0);
    testing::ExpectThirdLaw(b, mi, mj, 0.0);
  }
}

}  // namespace
}  // namespace flexmb::vehicle
