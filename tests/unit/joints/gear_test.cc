// Gear joint: D against central differences of phi (PerturbMarker), the
// geometric stiffness against differences of D, and the kinematic ratio of
// two shafts on a moving carrier in a simulation.
#include "flexmb/joints/gear.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/math/scalar_function.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

JointEval GearEvalOf(const GearJoint& g, const MarkerState& mi, const MarkerState& mj) {
  JointEval e;
  e.phi.resize(1);
  e.phi_t.resize(1);
  e.D.resize(1, 12);
  g.Evaluate(mi, mj, 0.0, e);
  return e;
}

TEST(GearJoint, JacobianAndGeometricStiffnessMatchFiniteDifferences) {
  std::mt19937 rng(35);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const GearJoint g("g", -20.0);
  for (int trial = 0; trial < 6; ++trial) {
    MarkerState mi, mj;
    mi.p_WM = Vec3(u(rng), u(rng), u(rng));
    mj.p_WM = Vec3(u(rng), u(rng), u(rng));
    mi.R_WM = ExpSO3(Vec3(u(rng), u(rng), u(rng)));
    mj.R_WM = ExpSO3(Vec3(u(rng), u(rng), u(rng)));
    const JointEval e = GearEvalOf(g, mi, mj);
    Vec12 fd;
    for (int k = 0; k < 12; ++k) {
      const bool on_i = k < 6;
      const double h = 1e-6;
      const MarkerState ip = on_i ? PerturbMarker(mi, k, h) : mi, im = on_i ? PerturbMarker(mi, k, -h) : mi;
      const MarkerState jp = on_i ? mj : PerturbMarker(mj, k - 6, h), jm = on_i ? mj : PerturbMarker(mj, k - 6, -h);
      const double dphi = GearEvalOf(g, ip, jp).phi[0] - GearEvalOf(g, im, jm).phi[0];
      fd[k] = std::remainder(dphi, 2 * M_PI) / (2 * h);
    }
    const Vec12 d = e.D.row(0).transpose();
    EXPECT_LT((d - fd).norm(), 1e-6 * std::max(1.0, fd.norm())) << "D " << d.transpose() << "\nfd " << fd.transpose();
    EXPECT_EQ(d.segment<3>(0).norm() + d.segment<3>(6).norm(), 0.0);
    // H = lambda dD/dx by another step (1e-5), lambda = 0.7
    Mat12 H = Mat12::Zero(), Hfd = Mat12::Zero();
    const double lambda = 0.7;
    g.AddGeometricStiffness(mi, mj, &lambda, H);
    for (int k = 0; k < 12; ++k) {
      const bool on_i = k < 6;
      const double h = 1e-5;
      const MarkerState ip = on_i ? PerturbMarker(mi, k, h) : mi, im = on_i ? PerturbMarker(mi, k, -h) : mi;
      const MarkerState jp = on_i ? mj : PerturbMarker(mj, k - 6, h), jm = on_i ? mj : PerturbMarker(mj, k - 6, -h);
      Hfd.col(k) = lambda * (GearEvalOf(g, ip, jp).D.row(0) - GearEvalOf(g, im, jm).D.row(0)).transpose() / (2 * h);
    }
    EXPECT_LT((H - Hfd).norm(), 1e-5 * std::max(1.0, Hfd.norm()));
  }
  EXPECT_THROW(GearJoint("g", 0.0), InputError);
  MarkerState par;
  EXPECT_THROW(GearEvalOf(g, par, par), NumericalError);
}

// Two shafts on revolutes of a carrier that itself turns about a third
// axis (driven); shaft 1 is driven through three revolutions; the gear
// (ratio -20) must keep shaft 2's revolute angle at -1/20 of shaft 1's,
// measured relative to the carrier, whatever the carrier does.
TEST(GearJoint, KinematicRatioOnMovingCarrier) {
  Model m;
  m.gravity_W = Vec3(0, 0, -9.81);
  m.solver.dt = 2e-3;
  auto body = [&](const char* name, const Vec3& c) {
    RigidBodyData b;
    b.mass = 2.0;
    b.inertia_C = Vec3(0.1, 0.2, 0.15).asDiagonal();
    b.c_B = c;
    return m.AddBody(std::make_unique<RigidBody>(name, b));
  };
  const int carrier = body("carrier", Vec3(0.2, 0, 0));
  const int shaft1 = body("shaft1", Vec3(0, 0, 0.5));
  const int shaft2 = body("shaft2", Vec3(0.4, 0, 0));
  // shaft 1 axis: inclined column a1 in the x-z plane; shaft 2 axis: y
  const Vec3 a1 = Vec3(-0.5, 0, 1).normalized(), a2 = Vec3::UnitY();
  Mat3 R1, R2;  // gear markers: x_1 along a2, x_2 along a1
  R1.col(0) = a2;
  R1.col(2) = a1;
  R1.col(1) = a1.cross(a2);
  R2.col(0) = a1;
  R2.col(2) = a2;
  R2.col(1) = a2.cross(a1);
  Mat3 Rc;  // carrier turns about world x
  Rc << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  const int jc = m.AddJoint(std::make_unique<RevoluteJoint>("carrier_rev"), m.AddMarker(0, "c", Vec3::Zero(), Rc),
                            m.AddMarker(carrier, "c", Vec3::Zero(), Rc));
  const int j1 = m.AddJoint(std::make_unique<RevoluteJoint>("rev1"), m.AddMarker(carrier, "s1", Vec3(0, 0, 0.3), R1),
                            m.AddMarker(shaft1, "s1", Vec3(0, 0, 0.3), R1));
  const int j2 = m.AddJoint(std::make_unique<RevoluteJoint>("rev2"), m.AddMarker(carrier, "s2", Vec3(0.4, 0, 0), R2),
                            m.AddMarker(shaft2, "s2", Vec3(0.4, 0, 0), R2));
  m.AddJoint(std::make_unique<GearJoint>("gear", -20.0), m.joints[j1]->marker_j, m.joints[j2]->marker_j);
  m.AddJoint(std::make_unique<MotionDriver>("drive_carrier", m.joints[jc].get(), 0,
                                            std::make_shared<ExpressionFunction>("0.4*sin(3*t)")),
             m.joints[jc]->marker_i, m.joints[jc]->marker_j);
  m.AddJoint(std::make_unique<MotionDriver>("drive1", m.joints[j1].get(), 0,
                                            std::make_shared<ExpressionFunction>("6*pi*t*t")),
             m.joints[j1]->marker_i, m.joints[j1]->marker_j);
  m.Finalize();
  Simulator sim(m);
  sim.Initialize();
  double worst = 0.0;
  int samples = 0;
  sim.Run(1.0, 0.01, [&](const State& st, const Workspace& ws) {
    const Joint& r1 = *m.joints[j1];
    const Joint& r2 = *m.joints[j2];
    const double th1 = 6 * M_PI * st.t * st.t;
    const double c1 = r1.Coordinate(0, ws.markers[r1.marker_i], ws.markers[r1.marker_j], nullptr);
    const double c2 = r2.Coordinate(0, ws.markers[r2.marker_i], ws.markers[r2.marker_j], nullptr);
    EXPECT_NEAR(std::remainder(c1 - th1, 2 * M_PI), 0.0, 1e-8);
    worst = std::max(worst, std::abs(c2 + th1 / 20.0));
    ++samples;
  });
  EXPECT_GT(samples, 90);
  EXPECT_LT(worst, 1e-8);
}

}  // namespace
}  // namespace flexmb
