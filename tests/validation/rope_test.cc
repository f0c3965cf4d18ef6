// The hoisting rope (flexmb/forces/rope.h) in the engine, against closed
// forms: the static stretch of a hook block on n falls, the period of a
// payload swinging on the elastic rope, the peak rope force of a lift-off
// at constant hoisting speed, a load dropped into the slack rope until it
// snaps taut, and the damping ratio from the damping time. Derivations and
// measured values: docs/validation.md, "Hoisting rope".

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "example_model.h"
#include "flexmb/solver/statics.h"

namespace flexmb::validation {
namespace rope_test {

constexpr double kRopeG = 9.81;

/// A hook block `hook` (mass m, origin = rope marker `top`) hanging from the
/// ground marker `head` at the origin on a rope with the given extra keys.
std::string RopeModel(double m, const std::string& hook_position, const std::string& rope_keys,
                      const std::string& extra) {
  return "gravity: [0, 0, -9.81]\n"
         "ground:\n"
         "  markers:\n"
         "    - {name: head, position: [0, 0, 0]}\n"
         "bodies:\n"
         "  - name: hook\n"
         "    mass: " + ExactNumber(m) + "\n"
         "    inertia: [10, 10, 10]\n"
         "    position: " + hook_position + "\n"
         "    markers:\n"
         "      - {name: top, position: [0, 0, 0]}\n"
         "forces:\n"
         "  - {name: rope, type: rope, i: ground.head, j: hook.top, " + rope_keys + "}\n" + extra;
}

/// Height z of the hook's origin.
double HookZ(const Model& model, const State& s) {
  return s.q(model.bodies[model.FindBody("hook")]->q_offset + 2);
}

// Static stretch: n T = m g and T = EA (n l - L0) / L0 give exactly
// l = L0 / n + m g L0 / (n^2 EA): the hook sits m g L0 / (n^2 EA) below the
// unstretched position L0 / n (the rope law is linear in l at fixed L0).
TEST(Rope, StaticStretchOnFalls) {
  const double m = 2000.0, EA = 5e7, L0 = 40.0;
  for (int n : {1, 4}) {
    // start 1 mm below the unstretched position (taut), on a vertical slide
    const double z0 = -(L0 / n + 1e-3);
    auto model = LoadModelString(
        RopeModel(m, "[0, 0, " + ExactNumber(z0) + "]",
                  "axial_stiffness: 5e7, free_length: 40, falls: " + std::to_string(n),
                  "joints:\n  - {name: slide, type: prismatic, i: ground.head, j: hook.top}\n"),
        "static.yaml");
    Simulator sim(*model);
    sim.Initialize();
    sim.SettleStatics();
    const double drop = -HookZ(*model, sim.state()) - L0 / n;
    const double ref = m * kRopeG * L0 / (n * n * EA);
    std::printf("rope static, %d falls: stretch %.9e m, closed form %.9e m\n", n, drop, ref);
    EXPECT_NEAR(drop, ref, 1e-4 * ref) << n << " falls";
    // the hook carries m g
    sim.RefreshWorkspace();
    const Vec12& w = sim.workspace().forces[0].wrench;
    EXPECT_NEAR(w(8), m * kRopeG, 1e-6 * m * kRopeG);
  }
}

// Small swing of a payload on the elastic rope: linearized about the
// hanging equilibrium (T = m g, l = L = L0 (1 + m g / EA)) the lateral
// stiffness is T / L = m g / L, so the period is 2 pi sqrt(L / g) with the
// stretched length L. Amplitude 0.02 rad: the large-amplitude correction
// theta0^2 / 16 = 2.5e-5 is below the tolerance; the stretch mode
// (sqrt(EA / (L0 m)) = 10 rad/s) is ten times faster than the swing.
TEST(Rope, PendulumPeriodWithStretchedLength) {
  const double m = 100.0, EA = 1e5, L0 = 10.0, theta0 = 0.02;
  const double L = L0 * (1.0 + m * kRopeG / EA);
  const double x0 = L * std::sin(theta0), z0 = -L * std::cos(theta0);
  auto model = LoadModelString(
      RopeModel(m, "[" + ExactNumber(x0) + ", 0, " + ExactNumber(z0) + "]",
                "axial_stiffness: 1e5, free_length: 10", "solver: {t_end: 30, dt: 0.005}\n"),
      "pendulum.yaml");
  Simulator sim(*model);
  sim.Initialize();
  const int qx = model->bodies[model->FindBody("hook")]->q_offset;
  double t_prev = 0.0, x_prev = x0, t_first = -1.0, t_last = -1.0;
  int crossings = 0;
  sim.Run(26.0, 0.0, [&](const State& s, const Workspace&) {
    const double x = s.q(qx);
    if (s.t > 0.0 && x_prev > 0.0 && x <= 0.0) {
      // downward zero crossing, interpolated linearly
      const double tc = t_prev + (s.t - t_prev) * x_prev / (x_prev - x);
      if (t_first < 0.0) t_first = tc;
      t_last = tc;
      ++crossings;
    }
    t_prev = s.t;
    x_prev = x;
  });
  ASSERT_GE(crossings, 4);
  const double period = (t_last - t_first) / (crossings - 1);
  const double ref = 2.0 * std::numbers::pi * std::sqrt(L / kRopeG);
  const double unstretched = 2.0 * std::numbers::pi * std::sqrt(L0 / kRopeG);
  std::printf("rope pendulum: period %.6f s, 2 pi sqrt(L/g) %.6f s (L = %.5f m), unstretched %.6f s\n",
              period, ref, L, unstretched);
  EXPECT_NEAR(period, ref, 1e-3 * ref);
  EXPECT_EQ(sim.stats().rejected, 0);
}

// Lift-off at constant hoisting speed v, started at the instant of lift-off
// (flexmb has no unilateral contact to rest the load on): the rope carries
// m g, the load is at rest, the winch reels in v. The hook on n falls is a
// mass on a spring k = n^2 EA / L0 whose end moves at v / n; with z the
// hook's rise, m z'' = k (v t / n - z), z(0) = z'(0) = 0, so
// z = v/n (t - sin(w t) / w), w = sqrt(k / m), and the hook force
// n T = m g + (v / n) sqrt(k m) sin(w t): the peak m g + v sqrt(EA m / L0),
// the dynamic factor phi = 1 + v sqrt(EA / (L0 m)) / g. The free length
// shrinks by v pi / (2 w) = 0.033 m (0.08 % of L0) until the peak, which
// the closed form neglects.
TEST(Rope, LiftOffPeakForce) {
  const double m = 5000.0, EA = 4e7, L0 = 40.0, v = 0.6;
  const int n = 2;
  const double l0 = L0 / n + m * kRopeG * L0 / (n * n * EA);
  auto model = LoadModelString(
      RopeModel(m, "[0, 0, " + ExactNumber(-l0) + "]",
                "axial_stiffness: 4e7, free_length: 40, falls: 2, hoist_speed: 0.6",
                "solver: {t_end: 0.3, dt: 2.5e-4}\n"),
      "liftoff.yaml");
  Simulator sim(*model);
  sim.Initialize();
  double peak = 0.0;
  sim.Run(0.15, 0.0,
          [&](const State&, const Workspace& ws) { peak = std::max(peak, ws.forces[0].wrench(8)); });
  const double ref = m * kRopeG + v * std::sqrt(EA * m / L0);
  // the same hook with the shrinking free length L0 - v t kept:
  // m z'' = n EA (n (l0 - z) - L0 + v t) / (L0 - v t) - m g, by RK4
  auto hook_force = [&](double t, double z) {
    return n * EA * (n * (l0 - z) - (L0 - v * t)) / (L0 - v * t);
  };
  auto accel = [&](double t, double z) { return hook_force(t, z) / m - kRopeG; };
  double z = 0.0, zd = 0.0, rk4_peak = 0.0;
  const double h = 1e-6;
  for (int k = 0; k < 150000; ++k) {
    const double t = k * h;
    const double a1 = accel(t, z), z2 = z + 0.5 * h * zd, v2 = zd + 0.5 * h * a1;
    const double a2 = accel(t + 0.5 * h, z2), z3 = z + 0.5 * h * v2, v3 = zd + 0.5 * h * a2;
    const double a3 = accel(t + 0.5 * h, z3), z4 = z + h * v3, v4 = zd + h * a3;
    const double a4 = accel(t + h, z4);
    z += h / 6.0 * (zd + 2.0 * v2 + 2.0 * v3 + v4);
    zd += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    rk4_peak = std::max(rk4_peak, hook_force(t + h, z));
  }
  std::printf("rope lift-off: peak hook force %.1f N, closed form %.1f N (phi = %.4f), with the "
              "shrinking free length (RK4) %.1f N\n", peak, ref, ref / (m * kRopeG), rk4_peak);
  EXPECT_NEAR(peak, ref, 1e-2 * ref);
  EXPECT_NEAR(peak, rk4_peak, 1e-4 * rk4_peak);
}

// A load dropped into the slack rope: it falls freely by h until the rope
// becomes taut, then stretches it by x. Energy (no damping, constant L0):
// m g (h + x) = k x^2 / 2, k = EA / L0, so the peak force
// F = k x = m g (1 + sqrt(1 + 2 k h / (m g))).
double DropPeak(double dt, long& rejected) {
  const double L0 = 20.0, h = 0.5;
  auto model = LoadModelString(
      RopeModel(1000.0, "[0, 0, " + ExactNumber(-(L0 - h)) + "]",
                "axial_stiffness: 2e7, free_length: 20",
                "solver: {t_end: 0.5, dt: " + ExactNumber(dt) + "}\n"),
      "drop.yaml");
  Simulator sim(*model);
  sim.Initialize();
  double peak = 0.0;
  sim.Run(0.5, 0.0,
          [&](const State&, const Workspace& ws) { peak = std::max(peak, ws.forces[0].wrench(8)); });
  rejected = sim.stats().rejected;
  return peak;
}

TEST(Rope, SlackThenSnapTaut) {
  const double m = 1000.0, k = 2e7 / 20.0, h = 0.5;
  const double ref = m * kRopeG * (1.0 + std::sqrt(1.0 + 2.0 * k * h / (m * kRopeG)));
  long rejected_coarse = 0, rejected_fine = 0;
  const double coarse = DropPeak(1e-3, rejected_coarse);  // the default step
  const double fine = DropPeak(2.5e-4, rejected_fine);
  std::printf("rope snap: peak %.1f N (dt 1e-3, %ld rejected), %.1f N (dt 2.5e-4, %ld rejected), "
              "closed form %.1f N\n", coarse, rejected_coarse, fine, rejected_fine, ref);
  EXPECT_EQ(rejected_coarse, 0);
  EXPECT_EQ(rejected_fine, 0);
  EXPECT_LT(std::abs(fine - ref), std::abs(coarse - ref));
  EXPECT_NEAR(coarse, ref, 1e-3 * ref);
  EXPECT_NEAR(fine, ref, 1e-4 * ref);
}

// Material damping: on n falls with constant L0 the damping force on the
// hook is n beta EA n dl/dt / L0 = beta k dl/dt with k = n^2 EA / L0, so
// the hook is a mass-spring-damper c = beta k, damping ratio
// zeta = c / (2 m w) = beta w / 2, w = sqrt(k / m). Released 1 mm below
// the hanging equilibrium (less than the static stretch 2.45 mm: the rope
// stays taut), rho_inf = 1 (no numerical damping); zeta from the
// logarithmic decrement of the lower turning points over 4 periods.
TEST(Rope, DampingTimeGivesDampingRatio) {
  const double m = 1000.0, EA = 2e7, L0 = 20.0, beta = 1e-3;
  const int n = 2;
  const double k = n * n * EA / L0, w = std::sqrt(k / m);
  const double z_eq = -(L0 / n + m * kRopeG * L0 / (n * n * EA));
  auto model = LoadModelString(
      RopeModel(m, "[0, 0, " + ExactNumber(z_eq - 1e-3) + "]",
                "axial_stiffness: 2e7, free_length: 20, falls: 2, damping_time: 0.001",
                "solver: {t_end: 1, dt: 1e-4, rho_inf: 1}\n"),
      "damping.yaml");
  Simulator sim(*model);
  sim.Initialize();
  std::vector<double> lows;
  double x1 = 0.0, x2 = 0.0;  // the two previous displacements
  int samples = 0;
  sim.Run(0.55, 0.0, [&](const State& s, const Workspace&) {
    const double x = HookZ(*model, s) - z_eq;
    if (samples >= 2 && x1 < x2 && x1 <= x) {
      // a lower turning point: vertex of the parabola through 3 samples
      const double c = 0.5 * (x2 + x) - x1, b = 0.5 * (x - x2);
      lows.push_back(x1 - 0.25 * b * b / c);
    }
    x2 = x1;
    x1 = x;
    ++samples;
  });
  ASSERT_GE(lows.size(), 4u);
  const int periods = static_cast<int>(lows.size()) - 1;
  const double delta = std::log(lows.front() / lows.back()) / periods;
  const double zeta = delta / std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + delta * delta);
  std::printf("rope damping: zeta %.8f from %d periods, beta w / 2 = %.8f\n", zeta, periods, 0.5 * beta * w);
  EXPECT_NEAR(zeta, 0.5 * beta * w, 5e-3 * 0.5 * beta * w);
}

}  // namespace rope_test
}  // namespace flexmb::validation
