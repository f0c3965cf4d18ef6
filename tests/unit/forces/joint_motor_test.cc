#include "flexmb/forces/joint_motor.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/joints/constraint_primitives.h"
#include "flexmb/joints/cylindrical.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/solver/simulator.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

using namespace flexmb::testing;

std::shared_ptr<const ScalarFunction> Smooth() {
  return std::make_shared<TableFunction>(std::vector<double>{0, 1, 2, 3},
                                         std::vector<double>{0.2, 1.0, -0.4, 0.3},
                                         TableFunction::Interpolation::kCubicSpline, false);
}

TEST(JointMotor, TangentsMatchFiniteDifferences) {
  RevoluteJoint rev("rev");
  PrismaticJoint pri("pri");
  CylindricalJoint cyl("cyl");
  JointMotorPd pd{Smooth(), 350.0, 22.0};
  const JointMotor motors[] = {
      JointMotor("a", &rev, 0, Smooth()),      JointMotor("b", &pri, 0, Smooth()),
      JointMotor("c", &rev, 0, Smooth(), pd),  JointMotor("d", &pri, 0, Smooth(), pd),
      JointMotor("e", &cyl, 0, nullptr, pd),   JointMotor("f", &cyl, 1, nullptr, pd)};
  std::mt19937 rng(17);
  for (int trial = 0; trial < 10; ++trial) {
    const MarkerState mi = RandomMarker(rng), mj = RandomMarker(rng);
    for (const JointMotor& m : motors) {
      ExpectTangents(m, mi, mj, 1.7);
      ExpectThirdLaw(m, mi, mj, 1.7);
    }
  }
}

TEST(JointMotor, KnownTorqueAndForce) {
  RevoluteJoint rev("rev");
  PrismaticJoint pri("pri");
  auto tau = std::make_shared<ConstantFunction>(12.0);
  MarkerState mi, mj;
  mi.R_WM = ExpSO3(Vec3(M_PI / 2, 0, 0));  // z_i = -world y
  mj.R_WM = mi.R_WM * ExpSO3(Vec3(0, 0, 0.4));
  mj.p_WM = Vec3(0, -2, 0);
  const Vec12 wr = Wrench(JointMotor("r", &rev, 0, tau), mi, mj, 0.0);
  EXPECT_NEAR((wr.segment<3>(9) - Vec3(0, -12, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((wr.segment<3>(3) - Vec3(0, 12, 0)).norm(), 0.0, 1e-12);
  const Vec12 wp = Wrench(JointMotor("p", &pri, 0, tau), mi, mj, 0.0);
  EXPECT_NEAR((wp.segment<3>(6) - Vec3(0, -12, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((wp.segment<3>(0) - Vec3(0, 12, 0)).norm(), 0.0, 1e-12);

  // PD: angle 0.4, target 1.0 rad at rate 0 with kp = 10, kd = 2, j turning at +0.5 rad/s about z_i
  JointMotorPd pd{std::make_shared<ConstantFunction>(1.0), 10.0, 2.0};
  mj.w_WM = 0.5 * mi.R_WM.col(2);
  const Vec12 wc = Wrench(JointMotor("c", &rev, 0, nullptr, pd), mi, mj, 0.0);
  EXPECT_NEAR(wc.segment<3>(9).dot(mi.R_WM.col(2)), 10.0 * 0.6 - 2.0 * 0.5, 1e-12);
  // target 1 rad "behind" by more than pi is reached the short way
  JointMotorPd wrap{std::make_shared<ConstantFunction>(0.4 + 2 * M_PI - 0.1), 10.0, 0.0};
  mj.w_WM.setZero();
  const Vec12 ww = Wrench(JointMotor("w", &rev, 0, nullptr, wrap), mi, mj, 0.0);
  EXPECT_NEAR(ww.segment<3>(9).dot(mi.R_WM.col(2)), -1.0, 1e-9);
}

TEST(JointMotor, RejectsJointWithoutCoordinate) {
  SphericalJoint sph("sph");
  RevoluteJoint rev("rev");
  EXPECT_THROW(JointMotor("m", &sph, 0, Smooth()), InputError);
  EXPECT_THROW(JointMotor("m", &rev, 1, Smooth()), InputError);
  EXPECT_THROW(JointMotor("m", &rev, 0, nullptr), InputError);
}

// A PD motor drives a wheel (J = 0.2 kg m^2) on a revolute joint towards a
// fixed target: a damped oscillator J th'' + kd th' + kp (th - r) = 0.
TEST(JointMotor, PdControlledWheelMatchesAnalyticSolution) {
  const double J = 0.2, kp = 20.0, kd = 1.0, r = 0.5;
  Model model;
  model.gravity_W.setZero();
  RigidBodyData d;
  d.mass = 1.0;
  d.inertia_C = Vec3(0.1, 0.15, J).asDiagonal();
  const int b = model.AddBody(std::make_unique<RigidBody>("wheel", d));
  const int g = model.AddMarker(0, "pin", Vec3::Zero(), Mat3::Identity());
  const int p = model.AddMarker(b, "pin", Vec3::Zero(), Mat3::Identity());
  const int jn = model.AddJoint(std::make_unique<RevoluteJoint>("pin"), g, p);
  JointMotorPd pd{std::make_shared<ConstantFunction>(r), kp, kd};
  model.AddForce(std::make_unique<JointMotor>("motor", model.joints[jn].get(), 0, nullptr, pd), g, p);
  model.solver.dt = 1e-3;
  model.solver.rho_inf = 1.0;
  model.Finalize();
  Simulator sim(model);
  sim.Initialize();
  const double w = std::sqrt(kp / J), zeta = kd / (2 * std::sqrt(kp * J));
  const double wd = w * std::sqrt(1 - zeta * zeta);
  double max_err = 0.0;
  sim.Run(2.0, 0.0, [&](const State& st, const Workspace& ws) {
    const double th = primitives::RelativeAngle(ws.markers[g], ws.markers[p], nullptr);
    const double ref = r - r * std::exp(-zeta * w * st.t) *
                               (std::cos(wd * st.t) + zeta * w / wd * std::sin(wd * st.t));
    max_err = std::max(max_err, std::abs(th - ref));
  });
  EXPECT_LT(max_err, 5e-5);
}

}  // namespace
}  // namespace flexmb
