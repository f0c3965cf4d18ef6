// IFToMM benchmark A03, Andrews' squeezing mechanism, run from
// examples/andrews_squeezer against the reference solution of the Test Set
// for IVP Solvers (Mazzia, Magherini; University of Bari, release 2.4,
// problem "andrews", subroutine andsoln: PSIDE, rtol = atol = 1e-14).
// Details: docs/validation.md, "IFToMM A03".

#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "example_model.h"

namespace flexmb::validation {
namespace andrews_squeezer_test {

constexpr const char* kAngles[7] = {"beta", "Theta", "gamma", "Phi", "delta", "Omega", "epsilon"};
// y(1..7) at t = 0.03 s from andsoln
constexpr double kReference[7] = {0.1581077119629904e+2,  -0.1575637105984298e+2,
                                  0.4082224013073101e-1,  -0.5347301163226948e+0,
                                  0.5244099658805304e+0,  0.5347301163226948e+0,
                                  0.1048080741042263e+1};
constexpr double kMom = 0.033;  // drive torque [N m]

struct AndrewsRun {
  std::array<double, 7> angle{};  // unwrapped angles at t = 0.03 s [rad]
  double max_dw = 0.0;            // max |T + V - mom (beta - beta0) - E0| [J]
  double beta_dd0 = 0.0, theta_dd0 = 0.0;  // initial accelerations [rad/s^2]
  ConstraintReport report;
};

AndrewsRun RunAndrews(double dt) {
  auto model = LoadExample("andrews_squeezer");
  model->solver.dt = dt;
  Simulator sim(*model);
  AndrewsRun r;
  r.report = sim.Initialize();
  // initial accelerations: angular accelerations (z) of crank and rod
  const Body& crank = *model->bodies[model->FindBody("crank")];
  const Body& rod = *model->bodies[model->FindBody("rod")];
  r.beta_dd0 = sim.workspace().vdot(crank.v_offset + 5);
  r.theta_dd0 = sim.workspace().vdot(rod.v_offset + 5) - r.beta_dd0;

  std::vector<SensorValue> angle;
  for (const char* a : kAngles) angle.emplace_back(*model, a, "value");
  SensorValue energy(*model, "energy", "total");
  std::array<Unwrapper, 7> unwrap;
  double e0 = 0.0;
  bool first = true;
  // the crank turns at up to ~1400 rad/s: output every 0.1 ms (0.14 rad)
  sim.Run(0.03, model->output.interval, [&](const State& s, const Workspace& ws) {
    for (int k = 0; k < 7; ++k) r.angle[k] = unwrap[k](angle[k](s, ws));
    // no gravity: kinetic + spring energy - work of the constant torque
    const double w = energy(s, ws) - kMom * r.angle[0];
    if (first) e0 = w, first = false;
    r.max_dw = std::max(r.max_dw, std::abs(w - e0));
  });
  return r;
}

TEST(IftommA03, AndrewsSqueezerAgainstTestSet) {
  const double h = 1e-5;
  const AndrewsRun fine = RunAndrews(h), coarse = RunAndrews(2 * h);

  // 7 bodies x 6 = 42 coordinates, 10 revolute joints x 5 = 50 equations,
  // 9 of them redundant in 3D (3 per closed planar loop): 1 degree of freedom
  EXPECT_EQ(fine.report.equations, 50);
  EXPECT_EQ(fine.report.redundant.size(), 9u);
  EXPECT_EQ(fine.report.dof, 1);

  // consistent initial accelerations of the test set (andrews.f, yprime(15:16))
  EXPECT_NEAR(fine.beta_dd0 / 14222.4439199541138705911625887 - 1.0, 0.0, 1e-8);
  EXPECT_NEAR(fine.theta_dd0 / -10666.8329399655854029433719415 - 1.0, 0.0, 1e-8);

  double max_err = 0.0, max_extrap = 0.0;
  for (int k = 0; k < 7; ++k) {
    const double err = fine.angle[k] - kReference[k];
    // Richardson: for a second-order method the error of the fine run is
    // about (y_h - y_2h) / 3; it must explain the actual error
    const double est = (fine.angle[k] - coarse.angle[k]) / 3.0;
    const double extrapolated = fine.angle[k] + est;
    max_err = std::max(max_err, std::abs(err));
    max_extrap = std::max(max_extrap, std::abs(extrapolated - kReference[k]));
    EXPECT_LT(std::abs(err), 2e-4) << kAngles[k];
    EXPECT_LT(std::abs(extrapolated - kReference[k]), 1e-6) << kAngles[k];
    std::printf("A03 %-8s h: %+.3e  2h: %+.3e  extrapolated: %+.3e rad\n", kAngles[k], err,
                coarse.angle[k] - kReference[k], extrapolated - kReference[k]);
  }
  // energy balance T + V = E0 + mom (beta - beta0), of a work input of
  // 0.52 J: second-order error (measured 5.0e-5 J at h, 2.0e-4 J at 2h)
  EXPECT_LT(fine.max_dw, 1e-4);
  EXPECT_NEAR(coarse.max_dw / fine.max_dw, 4.0, 0.4);
  std::printf("A03: max angle error %.3e rad at h = %g s, %.3e after extrapolation; energy "
              "balance %.3e J (h), %.3e J (2h)\n",
              max_err, h, max_extrap, fine.max_dw, coarse.max_dw);
}

}  // namespace andrews_squeezer_test
}  // namespace flexmb::validation
