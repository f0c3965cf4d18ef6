#include "flexmb/forces/rotational_spring_damper.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/joints/constraint_primitives.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/solver/simulator.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

using namespace flexmb::testing;

RotationalSpringDamperLaw LinearRotational(double k, double c, double a0, double t0) {
  RotationalSpringDamperLaw law;
  law.stiffness = k;
  law.damping = c;
  law.angle0 = a0;
  law.preload = t0;
  return law;
}

TEST(RotationalSpringDamper, TangentsMatchFiniteDifferences) {
  std::mt19937 rng(3);
  const RotationalSpringDamper linear("r", LinearRotational(250.0, 12.0, 0.4, -7.0));
  RotationalSpringDamperLaw law = LinearRotational(0.0, 5.0, -0.2, 1.0);
  law.torque_angle = std::make_shared<TableFunction>(
      std::vector<double>{-4, -1, 0, 1, 4}, std::vector<double>{-900, -90, 0, 110, 700},
      TableFunction::Interpolation::kCubicSpline, true);
  const RotationalSpringDamper table("t", law);
  for (int trial = 0; trial < 20; ++trial) {
    const MarkerState mi = RandomMarker(rng);
    MarkerState mj = RandomMarker(rng);
    // general poses (z_j not parallel to z_i) and aligned ones
    for (bool aligned : {false, true}) {
      if (aligned) mj.R_WM = mi.R_WM * ExpSO3(Vec3(0, 0, 0.9 * trial - 9.0));
      ExpectTangents(linear, mi, mj, 0.0);
      ExpectTangents(table, mi, mj, 0.0);
      ExpectThirdLaw(linear, mi, mj, 0.0);
    }
  }
}

TEST(RotationalSpringDamper, KnownTorqueAndEnergy) {
  // j turned by 0.5 rad about z_i = world y, turning at 2 rad/s relative to i
  const double k = 40.0, c = 3.0, a0 = 0.1, t0 = 2.0;
  const RotationalSpringDamper r("r", LinearRotational(k, c, a0, t0));
  MarkerState mi, mj;
  mi.R_WM = ExpSO3(Vec3(-M_PI / 2, 0, 0));  // z_i = +y
  mj.R_WM = ExpSO3(Vec3(0, 0.5, 0)) * mi.R_WM;
  mi.w_WM = Vec3(0, 1, 0);
  mj.w_WM = Vec3(0, 3, 0);
  const double T = -(k * 0.4 + t0 + c * 2.0);
  const Vec12 w = Wrench(r, mi, mj, 0.0);
  EXPECT_NEAR((w.segment<3>(9) - Vec3(0, T, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((w.segment<3>(3) - Vec3(0, -T, 0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(w.segment<3>(0).norm() + w.segment<3>(6).norm(), 0.0);
  EXPECT_NEAR(r.PotentialEnergy(mi, mj, 0.0), 0.5 * k * 0.16 + t0 * 0.4, 1e-12);
  // dV/dtheta (turning j about z_i) is minus the spring torque on j
  const double h = 1e-6;
  MarkerState jp = mj, jm = mj;
  jp.R_WM = ExpSO3(Vec3(0, h, 0)) * mj.R_WM;
  jm.R_WM = ExpSO3(Vec3(0, -h, 0)) * mj.R_WM;
  const double dV = (r.PotentialEnergy(mi, jp, 0.0) - r.PotentialEnergy(mi, jm, 0.0)) / (2 * h);
  EXPECT_NEAR(dV, k * 0.4 + t0, 1e-6);
}

TEST(RotationalSpringDamper, UndefinedAngleThrows) {
  const RotationalSpringDamper r("r", LinearRotational(1.0, 0.0, 0.0, 0.0));
  MarkerState mi, mj;
  mj.R_WM = ExpSO3(Vec3(0, -M_PI / 2, 0));  // x_j = +z = z_i
  EXPECT_THROW(Wrench(r, mi, mj, 0.0), NumericalError);
}

// A disk (J = 0.5 kg m^2 about its axis) on a revolute joint with a
// torsion spring k = 8 N m/rad, released at 0.3 rad: theta = 0.3 cos(w t),
// w = sqrt(k / J).
TEST(RotationalSpringDamper, TorsionPendulumMatchesAnalyticSolution) {
  const double J = 0.5, k = 8.0, th0 = 0.3;
  Model model;
  model.gravity_W.setZero();
  RigidBodyData d;
  d.mass = 3.0;
  d.inertia_C = Vec3(0.3, 0.3, J).asDiagonal();
  d.R_WB = ExpSO3(Vec3(0, 0, th0));
  const int b = model.AddBody(std::make_unique<RigidBody>("disk", d));
  const int g = model.AddMarker(0, "pin", Vec3::Zero(), Mat3::Identity());
  const int p = model.AddMarker(b, "pin", Vec3::Zero(), Mat3::Identity());
  model.AddJoint(std::make_unique<RevoluteJoint>("pin"), g, p);
  model.AddForce(std::make_unique<RotationalSpringDamper>("spring", LinearRotational(k, 0.0, 0.0, 0.0)), g, p);
  model.solver.dt = 1e-3;
  model.solver.rho_inf = 1.0;
  model.Finalize();
  Simulator sim(model);
  sim.Initialize();
  const double w = std::sqrt(k / J);
  double max_err = 0.0;
  sim.Run(2.0, 0.0, [&](const State& st, const Workspace& ws) {
    const double th = primitives::RelativeAngle(ws.markers[g], ws.markers[p], nullptr);
    max_err = std::max(max_err, std::abs(th - th0 * std::cos(w * st.t)));
  });
  EXPECT_LT(max_err, 2e-5);
}

}  // namespace
}  // namespace flexmb
