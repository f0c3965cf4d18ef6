// A reeved rope that feeds an ANCF hanging span (forces/reeved_rope.h,
// RopeSpan): the path's free length takes what the span's free length gains
// on n falls; its pull on the span's payout marker is minus the energy's
// derivative, and K and C match central differences, with and without a
// drum; bad input is named.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/forces/reeved_rope.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/math/rotation.h"
#include "flexmb/model_file/model_file.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

ForceEval SpanEval(const ReevedRope& rope, const std::vector<MarkerState>& ms, bool tangents = true) {
  ForceEval e;
  const int n = 6 * static_cast<int>(ms.size());
  e.wrench_n.setZero(n);
  e.K_n.setZero(n, n);
  e.C_n.setZero(n, n);
  e.tangents = tangents;
  std::vector<const MarkerState*> p;
  for (const MarkerState& m : ms) p.push_back(&m);
  rope.EvaluateMarkers(p.data(), 0.0, e);
  return e;
}

double SpanEnergy(const ReevedRope& rope, const std::vector<MarkerState>& ms) {
  std::vector<const MarkerState*> p;
  for (const MarkerState& m : ms) p.push_back(&m);
  return rope.PotentialEnergyMarkers(p.data(), 0.0);
}

// the span's payout marker: L along world x, its rate along x
MarkerState Payout(double L, double Ldot) {
  MarkerState m;
  m.p_WM = Vec3(L, 0, 0);
  m.v_WM = Vec3(Ldot, 0, 0);
  return m;
}

TEST(ReevedRopeSpan, PullOnThePayoutIsTheSpansShareOfTheTension) {
  // exit (0,0,0) to sheave (0,0,20); span 10 m at the start, now 10.5 m on
  // 2 falls: the path's free length 19.9 - 2 * 0.5 = 18.9 m
  const ReevedRope rope("r", testing::TestRopeLaw(1e6, 2, 0.0, 19.9), 2, RopeDrum{}, RopeSpan{true, 10.0});
  std::vector<MarkerState> ms(3);
  ms[1].p_WM = Vec3(0, 0, 20);
  ms[2] = Payout(10.5, 0.0);
  const ForceEval e = SpanEval(rope, ms);
  const double eps = 20.0 / 18.9 - 1.0, T = 1e6 * eps;
  EXPECT_NEAR(e.wrench_n(2), T, 1e-6 * T);      // exit pulled towards the sheave
  EXPECT_NEAR(e.wrench_n(8), -T, 1e-6 * T);     // the sheave towards the exit (one segment)
  // the span hauled in by both falls: -2 EA eps (1 + eps / 2)
  EXPECT_NEAR(e.wrench_n(12), -2.0 * T * (1.0 + 0.5 * eps), 1e-6 * T);
  // the same without tangents
  EXPECT_NEAR(SpanEval(rope, ms, false).wrench_n(12), e.wrench_n(12), 1e-9 * T);
  // slack when the span took in rope
  ms[2] = Payout(9.0, 0.0);
  EXPECT_EQ(SpanEval(rope, ms).wrench_n.cwiseAbs().maxCoeff(), 0.0);
}

TEST(ReevedRopeSpan, WrenchIsMinusTheEnergyGradientAndTangentsMatchFiniteDifferences) {
  std::mt19937 rng(41);
  RevoluteJoint joint("winch");
  for (int drum = 0; drum < 2; ++drum)
    for (int trial = 0; trial < 6; ++trial) {
      const int path = 2 + trial % 2, falls = 1 + trial % 3;
      std::vector<MarkerState> ms;
      for (int k = 0; k < path; ++k) ms.push_back(testing::RandomMarker(rng));
      double l = 0.0;
      for (int s = 0; s + 1 < path; ++s) l += (ms[s + 1].p_WM - ms[s].p_WM).norm();
      const double angle = std::uniform_real_distribution<double>(-3.0, 3.0)(rng);
      RopeDrum d;
      if (drum) {
        d = RopeDrum{&joint, 0.2};
        ms.resize(path + 2);
        MarkerState& di = ms[path];
        MarkerState& dj = ms[path + 1];
        di = testing::RandomMarker(rng);
        dj = testing::RandomMarker(rng);
        dj.p_WM = di.p_WM;
        dj.R_WM = di.R_WM * ExpSO3(Vec3(0, 0, angle));
      }
      ms.push_back(Payout(7.3, std::uniform_real_distribution<double>(-0.5, 0.5)(rng)));
      // taut: the path's free length 4 % short of the path
      const double L0 = l / 1.04 - (drum ? 0.2 * angle : 0.0) + falls * (7.3 - 7.0);
      for (double beta : {0.0, 0.002}) {
        const ReevedRope rope("r", testing::TestRopeLaw(1e5, falls, beta, L0), path, d, RopeSpan{true, 7.0});
        const ForceEval e = SpanEval(rope, ms);
        ASSERT_GT(std::abs(e.wrench_n(e.wrench_n.size() - 6)), 1e2) << "no pull on the span";
        MatX Kfd, Cfd;
        const double h = 1e-6;
        testing::MarkerFiniteDifferences([&](const std::vector<MarkerState>& x) { return SpanEval(rope, x).wrench_n; },
                                         ms, h, Kfd, Cfd);
        // the elastic wrench is minus the energy's gradient
        for (int c = 0; beta == 0.0 && c < 6 * static_cast<int>(ms.size()); ++c) {
          std::vector<MarkerState> p = ms, m = ms;
          p[c / 6] = testing::Perturbed(ms[c / 6], c % 6, h);
          m[c / 6] = testing::Perturbed(ms[c / 6], c % 6, -h);
          const double grad = (SpanEnergy(rope, p) - SpanEnergy(rope, m)) / (2 * h);
          EXPECT_NEAR(e.wrench_n(c), -grad, 1e-6 * e.wrench_n.cwiseAbs().maxCoeff()) << "component " << c;
        }
        EXPECT_LT((e.K_n - Kfd).cwiseAbs().maxCoeff(), 1e-6 * std::max(1.0, Kfd.cwiseAbs().maxCoeff()))
            << "drum " << drum << " path " << path << " beta " << beta;
        EXPECT_LT((e.C_n - Cfd).cwiseAbs().maxCoeff(), 1e-6 * std::max(1.0, Cfd.cwiseAbs().maxCoeff()))
            << "drum " << drum << " path " << path << " beta " << beta;
      }
    }
}

// with damping, the rope's power on its markers (drum and span included)
// is -dV/dt - beta EA L0 eps_dot^2 (the dissipation function's rate)
TEST(ReevedRopeSpan, DampingOnlyDissipates) {
  std::mt19937 rng(7);
  RevoluteJoint joint("winch");
  std::vector<MarkerState> ms = {testing::RandomMarker(rng), testing::RandomMarker(rng)};
  ms.resize(4);
  ms[2] = testing::RandomMarker(rng);
  ms[3] = testing::RandomMarker(rng);
  ms[3].p_WM = ms[2].p_WM;
  ms[3].R_WM = ms[2].R_WM * ExpSO3(Vec3(0, 0, 0.8));
  ms.push_back(Payout(5.2, 0.37));
  const double l = (ms[1].p_WM - ms[0].p_WM).norm(), beta = 0.01, EA = 1e5, R = 0.25, n = 2;
  const double L0 = l / 1.03 - R * 0.8 + n * (5.2 - 5.0);  // free length at theta = 0, span at its start
  const ReevedRope rope("d", testing::TestRopeLaw(EA, 2, beta, L0), 2, RopeDrum{&joint, R}, RopeSpan{true, 5.0});
  const ForceEval e = SpanEval(rope, ms);
  const double power = testing::MarkerPower(e.wrench_n, ms);
  const double dt = 1e-6;
  const double Vdot =
      (SpanEnergy(rope, testing::MarkersMoved(ms, dt)) - SpanEnergy(rope, testing::MarkersMoved(ms, -dt))) / (2 * dt);
  // eps_dot from the rates: path, drum and span
  const Vec3 u = (ms[1].p_WM - ms[0].p_WM) / l;
  const double ldot = u.dot(ms[1].v_WM - ms[0].v_WM);
  const double thdot = ms[2].R_WM.col(2).dot(ms[3].w_WM - ms[2].w_WM);
  const double L0now = L0 + R * 0.8 - n * (5.2 - 5.0), L0dot = R * thdot - n * 0.37;
  const double eps_dot = ldot / L0now - l * L0dot / (L0now * L0now);
  const double dissipation = beta * EA * L0now * eps_dot * eps_dot;
  EXPECT_GT(dissipation, 1e-3);
  EXPECT_NEAR(power, -Vdot - dissipation, 1e-6 * (std::abs(Vdot) + dissipation));
}

TEST(ReevedRopeSpan, BadSpanInputIsNamed) {
  const auto message = [](auto&& make) { return testing::InputErrorMessage(make); };
  EXPECT_NE(message([] { ReevedRope("hoist", testing::TestRopeLaw(1e6, 2, 0.0, 10.0), 2, RopeDrum{}, RopeSpan{true, 0.0}); })
                .find("span's free length must be > 0"),
            std::string::npos);
  // the span took more than the path holds
  const ReevedRope rope("hoist", testing::TestRopeLaw(1e6, 2, 0.0, 1.0), 2, RopeDrum{}, RopeSpan{true, 5.0});
  std::vector<MarkerState> ms(3);
  ms[1].p_WM = Vec3(0, 0, 2.0);
  ms[2] = Payout(5.6, 0.0);
  EXPECT_NE(message([&] { SpanEval(rope, ms); }).find("after what the span took"), std::string::npos);
}

constexpr const char* kSpanModel =
    "ground:\n"
    "  markers:\n"
    "    - {name: exit, position: [-20, 0, 0]}\n"
    "    - {name: sheave, position: [0, 0, 20]}\n"
    "bodies:\n"
    "  - {name: span, type: ancf_hoist_rope, free_length: 10, stored_length: 20, elements: 4,\n"
    "     section: {area: 1e-4, inertia: 1e-10}, material: {E: 1e11, rho: 8000}, start: [0, 0, 20],\n"
    "     markers: [{name: top, end: start}]}\n"
    "  - {name: hooked, type: ancf_hoist_rope, free_length: 10, elements: 2,\n"
    "     section: {area: 1e-4, inertia: 1e-10}, material: {E: 1e11, rho: 8000},\n"
    "     drum: {position: [0, 0, 0], radius: 0.3, inertia: 1}}\n"
    "forces:\n";

TEST(ReevedRopeSpan, ModelFileEntryAndBadInput) {
  auto m = LoadModelString(std::string(kSpanModel) +
                               "  - {name: r, type: rope, path: [ground.exit, ground.sheave], span: span, falls: 2,\n"
                               "     axial_stiffness: 1e7}\n",
                           "s.yaml");
  const auto& r = dynamic_cast<const ReevedRope&>(*m->forces[0]);
  EXPECT_TRUE(r.span().present);
  EXPECT_EQ(r.span().free_length, 10.0);
  EXPECT_EQ(r.NumMarkers(), 3);
  EXPECT_EQ(r.MarkerAt(2), m->FindMarker("span.payout"));
  EXPECT_NEAR(r.law().free_length, std::sqrt(800.0), 1e-12);  // the path unstretched, once (not on the falls)

  // errors at the rope (line 13) or at the span body (line 6)
  auto expect_error = [](const std::string& forces, const char* part, const char* at = "s.yaml:13: ") {
    testing::ExpectModelError(std::string(kSpanModel) + forces, "s.yaml", at, part);
  };
  expect_error("  - {name: r, type: rope, path: [ground.exit, ground.sheave], span: hooked, axial_stiffness: 1e7}\n",
               "has a 'drum' of its own");
  expect_error("  - {name: r, type: rope, path: [ground.exit, ground.sheave], span: ground, axial_stiffness: 1e7}\n",
               "is not an ancf_hoist_rope");
  expect_error("  - {name: r, type: rope, path: [ground.exit, ground.sheave], span: span, hoist_speed: 0.1,\n"
               "     axial_stiffness: 1e7}\n",
               "neither 'hoist_speed'");
  expect_error("  - {name: r, type: rope, path: [ground.exit, ground.sheave], span: span,\n"
               "     free_length: {expression: '30 - t'}, axial_stiffness: 1e7}\n",
               "neither 'hoist_speed'");

  // who pays the drum-less span out: exactly one rope or winch
  const char* at_span = "s.yaml:6: body 'span': ";
  expect_error("  []\n", "nothing pays it out", at_span);
  expect_error("  - {name: r, type: rope, path: [ground.exit, ground.sheave], span: span, axial_stiffness: 1e7}\n"
                    "  - {name: q, type: rope, path: [ground.exit, ground.sheave], span: span, axial_stiffness: 1e7}\n",
                    "rope 'r' and rope 'q'", at_span);
  expect_error("  - {name: r, type: rope, path: [ground.exit, ground.sheave], span: span, axial_stiffness: 1e7}\n"
                    "drivers:\n  - {name: w, type: winch, rope: span}\n",
                    "rope 'r' and winch driver 'w'", at_span);
  // a winch alone pays it out
  EXPECT_NO_THROW(LoadModelString(std::string(kSpanModel) + "  []\ndrivers:\n  - {name: w, type: winch, rope: span}\n",
                                  "s.yaml"));
}

}  // namespace
}  // namespace flexmb
