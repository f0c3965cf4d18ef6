// A joint with a release time (Joint::release_time, model-file key
// `release_time`): a hook on a spring carries a second mass through a fixed
// joint; at the release time the second mass falls freely and the hook
// oscillates about its new equilibrium. References: the closed-form motion of
// a mass on a linear spring and of a free fall, and EN 13001-2's sudden
// release (minimum spring force (m1 - m2) g, phi_3 = 1 - 2 m2 / (m1 + m2)).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

constexpr double kReleaseG = 9.81, kReleaseK = 4.0e4, kReleaseM1 = 30.0, kReleaseM2 = 20.0;
constexpr double kReleaseL0 = 1.0, kReleaseT = 0.25;

// hook and part start at the static equilibrium of both masses
std::string ReleaseModel(const std::string& part_joint_extra, const std::string& tail = "") {
  const double z0 = -(kReleaseL0 + (kReleaseM1 + kReleaseM2) * kReleaseG / kReleaseK);
  char z[32];
  std::snprintf(z, sizeof z, "%.17g", z0);
  return "gravity: [0, 0, -9.81]\n"
         "ground: {markers: [{name: top}]}\n"
         "bodies:\n"
         "  - {name: hook, mass: 30, inertia: [1, 1, 1], position: [0, 0, " + std::string(z) +
         "], markers: [{name: eye}]}\n"
         "  - {name: part, mass: 20, inertia: [1, 1, 1], position: [0, 0, " + std::string(z) +
         "], markers: [{name: eye}]}\n"
         "joints:\n"
         "  - {name: grab, type: fixed, i: hook.eye, j: part.eye" + part_joint_extra + "}\n"
         "forces:\n"
         "  - {name: rope, type: spring_damper, i: ground.top, j: hook.eye, stiffness: 40000, free_length: 1}\n"
         "solver: {t_end: 1, dt: 1.0e-4, rho_inf: 1.0}\n" + tail;
}

// runs the release at time t_r [s] and checks the closed forms
void CheckRelease(double t_r) {
  char extra[64];
  std::snprintf(extra, sizeof extra, ", release_time: %.17g", t_r);
  auto model = LoadModelString(ReleaseModel(extra), "release.yaml");
  ASSERT_EQ(model->joints[0]->release_time, t_r);
  Simulator sim(*model);
  sim.Initialize();
  const Body& hook = *model->bodies[1];
  const Body& part = *model->bodies[2];
  const double z0 = sim.state().q(part.q_offset + 2);
  const double w = std::sqrt(kReleaseK / kReleaseM1);
  const double z_eq1 = -(kReleaseL0 + kReleaseM1 * kReleaseG / kReleaseK);
  double max_hook_err = 0.0, max_part_err = 0.0, lambda_before = 0.0, lambda_after = 0.0, min_force = 1e30;
  bool at_release = false;
  sim.Run(0.6, 0.0, [&](const State& s, const Workspace&) {
    const double zh = s.q(hook.q_offset + 2), zp = s.q(part.q_offset + 2);
    const double lam = s.lambda.segment(model->joints[0]->lambda_offset, 3).norm();
    at_release |= std::abs(s.t - t_r) < 1e-12;
    if (s.t < t_r - 1e-12) {
      // at rest: the joint carries the part's weight
      max_hook_err = std::max(max_hook_err, std::abs(zh - z0));
      lambda_before = std::max(lambda_before, std::abs(lam - kReleaseM2 * kReleaseG));
      return;
    }
    const double tau = s.t - t_r;
    max_hook_err = std::max(max_hook_err, std::abs(zh - (z_eq1 + (z0 - z_eq1) * std::cos(w * tau))));
    max_part_err = std::max(max_part_err, std::abs(zp - (z0 - 0.5 * kReleaseG * tau * tau)));
    lambda_after = std::max(lambda_after, lam);
    min_force = std::min(min_force, kReleaseK * (-zh - kReleaseL0));
  });
  EXPECT_TRUE(at_release) << "no step ended at the release time " << t_r;
  EXPECT_LT(lambda_before, 1e-6 * kReleaseM2 * kReleaseG);
  EXPECT_LT(lambda_after, 1e-9 * kReleaseM2 * kReleaseG);
  // second-order integration at h = 1e-4 s, hook amplitude 4.9 mm; the
  // integrator restarts at the release (constant acceleration: exact fall)
  EXPECT_LT(max_hook_err, 1e-3 * (z_eq1 - z0));
  EXPECT_LT(max_part_err, 1e-9);
  // sudden release: phi_3 = 1 - 2 m2 / (m1 + m2) of the static rope force
  const double phi3 = min_force / ((kReleaseM1 + kReleaseM2) * kReleaseG);
  EXPECT_NEAR(phi3, 1.0 - 2.0 * kReleaseM2 / (kReleaseM1 + kReleaseM2), 1e-4);
}

TEST(JointRelease, PartFallsFreelyAndHookOscillatesAboutItsNewEquilibrium) {
  CheckRelease(kReleaseT);       // on the step grid
  CheckRelease(kReleaseT + 3.7e-5);  // between two steps: the step is shortened
}

TEST(JointRelease, WithoutReleaseTimeNothingMoves) {
  auto model = LoadModelString(ReleaseModel(""), "release.yaml");
  EXPECT_FALSE(std::isfinite(model->joints[0]->release_time));
  Simulator sim(*model);
  sim.Initialize();
  const double z0 = sim.state().q(model->bodies[2]->q_offset + 2);
  sim.Run(0.3, 0.0, nullptr);
  EXPECT_NEAR(sim.state().q(model->bodies[2]->q_offset + 2), z0, 1e-9);
}

TEST(JointRelease, ManoeuvreSetsTheReleaseTimeAndBadValuesAreNamed) {
  SolverOverrides o;
  o.manoeuvre = "drop";
  const std::string tail =
      "manoeuvres:\n"
      "  drop: {joints: {grab: {release_time: 0.4}}}\n";
  auto m = LoadModelString(ReleaseModel("", tail), "release.yaml", o);
  EXPECT_EQ(m->joints[0]->release_time, 0.4);
  auto error = [](const std::string& yaml, const std::string& manoeuvre) -> std::string {
    SolverOverrides ov;
    ov.manoeuvre = manoeuvre;
    try {
      LoadModelString(yaml, "release.yaml", ov);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(error(ReleaseModel(", release_time: -1"), "").find("release.yaml:7: joint 'grab': 'release_time' must be positive"),
            std::string::npos)
      << error(ReleaseModel(", release_time: -1"), "");
  EXPECT_NE(error(ReleaseModel("", "manoeuvres:\n  drop: {joints: {hinge: {release_time: 1}}}\n"), "")
                .find("the file has no joint named 'hinge'"),
            std::string::npos);
  EXPECT_NE(error(ReleaseModel("", "manoeuvres:\n  drop: {joints: {grab: {i: ground.top}}}\n"), "")
                .find("a manoeuvre sets a joint's 'release_time' only, not its 'i'"),
            std::string::npos);
  // a manoeuvre may start the bodies elsewhere, not change them
  o.manoeuvre = "high";
  auto high = LoadModelString(ReleaseModel("", "manoeuvres:\n  high: {bodies: {part: {position: [0, 0, 2]}}}\n"),
                              "release.yaml", o);
  VecX q = VecX::Zero(high->bodies[2]->nq()), v = VecX::Zero(high->bodies[2]->nv());
  high->bodies[2]->InitialCoordinates(q.data(), v.data());
  EXPECT_EQ(q(2), 2.0);
  EXPECT_NE(error(ReleaseModel("", "manoeuvres:\n  drop: {bodies: {part: {mass: 1}}}\n"), "")
                .find("not its 'mass'"),
            std::string::npos);
}

}  // namespace
}  // namespace flexmb
