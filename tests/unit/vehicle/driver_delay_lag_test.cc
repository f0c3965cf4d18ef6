// Driver's reaction delay and neuromuscular lag (issue 18), against their
// definitions: with a delay tau_d the steering-wheel angle follows the
// steering law's target tau_d later (zero-order hold of the sampled
// targets); with a lag tau_n it follows a held target u as the exact
// first-order response u (1 - exp(-t / tau_n)); both together compose.
// The target is made to jump by moving the vehicle sideways off the centre
// line of the course (the preview law's target for a lateral offset, read
// from a driver without delay or lag). The steering law's own wheelbase
// (VehicleView::steering_wheelbase) against the law's formula.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/vehicle/driver.h"

namespace flexmb::vehicle {
namespace {

// a vehicle in section 1 at 10 m/s, `y` to the side of the centre line
VehicleView DriverDelayView(double t, double y) {
  VehicleView v;
  v.t = t;
  v.x_front = 5.0;
  v.x_rear = 1.0;
  v.wheelbase = 4.0;
  v.speed = 10.0;
  v.y_rear = y;
  v.y_front = y;
  return v;
}

DriverData DriverDelayData() {
  DriverData d;
  d.max_wheel_rate = 1e6;  // no rate limit in the way
  d.hold_speed = false;
  return d;
}

// the steering-wheel angle over 0, 0.01, ..., 1 s with the vehicle moved
// sideways by 0.3 m at t = 0.2 s
std::vector<double> DriverDelayRun(const DriverData& d) {
  const LaneChangeCourse course(LaneChangeCourseData{});
  Driver drv(d, course, 10.0);
  std::vector<double> out;
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k;
    drv.Update(DriverDelayView(t, t >= 0.2 - 1e-12 ? 0.3 : 0.0));
    out.push_back(*drv.steering_wheel_angle());
  }
  return out;
}

TEST(DriverDelayLag, DelayShiftsTheResponseByTheDelay) {
  const std::vector<double> plain = DriverDelayRun(DriverDelayData());
  const double u = plain[50];
  ASSERT_GT(std::abs(u), 0.05);  // the offset asks for a real steer
  EXPECT_EQ(plain[19], 0.0);
  EXPECT_EQ(plain[20], u);
  DriverData d = DriverDelayData();
  d.reaction_delay = 0.155;  // the target of t = 0.2 s is seen from the sample at 0.36 s
  const std::vector<double> late = DriverDelayRun(d);
  for (int k = 0; k <= 100; ++k) EXPECT_EQ(late[k], k >= 36 ? u : 0.0) << "t = " << 0.01 * k;
}

TEST(DriverDelayLag, LagIsTheExactFirstOrderResponse) {
  const std::vector<double> plain = DriverDelayRun(DriverDelayData());
  const double u = plain[50];
  DriverData d = DriverDelayData();
  d.neuromuscular_lag = 0.1;
  const std::vector<double> lag = DriverDelayRun(d);
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k;
    EXPECT_NEAR(lag[k], t > 0.2 ? u * (1.0 - std::exp(-(t - 0.2) / 0.1)) : 0.0, 1e-12 * std::abs(u)) << t;
  }
  // both: the lag starts after the delay
  d.reaction_delay = 0.155;
  const std::vector<double> both = DriverDelayRun(d);
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k;
    EXPECT_NEAR(both[k], k > 36 ? u * (1.0 - std::exp(-(t - 0.36) / 0.1)) : 0.0, 1e-12 * std::abs(u)) << t;
  }
}

TEST(DriverDelayLag, LongDelayWithManySamplesAndBadValues) {
  // 2 s of delay over 1 ms samples: the history grows past its first room
  DriverData d = DriverDelayData();
  d.reaction_delay = 2.0005;  // half a sample off the grid: the sample 2.001 s before
  const LaneChangeCourse course(LaneChangeCourseData{});
  Driver drv(d, course, 10.0);
  Driver plain(DriverDelayData(), course, 10.0);
  std::vector<double> ref;
  for (int k = 0; k <= 3000; ++k) {
    const double t = 0.001 * k, y = 0.3 * std::sin(3.0 * t);
    plain.Update(DriverDelayView(t, y));
    ref.push_back(*plain.steering_wheel_angle());
    drv.Update(DriverDelayView(t, y));
    if (k >= 2001) EXPECT_EQ(*drv.steering_wheel_angle(), ref[static_cast<size_t>(k - 2001)]) << t;
  }
  for (const double bad : {-0.1, std::nan(""), std::numeric_limits<double>::infinity()}) {
    DriverData b = DriverDelayData();
    b.reaction_delay = bad;
    EXPECT_THROW(Driver(b, course, 10.0), InputError);
    b = DriverDelayData();
    b.neuromuscular_lag = bad;
    EXPECT_THROW(Driver(b, course, 10.0), InputError);
  }
}

// VehicleView::steering_wheelbase (a multi-axle truck's equivalent
// wheelbase) enters the steering law, road angle = atan((L_s + K v^2 / g)
// kappa), and not the preview point, which stays `wheelbase` ahead of the
// rear axle
TEST(DriverDelayLag, SteeringWheelbaseScalesTheLawNotThePreviewPoint) {
  const LaneChangeCourse course(LaneChangeCourseData{});
  const DriverData d = DriverDelayData();
  auto road = [&](double steering_wheelbase, double wheelbase) {
    Driver drv(d, course, 10.0);
    for (const double t : {0.0, 0.01}) {  // the first sample starts the driver's clock
      VehicleView v = DriverDelayView(t, 0.3);
      v.wheelbase = wheelbase;
      v.steering_wheelbase = steering_wheelbase;
      drv.Update(v);
    }
    return std::tan(*drv.steering_wheel_angle() / d.steering_ratio);
  };
  const double k = d.understeer_gradient * 100.0 / 9.81;
  const double base = road(0.0, 4.0);
  ASSERT_GT(std::abs(base), 1e-3);
  EXPECT_NEAR(road(6.0, 4.0) / base, (6.0 + k) / (4.0 + k), 1e-12);
  EXPECT_EQ(road(4.0, 4.0), base);
  EXPECT_GT(std::abs(road(6.0, 6.0) / base - (6.0 + k) / (4.0 + k)), 1e-3);  // the preview point moves too
}

}  // namespace
}  // namespace flexmb::vehicle
