// The rope reeved over sheaves onto a winch drum: tension along the path
// (falls on the last segment), the drum torque, K and C against central
// differences with and without a drum, the potential gradient, the power
// balance (elastic power + dissipation), unwrapping of the drum angle over
// several turns, and bad input.

#include "flexmb/forces/reeved_rope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/math/rotation.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/solver/simulator.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

/// Evaluates the rope on the marker states `ms` (with tangents).
ForceEval ReevedEval(const ReevedRope& rope, const std::vector<MarkerState>& ms, double t) {
  ForceEval e;
  const int n = 6 * static_cast<int>(ms.size());
  e.wrench_n.setZero(n);
  e.K_n.setZero(n, n);
  e.C_n.setZero(n, n);
  std::vector<const MarkerState*> p;
  for (const MarkerState& m : ms) p.push_back(&m);
  rope.EvaluateMarkers(p.data(), t, e);
  return e;
}

double ReevedEnergy(const ReevedRope& rope, const std::vector<MarkerState>& ms, double t) {
  std::vector<const MarkerState*> p;
  for (const MarkerState& m : ms) p.push_back(&m);
  return rope.PotentialEnergyMarkers(p.data(), t);
}

/// Drum markers: i with a random orientation, j on it turned by `angle`
/// about z_i, both with random twists.
void ReevedDrumMarkers(std::mt19937& rng, double angle, MarkerState& di, MarkerState& dj) {
  di = testing::RandomMarker(rng);
  dj = testing::RandomMarker(rng);
  dj.p_WM = di.p_WM;
  dj.R_WM = di.R_WM * ExpSO3(Vec3(0, 0, angle));
}

TEST(ReevedRope, TensionAlongThePathAndOnTheFalls) {
  // winch exit (0,0,2), sheave (10,0,12), hook 9 m below on 2 falls:
  // l = 10 sqrt(2) + 2 * 9; L0 = l / 1.002: eps = 2e-3, T = 2000 N
  const double l = 10.0 * std::sqrt(2.0) + 18.0;
  const ReevedRope rope("r", testing::TestRopeLaw(1e6, 2, 0.0, l / 1.002), 3);
  std::vector<MarkerState> ms(3);
  ms[0].p_WM = Vec3(0, 0, 2);
  ms[1].p_WM = Vec3(10, 0, 12);
  ms[2].p_WM = Vec3(10, 0, 3);
  const ForceEval e = ReevedEval(rope, ms, 0.0);
  const double T = 1e6 * (1.002 - 1.0);
  const Vec3 u(1.0 / std::sqrt(2.0), 0, 1.0 / std::sqrt(2.0));
  EXPECT_LT((e.wrench_n.segment<3>(0) - T * u).norm(), 1e-6);                        // winch pulled up the rope
  EXPECT_LT((e.wrench_n.segment<3>(6) - (-T * u + Vec3(0, 0, -2 * T))).norm(), 1e-6);  // sheave: both spans
  EXPECT_LT((e.wrench_n.segment<3>(12) - Vec3(0, 0, 2 * T)).norm(), 1e-6);            // hook on 2 falls
  EXPECT_NEAR(ReevedEnergy(rope, ms, 0.0), 0.5 * 1e6 * (l / 1.002) * 4e-6, 1e-9);
  // slack
  const ReevedRope slack("s", testing::TestRopeLaw(1e6, 2, 0.0, l + 1e-3), 3);
  EXPECT_EQ(ReevedEval(slack, ms, 0.0).wrench_n.cwiseAbs().maxCoeff(), 0.0);
}

TEST(ReevedRope, DrumTorqueIsTheEnergyDerivative) {
  // drum of radius 0.3 m turned by 0.5 rad pays out 0.15 m: L0 = 20.15 m
  RevoluteJoint joint("winch");
  const ReevedRope rope("r", testing::TestRopeLaw(2e6, 1, 0.0, 20.0), 2, RopeDrum{&joint, 0.3});
  std::vector<MarkerState> ms(4);
  ms[0].p_WM = Vec3(0, 0, 0);
  ms[1].p_WM = Vec3(0, 0, -20.2);
  ms[3].R_WM = ExpSO3(Vec3(0, 0, 0.5));
  const ForceEval e = ReevedEval(rope, ms, 0.0);
  const double L0 = 20.15, eps = 20.2 / L0 - 1.0, T = 2e6 * eps;
  EXPECT_NEAR(e.wrench_n(8), T, 1e-6);
  // torque on the drum about z: R T (1 + eps / 2), the reaction on its frame
  EXPECT_NEAR(e.wrench_n(6 * 3 + 5), 0.3 * T * (1.0 + 0.5 * eps), 1e-6);
  EXPECT_NEAR(e.wrench_n(6 * 2 + 5), -0.3 * T * (1.0 + 0.5 * eps), 1e-6);
}

TEST(ReevedRope, TangentsMatchFiniteDifferences) {
  std::mt19937 rng(23);
  RevoluteJoint joint("winch");
  for (int drum = 0; drum < 2; ++drum)
    for (int trial = 0; trial < 8; ++trial) {
      const int path = 2 + trial % 3;
      std::vector<MarkerState> ms;
      for (int k = 0; k < path; ++k) ms.push_back(testing::RandomMarker(rng));
      double l = 0.0;
      for (int s = 0; s + 1 < path; ++s) l += (s + 2 == path ? 3 : 1) * (ms[s + 1].p_WM - ms[s].p_WM).norm();
      const double angle = std::uniform_real_distribution<double>(-3.0, 3.0)(rng);
      RopeDrum d;
      if (drum) {
        d = RopeDrum{&joint, 0.2};
        ms.resize(path + 2);
        ReevedDrumMarkers(rng, angle, ms[path], ms[path + 1]);
      }
      // taut: free length 5 % short of the path; damping with a kept sign
      const double L0 = l / 1.05 - (drum ? 0.2 * angle : 0.0);
      const ReevedRope rope("r", testing::TestRopeLaw(1e5, 3, 0.002, L0), path, d);
      const ForceEval e = ReevedEval(rope, ms, 0.0);
      ASSERT_GT(e.wrench_n.cwiseAbs().maxCoeff(), 1e-3) << "trivial wrench";
      MatX Kfd, Cfd;
      testing::MarkerFiniteDifferences([&](const std::vector<MarkerState>& x) { return ReevedEval(rope, x, 0.0).wrench_n; },
                                       ms, 1e-6, Kfd, Cfd);
      const double scale = std::max(1.0, Kfd.cwiseAbs().maxCoeff());
      EXPECT_LT((e.K_n - Kfd).cwiseAbs().maxCoeff(), 1e-6 * scale) << "drum " << drum << " path " << path;
      EXPECT_LT((e.C_n - Cfd).cwiseAbs().maxCoeff(), 1e-6 * std::max(1.0, Cfd.cwiseAbs().maxCoeff()))
          << "drum " << drum << " path " << path;
    }
}

TEST(ReevedRope, ElasticWrenchIsMinusTheEnergyGradientAndDampingDissipates) {
  std::mt19937 rng(5);
  RevoluteJoint joint("winch");
  std::vector<MarkerState> ms = {testing::RandomMarker(rng), testing::RandomMarker(rng), testing::RandomMarker(rng)};
  ms.resize(5);
  ReevedDrumMarkers(rng, 1.2, ms[3], ms[4]);
  const double l = (ms[1].p_WM - ms[0].p_WM).norm() + 2.0 * (ms[2].p_WM - ms[1].p_WM).norm();
  const double L0 = l / 1.03 - 0.25 * 1.2;
  const ReevedRope elastic("e", testing::TestRopeLaw(1e5, 2, 0.0, L0), 3, RopeDrum{&joint, 0.25});
  const ForceEval e = ReevedEval(elastic, ms, 0.0);
  const double h = 1e-6;
  for (int c = 0; c < 30; ++c) {
    std::vector<MarkerState> p = ms, m = ms;
    p[c / 6] = testing::Perturbed(ms[c / 6], c % 6, h);
    m[c / 6] = testing::Perturbed(ms[c / 6], c % 6, -h);
    const double grad = (ReevedEnergy(elastic, p, 0.0) - ReevedEnergy(elastic, m, 0.0)) / (2 * h);
    EXPECT_NEAR(e.wrench_n(c), -grad, 1e-6 * e.wrench_n.cwiseAbs().maxCoeff()) << "component " << c;
  }
  // with damping, the rope's power on the markers is -dV/dt - beta EA L0 eps_dot^2
  const double beta = 0.01;
  const ReevedRope damped("d", testing::TestRopeLaw(1e5, 2, beta, L0), 3, RopeDrum{&joint, 0.25});
  const ForceEval ed = ReevedEval(damped, ms, 0.0);
  const double power = testing::MarkerPower(ed.wrench_n, ms);
  double ldot = 0.0;
  // dV/dt along the motion from central differences in time
  const double dt = 1e-6;
  const double Vdot = (ReevedEnergy(damped, testing::MarkersMoved(ms, dt), 0.0) -
                       ReevedEnergy(damped, testing::MarkersMoved(ms, -dt), 0.0)) /
                      (2 * dt);
  const Vec3 a = ms[3].R_WM.col(2);
  const double thdot = a.dot(ms[4].w_WM - ms[3].w_WM);
  for (int s = 0; s < 2; ++s) {
    const Vec3 d = ms[s + 1].p_WM - ms[s].p_WM;
    ldot += (s == 1 ? 2.0 : 1.0) * d.normalized().dot(ms[s + 1].v_WM - ms[s].v_WM);
  }
  const double L0now = L0 + 0.25 * 1.2, lnow = l;
  const double eps_dot = ldot / L0now - lnow * 0.25 * thdot / (L0now * L0now);
  const double dissipation = beta * 1e5 * L0now * eps_dot * eps_dot;
  EXPECT_GT(dissipation, 1e-3);
  EXPECT_NEAR(power, -Vdot - dissipation, 1e-6 * (std::abs(Vdot) + dissipation));
}

TEST(ReevedRope, DrumAngleIsUnwrappedOverTurns) {
  // 3.5 turns in steps of 0.3 rad pay out 2 pi 3.5 R of rope
  RevoluteJoint joint("winch");
  const double R = 0.2;
  const ReevedRope rope("r", testing::TestRopeLaw(1e6, 1, 0.0, 10.0), 2, RopeDrum{&joint, R});
  std::vector<MarkerState> ms(4);
  ms[1].p_WM = Vec3(0, 0, -30.0);
  double angle = 0.0;
  for (; angle < 7.0 * M_PI; angle += 0.3) {
    ms[3].R_WM = ExpSO3(Vec3(0, 0, angle));
    ReevedEval(rope, ms, 0.0);
  }
  angle -= 0.3;
  const double L0 = 10.0 + R * angle, eps = 30.0 / L0 - 1.0;
  EXPECT_NEAR(ReevedEval(rope, ms, 0.0).wrench_n(2), -1e6 * eps, 1e-6 * 1e6 * eps);  // P_0 pulled down
}

TEST(ReevedRope, BadInputIsNamed) {
  RevoluteJoint joint("winch");
  const auto message = [](auto&& make) { return testing::InputErrorMessage(make); };
  EXPECT_NE(message([&] { ReevedRope("hoist", testing::TestRopeLaw(1e6, 1, 0.0, 10.0), 2, RopeDrum{&joint, 0.0}); })
                .find("drum radius"), std::string::npos);
  EXPECT_NE(message([&] { ReevedRope("hoist", testing::TestRopeLaw(1e6, 1, 0.0, 10.0), 2, RopeDrum{&joint, -0.1}); })
                .find("hoist"), std::string::npos);
  EXPECT_NE(message([&] { ReevedRope("hoist", testing::TestRopeLaw(1e6, 1, 0.0, 10.0), 1); }).find("two markers"),
            std::string::npos);
  // paying in more than there is
  const ReevedRope rope("hoist", testing::TestRopeLaw(1e6, 1, 0.0, 1.0), 2, RopeDrum{&joint, 0.5});
  std::vector<MarkerState> ms(4);
  ms[1].p_WM = Vec3(0, 0, -3.0);
  ms[3].R_WM = ExpSO3(Vec3(0, 0, -2.5));
  EXPECT_NE(message([&] { ReevedEval(rope, ms, 0.0); }).find("drum would be empty"), std::string::npos);
}

constexpr const char* kReevedTestModel =
    "ground:\n"
    "  markers:\n"
    "    - {name: exit, position: [-4, 0, 1]}\n"
    "    - {name: sheave, position: [0, 0, 10]}\n"
    "    - {name: axle, position: [-4, 0, 0.8], orientation: {z_axis: [0, 1, 0]}}\n"
    "bodies:\n"
    "  - name: drum\n"
    "    mass: 100\n"
    "    inertia: [5, 5, 5]\n"
    "    position: [-4, 0, 0.8]\n"
    "    markers: [{name: axle, orientation: {z_axis: [0, 1, 0]}}]\n"
    "  - name: hook\n"
    "    mass: 100\n"
    "    inertia: [1, 1, 1]\n"
    "    position: [0, 0, 4]\n"
    "    markers: [{name: top}]\n"
    "joints:\n"
    "  - {name: winch, type: revolute, i: ground.axle, j: drum.axle}\n"
    "  - {name: slide, type: prismatic, i: ground.sheave, j: hook.top}\n"
    "forces:\n";

TEST(ReevedRope, ModelFileEntry) {
  auto m = LoadModelString(std::string(kReevedTestModel) +
                               "  - {name: r, type: rope, path: [ground.exit, ground.sheave, hook.top], falls: 2,\n"
                               "     drum: {joint: winch, radius: 0.3}, axial_stiffness: 2e7}\n",
                           "r.yaml");
  const auto& r = dynamic_cast<const ReevedRope&>(*m->forces[0]);
  EXPECT_EQ(r.path_markers(), 3);
  EXPECT_EQ(r.drum().radius, 0.3);
  EXPECT_EQ(r.NumMarkers(), 5);
  EXPECT_EQ(r.MarkerAt(3), m->joints[0]->marker_i);
  // unstretched at the start (free length sqrt(4^2 + 9^2) + 2 * 6 m): no force
  Simulator sim(*m);
  sim.Initialize();
  sim.RefreshWorkspace();
  EXPECT_EQ(sim.workspace().forces[0].wrench_n.cwiseAbs().maxCoeff(), 0.0);

  auto expect_error = [](const std::string& force, const char* part, const char* line = "r.yaml:21: ") {
    testing::ExpectModelError(std::string(kReevedTestModel) + force, "r.yaml", line, part);
  };
  expect_error("  - {name: r, type: rope, path: [ground.exit], axial_stiffness: 1e6}\n", "at least two markers");
  expect_error("  - {name: r, type: rope, path: [ground.exit, hook.nothing], axial_stiffness: 1e6}\n",
               "no marker named 'nothing'");
  expect_error("  - {name: r, type: rope, path: [ground.exit, hook.top], i: ground.exit, axial_stiffness: 1e6}\n",
               "not both");
  expect_error("  - {name: r, type: rope, path: [ground.exit, hook.top], drum: {joint: slide, radius: 0.3},\n"
               "     axial_stiffness: 1e6}\n", "first coordinate is not an angle");
  expect_error("  - {name: r, type: rope, path: [ground.exit, ground.exit, hook.top], axial_stiffness: 1e6}\n",
               "twice in a row");
  expect_error("  - {name: r, type: rope, path: [ground.exit, hook.top], drum: {joint: winch, radius: 0},\n"
               "     axial_stiffness: 1e6}\n", "drum radius must be finite and > 0, got 0 m");
  expect_error("  - {name: r, type: rope, path: [ground.exit, hook.top], drum: {joint: winch, radius: 0.3},\n"
               "     hoist_speed: 0.5, axial_stiffness: 1e6}\n", "hoist_speed", "r.yaml:22: ");
  expect_error("  - {name: r, type: rope, path: [ground.exit, hook.top], drum: {joint: none, radius: 0.3},\n"
               "     axial_stiffness: 1e6}\n", "no joint named 'none'");
}

}  // namespace
}  // namespace flexmb
