#include "flexmb/solver/generalized_alpha.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

// Rigid rod pendulum (uniform rod, L = 1 m, m = 1 kg) pinned at one end,
// released horizontal. The exact motion is theta(t) with
// thetadot^2 = (3 g / L) sin(theta) (energy); we use it through the time at
// which the rod first reaches the vertical: t* = int_0^{pi/2} dtheta / thetadot.
struct Rod {
  std::unique_ptr<Model> model;
  int body = 0;
};

Rod MakeRod(double dt, double rho, bool adaptive) {
  Rod r;
  r.model = std::make_unique<Model>();
  Model& m = *r.model;
  m.gravity_W = Vec3(0, -9.81, 0);
  RigidBodyData d;
  d.mass = 1.0;
  d.inertia_C = Vec3(1e-4, 1.0 / 12, 1.0 / 12).asDiagonal();
  d.c_B = Vec3(0.5, 0, 0);
  r.body = m.AddBody(std::make_unique<RigidBody>("rod", d));
  m.AddJoint(std::make_unique<RevoluteJoint>("pin"), m.AddMarker(0, "o", Vec3::Zero(), Mat3::Identity()),
             m.AddMarker(r.body, "o", Vec3::Zero(), Mat3::Identity()));
  m.solver.dt = dt;
  m.solver.rho_inf = rho;
  m.solver.adaptive = adaptive;
  m.solver.rtol = 1e-6;
  m.solver.atol = 1e-8;
  m.Finalize();
  return r;
}

// angle of the rod below the horizontal after t_end
double AngleAt(double dt, double rho, double t_end, long* steps = nullptr, bool adaptive = false) {
  Rod r = MakeRod(dt, rho, adaptive);
  Simulator sim(*r.model);
  sim.Initialize();
  sim.Run(t_end, 0.0, nullptr);
  if (steps) *steps = sim.stats().steps;
  const Body& b = *r.model->bodies[r.body];
  Vec3 p;
  Mat3 R;
  b.BodyFramePose(sim.state().q.data() + b.q_offset, p, R);
  return std::atan2(-R(1, 0), R(0, 0));
}

// reference: RK4 on theta'' = (3 g / (2 L)) cos(theta) with a tiny step
double ReferenceAngle(double t_end) {
  const double c = 1.5 * 9.81;
  double th = 0.0, om = 0.0;
  const int n = 200000;
  const double h = t_end / n;
  auto f = [&](double t, double w) { return std::pair<double, double>(w, c * std::cos(t)); };
  for (int k = 0; k < n; ++k) {
    auto [k1a, k1b] = f(th, om);
    auto [k2a, k2b] = f(th + 0.5 * h * k1a, om + 0.5 * h * k1b);
    auto [k3a, k3b] = f(th + 0.5 * h * k2a, om + 0.5 * h * k2b);
    auto [k4a, k4b] = f(th + h * k3a, om + h * k3b);
    th += h / 6 * (k1a + 2 * k2a + 2 * k3a + k4a);
    om += h / 6 * (k1b + 2 * k2b + 2 * k3b + k4b);
  }
  return th;
}

TEST(GeneralizedAlpha, SecondOrderConvergence) {
  const double t_end = 0.5, ref = ReferenceAngle(t_end);
  for (double rho : {1.0, 0.8, 0.5}) {
    const double e1 = std::abs(AngleAt(4e-3, rho, t_end) - ref);
    const double e2 = std::abs(AngleAt(2e-3, rho, t_end) - ref);
    const double e3 = std::abs(AngleAt(1e-3, rho, t_end) - ref);
    // halving the step divides the error by about 4
    EXPECT_GT(e1 / e2, 3.3) << "rho " << rho;
    EXPECT_GT(e2 / e3, 3.3) << "rho " << rho;
    EXPECT_LT(e3, 1e-4);
    std::printf("rho %.1f errors %.3e %.3e %.3e\n", rho, e1, e2, e3);
  }
}

TEST(GeneralizedAlpha, AdaptiveStepMeetsTolerance) {
  const double t_end = 0.5, ref = ReferenceAngle(t_end);
  long steps = 0;
  const double err = std::abs(AngleAt(1e-2, 0.9, t_end, &steps, true) - ref);
  EXPECT_LT(err, 1e-4);
  std::printf("adaptive: error %.3e in %ld steps\n", err, steps);
  EXPECT_GT(steps, 5);
  EXPECT_LT(steps, 2000);
}

// angle of the rod after t_end and the integrator's counters, full Newton or
// modified Newton (SolverSettings::jacobian_reuse)
// runs the rod to t_end; its angle then, and the integrator's counters
double RodAngleAt(const Rod& r, double t_end, IntegratorStats& stats) {
  Simulator sim(*r.model);
  sim.Initialize();
  sim.Run(t_end, 0.0, nullptr);
  stats = sim.stats();
  const Body& b = *r.model->bodies[r.body];
  Vec3 p;
  Mat3 R;
  b.BodyFramePose(sim.state().q.data() + b.q_offset, p, R);
  return std::atan2(-R(1, 0), R(0, 0));
}

double AngleWithReuse(bool reuse, bool adaptive, IntegratorStats& stats, double newton_tol = 1e-10) {
  Rod r = MakeRod(adaptive ? 1e-2 : 1e-3, 0.8, adaptive);
  r.model->solver.jacobian_reuse = reuse;
  r.model->solver.newton_tol = newton_tol;
  return RodAngleAt(r, 0.5, stats);
}

TEST(GeneralizedAlpha, JacobianReuseConvergesToTheSameSolution) {
  // modified Newton solves the same equations to the same tolerance: the
  // angle equals full Newton's far below the integration error (reference:
  // the full Newton run and the RK4 reference), with fewer factorizations
  const double ref = ReferenceAngle(0.5);
  for (const bool adaptive : {false, true}) {
    IntegratorStats full, reuse;
    const double a_full = AngleWithReuse(false, adaptive, full);
    const double a_reuse = AngleWithReuse(true, adaptive, reuse);
    EXPECT_LT(std::abs(a_reuse - a_full), 1e-8) << "adaptive " << adaptive;
    EXPECT_LT(std::abs(a_reuse - ref), 1e-4) << "adaptive " << adaptive;
    if (adaptive) {
      // the step size changes every step, so the matrix is refreshed per
      // step (not per iteration)
      EXPECT_NEAR(double(reuse.steps), double(full.steps), 0.05 * full.steps);
      EXPECT_LE(reuse.factorizations, full.factorizations);
      EXPECT_LE(reuse.factorizations, reuse.steps + reuse.rejected);
    } else {
      EXPECT_EQ(reuse.steps, full.steps);
      EXPECT_LT(reuse.factorizations, full.factorizations / 2);
    }
    std::printf("adaptive %d: factorizations %ld / %ld, iterations %ld / %ld (reuse / full)\n", adaptive,
                reuse.factorizations, full.factorizations, reuse.newton_iterations, full.newton_iterations);
  }
}

TEST(GeneralizedAlpha, KeptMatrixLeavesLessThanItsShareOfTheTolerance) {
  // at a loose Newton tolerance the kept matrix's remaining error shows: it
  // must stay a small share (kKeptMatrixErrorFraction) of newton_tol per
  // step, so that 1000 steps move the angle by far less than 1000 newton_tol.
  // Measured: 3.6e-8 rad; 1.2e-5 rad when an iterate was accepted on the
  // estimate rate / (1 - rate) |dx| alone (full Newton: 3e-13 from its
  // value at 1e-10)
  IntegratorStats full, reuse;
  const double a_full = AngleWithReuse(false, false, full, 1e-8);
  const double a_reuse = AngleWithReuse(true, false, reuse, 1e-8);
  std::printf("newton_tol 1e-8: kept matrix against full Newton %.2e rad; factorizations %ld / %ld, iterations %ld / %ld\n",
              a_reuse - a_full, reuse.factorizations, full.factorizations, reuse.newton_iterations, full.newton_iterations);
  EXPECT_LT(std::abs(a_reuse - a_full), 1e-7);
  EXPECT_LT(reuse.factorizations, full.factorizations / 10);
}

TEST(GeneralizedAlpha, FullNewtonChordCheckLeavesFarLessThanTheTolerance) {
  // full Newton accepts the previous factorization's correction when it is
  // within newton_tol (kChordAcceptFraction): one factorization per step on
  // this smooth motion, and at a loose tolerance the angle after 500 steps
  // stays within one newton_tol of the tight-tolerance angle (500 steps
  // could accumulate 500 newton_tol; measured 4e-16 rad)
  IntegratorStats loose, tight;
  const double a_loose = AngleWithReuse(false, false, loose, 1e-9);
  const double a_tight = AngleWithReuse(false, false, tight, 1e-13);
  std::printf("full Newton, newton_tol 1e-9 against 1e-13: %.2e rad; factorizations %ld / %ld, chord checks %ld / %ld, steps %ld\n",
              a_loose - a_tight, loose.factorizations, tight.factorizations, loose.chord_checks, tight.chord_checks,
              loose.steps);
  EXPECT_LT(std::abs(a_loose - a_tight), 1e-9);
  EXPECT_EQ(loose.factorizations, loose.steps);
  EXPECT_GT(loose.chord_checks, 0);
  EXPECT_GE(tight.factorizations, loose.factorizations);
}

// The rod at a 20 ms step, where Newton needs three iterations: the second
// iteration's chord correction is above the tolerance but contracts more
// than 100-fold (kChordKeepRate), so it is taken without a new matrix and
// the third iteration checks again with the same one: one factorization per
// step, and the angle equals that of a run with a tolerance 1e4 times
// tighter to within the looser tolerance.
TEST(GeneralizedAlpha, FullNewtonTakesAFastContractingChordStepWithoutANewMatrix) {
  auto angle = [](double newton_tol, IntegratorStats& stats) {
    Rod r = MakeRod(2e-2, 0.8, false);
    r.model->solver.newton_tol = newton_tol;
    return RodAngleAt(r, 1.0, stats);
  };
  IntegratorStats s10, s14;
  const double a10 = angle(1e-10, s10), a14 = angle(1e-14, s14);
  std::printf("dt 20 ms: iterations %ld, factorizations %ld, chord steps %ld, steps %ld; against 1e-14: %.2e rad\n",
              s10.newton_iterations, s10.factorizations, s10.chord_steps, s10.steps, a10 - a14);
  EXPECT_GT(s10.chord_steps, 0);
  EXPECT_GT(s10.newton_iterations, 2 * s10.steps);
  EXPECT_EQ(s10.factorizations, s10.steps);
  EXPECT_LT(std::abs(a10 - a14), 1e-10);
}

}  // namespace
}  // namespace flexmb
