// Unit tests of the planar ANCF beam body: marker kinematics (Jacobian,
// acceleration bias, wrench and twist tangents) against finite differences,
// gravity against its potential, energy and momentum against the mass matrix,
// assembled forces against the elements, bad input.
#include "flexmb/ancf/ancf_beam2d_body.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb::ancf {
namespace {

AncfBeam2dData BeamData() {
  AncfBeam2dData d;
  d.length = 1.5;
  d.elements = 3;
  d.section.E = 1e8;
  d.section.A = 1e-3;
  d.section.I = 2e-8;
  d.section.rho = 2700.0;
  d.section.damping = 0.01;
  d.start_W = Vec3(0.5, -1.0, 2.0);
  d.direction_W = Vec3(1.0, 1.0, 0.3);
  d.normal_W = Vec3(0.0, -0.3, 1.0);
  d.load_per_length_W = Vec3(2.0, -3.0, 1.0);
  return d;
}

// a deformed state and a velocity
void State(const AncfBeam2dBody& b, VecX& q, VecX& v) {
  test_util::PerturbedBodyState(b, 0.05, q, v);
}

Marker BeamNodeMarker(int node) {
  return test_util::NodeTestMarker("beam.m", node);
}

TEST(AncfBeam2dBody, MarkerJacobianMatchesFiniteDifferences) {
  const AncfBeam2dBody b("beam", BeamData());
  VecX q, v;
  State(b, q, v);
  const Marker m = BeamNodeMarker(2);
  test_util::ExpectMarkerJacobianMatchesCentralDifferences(b, q, v, m);
  MarkerState ms;
  b.EvaluateMarker(q.data(), v.data(), m, ms);
  // the node frame's x axis follows the slope, its z axis the plane normal
  const Vec3 slope = b.R_WP().leftCols<2>() * q.segment<2>(4 * 2 + 2);
  const Mat3 R_WN = ms.R_WM * m.R_BM.transpose();
  EXPECT_LT((R_WN.col(0) - slope.normalized()).norm(), 1e-12);
  EXPECT_LT((R_WN.col(2) - b.R_WP().col(2)).norm(), 1e-12);
}

TEST(AncfBeam2dBody, MarkerAccelerationBiasMatchesFiniteDifferences) {
  const AncfBeam2dBody b("beam", BeamData());
  VecX q, v;
  State(b, q, v);
  test_util::ExpectMarkerBiasMatchesCentralDifferences(b, q, v, test_util::TestAcceleration(b), BeamNodeMarker(1));
}

TEST(AncfBeam2dBody, MarkerTangentsMatchFiniteDifferences) {
  const AncfBeam2dBody b("beam", BeamData());
  VecX q, v;
  State(b, q, v);
  test_util::ExpectMarkerTangentsMatchCentralDifferences(b, q, v, BeamNodeMarker(3), test_util::TestWrench());
}

TEST(AncfBeam2dBody, ForcesTangentsGravityAndEnergy) {
  const AncfBeam2dData d = BeamData();
  const AncfBeam2dBody b("beam", d);
  VecX q, v;
  State(b, q, v);
  const Vec3 g(0.0, 0.0, -9.81);
  const int n = b.nv();
  test_util::ExpectBodyForceTangentsMatchCentralDifferences(b, q, v, g);
  // the gravity part of Q is minus the gradient of the gravity potential
  AncfBeam2dData d0 = d;
  d0.load_per_length_W.setZero();
  d0.section.damping = 0.0;
  const AncfBeam2dBody b0("beam", d0);
  test_util::ExpectBodyForcesArePotentialGradients(b0, q, g);
  // potential of the undeformed beam: m g . (centre of the line) with a minus sign
  VecX q0(n), v0(n);
  b0.InitialCoordinates(q0.data(), v0.data());
  const double mass = d.section.rho * d.section.A * d.length;
  const Vec3 centre = d.start_W + 0.5 * d.length * b0.R_WP().col(0);
  EXPECT_NEAR(b0.GravityPotential(q0.data(), g), -mass * g.dot(centre), 1e-9 * mass);
  // kinetic energy and momentum against the assembled mass matrix
  MatX M;
  b.MassMatrix(q.data(), M);
  EXPECT_NEAR(b.KineticEnergy(q.data(), v.data()), 0.5 * v.dot(M * v), 1e-12 * v.dot(M * v));
  // rigid translation with velocity u: momentum m u, angular O x m u + ...
  const Vec3 u = b0.R_WP().leftCols<2>() * Eigen::Vector2d(0.3, -0.8);
  VecX vt = VecX::Zero(n);
  for (int k = 0; k < b.nodes(); ++k) vt.segment<2>(4 * k) = Eigen::Vector2d(0.3, -0.8);
  const Vec6 hm = b0.Momentum(q0.data(), vt.data());
  EXPECT_LT((hm.head<3>() - mass * u).norm(), 1e-12 * mass);
  EXPECT_LT((hm.tail<3>() - centre.cross(mass * u)).norm(), 1e-10 * mass);
}

TEST(AncfBeam2dBody, BadInputThrowsNamingTheBody) {
  AncfBeam2dData d = BeamData();
  d.elements = 0;
  try {
    AncfBeam2dBody("rope", d);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.context().entity, "body 'rope'");
  }
  // zero or negative length, element count, section
  auto expect_named = [](const AncfBeam2dData& bad) {
    try {
      AncfBeam2dBody("rope", bad);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.context().entity, "body 'rope'");
    }
  };
  for (double x : {0.0, -1.0}) {
    d = BeamData();
    d.length = x;
    expect_named(d);
    d = BeamData();
    d.section.A = x;
    expect_named(d);
    d = BeamData();
    d.section.I = x;
    expect_named(d);
  }
  d = BeamData();
  d.elements = -2;
  expect_named(d);
  d = BeamData();
  d.direction_W = d.normal_W;
  EXPECT_THROW(AncfBeam2dBody("rope", d), InputError);
  const AncfBeam2dBody b("rope", BeamData());
  VecX q(b.nq()), v(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  MarkerState ms;
  EXPECT_THROW(b.EvaluateMarker(q.data(), v.data(), BeamNodeMarker(4), ms), InputError);
}

}  // namespace
}  // namespace flexmb::ancf
