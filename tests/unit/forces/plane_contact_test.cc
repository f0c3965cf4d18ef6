#include "flexmb/forces/plane_contact.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/common/error.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

using namespace flexmb::testing;

PlaneContactLaw TiltedLaw(double mu) {
  PlaneContactLaw law;
  law.point_W = Vec3(0.2, -0.1, 0.3);
  law.normal_W = Vec3(0.3, -0.2, 1.0);  // normalized by the element
  law.stiffness = 2e5;
  law.damping = 300.0;
  law.friction = mu;
  law.slip_velocity = 0.05;
  return law;
}

// a random marker whose origin lies `depth` below the plane of `c`
MarkerState PenetratingMarker(const PlaneContact& c, std::mt19937& rng, double depth) {
  MarkerState m = RandomMarker(rng);
  const Vec3& n = c.law().normal_W;
  m.p_WM += (-depth - n.dot(m.p_WM - c.law().point_W)) * n;
  return m;
}

TEST(PlaneContact, TangentsMatchFiniteDifferences) {
  std::mt19937 rng(3);
  for (const double mu : {0.0, 0.6}) {
    const PlaneContact c("pad", TiltedLaw(mu));
    int active = 0;
    for (int trial = 0; trial < 30; ++trial) {
      MarkerState m = PenetratingMarker(c, rng, 0.01);
      // keep the normal force well away from its kink at zero
      const double gdot = -c.law().normal_W.dot(m.v_WM);
      if (c.law().stiffness * 0.01 + c.law().damping * gdot < 200.0) continue;
      ++active;
      ExpectTangents(c, m, MarkerState{}, 0.0, 6);
    }
    EXPECT_GT(active, 10);
  }
}

TEST(PlaneContact, ElasticForceIsMinusPotentialGradient) {
  std::mt19937 rng(5);
  PlaneContactLaw law = TiltedLaw(0.0);
  law.damping = 0.0;
  const PlaneContact c("pad", law);
  for (int trial = 0; trial < 10; ++trial) ExpectPotentialGradient(c, PenetratingMarker(c, rng, 0.02), {}, 0.0);
}

TEST(PlaneContact, NormalForceAndFrictionByHand) {
  PlaneContactLaw law;
  law.stiffness = 1e6;
  law.damping = 1e3;
  law.friction = 0.5;
  law.slip_velocity = 1e-3;
  const PlaneContact c("foot", law);
  MarkerState m;
  m.p_WM = Vec3(4.0, 2.0, -0.002);  // 2 mm into the ground z = 0
  m.v_WM = Vec3(3.0, -4.0, -0.1);   // sliding at 5 m/s, approaching at 0.1 m/s
  ForceEval e;
  c.Evaluate(m, {}, 0.0, e);
  const double Fn = 1e6 * 0.002 + 1e3 * 0.1;
  EXPECT_NEAR(e.wrench(2), Fn, 1e-9 * Fn);
  const double s = std::sqrt(25.0 + 1e-6);
  EXPECT_NEAR(e.wrench(0), -0.5 * Fn * 3.0 / s, 1e-9 * Fn);
  EXPECT_NEAR(e.wrench(1), 0.5 * Fn * 4.0 / s, 1e-9 * Fn);
  EXPECT_EQ(e.wrench.tail<9>().norm(), 0.0);
  EXPECT_NEAR(c.PotentialEnergy(m, {}, 0.0), 0.5 * 1e6 * 4e-6, 1e-12);
}

TEST(PlaneContact, NeverPulls) {
  PlaneContactLaw law;
  law.stiffness = 1e6;
  law.damping = 1e4;
  law.friction = 0.8;
  const PlaneContact c("foot", law);
  MarkerState m;
  ForceEval e;
  // above the plane: nothing
  m.p_WM = Vec3(0, 0, 1e-6);
  m.v_WM = Vec3(1, 0, -5);
  c.Evaluate(m, {}, 0.0, e);
  EXPECT_EQ(e.wrench.norm(), 0.0);
  EXPECT_EQ(c.PotentialEnergy(m, {}, 0.0), 0.0);
  // in the plane but leaving faster than the spring pushes: the damper lets go
  m.p_WM = Vec3(0, 0, -1e-3);
  m.v_WM = Vec3(1, 0, 0.2);  // k g = 1000 N < c gdot = 2000 N
  c.Evaluate(m, {}, 0.0, e);
  EXPECT_EQ(e.wrench.norm(), 0.0);
  EXPECT_EQ(e.K.norm() + e.C.norm(), 0.0);
}

TEST(PlaneContact, RejectsBadParameters) {
  auto make = [](auto edit) {
    PlaneContactLaw law;
    law.stiffness = 1e5;
    edit(law);
    return PlaneContact("pad", law);
  };
  EXPECT_THROW(make([](PlaneContactLaw& l) { l.stiffness = 0.0; }), InputError);
  EXPECT_THROW(make([](PlaneContactLaw& l) { l.damping = -1.0; }), InputError);
  EXPECT_THROW(make([](PlaneContactLaw& l) { l.friction = -0.1; }), InputError);
  EXPECT_THROW(make([](PlaneContactLaw& l) { l.slip_velocity = 0.0; }), InputError);
  EXPECT_THROW(make([](PlaneContactLaw& l) { l.normal_W.setZero(); }), InputError);
  EXPECT_THROW(make([](PlaneContactLaw& l) { l.point_W(1) = NAN; }), InputError);
  try {
    make([](PlaneContactLaw& l) { l.stiffness = -3.0; });
    FAIL();
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("force 'pad'"), std::string::npos) << err.what();
  }
}

}  // namespace
}  // namespace flexmb
