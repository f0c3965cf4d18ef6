// Limits of a joint coordinate (model-file key `limits`, Joint::coordinate_min
// and coordinate_max): a slider falling along a vertical prismatic joint
// stops the run with an error naming the joint when it leaves its stroke, at
// the step where the free fall z = -g t^2 / 2 (the reference) passes the limit.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/statics.h"

namespace flexmb {
namespace {

// a slider on a vertical guide (the prismatic joint's translation is along
// the ground marker's z, up), released at rest at z = 0
std::string LimitsModel(const std::string& limits) {
  return "gravity: [0, 0, -9.81]\n"
         "ground: {markers: [{name: guide}]}\n"
         "bodies:\n"
         "  - {name: slider, mass: 2, inertia: [1, 1, 1], markers: [{name: c}]}\n"
         "joints:\n"
         "  - {name: stroke, type: prismatic, i: ground.guide, j: slider.c" + limits + "}\n"
         "solver: {t_end: 1, dt: 1.0e-3}\n";
}

std::string LimitsError(const std::string& yaml) {
  try {
    auto m = LoadModelString(yaml, "limits.yaml");
    Simulator sim(*m);
    sim.Initialize();
    sim.Run(m->solver.t_end, 0.0, nullptr);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(JointLimits, RunStopsWhereTheCoordinateLeavesTheLimits) {
  auto m = LoadModelString(LimitsModel(", limits: [-0.2, 0.5]"), "limits.yaml");
  EXPECT_EQ(m->joints[0]->coordinate_min, -0.2);
  EXPECT_EQ(m->joints[0]->coordinate_max, 0.5);
  Simulator sim(*m);
  sim.Initialize();
  try {
    sim.Run(1.0, 0.0, nullptr);
    FAIL() << "expected the run to stop at the lower limit";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("joint 'stroke'"), std::string::npos) << what;
    EXPECT_NE(what.find("translation"), std::string::npos) << what;
    EXPECT_NE(what.find("outside the joint's limits [-0.2, 0.5] m"), std::string::npos) << what;
  }
  // the free fall reaches -0.2 m at sqrt(2 0.2 / g) = 0.2019 s: the run stops
  // at the first step beyond it
  const double t_hit = std::sqrt(2.0 * 0.2 / 9.81);
  EXPECT_GE(sim.state().t, t_hit);
  EXPECT_LT(sim.state().t, t_hit + 1.0e-3 + 1e-12);
  // without limits the same run goes on to its end
  auto unlimited = LoadModelString(LimitsModel(""), "limits.yaml");
  Simulator sim2(*unlimited);
  sim2.Initialize();
  sim2.Run(0.5, 0.0, nullptr);
  EXPECT_NEAR(sim2.state().t, 0.5, 1e-12);
}

TEST(JointLimits, BadLimitsAndAStartOutsideThemAreNamed) {
  EXPECT_NE(LimitsError(LimitsModel(", limits: [0.1, 0.5]")).find("outside the joint's limits [0.1, 0.5] m at t = 0 s"),
            std::string::npos)
      << LimitsError(LimitsModel(", limits: [0.1, 0.5]"));
  EXPECT_NE(LimitsError(LimitsModel(", limits: [0.5, -0.5]")).find("limits.yaml:6: joint 'stroke': 'limits' needs lower < upper"),
            std::string::npos)
      << LimitsError(LimitsModel(", limits: [0.5, -0.5]"));
  EXPECT_NE(LimitsError(LimitsModel(", limits: [0.5]")).find("expected 'limits' as [lower, upper] of the joint's translation"),
            std::string::npos);
  std::string spherical = LimitsModel(", limits: [0, 1]");
  spherical.replace(spherical.find("prismatic"), 9, "spherical");
  EXPECT_NE(LimitsError(spherical).find("a spherical joint has no coordinate to limit"), std::string::npos)
      << LimitsError(spherical);
}

// statics: a slider hanging on a spring (k = 100 N/m) from 1 m above it,
// free length 1 m, sinks to z = -m g / k = -0.1962 m; inside limits
// [-0.5, 0.5] the equilibrium is that, with limits [-0.1, 0.5] SolveStatics
// stops naming the joint
TEST(JointLimits, StaticEquilibriumOutsideTheLimitsIsNamed) {
  auto text = [](const std::string& limits) {
    std::string y = LimitsModel(limits);
    const std::string ground = "ground: {markers: [{name: guide}]}";
    y.replace(y.find(ground), ground.size(), "ground: {markers: [{name: guide}, {name: anchor, position: [0, 0, 1]}]}");
    y.insert(y.find("solver:"),
             "forces:\n  - {name: spring, type: spring_damper, i: ground.anchor, j: slider.c, stiffness: 100, "
             "free_length: 1}\n");
    return y;
  };
  auto solve = [](const std::string& yaml) {
    auto m = LoadModelString(yaml, "limits.yaml");
    State s = m->InitialState();
    Workspace ws;
    MakeConsistent(*m, s, ws);
    SolveStatics(*m, s, ws);
    return s.q(2);
  };
  EXPECT_NEAR(solve(text(", limits: [-0.5, 0.5]")), -2.0 * 9.81 / 100.0, 1e-9);
  try {
    solve(text(", limits: [-0.1, 0.5]"));
    FAIL() << "expected the statics to stop at the limit";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("joint 'stroke'"), std::string::npos) << what;
    EXPECT_NE(what.find("translation -0.1962 m outside the joint's limits [-0.1, 0.5] m at the static equilibrium"),
              std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace flexmb
