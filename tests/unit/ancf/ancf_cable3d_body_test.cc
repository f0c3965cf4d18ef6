// Unit tests of the 3D ANCF cable body: marker kinematics (Jacobian,
// acceleration bias, wrench and twist tangents) against finite differences,
// the node-frame rule (x along the slope, minimal rotation from the
// reference frame), force tangents against finite differences, gravity and
// strain energy against their potentials, kinetic energy and momentum of a
// rigid rotation against the rigid-rod formulas, bad input.
#include "flexmb/ancf/ancf_cable3d_body.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb::ancf {
namespace {

AncfCable3dData CableData() {
  AncfCable3dData d;
  d.length = 1.5;
  d.elements = 3;
  d.section = test_util::MakeSection(1e8, 1e-3, 2e-8, 2700.0, 0.01);
  d.start_W = Vec3(0.5, -1.0, 2.0);
  d.direction_W = Vec3(1.0, 1.0, 0.3);
  d.normal_W = Vec3(0.0, -0.3, 1.0);
  d.load_per_length_W = Vec3(2.0, -3.0, 1.0);
  return d;
}

// a deformed state (slopes turned by up to ~0.4 rad) and a velocity
void State(const AncfCable3dBody& b, VecX& q, VecX& v) {
  test_util::PerturbedBodyState(b, 0.15, q, v);
}

Marker CableNodeMarker(int node) {
  return test_util::NodeTestMarker("cable.m", node);
}

TEST(AncfCable3dBody, MarkerKinematicsMatchFiniteDifferences) {
  const AncfCable3dBody b("cable", CableData());
  VecX q, v;
  State(b, q, v);
  test_util::ExpectNodeMarkerKinematicsMatchCentralDifferences(b, q, v, {0, 2, 3});
}

TEST(AncfCable3dBody, NodeFrameIsTheMinimalRotationOfTheReference) {
  const AncfCable3dBody b("cable", CableData());
  VecX q, v;
  State(b, q, v);
  // reference frame: x along the direction, z the part of the normal normal to it
  const Mat3& R0 = b.R_W0();
  EXPECT_LT((R0.transpose() * R0 - Mat3::Identity()).norm(), 1e-14);
  EXPECT_NEAR(R0.determinant(), 1.0, 1e-14);
  EXPECT_LT((R0.col(0) - CableData().direction_W.normalized()).norm(), 1e-14);
  EXPECT_NEAR(R0.col(0).dot(R0.col(2).cross(CableData().normal_W)), 0.0, 1e-14);
  EXPECT_GT(R0.col(2).dot(CableData().normal_W), 0.0);
  Marker m = CableNodeMarker(1);
  m.p_BM.setZero();
  m.R_BM.setIdentity();
  MarkerState ms;
  b.EvaluateMarker(q.data(), v.data(), m, ms);
  // x along the slope; R_WN R0^T turns about an axis normal to t0 and t
  const Vec3 t = q.segment<3>(6 + 3).normalized();
  EXPECT_LT((ms.R_WM.col(0) - t).norm(), 1e-12);
  const Vec3 axis = LogSO3(ms.R_WM * R0.transpose());
  EXPECT_NEAR(axis.dot(t), 0.0, 1e-12);
  EXPECT_NEAR(axis.dot(R0.col(0)), 0.0, 1e-12);
  EXPECT_NEAR(axis.norm(), std::acos(t.dot(R0.col(0))), 1e-12);
  // the undeformed cable: every node frame is the reference frame
  VecX q0(b.nq()), v0(b.nv());
  b.InitialCoordinates(q0.data(), v0.data());
  b.EvaluateMarker(q0.data(), v0.data(), m, ms);
  EXPECT_LT((ms.R_WM - R0).norm(), 1e-14);
  // the slope turned back against the direction: a clear error
  q.segment<3>(6 + 3) = -R0.col(0);
  EXPECT_THROW(b.EvaluateMarker(q.data(), v.data(), m, ms), NumericalError);
}

TEST(AncfCable3dBody, ForcesTangentsAndPotentials) {
  const AncfCable3dData d = CableData();
  const AncfCable3dBody b("cable", d);
  VecX q, v;
  State(b, q, v);
  const Vec3 g(0.0, 0.0, -9.81);
  test_util::ExpectBodyForceTangentsMatchCentralDifferences(b, q, v, g);
  AncfCable3dData d0 = d;
  d0.load_per_length_W.setZero();
  d0.section.damping = 0.0;
  const AncfCable3dBody b0("cable", d0);
  test_util::ExpectBodyForcesArePotentialGradients(b0, q, g);
  // the undeformed cable: potential -m g . centre, no strain energy
  VecX q0(b.nq()), v0(b.nv());
  b0.InitialCoordinates(q0.data(), v0.data());
  const double mass = d.section.rho * d.section.A * d.length;
  const Vec3 centre = d.start_W + 0.5 * d.length * d.direction_W.normalized();
  EXPECT_NEAR(b0.GravityPotential(q0.data(), g), -mass * g.dot(centre), 1e-9 * mass);
  EXPECT_LT(b0.ElasticEnergy(q0.data()), 1e-20 * d.section.E * d.section.A * d.length);
  EXPECT_GT(b0.ElasticEnergy(q.data()), 0.0);
}

TEST(AncfCable3dBody, RigidRotationEnergyAndMomentum) {
  // the straight cable turning rigidly about its start point: a rod of mass
  // m, inertia about the start I = m L^2 / 3 (1 - t t^T)
  AncfCable3dData d = CableData();
  d.angular_velocity_W = Vec3(0.4, -1.1, 0.7);
  const AncfCable3dBody b("cable", d);
  VecX q(b.nq()), v(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  const double m = d.section.rho * d.section.A * d.length, L = d.length;
  const Vec3 t = d.direction_W.normalized(), w = d.angular_velocity_W;
  const Mat3 I = m * L * L / 3.0 * (Mat3::Identity() - t * t.transpose());
  EXPECT_NEAR(b.KineticEnergy(q.data(), v.data()), 0.5 * w.dot(I * w), 1e-12 * w.dot(I * w));
  const Vec3 p = m * w.cross(0.5 * L * t);
  const Vec6 h = b.Momentum(q.data(), v.data());
  EXPECT_LT((h.head<3>() - p).norm(), 1e-12 * p.norm());
  EXPECT_LT((h.tail<3>() - (d.start_W.cross(p) + I * w)).norm(), 1e-12 * m * L * L);
  // a rigid motion strains nothing: no elastic or damping force
  VecX Q = VecX::Zero(b.nv());
  MatX K = MatX::Zero(b.nv(), b.nv()), C = MatX::Zero(b.nv(), b.nv());
  AncfCable3dData d0 = d;
  d0.load_per_length_W.setZero();
  const AncfCable3dBody b0("cable", d0);
  b0.AddForces(q.data(), v.data(), Vec3::Zero(), Q, K, C);
  EXPECT_LT(Q.norm(), 1e-10 * d.section.E * d.section.A);
  // mass matrix against the kinetic energy
  MatX M;
  b.MassMatrix(q.data(), M);
  EXPECT_NEAR(0.5 * v.dot(M * v), b.KineticEnergy(q.data(), v.data()), 1e-12 * v.dot(M * v));
}

TEST(AncfCable3dBody, BadInputThrowsNamingTheBody) {
  AncfCable3dData d = CableData();
  d.elements = 0;
  try {
    AncfCable3dBody("rope", d);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.context().entity, "body 'rope'");
  }
  // zero or negative length, element count, section
  auto expect_named = [](const AncfCable3dData& bad) {
    try {
      AncfCable3dBody("rope", bad);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.context().entity, "body 'rope'");
    }
  };
  for (double x : {0.0, -1.0}) {
    d = CableData();
    d.length = x;
    expect_named(d);
    d = CableData();
    d.section.A = x;
    expect_named(d);
    d = CableData();
    d.section.I = x;
    expect_named(d);
  }
  d = CableData();
  d.elements = -2;
  expect_named(d);
  d = CableData();
  d.direction_W.setZero();
  EXPECT_THROW(AncfCable3dBody("rope", d), InputError);
  d = CableData();
  d.normal_W = 2.0 * d.direction_W;
  EXPECT_THROW(AncfCable3dBody("rope", d), InputError);
  const AncfCable3dBody b("rope", CableData());
  VecX q(b.nq()), v(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  MarkerState ms;
  EXPECT_THROW(b.EvaluateMarker(q.data(), v.data(), CableNodeMarker(4), ms), InputError);
}

}  // namespace
}  // namespace flexmb::ancf
