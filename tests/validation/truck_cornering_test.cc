// Steady-state cornering of the truck at a constant steer angle and three
// speeds: lateral acceleration equals v^2/R = v r at steady state, and the
// understeer and roll gradients fall in the range of heavy trucks
// (docs/validation.md, "Truck").
#include <gtest/gtest.h>

#include <cmath>

#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_cornering_test {

struct SteadyState {
  double speed = 0, yaw_rate = 0, ay = 0, roll = 0;
};

SteadyState Corner(const TruckData& d, double speed, double road_angle) {
  SteadyState a;
  int n = 0;
  RunTruck(d, speed, road_angle, 6.0, true, [&](const TruckSample& s) {
    if (s.t < 4.5) return;
    a.speed += s.speed;
    a.yaw_rate += s.yaw_rate;
    a.ay += s.lateral_acceleration;
    a.roll += s.roll;
    ++n;
  });
  a.speed /= n;
  a.yaw_rate /= n;
  a.ay /= n;
  a.roll /= n;
  return a;
}

TEST(TruckValidation, SteadyStateCornering) {
  const TruckData d = LoadLaneChangeTruck(TruckFile());
  const double g = 9.81, deg = 180 / M_PI, delta = 4.0 / deg;
  const SteadyState lo = Corner(d, 20 / 3.6, delta);
  const SteadyState hi = Corner(d, 40 / 3.6, delta);
  for (const SteadyState& s : {lo, hi}) {
    // a_y = v^2 / R with R = v / r: the kinematics of steady circular motion
    EXPECT_NEAR(s.ay, s.speed * s.yaw_rate, 0.01 * std::abs(s.ay));
    EXPECT_GT(s.yaw_rate, 0.0);
    // left turn: the body rolls to the right (positive roll about x)
    EXPECT_GT(s.roll, 0.0);
  }
  // constant-steer method: delta = L / R + K a_y / g
  const double K = -(Wheelbase(d) * (hi.yaw_rate / hi.speed - lo.yaw_rate / lo.speed)) / ((hi.ay - lo.ay) / g) * deg;
  const double roll_gradient = (hi.roll - lo.roll) / ((hi.ay - lo.ay) / g) * deg;
  std::printf("understeer gradient %.2f deg/g, roll gradient %.2f deg/g, a_y %.2f and %.2f m/s^2\n", K, roll_gradient,
              lo.ay, hi.ay);
  EXPECT_GT(K, 0.0);
  EXPECT_LT(K, 8.0);
  EXPECT_GT(roll_gradient, 2.0);
  EXPECT_LT(roll_gradient, 12.0);
}

}  // namespace truck_cornering_test
}  // namespace flexmb::vehicle::testing
