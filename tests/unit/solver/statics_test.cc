#include "flexmb/solver/statics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/forces/plane_contact.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

// a rod of 2 kg (centre of mass at body x = 0.5 m) pinned at its body
// origin to the world origin by a revolute joint about z, turned by angle_z
// [rad] about z from body x = world x; gravity 9.81 m/s^2 along -y; m
// finalized. Returns the rod's body index.
int StaticsPinnedRod(Model& m, double angle_z) {
  m.gravity_W = Vec3(0, -9.81, 0);
  RigidBodyData d;
  d.mass = 2.0;
  d.inertia_C = Vec3(0.01, 0.2, 0.2).asDiagonal();
  d.c_B = Vec3(0.5, 0, 0);
  d.R_WB = Eigen::AngleAxisd(angle_z, Vec3::UnitZ()).toRotationMatrix();
  const int b = m.AddBody(std::make_unique<RigidBody>("rod", d));
  m.AddJoint(std::make_unique<RevoluteJoint>("pin"), m.AddMarker(0, "o", Vec3::Zero(), Mat3::Identity()),
             m.AddMarker(b, "o", Vec3::Zero(), Mat3::Identity()));
  m.Finalize();
  return b;
}

// A pendulum released at 60 degrees from the downward vertical hangs straight
// down at equilibrium; the pin carries m g.
TEST(Statics, PendulumHangsDownWithPinForceMg) {
  Model m;
  const int b = StaticsPinnedRod(m, -M_PI / 2 + M_PI / 3);  // 60 deg from hanging
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  const StaticsResult r = SolveStatics(m, s, ws);
  EXPECT_LT(r.iterations, 30);
  const Body& rod = *m.bodies[b];
  Vec3 p;
  Mat3 R;
  rod.BodyFramePose(s.q.data() + rod.q_offset, p, R);
  // body x axis points straight down
  EXPECT_LT((R.col(0) - Vec3(0, -1, 0)).norm(), 1e-8);
  // constraint force on the rod, -B^T lambda, balances gravity: |lambda_y| = m g
  EXPECT_NEAR(std::abs(s.lambda(1)), 2.0 * 9.81, 1e-8);
}

// Newton limited to one iteration per load increment cannot converge: the
// increments are halved below min_increment and the error names the load
// factor reached and a body coordinate or joint equation; the state is
// back at the last equilibrium of the continuation (the start).
TEST(Statics, FailureNamesLoadFactorAndEntityAndRestoresState) {
  Model m;
  const int b = StaticsPinnedRod(m, -M_PI / 6);
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  const VecX q0 = s.q;
  StaticsSettings set;
  set.max_iterations = 1;
  set.min_increment = 0.3;
  try {
    SolveStatics(m, s, ws, set);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("beyond load factor 0 of 1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("load increment below 0.3"), std::string::npos) << msg;
    EXPECT_TRUE(msg.find("body 'rod'") != std::string::npos || msg.find("joint 'pin'") != std::string::npos) << msg;
  }
  EXPECT_EQ((s.q - q0).norm(), 0.0);
  // with the defaults: the full load at once, one increment, no cut
  const StaticsResult r = SolveStatics(m, s, ws);
  EXPECT_EQ(r.increments, 1);
  EXPECT_EQ(r.cuts, 0);
  Vec3 p;
  Mat3 R;
  m.bodies[b]->BodyFramePose(s.q.data() + m.bodies[b]->q_offset, p, R);
  EXPECT_LT((R.col(0) - Vec3(0, -1, 0)).norm(), 1e-8);
}

// A free body under gravity has no static equilibrium: the error names it.
TEST(Statics, FreeBodyIsNamed) {
  Model m;
  RigidBodyData d;
  d.mass = 1.0;
  d.inertia_C = Mat3::Identity();
  m.AddBody(std::make_unique<RigidBody>("floating_box", d));
  m.Finalize();
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  try {
    SolveStatics(m, s, ws);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("floating_box"), std::string::npos) << e.what();
  }
}

// A block standing on four ground contacts: vertical, roll and pitch have
// contact stiffness, but only the friction (damping, at rest) holds it
// sideways and in yaw. Statics settles it at the penetration m g / (4 k)
// without moving it sideways; without friction it is a neutral equilibrium
// sideways (kept in place by the inertia hold) unless a load pushes it
// there; with the hold switched off the sideways freedom is a free motion,
// named.
void StaticsBlockOnGround(Model& m, double mu, const Vec3& v_WB = Vec3::Zero()) {
  RigidBodyData d;
  d.mass = 400.0;
  d.inertia_C = Mat3::Identity() * 50.0;
  d.p_WB = Vec3(0.3, -0.2, 0.2499);
  d.v_WB = v_WB;
  const int b = m.AddBody(std::make_unique<RigidBody>("block", d));
  PlaneContactLaw law;
  law.stiffness = 2e6;
  law.damping = 1e4;
  law.friction = mu;
  int n = 0;
  for (const double x : {-0.5, 0.5})
    for (const double y : {-0.5, 0.5}) {
      const std::string name = "c" + std::to_string(n++);
      m.AddForce(std::make_unique<PlaneContact>(name, law), m.AddMarker(b, name, Vec3(x, y, -0.25), Mat3::Identity()),
                 -1);
    }
  m.Finalize();
}

TEST(Statics, DampingHoldsDirectionsWithoutStiffness) {
  Model m;
  StaticsBlockOnGround(m, 0.5);
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  SolveStatics(m, s, ws);
  const double g = -m.gravity_W.z();
  EXPECT_NEAR(s.q(2), 0.25 - 400.0 * g / (4 * 2e6), 1e-12);
  EXPECT_NEAR(s.q(0), 0.3, 1e-12);
  EXPECT_NEAR(s.q(1), -0.2, 1e-12);

  // no friction: nothing holds it sideways, nothing pushes it either: a
  // neutral equilibrium, kept where it is by the inertia hold
  Model free;
  StaticsBlockOnGround(free, 0.0);
  State s2 = free.InitialState();
  Workspace ws2;
  MakeConsistent(free, s2, ws2);
  SolveStatics(free, s2, ws2);
  EXPECT_NEAR(s2.q(2), 0.25 - 400.0 * g / (4 * 2e6), 1e-12);
  EXPECT_NEAR(s2.q(0), 0.3, 1e-12);
  EXPECT_NEAR(s2.q(1), -0.2, 1e-12);
  // ... unless a load pushes along such a direction: a free motion
  Model pushed;
  StaticsBlockOnGround(pushed, 0.0);
  pushed.gravity_W.x() = 0.5;
  State s4 = pushed.InitialState();
  Workspace ws4;
  MakeConsistent(pushed, s4, ws4);
  EXPECT_THROW(SolveStatics(pushed, s4, ws4), NumericalError);
  // friction, but the hold switched off
  Model off_model;
  StaticsBlockOnGround(off_model, 0.5);
  State s3 = off_model.InitialState();
  Workspace ws3;
  MakeConsistent(off_model, s3, ws3);
  StaticsSettings off;
  off.damping_hold_time = 0.0;
  try {
    SolveStatics(off_model, s3, ws3, off);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("block"), std::string::npos) << e.what();
  }
}

}  // namespace
// hold_always (the truck's settle): the pseudo-transient matrix from the
// first iteration reaches the same equilibrium as the plain solve; a load
// that nothing but the friction's damping holds (a creep) stops it once
// the residual is below the tolerance and no longer falls, and `creep`
// names the coordinate, where the plain solve cannot converge.
TEST(Statics, HoldAlwaysReachesTheSameEquilibriumAndNamesACreep) {
  Model m;
  StaticsBlockOnGround(m, 0.5);
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  StaticsSettings held;
  held.hold_always = true;
  held.residual_tol = 1e-7;
  const StaticsResult r = SolveStatics(m, s, ws, held);
  const double g = -m.gravity_W.z();
  EXPECT_NEAR(s.q(2), 0.25 - 400.0 * g / (4 * 2e6), 1e-12);
  EXPECT_NEAR(s.q(0), 0.3, 1e-12);
  EXPECT_NEAR(s.q(1), -0.2, 1e-12);
  EXPECT_TRUE(r.creep.empty()) << r.creep;

  // a push of 2e-4 N (5e-8 of the weight) along the ground
  Model pushed;
  StaticsBlockOnGround(pushed, 0.5);
  pushed.gravity_W.x() = 5e-7;
  State s2 = pushed.InitialState();
  Workspace ws2;
  MakeConsistent(pushed, s2, ws2);
  const StaticsResult r2 = SolveStatics(pushed, s2, ws2, held);
  EXPECT_NE(r2.creep.find("block"), std::string::npos) << r2.creep;
  EXPECT_LE(r2.residual, 1e-7 * 400.0 * g);
  EXPECT_NEAR(s2.q(2), 0.25 - 400.0 * g / (4 * 2e6), 1e-9);
  State s3 = pushed.InitialState();
  Workspace ws3;
  MakeConsistent(pushed, s3, ws3);
  EXPECT_THROW(SolveStatics(pushed, s3, ws3), NumericalError);
}

// Simulator::SettleStatics with keep_velocities: the positions settle (the
// block on its contacts), the velocities of before come back (a block
// sliding at 2 m/s keeps sliding); without it they are zero.
TEST(Statics, SettleKeepsTheVelocitiesWhenAsked) {
  for (const bool keep : {true, false}) {
    Model moving;
    StaticsBlockOnGround(moving, 0.5, Vec3(2.0, 0.0, 0.0));
    Simulator sim(moving);
    sim.Initialize();
    StaticsSettings held;
    held.hold_always = true;
    sim.SettleStatics(held, keep);
    const double g = -moving.gravity_W.z();
    EXPECT_NEAR(sim.state().q(2), 0.25 - 400.0 * g / (4 * 2e6), 1e-12);
    EXPECT_NEAR(sim.state().q(0), 0.3, 1e-12);
    EXPECT_NEAR(sim.state().v(0), keep ? 2.0 : 0.0, 1e-12);
    EXPECT_NEAR(sim.state().v(2), 0.0, 1e-12);
  }
}

}  // namespace flexmb
