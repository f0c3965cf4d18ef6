// Lane-change course geometry and the driver's limits, against hand values.
#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/vehicle/driver.h"
#include "flexmb/vehicle/lane_change_course.h"

namespace flexmb::vehicle {
namespace {

TEST(LaneChangeCourse, CentreLineMarginAndDistance) {
  const LaneChangeCourse c(LaneChangeCourseData{20, 20, 3.0, 3.5, 3.5});
  EXPECT_EQ(c.Section(-1), 1);
  EXPECT_EQ(c.Section(25), 2);
  EXPECT_EQ(c.Section(40), 3);
  EXPECT_DOUBLE_EQ(c.CentreLine(10), 0.0);
  EXPECT_NEAR(c.CentreLine(30), 1.75, 1e-12);  // half way: half the offset
  EXPECT_DOUBLE_EQ(c.CentreLine(50), 3.5);
  EXPECT_NEAR(c.Margin(10, 1.0), 0.5, 1e-12);     // section 1: |y| <= 1.5
  EXPECT_NEAR(c.Margin(10, -2.0), -0.5, 1e-12);
  EXPECT_NEAR(c.Margin(50, 3.0), 1.25, 1e-12);    // section 3: 1.75 .. 5.25
  EXPECT_NEAR(c.Margin(30, -1.0), 0.5, 1e-12);    // section 2: -1.5 .. 5.25
  EXPECT_DOUBLE_EQ(c.TestDistance(), (20 + 4 * 20) * 1.2);
}

TEST(LaneChangeCourse, StartShiftsTheWholeCourse) {
  // the same course beginning at world x = 15 (a run-up of 15 m)
  const LaneChangeCourse c0(LaneChangeCourseData{20, 20, 3.0, 3.5, 3.5});
  const LaneChangeCourse c(LaneChangeCourseData{20, 20, 3.0, 3.5, 3.5, 15.0});
  for (double x : {-30.0, -1.0, 0.0, 14.9, 19.99, 25.0, 31.0, 39.99, 40.0, 100.0}) {
    EXPECT_EQ(c.Section(x + 15), c0.Section(x)) << x;
    EXPECT_EQ(c.CentreLine(x + 15), c0.CentreLine(x)) << x;
    for (double y : {-2.0, 0.3, 2.0, 4.0}) EXPECT_EQ(c.Margin(x + 15, y), c0.Margin(x, y)) << x << " " << y;
  }
  EXPECT_EQ(c.Section(10), 1);  // the run-up counts as section 1
  EXPECT_DOUBLE_EQ(c.CentreLine(45), 1.75);
  EXPECT_DOUBLE_EQ(c.TestDistance(), c0.TestDistance());
  LaneChangeCourseData bad{20, 20, 3.0, 3.5, 3.5, std::nan("")};
  EXPECT_THROW(LaneChangeCourse{bad}, InputError);
}

TEST(Driver, NeutralInSection1RateLimitedInSection2) {
  const LaneChangeCourse c(LaneChangeCourseData{20, 20, 3.0, 3.5, 3.5});
  DriverData d;
  d.steering_law = SteeringLaw::kPurePursuit;
  d.max_wheel_rate = 10.0;
  Driver drv(d, c, 15.0);
  drv.Update(VehicleView{0.0, 5.0, 0.8, 0.0, 0.0, 15.0, 4.2});
  drv.Update(VehicleView{0.01, 5.15, 0.95, 0.0, 0.0, 15.0, 4.2});
  EXPECT_EQ(*drv.steering_wheel_angle(), 0.0);
  // in section 2 the target is a left turn; the wheel moves by at most rate * dt
  drv.Update(VehicleView{0.02, 21.0, 16.8, 0.0, 0.0, 15.0, 4.2});
  EXPECT_NEAR(*drv.steering_wheel_angle(), 10.0 * 0.01, 1e-12);
  // speed controller: below the target speed it drives
  EXPECT_GT(*drv.drive_torque(), -1e-9);
  drv.Update(VehicleView{0.03, 21.1, 16.9, 0.0, 0.0, 14.0, 4.2});
  EXPECT_GT(*drv.drive_torque(), 0.0);
}

// the preview law's road-wheel angle after one unlimited sample
double DriverPreviewRoadAngle(const DriverData& d, const LaneChangeCourse& c, VehicleView v) {
  Driver drv(d, c, v.speed);
  drv.Update(v);
  v.t += 0.01;
  drv.Update(v);
  return drv.road_wheel_angle();
}

TEST(Driver, PreviewLawSteersTheArcThroughThePreviewPoint) {
  const LaneChangeCourse c(LaneChangeCourseData{20, 20, 3.0, 3.5, 3.5});
  DriverData d;
  d.max_wheel_rate = 1e6;
  d.lag_time = 0.0;
  d.preview_time = 1.0;
  d.min_preview = 8.0;
  const double L = 4.2, V = 15.0;
  // front axle at x = 10 in section 1: the preview point (15 m ahead) is in
  // the lane change, the driver already steers left
  const VehicleView v{0.0, 10.0, 10.0 - L, 0.0, 0.0, V, L, 0.0, 0.0};
  const double road = DriverPreviewRoadAngle(d, c, v);
  ASSERT_GT(road, 0.0);
  // the arc of curvature kappa from the rear axle, tangent to x, passes
  // through the centre-line point 15 m ahead of the front axle
  const double kappa = std::tan(road) / (L + d.understeer_gradient * V * V / 9.81);
  const double xp = 25.0, yp = c.CentreLine(xp);
  const double radius = 1.0 / kappa;
  EXPECT_NEAR(std::hypot(xp - v.x_rear, yp - radius), radius, 1e-9 * radius);
  // the first version's law and steer_in_section1: false hold the wheel
  DriverData late = d;
  late.steer_in_section1 = false;
  EXPECT_EQ(DriverPreviewRoadAngle(late, c, v), 0.0);
  late.steering_law = SteeringLaw::kPurePursuit;
  EXPECT_EQ(DriverPreviewRoadAngle(late, c, v), 0.0);
  // on the new lane's centre line, heading along it, not turning: straight
  EXPECT_NEAR(DriverPreviewRoadAngle(d, c, VehicleView{0.0, 60.0, 60.0 - L, 3.5, 0.0, V, L, 3.5, 0.0}), 0.0, 1e-15);
  // with the same prediction horizon, a left yaw rate (predicted heading
  // turned to the left) reduces the left steering demand
  DriverData lag = d;
  lag.lag_time = 0.3;
  VehicleView turning = v;
  turning.yaw_rate = 0.1;
  EXPECT_LT(DriverPreviewRoadAngle(lag, c, turning), DriverPreviewRoadAngle(lag, c, v));
}

}  // namespace
}  // namespace flexmb::vehicle
