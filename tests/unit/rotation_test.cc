#include "flexmb/math/rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace flexmb {
namespace {

TEST(Rotation, ExpLogRoundTripAtAllAngles) {
  std::mt19937 rng(1);
  std::normal_distribution<double> n(0.0, 1.0);
  for (double angle : {0.0, 1e-12, 1e-6, 1e-4, 0.1, 1.0, 3.0, M_PI - 1e-9, M_PI}) {
    for (int k = 0; k < 20; ++k) {
      const Vec3 axis = Vec3(n(rng), n(rng), n(rng)).normalized();
      const Vec3 phi = angle * axis;
      const Vec3 back = LogQuat(ExpQuat(phi));
      if (angle < M_PI - 1e-6) {
        EXPECT_LT((back - phi).norm(), 1e-12 * std::max(1.0, angle)) << angle;
      } else {  // at pi the axis sign is ambiguous
        EXPECT_NEAR(back.norm(), angle, 1e-8);
        EXPECT_LT(back.cross(phi).norm(), 1e-6);
      }
      EXPECT_LT((ExpSO3(phi) - Eigen::AngleAxisd(angle, axis).toRotationMatrix()).norm(), 1e-14);
      EXPECT_LT((ExpSO3(LogSO3(ExpSO3(phi))) - ExpSO3(phi)).norm(), 1e-12);
    }
  }
}

TEST(Rotation, LargeRotationVectorsWrap) {
  // exp(phi) for |phi| > pi equals exp of the wrapped vector; log returns it
  const Vec3 axis = Vec3(1, 2, 3).normalized();
  const Vec3 back = LogQuat(ExpQuat(5.0 * axis));
  EXPECT_LT((back - (5.0 - 2 * M_PI) * axis).norm(), 1e-12);
}

TEST(Rotation, TangentOperatorMatchesFiniteDifference) {
  // d/dt exp(phi + t dphi) at t=0 = exp(phi) skew(T(phi) dphi)
  const Vec3 phi(0.3, -1.2, 2.0), dphi(0.7, 0.1, -0.4);
  const double h = 1e-6;
  const Mat3 R = ExpSO3(phi);
  const Mat3 dR = (ExpSO3(phi + h * dphi) - ExpSO3(phi - h * dphi)) / (2 * h);
  const Mat3 S = R.transpose() * dR;
  const Vec3 w(S(2, 1), S(0, 2), S(1, 0));
  EXPECT_LT((w - TangentSO3(phi) * dphi).norm(), 1e-8);
  // and at a tiny angle (Taylor branch)
  const Vec3 small(1e-6, -2e-6, 0.5e-6);
  EXPECT_LT((TangentSO3(small) - Mat3::Identity()).norm(), 1e-5);
}

TEST(Rotation, RollPitchYawRoundTrip) {
  for (const Vec3 rpy : {Vec3(0.1, 0.2, 0.3), Vec3(-2.0, 1.2, 3.0), Vec3(3.1, -1.5, -3.1)}) {
    EXPECT_LT((RollPitchYaw(FromRollPitchYaw(rpy)) - rpy).norm(), 1e-12);
  }
}

TEST(Rotation, SkewIsCrossProduct) {
  const Vec3 a(1, -2, 3), b(0.5, 4, -1);
  EXPECT_LT((Skew(a) * b - a.cross(b)).norm(), 1e-15);
}

}  // namespace
}  // namespace flexmb
