#include "flexmb/solver/linearization.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/statics.h"
#include "flexmb/solver/system_modes.h"

namespace flexmb {
namespace {

// a rod (2 kg, centre of mass at body x = 0.5 m, I_zz = 0.2 kg m^2 about
// it) pinned at its body origin to the world origin about z, hanging along
// -y under gravity 9.81 m/s^2; m finalized
void LinearizationPinnedRod(Model& m) {
  m.gravity_W = Vec3(0, -9.81, 0);
  RigidBodyData d;
  d.mass = 2.0;
  d.inertia_C = Vec3(0.01, 0.2, 0.2).asDiagonal();
  d.c_B = Vec3(0.5, 0, 0);
  d.R_WB = Eigen::AngleAxisd(-M_PI / 2 + 0.3, Vec3::UnitZ()).toRotationMatrix();
  const int b = m.AddBody(std::make_unique<RigidBody>("rod", d));
  m.AddJoint(std::make_unique<RevoluteJoint>("pin"), m.AddMarker(0, "o", Vec3::Zero(), Mat3::Identity()),
             m.AddMarker(b, "o", Vec3::Zero(), Mat3::Identity()));
  m.Finalize();
}

// the reduced system of the pendulum: one coordinate, Kr / Mr = m g d /
// (I_C + m d^2) (closed form), whatever the basis N
TEST(Linearization, PinnedRodAtItsEquilibrium) {
  Model m;
  LinearizationPinnedRod(m);
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  SolveStatics(m, s, ws);
  const LinearizedSystem L = Linearize(m, s, VecX::Zero(m.nv), ws);
  ASSERT_EQ(L.N.cols(), 1);
  EXPECT_EQ(L.constraint_rank, 5);
  EXPECT_LT((L.B * L.N).norm(), 1e-12);
  const double w2 = 2.0 * 9.81 * 0.5 / (0.2 + 2.0 * 0.25);
  EXPECT_NEAR(L.Kr(0, 0) / L.Mr(0, 0) / w2, 1.0, 1e-12);
  EXPECT_EQ(L.Cr(0, 0), 0.0);
  const std::vector<SystemMode> modes = SolveSystemModes(L);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_EQ(modes[0].kind, ModeKind::kOscillatory);
  EXPECT_NEAR(modes[0].frequency_hz * 2.0 * M_PI / std::sqrt(w2), 1.0, 1e-12);
}

// a damped oscillator through the first-order form: C = 2 zeta w M
TEST(Linearization, FirstOrderFormGivesDampingRatio) {
  LinearizedSystem L;
  L.N = MatX::Identity(1, 1);
  L.Mr = MatX::Constant(1, 1, 3.0);
  L.Kr = MatX::Constant(1, 1, 3.0 * 16.0);
  L.Cr = MatX::Constant(1, 1, 2.0 * 0.1 * 4.0 * 3.0);
  const std::vector<SystemMode> modes = SolveSystemModes(L);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_NEAR(modes[0].damping_ratio, 0.1, 1e-12);
  EXPECT_NEAR(modes[0].frequency_hz * 2.0 * M_PI, 4.0, 1e-12);
  EXPECT_NEAR(modes[0].damped_frequency_hz * 2.0 * M_PI, 4.0 * std::sqrt(1.0 - 0.01), 1e-12);
  // overdamped: two real decaying modes, s = -w (zeta -+ sqrt(zeta^2 - 1))
  L.Cr(0, 0) = 2.0 * 2.0 * 4.0 * 3.0;
  const std::vector<SystemMode> slow = SolveSystemModes(L);
  ASSERT_EQ(slow.size(), 2u);
  EXPECT_EQ(slow[0].kind, ModeKind::kOverdamped);
  EXPECT_NEAR(slow[0].eigenvalue.real(), -4.0 * (2.0 - std::sqrt(3.0)), 1e-10);
  EXPECT_NEAR(slow[1].eigenvalue.real(), -4.0 * (2.0 + std::sqrt(3.0)), 1e-10);
}

}  // namespace
}  // namespace flexmb
