// Truck at rest: the axle loads after settling equal the lever-rule
// distribution of the parts' weights, computed here by hand from the masses
// and positions of examples/truck_lane_change/truck.yaml.
#include <gtest/gtest.h>

#include <cmath>

#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_static_test {

TEST(TruckValidation, StaticAxleLoadsEqualMassDistribution) {
  const TruckData d = LoadLaneChangeTruck(TruckFile());
  const double g = 9.81, L = Wheelbase(d);
  // every part's weight on the axles by the lever rule about the rear axle
  struct Part {
    double m, x;
  };
  const Part parts[] = {{d.frame.mass, d.frame.cg.x()},
                        {d.cab.mass, d.cab.cg.x()},
                        {d.powertrain.mass, d.powertrain.cg.x()},
                        {d.cargo.mass, d.cargo.cg.x()},
                        {d.axles[0].axle.mass + 2 * d.knuckle.mass + 2 * d.axles[0].wheel.mass, 0.0},
                        {d.axles[1].axle.mass + 2 * d.axles[1].wheel.mass, -L},
                        // tire contact-patch bodies (relaxation length), on the axles
                        {2.0 * d.axles[0].tire.count * d.axles[0].tire.patch_mass * (d.axles[0].tire.relaxation_length > 0), 0.0},
                        {2.0 * d.axles[1].tire.count * d.axles[1].tire.patch_mass * (d.axles[1].tire.relaxation_length > 0), -L},
                        // hubs of the axles with the additional arm
                        {d.axles[0].suspension.extra_arm_height > 0 ? kAxleHubMass : 0.0, 0.0},
                        {d.axles[1].suspension.extra_arm_height > 0 ? kAxleHubMass : 0.0, -L},
                        {d.arm.mass, 0.5 * d.axles[0].suspension.arm_length},
                        {d.arm.mass, -L + 0.5 * d.axles[1].suspension.arm_length},
                        {d.steering_linkage ? d.pitman_arm_mass : 0.0, d.drag_link_length},
                        // steering column: centre of mass half-way up the column leaning rearwards
                        {d.steering_linkage && d.steering_column ? d.column_mass : 0.0,
                         d.drag_link_length - 0.5 * d.column_length * std::sin(d.column_inclination)}};
  double W = 0, M = 0;
  for (const Part& p : parts) {
    W += p.m * g;
    M += p.m * g * (p.x + L);
  }
  const double front = M / L, rear = W - front;
  TruckSample last;
  RunTruck(d, 0.0, 0.0, 2.0, false, [&](const TruckSample& s) { last = s; });
  EXPECT_NEAR(last.axle_load[0] + last.axle_load[1], W, 1e-3 * W);
  EXPECT_NEAR(last.axle_load[0], front, 2e-3 * front);
  EXPECT_NEAR(last.axle_load[1], rear, 2e-3 * rear);
  // about 12 t gross, front axle share 30-40 % (4x2 truck)
  EXPECT_NEAR(W / g, 11900.0, 300.0);
  EXPECT_GT(front / W, 0.30);
  EXPECT_LT(front / W, 0.40);
}

}  // namespace truck_static_test
}  // namespace flexmb::vehicle::testing
