// IFToMM benchmark A02 with N = 2 (two four-bar linkages, 5 links), run from
// examples/four_bar_2: redundant equations of the planar loops, energy
// conservation through the singular configurations, and the position of B0
// against the one-degree-of-freedom reduction (a peer computation, not a
// published number). Details: docs/validation.md, "IFToMM A02".

#include <gtest/gtest.h>

#include <cstdio>

#include "example_model.h"

namespace flexmb::validation {
namespace four_bar_a02_test {

constexpr int kN = 2;

// every window is a parallelogram, so the crank angle phi from the upward
// vertical (B0 = (sin phi, cos phi)) obeys I phi'' = M sin phi with
// I = (N+1)/3 + N and M = g ((N+1)/2 + N); classical RK4 with a fine step
struct Reduced {
  double phi = 0.0, rate = 1.0;  // phi(0) = 0, phi'(0) = 1 rad/s (B0 at +1 m/s in x)
  void Advance(double dt, int steps) {
    const double I = (kN + 1) / 3.0 + kN, M = 9.81 * ((kN + 1) / 2.0 + kN);
    auto acc = [&](double p) { return M / I * std::sin(p); };
    for (int i = 0; i < steps; ++i) {
      const double k1p = rate, k1v = acc(phi);
      const double k2p = rate + 0.5 * dt * k1v, k2v = acc(phi + 0.5 * dt * k1p);
      const double k3p = rate + 0.5 * dt * k2v, k3v = acc(phi + 0.5 * dt * k2p);
      const double k4p = rate + dt * k3v, k4v = acc(phi + dt * k3p);
      phi += dt / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
      rate += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
  }
};

struct RunResult {
  double max_de = 0.0;     // max |E - E0| [J]
  double max_dpos = 0.0;   // max |B0 - B0_reduced| [m]
  double e0 = 0.0;
};

RunResult RunFourBar(double dt) {
  auto model = LoadExample("four_bar_2");
  model->solver.dt = dt;
  Simulator sim(*model);
  const ConstraintReport& rep = sim.Initialize();
  // 5 bodies x 6 = 30 coordinates, 7 revolute joints x 5 = 35 equations, of
  // which 6 (3 per closed planar loop) are redundant: 1 degree of freedom
  EXPECT_EQ(rep.equations, 35);
  EXPECT_EQ(rep.redundant.size(), 6u);
  // one message per joint that closes a loop, naming its 3 equations
  EXPECT_EQ(rep.messages.size(), 2u);
  EXPECT_EQ(rep.dof, 1);
  for (const std::string& m : rep.messages) {
    EXPECT_NE(m.find("joint '"), std::string::npos) << m;
    EXPECT_NE(m.find("3 redundant constraint equations removed"), std::string::npos) << m;
  }
  SensorValue x(*model, "b0", "x"), y(*model, "b0", "y"), e(*model, "energy", "total");
  RunResult r;
  r.e0 = e(sim.state(), sim.workspace());
  Reduced ref;
  double t_ref = 0.0;
  sim.Run(model->solver.t_end, model->output.interval, [&](const State& s, const Workspace& ws) {
    const int n = static_cast<int>(std::lround((s.t - t_ref) / 1e-5));
    ref.Advance(1e-5, n);
    t_ref += n * 1e-5;
    r.max_de = std::max(r.max_de, std::abs(e(s, ws) - r.e0));
    r.max_dpos = std::max(r.max_dpos, std::hypot(x(s, ws) - std::sin(ref.phi), y(s, ws) - std::cos(ref.phi)));
  });
  EXPECT_NEAR(sim.state().t, 10.0, 1e-9);
  // the reduction itself against the values in the notes (t = 10 s)
  EXPECT_NEAR(std::sin(ref.phi), 0.32845811, 2e-8);
  EXPECT_NEAR(std::cos(ref.phi), 0.94451854, 2e-8);
  return r;
}

TEST(IftommA02, TwoFourBarsEnergyAndReducedModel) {
  const RunResult a = RunFourBar(1e-3), b = RunFourBar(5e-4);
  // E = KE + PE = 1.5 + 34.335 J (datum at the ground pins)
  EXPECT_NEAR(a.e0, 35.835, 1e-9);
  // energy error: bounded, second order in h (measured 1.1e-3 J and 2.8e-4 J),
  // no drift through the 6 passes of the singular configuration in 10 s
  EXPECT_LT(a.max_de, 2e-3);
  EXPECT_NEAR(a.max_de / b.max_de, 4.0, 0.4);
  // B0 against the reduced model, max over the 201 outputs in 10 s: the
  // O(h^2) phase error (measured 1.9e-4 m and 4.8e-5 m)
  EXPECT_LT(a.max_dpos, 3e-4);
  EXPECT_NEAR(a.max_dpos / b.max_dpos, 4.0, 0.4);
  std::printf("A02 N=2: max |E - E0| %.3e / %.3e J, max |B0 - ref| %.3e / %.3e m (h = 1, 0.5 ms)\n",
              a.max_de, b.max_de, a.max_dpos, b.max_dpos);
}

}  // namespace four_bar_a02_test
}  // namespace flexmb::validation
