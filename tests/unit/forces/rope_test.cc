// The hoisting rope: tension law (stretched, slack, falls, damping clamp),
// K and C against central differences, potential gradient, the free length
// integrated from the hoisting speed against its closed form, bad input,
// and the model file's `rope` entry.

#include "flexmb/forces/rope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/model_file/model_file.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

/// Marker j at distance l below marker i, moving apart at `ldot`.
void RopeTestMarkers(double l, double ldot, MarkerState& mi, MarkerState& mj) {
  mi = MarkerState{};
  mj = MarkerState{};
  mi.p_WM = Vec3(1, 2, 30);
  mj.p_WM = mi.p_WM - Vec3(0, 0, l);
  mj.v_WM = Vec3(0.4, 0, -ldot);  // the sideways velocity does not change l
}

TEST(Rope, TensionLaw) {
  // EA = 1e6 N, 2 falls, L0 = 10 m, l = 5.01 m: eps = (10.02 - 10) / 10 = 2e-3,
  // T = 2000 N, the hook carries n T = 4000 N
  const Rope rope("r", testing::TestRopeLaw(1e6, 2, 0.0, 10.0));
  MarkerState mi, mj;
  RopeTestMarkers(5.01, 0.0, mi, mj);
  Vec12 w = testing::Wrench(rope, mi, mj, 0.0);
  EXPECT_NEAR(w(2), -4000.0, 1e-6);  // i pulled down towards the hook
  EXPECT_NEAR(w(8), 4000.0, 1e-6);   // the hook pulled up
  EXPECT_NEAR(w.segment<3>(0).norm() + w.segment<3>(6).norm(), 8000.0, 1e-6);
  EXPECT_NEAR(rope.PotentialEnergy(mi, mj, 0.0), 0.5 * 1e6 * 10.0 * 4e-6, 1e-9);
  // three falls at the same hook position: eps = (15.03 - 10) / 10
  const Rope three("r3", testing::TestRopeLaw(1e6, 3, 0.0, 10.0));
  w = testing::Wrench(three, mi, mj, 0.0);
  EXPECT_NEAR(w(8), 3.0 * 1e6 * 0.503, 1e-5);
  // slack: n l < L0, no force and no energy
  RopeTestMarkers(4.99, 0.0, mi, mj);
  EXPECT_EQ(testing::Wrench(rope, mi, mj, 0.0).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(rope.PotentialEnergy(mi, mj, 0.0), 0.0);
}

TEST(Rope, DampingAddsAndIsClampedAtZero) {
  // beta = 0.01 s, eps = 2e-3; separating at 0.1 m/s: d(eps)/dt = 2 * 0.1 / 10
  // = 0.02, T = 1e6 (2e-3 + 0.01 * 0.02) = 2200 N
  const Rope rope("r", testing::TestRopeLaw(1e6, 2, 0.01, 10.0));
  MarkerState mi, mj;
  RopeTestMarkers(5.01, 0.1, mi, mj);
  EXPECT_NEAR(testing::Wrench(rope, mi, mj, 0.0)(8), 2.0 * 2200.0, 1e-6);
  // closing at 1.5 m/s: 1e6 (2e-3 - 0.01 * 0.3) < 0: no push
  RopeTestMarkers(5.01, -1.5, mi, mj);
  ForceEval e;
  rope.Evaluate(mi, mj, 0.0, e);
  EXPECT_EQ(e.wrench.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(e.K.cwiseAbs().maxCoeff() + e.C.cwiseAbs().maxCoeff(), 0.0);
  // slack and separating fast: the damper does not pull
  RopeTestMarkers(4.99, 5.0, mi, mj);
  EXPECT_EQ(testing::Wrench(rope, mi, mj, 0.0).cwiseAbs().maxCoeff(), 0.0);
}

TEST(Rope, TangentsMatchFiniteDifferences) {
  std::mt19937 rng(19);
  for (int trial = 0; trial < 20; ++trial) {
    MarkerState mi = testing::RandomMarker(rng), mj = testing::RandomMarker(rng);
    const int n = 1 + trial % 3;
    const double l = (mj.p_WM - mi.p_WM).norm();
    if (l < 0.5) continue;  // keeps the damping below the elastic tension
    // stretched by 2 % .. 10 %; with and without damping and hoisting
    RopeLaw law = testing::TestRopeLaw(5e3, n, trial % 2 ? 5e-4 : 0.0, n * l / (1.02 + 0.004 * trial));
    if (trial % 4 >= 2) {
      law.free_length += 0.3 * 0.7;  // the same L0 at t = 0.7 s
      law.hoist_speed = std::make_shared<ConstantFunction>(0.3);
    }
    const Rope rope("r", law);
    // a damped rope keeps its tension positive for these velocities
    ForceEval e;
    rope.Evaluate(mi, mj, 0.7, e);
    ASSERT_GT(e.wrench.norm(), 0.0) << trial;
    testing::ExpectTangents(rope, mi, mj, 0.7);
    testing::ExpectThirdLaw(rope, mi, mj, 0.7);
    mi.v_WM.setZero();
    mj.v_WM.setZero();
    if (!law.hoist_speed) testing::ExpectPotentialGradient(rope, mi, mj, 0.7);
  }
}

TEST(Rope, FreeLengthFromHoistSpeed) {
  // v_h = 0.5 sin(t): L0(t) = 40 - 0.5 (1 - cos t), evaluated out of order
  RopeLaw law = testing::TestRopeLaw(1e6, 1, 0.0, 40.0);
  law.hoist_speed = std::make_shared<ExpressionFunction>("0.5*sin(t)");
  const Rope rope("r", law);
  double L0, L0dot;
  for (double t : {3.337, 0.25, 7.0051, 7.0049, 1.0}) {
    rope.FreeLength(t, L0, L0dot);
    EXPECT_NEAR(L0, 40.0 - 0.5 * (1.0 - std::cos(t)), 1e-12) << t;
    EXPECT_NEAR(L0dot, -0.5 * std::sin(t), 1e-8) << t;
  }
  // a trapezoidal manoeuvre (0 -> 2 m/s in 1 s, hold 3 s, down in 1 s):
  // 1 + 6 + 1 = 8 m reeled in
  RopeLaw trap = testing::TestRopeLaw(1e6, 1, 0.0, 10.0);
  trap.hoist_speed =
      std::make_shared<TableFunction>(std::vector<double>{0, 1, 4, 5}, std::vector<double>{0, 2, 2, 0},
                                      TableFunction::Interpolation::kLinear, false);
  const Rope hoist("h", trap);
  hoist.FreeLength(6.0, L0, L0dot);
  EXPECT_NEAR(L0, 2.0, 1e-12);
  hoist.FreeLength(2.5, L0, L0dot);
  EXPECT_NEAR(L0, 10.0 - 1.0 - 3.0, 1e-12);
  EXPECT_NEAR(L0dot, -2.0, 1e-12);
}

TEST(Rope, BadInputThrowsNamingTheRope) {
  auto expect = [](const RopeLaw& law, const char* part) {
    try {
      Rope r("hoist", law);
      ADD_FAILURE() << "no error for " << part;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("force 'hoist'"), std::string::npos) << what;
      EXPECT_NE(what.find(part), std::string::npos) << what;
    }
  };
  expect(testing::TestRopeLaw(0.0, 1, 0.0, 10.0), "axial_stiffness");
  expect(testing::TestRopeLaw(1e6, 0, 0.0, 10.0), "falls");
  expect(testing::TestRopeLaw(1e6, 1, -0.1, 10.0), "damping_time");
  expect(testing::TestRopeLaw(1e6, 1, 0.0, 0.0), "free length");
  // the winch reels in 1 m/s from 2 m: empty at t = 2 s
  RopeLaw law = testing::TestRopeLaw(1e6, 1, 0.0, 2.0);
  law.hoist_speed = std::make_shared<ConstantFunction>(1.0);
  const Rope rope("hoist", law);
  MarkerState mi, mj;
  RopeTestMarkers(1.0, 0.0, mi, mj);
  EXPECT_NO_THROW(testing::Wrench(rope, mi, mj, 1.9));
  try {
    testing::Wrench(rope, mi, mj, 2.5);
    ADD_FAILURE() << "no error for an empty winch";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("force 'hoist'"), std::string::npos) << e.what();
  }
}

const char* const kRopeTestModel =
    "ground:\n"
    "  markers:\n"
    "    - {name: head, position: [0, 0, 10]}\n"
    "bodies:\n"
    "  - name: hook\n"
    "    mass: 100\n"
    "    inertia: [1, 1, 1]\n"
    "    position: [0, 0, 4]\n"
    "    markers:\n"
    "      - {name: top, position: [0, 0, 0]}\n"
    "forces:\n";  // forces from line 12

TEST(Rope, ModelFileEntry) {
  auto m =
      LoadModelString(std::string(kRopeTestModel) +
                          "  - {name: r, type: rope, i: ground.head, j: hook.top, axial_stiffness: 2e7,\n"
                          "     falls: 4, damping_time: 0.01}\n"
                          "  - {name: h, type: rope, i: ground.head, j: hook.top, axial_stiffness: 1e6,\n"
                          "     free_length: 30, hoist_speed: {table: [[0, 0], [1, 0.5], [10, 0.5]]}}\n"
                          "  - {name: f, type: rope, i: ground.head, j: hook.top, axial_stiffness: 1e6,\n"
                          "     free_length: {expression: \"6 - 0.1*t\"}}\n",
                      "r.yaml");
  ASSERT_EQ(m->forces.size(), 3u);
  const auto& r = dynamic_cast<const Rope&>(*m->forces[0]);
  EXPECT_EQ(r.law().falls, 4);
  EXPECT_EQ(r.law().axial_stiffness, 2e7);
  EXPECT_EQ(r.law().damping_time, 0.01);
  EXPECT_NEAR(r.law().free_length, 4 * 6.0, 1e-12);  // unstretched at the start by default
  double L0, L0dot;
  dynamic_cast<const Rope&>(*m->forces[1]).FreeLength(3.0, L0, L0dot);
  EXPECT_NEAR(L0, 30.0 - 0.25 - 1.0, 1e-12);
  dynamic_cast<const Rope&>(*m->forces[2]).FreeLength(5.0, L0, L0dot);
  EXPECT_NEAR(L0, 5.5, 1e-12);
  EXPECT_NEAR(L0dot, -0.1, 1e-7);

  auto expect_error = [](const std::string& force, const char* part, const char* line = "r.yaml:12: ") {
    try {
      LoadModelString(std::string(kRopeTestModel) + force, "r.yaml");
      ADD_FAILURE() << "no error for " << force;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(line, 0), 0u) << what;
      EXPECT_NE(what.find(part), std::string::npos) << what;
    }
  };
  expect_error("  - {name: r, type: rope, i: ground.head, j: hook.top, axial_stiffness: 1e6, falls: 0}\n",
               "falls");
  expect_error("  - {name: r, type: rope, i: ground.head, j: hook.top}\n", "axial_stiffness");
  expect_error(
      "  - {name: r, type: rope, i: ground.head, j: hook.top, axial_stiffness: 1e6,\n"
      "     free_length: {expression: \"t\"}, hoist_speed: 1}\n",
      "free_length", "r.yaml:13: ");
}

}  // namespace
}  // namespace flexmb
