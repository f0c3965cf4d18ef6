// Truck brakes (WheelBrake on every wheel, shared front/rear by
// brake_front_share): straight-line braking decelerates at the rate of the
// commanded torque, and a braked truck at rest does not creep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_brake_test {

struct BrakeSample {
  double t = 0, x = 0, speed = 0, vx = 0, min_kappa = 0, min_spin = 0, max_spin = 0;
};

// Runs the truck (rigid frame) with the steering-wheel angle held at zero
// from `speed` [m/s] with no drive torque and the total brake torque
// `brake` [N m] applied from t = t_brake on; samples every accepted step
// (speed: the frame's horizontal speed).
std::vector<BrakeSample> RunBraking(const TruckData& d, double speed, double brake, double t_brake, double t_end) {
  auto steer = std::make_shared<double>(0.0);
  auto torque = std::make_shared<double>(0.0);
  auto brake_cmd = std::make_shared<double>(0.0);
  Model m;
  m.solver.dt = 0.004;
  m.solver.dt_min = 1e-8;
  m.solver.newton_tol = 1e-8;
  const TruckHandles h = BuildTruck(d, speed, 0.8, steer, torque, m, brake_cmd);
  m.Finalize();
  Simulator sim(m);
  sim.Initialize();
  std::vector<BrakeSample> out;
  sim.Run(t_end, 0.0, [&](const State& st, const Workspace& ws) {
    const MarkerState& fr = ws.markers[h.frame_ref];
    BrakeSample s;
    s.t = st.t;
    s.x = fr.p_WM.x();
    s.speed = fr.v_WM.head<2>().norm();
    s.vx = fr.v_WM.x();
    s.min_kappa = 1e300;
    s.min_spin = 1e300;
    s.max_spin = -1e300;
    for (int k = 0; k < 4; ++k) {
      const MarkerState& w = ws.markers[h.wheel_marker[k]];
      TireContact c;
      static_cast<const Tire&>(*m.forces[h.tire_force[k]]).Wrench(w.p_WM, w.R_WM, w.v_WM, w.w_WM, &c);
      s.min_kappa = std::min(s.min_kappa, c.kappa);
      // spin relative to the axle (the frame's pitch rate is common to both)
      const double spin = (w.w_WM - fr.w_WM).dot(w.R_WM.col(2));
      s.min_spin = std::min(s.min_spin, spin);
      s.max_spin = std::max(s.max_spin, spin);
    }
    out.push_back(s);
    *brake_cmd = st.t >= t_brake - 1e-9 ? brake : 0.0;
  });
  return out;
}

// Total mass of the truck by hand from the data (parts, unsprung parts,
// arms, pitman arm, steering column, tire contact patches).
double TruckMass(const TruckData& d) {
  auto patch = [](const TireData& t) { return t.relaxation_length > 0 ? t.count * t.patch_mass : 0.0; };
  return d.frame.mass + d.cab.mass + d.powertrain.mass + d.cargo.mass + d.front_axle.mass + d.rear_axle.mass +
         2 * (d.knuckle.mass + d.front_wheel.mass + d.rear_wheel.mass + d.arm.mass) +
         (d.steering_linkage ? d.pitman_arm_mass : 0.0) + (d.steering_linkage && d.steering_column ? d.column_mass : 0.0) +
         2 * (patch(d.front_tire) + patch(d.rear_tire)) + (d.front.extra_arm_height > 0 ? kAxleHubMass : 0.0) +
         (d.rear.extra_arm_height > 0 ? kAxleHubMass : 0.0);
}

// Reference: a wheel with brake torque T, spin inertia I and the tire's
// longitudinal force F at the contact point (lever arm: the loaded radius
// rho = R0 - deflection) obeys I dOmega/dt = -T + F rho, and rolls with
// V = Re Omega (Re = R0 - deflection / 3, the effective rolling radius; the
// slip ratio stays constant in steady braking). With T_f, T_r on the front
// and rear axles, the deflections at the static loads and the rolling
// resistance f_r W,
//   a = (T_f / rho_f + T_r / rho_r + f_r W) / (m + 2 I_f / (rho_f Re_f) + 2 I_r / (rho_r Re_r)).
// (With T / Re instead of T / rho the force would be 2.7 % low: the brief's
// F = sum T / r holds with r the lever arm of the tire force.) The simulated
// deceleration is the slope of a least-squares line through the frame's
// speed over 1.5 s once the pitch transient has decayed. Tolerance 1 %: the
// load transfer changes the deflections by ~ +-5 mm (front up, rear down;
// +-1 % in rho, cancelling to ~0.2 % with the 40/60 torque split), the slip
// ratio's drift scales the wheels' spin-down (3 % of the effective mass) by
// ~1 %, the residual pitch oscillation shifts the fitted slope by < 0.3 %.
TEST(TruckBrakes, StraightLineDecelerationEqualsBrakeTorqueOverTireLever) {
  // parallel kinematic steer (a servo on each knuckle): with the linkage the
  // brake dive steers the truck through the drag link (README, "Brakes")
  TruckData d = LoadLaneChangeTruck(TruckFile());
  d.steering_linkage = false;
  const double g = 9.81, T = 16000.0, V0 = 15.0;
  const double m = TruckMass(d);
  const std::array<double, 2> loads = StaticAxleLoads(d, g);
  const auto defl = [&](const TireData& t, double axle_load) {
    return 0.5 * axle_load / (t.count * t.vertical_stiffness);
  };
  const double df = defl(d.front_tire, loads[0]), dr = defl(d.rear_tire, loads[1]);
  const double rho_f = d.front_tire.unloaded_radius - df, rho_r = d.rear_tire.unloaded_radius - dr;
  const double re_f = d.front_tire.unloaded_radius - d.front_tire.rolling_radius_factor * df;
  const double re_r = d.rear_tire.unloaded_radius - d.rear_tire.rolling_radius_factor * dr;
  const double tf = d.brake_front_share * T, tr = (1 - d.brake_front_share) * T;
  const double fr = d.front_tire.rolling_resistance * loads[0] + d.rear_tire.rolling_resistance * loads[1];
  const double a_ref = (tf / rho_f + tr / rho_r + fr) /
                       (m + 2 * d.front_wheel.inertia.y() / (rho_f * re_f) + 2 * d.rear_wheel.inertia.y() / (rho_r * re_r));
  const std::vector<BrakeSample> s = RunBraking(d, V0, T, 0.5, 3.5);
  double st = 0, sv = 0, stt = 0, stv = 0, n = 0, min_kappa = 0, min_spin = 1e300;
  for (const BrakeSample& r : s) {
    min_kappa = std::min(min_kappa, r.min_kappa);
    min_spin = std::min(min_spin, r.min_spin);
    if (r.t < 2.0) continue;
    st += r.t;
    sv += r.speed;
    stt += r.t * r.t;
    stv += r.t * r.speed;
    n += 1;
  }
  ASSERT_GT(n, 100);
  const double slope = (n * stv - st * sv) / (n * stt - st * st);
  EXPECT_NEAR(-slope, a_ref, 0.01 * a_ref) << "a_ref " << a_ref << " m " << m;
  EXPECT_GT(a_ref, 2.0);
  // no lockup: every wheel keeps rolling, slip ratios stay in the linear range
  EXPECT_GT(min_spin, 0.5 * (V0 - 3.5 * a_ref) / d.rear_tire.unloaded_radius);
  EXPECT_GT(min_kappa, -0.05);
}

// Braking from 3 m/s to a stop with the brake held. The brake torque fades
// through zero wheel spin (tanh over omega_s), so there is no chatter: the
// wheel spin never alternates in sign from one step to the next. At the
// stop the body's pitch springs back and rocks the truck back by about a
// centimetre (the regularised brake holds only while |omega| < ~omega_s,
// docs/design.md "Vehicle: brakes"); the rocking decays. Reference for the
// rest: a truck at rest on a flat road under no longitudinal load does not
// move: over the last 2 s the frame moves by less than 0.5 mm and at less
// than 2 mm/s.
TEST(TruckBrakes, BrakedTruckStopsWithoutChatterAndDoesNotCreep) {
  const TruckData d = LoadLaneChangeTruck(TruckFile());
  const std::vector<BrakeSample> s = RunBraking(d, 3.0, 16000.0, 0.0, 5.0);
  double t_stop = -1.0, x_end = s.back().x, x3 = 0.0, x_stop = 0.0, x_min = 1e300;
  int alternations = 0;
  for (size_t k = 0; k < s.size(); ++k) {
    if (t_stop < 0 && s[k].vx < 0.01) {
      t_stop = s[k].t;
      x_stop = s[k].x;
    }
    if (s[k].t <= 3.0) x3 = s[k].x;
    if (t_stop >= 0) x_min = std::min(x_min, s[k].x);
    // chatter: the spin of the slowest wheel flips sign at two steps in a row
    // with more than 1e-3 rad/s (0.5 mm/s of road speed)
    if (k >= 2 && t_stop >= 0 && s[k].min_spin * s[k - 1].min_spin < 0 && s[k - 1].min_spin * s[k - 2].min_spin < 0 &&
        std::abs(s[k - 1].min_spin) > 1e-3)
      ++alternations;
  }
  ASSERT_GT(t_stop, 0.0);
  EXPECT_LT(t_stop, 2.0);
  EXPECT_EQ(alternations, 0) << "chatter at standstill";
  EXPECT_LT(x_stop - x_min, 0.03) << "roll-back after the stop";
  EXPECT_LT(std::abs(x_end - x3), 5e-4);
  for (const BrakeSample& r : s) {
    if (r.t <= 3.0) continue;
    EXPECT_LT(std::abs(r.vx), 2e-3) << "t = " << r.t;
  }
}

}  // namespace truck_brake_test
}  // namespace flexmb::vehicle::testing
