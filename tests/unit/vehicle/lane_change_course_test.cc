// Lane-change course geometry and the driver's limits, against hand values.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(Driver, NeutralInSection1RateLimitedInSection2) {
  const LaneChangeCourse c(LaneChangeCourseData{20, 20, 3.0, 3.5, 3.5});
  DriverData d;
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

}  // namespace
}  // namespace flexmb::vehicle
