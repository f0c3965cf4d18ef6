// Driver's speed controller: a PI law whose positive output is the drive
// torque and whose negative output is the brake torque, each clamped to its
// limit with anti-windup; values computed by hand from the gains.
#include <gtest/gtest.h>

#include "flexmb/common/error.h"
#include "flexmb/vehicle/driver.h"

namespace flexmb::vehicle {
namespace {

TEST(DriverSpeedControl, BrakesAboveTargetAndDrivesBelow) {
  const LaneChangeCourse course(LaneChangeCourseData{});
  DriverData d;
  d.speed_kp = 1000.0;
  d.speed_ki = 100.0;
  d.max_drive_torque = 5000.0;
  d.max_brake_torque = 8000.0;
  Driver drv(d, course, 10.0);
  VehicleView v;
  v.speed = 12.0;
  drv.Update(v);  // first sample: no integration yet
  EXPECT_EQ(*drv.drive_torque(), 0.0);
  EXPECT_DOUBLE_EQ(*drv.brake_torque(), 2000.0);
  v.t = 0.5;
  drv.Update(v);  // integral -1 m: tau = -2000 - 100
  EXPECT_DOUBLE_EQ(*drv.brake_torque(), 2100.0);
  v.speed = 20.0;
  v.t = 1.0;
  drv.Update(v);  // -10000 - ... clamped to the brake limit
  EXPECT_DOUBLE_EQ(*drv.brake_torque(), 8000.0);
  EXPECT_EQ(*drv.drive_torque(), 0.0);
  // anti-windup: the integral was reset so that the clamp holds exactly
  v.speed = 9.0;
  v.t = 1.5;
  drv.Update(v);  // integral (-8000 + 10000) / 100 + 0.5 = 20.5: tau = 1000 + 2050
  EXPECT_EQ(*drv.brake_torque(), 0.0);
  EXPECT_DOUBLE_EQ(*drv.drive_torque(), 3050.0);
  d.max_brake_torque = -1.0;
  EXPECT_THROW(Driver(d, course, 10.0), InputError);
}

}  // namespace
}  // namespace flexmb::vehicle
