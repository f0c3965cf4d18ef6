// Tire data shared by the tire tests: one 11R22.5 truck tire
// (examples/truck_lane_change/tire_11r22_5.yaml, rounded), each test
// adding what it varies.
#pragma once

#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {

/// One 11R22.5 tire: R0 0.527 m, 900 kN/m, 1.5 kN s/m, Fz0 25 kN, lateral
/// pure-slip coefficients (pdy1 1, pey1 -0.2, pky1 8.5, pky2 2).
inline TireData Tire11R22() {
  TireData d;
  d.unloaded_radius = 0.527;
  d.vertical_stiffness = 9e5;
  d.vertical_damping = 1.5e3;
  d.nominal_load = 25e3;
  d.pdy1 = 1.0;
  d.pey1 = -0.2;
  d.pky1 = 8.5;
  d.pky2 = 2.0;
  return d;
}

/// Tire11R22 for the transient rigs: no rolling resistance and trail, slip
/// regularisation speed 0.1 m/s (sqrt(Vx^2 + v_low^2) = Vx to 5e-5 at 10
/// m/s), lateral relaxation length sigma [m].
inline TireData Tire11R22Rig(double sigma) {
  TireData d = Tire11R22();
  d.rolling_resistance = 0.0;
  d.trail = 0.0;
  d.low_speed = 0.1;
  d.relaxation_length = sigma;
  return d;
}

}  // namespace flexmb::vehicle
