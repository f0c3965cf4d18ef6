#include "flexmb/forces/spring_damper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/solver/simulator.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

using namespace flexmb::testing;

SpringDamperLaw Linear(double k, double c, double l0, double f0) {
  SpringDamperLaw law;
  law.stiffness = k;
  law.damping = c;
  law.free_length = l0;
  law.preload = f0;
  return law;
}

// nonlinear laws: a progressive spline table and a degressive damper table
SpringDamperLaw Tabulated() {
  SpringDamperLaw law;
  law.free_length = 0.7;
  law.preload = 15.0;
  law.force_deflection = std::make_shared<TableFunction>(
      std::vector<double>{-2, -0.5, 0, 0.5, 2}, std::vector<double>{-900, -60, 0, 70, 1200},
      TableFunction::Interpolation::kCubicSpline, true);
  law.force_velocity = std::make_shared<TableFunction>(
      std::vector<double>{-10, -1, 0, 1, 10}, std::vector<double>{-300, -80, 0, 50, 200},
      TableFunction::Interpolation::kCubicSpline, true);
  return law;
}

TEST(SpringDamper, TangentsMatchFiniteDifferences) {
  std::mt19937 rng(7);
  const SpringDamper linear("s", Linear(1200.0, 35.0, 0.6, -40.0));
  const SpringDamper table("t", Tabulated());
  for (int trial = 0; trial < 20; ++trial) {
    const MarkerState mi = RandomMarker(rng), mj = RandomMarker(rng);
    ExpectTangents(linear, mi, mj, 0.0);
    ExpectTangents(table, mi, mj, 0.0);
    ExpectThirdLaw(linear, mi, mj, 0.0);
    ExpectThirdLaw(table, mi, mj, 0.0);
  }
}

TEST(SpringDamper, PotentialGradientIsMinusWrench) {
  std::mt19937 rng(11);
  const SpringDamper linear("s", Linear(800.0, 0.0, 0.9, 25.0));
  SpringDamperLaw law = Tabulated();
  law.force_velocity = nullptr;
  const SpringDamper table("t", law);
  for (int trial = 0; trial < 10; ++trial) {
    MarkerState mi = RandomMarker(rng), mj = RandomMarker(rng);
    mi.v_WM.setZero();
    mj.v_WM.setZero();
    ExpectPotentialGradient(linear, mi, mj, 0.0);
    // Simpson's rule on a piecewise cubic with knots inside the interval: ~1e-5
    ExpectPotentialGradient(table, mi, mj, 0.0, 1e-4);
  }
}

TEST(SpringDamper, KnownForce) {
  // j 2 m above i along z, closing at 0.5 m/s: F = k (2 - 1.5) + F0 + c (-0.5)
  const SpringDamper s("s", Linear(100.0, 10.0, 1.5, 3.0));
  MarkerState mi, mj;
  mj.p_WM = Vec3(0, 0, 2);
  mj.v_WM = Vec3(0.3, 0, -0.5);
  const double F = 100.0 * 0.5 + 3.0 - 10.0 * 0.5;
  const Vec12 w = Wrench(s, mi, mj, 0.0);
  EXPECT_NEAR((w.segment<3>(0) - Vec3(0, 0, F)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((w.segment<3>(6) - Vec3(0, 0, -F)).norm(), 0.0, 1e-12);
  EXPECT_EQ(w.segment<3>(3).norm() + w.segment<3>(9).norm(), 0.0);
  EXPECT_NEAR(s.PotentialEnergy(mi, mj, 0.0), 0.5 * 100.0 * 0.25 + 3.0 * 0.5, 1e-12);
}

TEST(SpringDamper, CoincidentOriginsThrow) {
  const SpringDamper s("s", Linear(100.0, 0.0, 1.0, 0.0));
  MarkerState m;
  EXPECT_THROW(Wrench(s, m, m, 0.0), NumericalError);
  EXPECT_THROW(SpringDamper("bad", Linear(-1.0, 0.0, 1.0, 0.0)), InputError);
}

// A mass m on a prismatic joint along z from the ground, held by a spring
// of law `law`, released at height z0 and rest, no gravity; returns the
// body's index.
int AddSpringMass(Model& model, double m, double z0, const SpringDamperLaw& law) {
  model.gravity_W.setZero();
  RigidBodyData d;
  d.mass = m;
  d.inertia_C = 0.1 * Mat3::Identity();
  d.p_WB = Vec3(0, 0, z0);
  const int b = model.AddBody(std::make_unique<RigidBody>("mass", d));
  const int g = model.AddMarker(0, "anchor", Vec3::Zero(), Mat3::Identity());
  const int s = model.AddMarker(b, "slide", Vec3::Zero(), Mat3::Identity());
  model.AddJoint(std::make_unique<PrismaticJoint>("slide"), g, s);
  model.AddForce(std::make_unique<SpringDamper>("spring", law), g, s);
  return b;
}

// A 2 kg mass on a prismatic joint along z held by a spring (k = 50 N/m,
// free length 0.8 m), released 0.2 m stretched: x(t) of the linear
// oscillator, x0 e^(-zeta w t) (cos wd t + zeta w / wd sin wd t).
void RunSpringMass(double zeta) {
  const double m = 2.0, k = 50.0, l0 = 0.8, x0 = 0.2;
  const double w = std::sqrt(k / m), c = 2.0 * zeta * std::sqrt(k * m);
  Model model;
  const int b = AddSpringMass(model, m, l0 + x0, Linear(k, c, l0, 0.0));
  model.solver.dt = 1e-3;
  model.solver.rho_inf = 1.0;
  model.Finalize();
  Simulator sim(model);
  sim.Initialize();
  const double wd = w * std::sqrt(1.0 - zeta * zeta);
  double max_err = 0.0;
  int n = 0;
  sim.Run(3.0, 0.0, [&](const State& st, const Workspace&) {
    const double t = st.t;
    const double x = st.q(model.bodies[b]->q_offset + 2) - l0;
    const double ref = x0 * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
    max_err = std::max(max_err, std::abs(x - ref));
    ++n;
  });
  EXPECT_GT(n, 2900);
  EXPECT_LT(max_err, 2e-5) << "zeta = " << zeta;  // period error O((w h)^2) ~ 1e-5 rad per cycle
}

TEST(SpringDamper, SpringMassMatchesAnalyticSolution) {
  RunSpringMass(0.0);
  RunSpringMass(0.05);
}

// The damper law with friction (ViscousCoulombFunction): derivatives against
// central differences; in the spring-damper its tangents as any rate law.
TEST(SpringDamper, ViscousCoulombLawAndTangents) {
  const ViscousCoulombFunction f(35.0, 400.0, 0.02);
  for (const double v : {-0.3, -0.02, -1e-3, 0.0, 5e-3, 0.02, 0.5}) {
    const double h = 1e-6;
    EXPECT_NEAR(f.Derivative(v), (f.Value(v + h) - f.Value(v - h)) / (2 * h), 1e-5 * (35.0 + 400.0 / 0.02)) << v;
    EXPECT_NEAR(f.SecondDerivative(v), (f.Derivative(v + h) - f.Derivative(v - h)) / (2 * h), 1e-3 * 400.0 / 4e-4)
        << v;
  }
  EXPECT_NEAR(f.Value(0.02), 35.0 * 0.02 + 400.0 * std::tanh(1.0), 1e-12);
  EXPECT_NEAR(f.Value(10.0), 350.0 + 400.0, 1e-9);  // far from zero: viscous plus the full friction force
  EXPECT_THROW(ViscousCoulombFunction(1.0, 1.0, 0.0), InputError);
  EXPECT_THROW(ViscousCoulombFunction(1.0, -1.0, 0.1), InputError);
  SpringDamperLaw law = Linear(1200.0, 0.0, 0.6, -40.0);
  law.force_velocity = std::make_shared<ViscousCoulombFunction>(35.0, 80.0, 0.5);
  const SpringDamper s("friction", law);
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const MarkerState mi = RandomMarker(rng), mj = RandomMarker(rng);
    ExpectTangents(s, mi, mj, 0.0);
    ExpectThirdLaw(s, mi, mj, 0.0);
  }
}

// Free vibration with Coulomb friction (Den Hartog, Mechanical Vibrations,
// 4th ed., sec. 8.2): every half period pi / w (the period of the
// frictionless oscillator) the amplitude drops by 2 F / k, until the mass
// stops within F / k of the spring's free length. Smoothed friction (rate
// 1e-4 m/s against peak rates of about 1 m/s) follows it closely.
TEST(SpringDamper, CoulombFrictionAmplitudeFallsBy2FOverKEveryHalfPeriod) {
  const double m = 2.0, k = 50.0, l0 = 0.8, x0 = 0.2, F = 0.5;
  const double w = std::sqrt(k / m);
  SpringDamperLaw law = Linear(k, 0.0, l0, 0.0);
  law.force_velocity = std::make_shared<ViscousCoulombFunction>(0.0, F, 1e-4);
  Model model;
  const int b = AddSpringMass(model, m, l0 + x0, law);
  model.solver.dt = 2e-4;
  model.solver.rho_inf = 1.0;
  model.Finalize();
  Simulator sim(model);
  sim.Initialize();
  // the extremes of x: where the rate changes sign
  std::vector<double> peaks{x0}, times{0.0};
  double v_prev = 0.0, x_prev = x0, t_prev = 0.0;
  sim.Run(6.0, 0.0, [&](const State& st, const Workspace&) {  // 9.5 half periods
    const double x = st.q(model.bodies[b]->q_offset + 2) - l0, v = st.v(model.bodies[b]->v_offset + 2);
    if (st.t > times.back() + 0.5 * M_PI / w && ((v_prev > 0 && v <= 0) || (v_prev < 0 && v >= 0))) {
      peaks.push_back(std::abs(x) > std::abs(x_prev) ? x : x_prev);
      times.push_back(std::abs(x) > std::abs(x_prev) ? st.t : t_prev);
    }
    v_prev = v, x_prev = x, t_prev = st.t;
  });
  // 0.2 -> -0.18 -> 0.16 ... -> 0.02, stopping inside |x| < F / k = 0.01 after 10 half periods
  ASSERT_GE(peaks.size(), 9u);
  for (size_t i = 1; i < 9; ++i) {
    const double expected = (i % 2 ? -1.0 : 1.0) * (x0 - 2.0 * F / k * static_cast<double>(i));
    EXPECT_NEAR(peaks[i], expected, 1e-3) << "extreme " << i;  // 5 % of the decrement 0.02
    EXPECT_NEAR(times[i] - times[i - 1], M_PI / w, 2e-3) << "half period " << i;
  }
}

}  // namespace
}  // namespace flexmb
