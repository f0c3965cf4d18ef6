// The lane change of examples/truck_lane_change/truck.yaml at 30 and
// 55 km/h runs to the end of the test distance (L0 + 4 L2) * 1.2.
#include <gtest/gtest.h>

#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace {

void RunAt(double kmh) {
  LaneChangeOptions o;
  o.file = TruckFile();
  o.speed_kmh = kmh;
  const LaneChangeResult r = RunLaneChange(o);
  EXPECT_TRUE(r.completed) << r.message;
  EXPECT_GE(r.distance, (20.0 + 4 * 20.0) * 1.2);
  // it did change lanes: the lateral acceleration and steering were used
  EXPECT_GT(r.max_lateral_acceleration, 0.5);
  EXPECT_GT(r.max_steering_wheel_deg, 10.0);
  std::printf("%.0f km/h: %s, max a_y %.2f m/s^2, max roll %.2f deg, min margin %.3f m, RTF %.1f\n", kmh,
              r.passed ? "passed" : "failed", r.max_lateral_acceleration, r.max_roll_deg, r.min_corridor_margin,
              r.real_time_factor);
}

TEST(TruckValidation, LaneChangeAt30KmhRunsToTheEnd) { RunAt(30.0); }
TEST(TruckValidation, LaneChangeAt55KmhRunsToTheEnd) { RunAt(55.0); }

}  // namespace
}  // namespace flexmb::vehicle::testing
