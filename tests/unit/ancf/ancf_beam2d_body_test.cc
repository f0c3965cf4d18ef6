// Unit tests of the planar ANCF beam body: marker kinematics (Jacobian,
// acceleration bias, wrench and twist tangents) against finite differences,
// gravity against its potential, energy and momentum against the mass matrix,
// assembled forces against the elements, bad input.
#include "flexmb/ancf/ancf_beam2d_body.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb::ancf {
namespace {

AncfBeam2dData Data() {
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
  q.resize(b.nq());
  v.resize(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  for (int j = 0; j < b.nq(); ++j) {
    q(j) += 0.05 * std::sin(1.3 * j + 0.2);
    v(j) = 0.4 * std::cos(0.7 * j);
  }
}

Marker NodeMarker(int node) {
  Marker m;
  m.name = "beam.m";
  m.node = node;
  m.p_BM = Vec3(0.1, -0.2, 0.05);
  m.R_BM = ExpSO3(Vec3(0.2, 0.1, -0.3));
  return m;
}

TEST(AncfBeam2dBody, MarkerJacobianMatchesFiniteDifferences) {
  const AncfBeam2dBody b("beam", Data());
  VecX q, v;
  State(b, q, v);
  const Marker m = NodeMarker(2);
  MarkerState ms;
  b.EvaluateMarker(q.data(), v.data(), m, ms);
  EXPECT_LT((ms.J.topRows<3>() * v - ms.v_WM).norm(), 1e-12);
  EXPECT_LT((ms.J.bottomRows<3>() * v - ms.w_WM).norm(), 1e-12);
  const double h = 1e-6;
  MarkerState mp, mm;
  for (int j = 0; j < b.nv(); ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    b.EvaluateMarker(qp.data(), v.data(), m, mp);
    b.EvaluateMarker(qm.data(), v.data(), m, mm);
    const Vec3 dp = (mp.p_WM - mm.p_WM) / (2 * h);
    const Vec3 dth = LogSO3(mp.R_WM * mm.R_WM.transpose()) / (2 * h);
    EXPECT_LT((dp - ms.J.block<3, 1>(0, j)).norm(), 1e-7) << j;
    EXPECT_LT((dth - ms.J.block<3, 1>(3, j)).norm(), 1e-7) << j;
  }
  // the node frame's x axis follows the slope, its z axis the plane normal
  const Vec3 slope = b.R_WP().leftCols<2>() * q.segment<2>(4 * 2 + 2);
  const Mat3 R_WN = ms.R_WM * m.R_BM.transpose();
  EXPECT_LT((R_WN.col(0) - slope.normalized()).norm(), 1e-12);
  EXPECT_LT((R_WN.col(2) - b.R_WP().col(2)).norm(), 1e-12);
}

TEST(AncfBeam2dBody, MarkerAccelerationBiasMatchesFiniteDifferences) {
  const AncfBeam2dBody b("beam", Data());
  VecX q, v;
  State(b, q, v);
  VecX acc(b.nv());
  for (int j = 0; j < b.nv(); ++j) acc(j) = 0.3 * std::sin(2.1 * j);
  const Marker m = NodeMarker(1);
  const double h = 1e-5;
  auto twist = [&](double t) {
    const VecX qt = q + t * v + 0.5 * t * t * acc;
    const VecX vt = v + t * acc;
    MarkerState ms;
    b.EvaluateMarker(qt.data(), vt.data(), m, ms);
    Vec6 tw;
    tw << ms.v_WM, ms.w_WM;
    return tw;
  };
  const Vec6 fd = (twist(h) - twist(-h)) / (2 * h);
  MarkerState ms;
  b.EvaluateMarker(q.data(), v.data(), m, ms);
  const Vec6 pred = ms.J * acc + b.MarkerAccelerationBias(q.data(), v.data(), m);
  EXPECT_LT((fd - pred).norm(), 1e-6 * pred.norm());
}

TEST(AncfBeam2dBody, MarkerTangentsMatchFiniteDifferences) {
  const AncfBeam2dBody b("beam", Data());
  VecX q, v;
  State(b, q, v);
  const Marker m = NodeMarker(3);
  Vec6 w;
  w << 3.0, -1.0, 2.0, 0.5, 0.7, -0.4;
  MatX K = MatX::Zero(b.nv(), b.nv());
  b.AddMarkerWrenchTangent(q.data(), m, w, K);
  MatX T(6, b.nv());
  b.MarkerTwistTangent(q.data(), v.data(), m, T);
  const double h = 1e-6;
  MarkerState mp, mm;
  for (int j = 0; j < b.nv(); ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    b.EvaluateMarker(qp.data(), v.data(), m, mp);
    b.EvaluateMarker(qm.data(), v.data(), m, mm);
    const VecX dQ = (mp.J.transpose() * w - mm.J.transpose() * w) / (2 * h);
    const Vec6 dtw = (mp.J * v - mm.J * v) / (2 * h);
    EXPECT_LT((dQ - K.col(j)).norm(), 1e-6 * (1.0 + K.norm())) << j;
    EXPECT_LT((dtw - T.col(j)).norm(), 1e-6 * (1.0 + T.norm())) << j;
  }
}

TEST(AncfBeam2dBody, ForcesTangentsGravityAndEnergy) {
  const AncfBeam2dData d = Data();
  const AncfBeam2dBody b("beam", d);
  VecX q, v;
  State(b, q, v);
  const Vec3 g(0.0, 0.0, -9.81);
  const int n = b.nv();
  auto forces = [&](const VecX& qq, const VecX& vv) {
    VecX Q = VecX::Zero(n);
    MatX K = MatX::Zero(n, n), C = MatX::Zero(n, n);
    b.AddForces(qq.data(), vv.data(), g, Q, K, C);
    return Q;
  };
  VecX Q = VecX::Zero(n);
  MatX K = MatX::Zero(n, n), C = MatX::Zero(n, n);
  b.AddForces(q.data(), v.data(), g, Q, K, C);
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    VecX qp = q, qm = q, vp = v, vm = v;
    qp(j) += h;
    qm(j) -= h;
    vp(j) += h;
    vm(j) -= h;
    EXPECT_LT(((forces(qp, v) - forces(qm, v)) / (2 * h) - K.col(j)).norm(), 1e-6 * K.norm());
    EXPECT_LT(((forces(q, vp) - forces(q, vm)) / (2 * h) - C.col(j)).norm(), 1e-6 * C.norm());
  }
  // the gravity part of Q is minus the gradient of the gravity potential
  AncfBeam2dData d0 = d;
  d0.load_per_length_W.setZero();
  d0.section.damping = 0.0;
  const AncfBeam2dBody b0("beam", d0);
  VecX Qg = VecX::Zero(n), Qe = VecX::Zero(n);
  MatX Kd = MatX::Zero(n, n), Cd = MatX::Zero(n, n);
  b0.AddForces(q.data(), v.data(), g, Qg, Kd, Cd);
  b0.AddForces(q.data(), v.data(), Vec3::Zero(), Qe, Kd, Cd);
  for (int j = 0; j < n; ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    const double dV = (b0.GravityPotential(qp.data(), g) - b0.GravityPotential(qm.data(), g)) / (2 * h);
    const double dW = (b0.StrainEnergy(qp.data()) - b0.StrainEnergy(qm.data())) / (2 * h);
    EXPECT_NEAR(Qg(j) - Qe(j), -dV, 1e-6 * (1.0 + Qg.norm()));
    EXPECT_NEAR(Qe(j), -dW, 1e-6 * Qe.norm());
  }
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
  AncfBeam2dData d = Data();
  d.elements = 0;
  try {
    AncfBeam2dBody("rope", d);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.context().entity, "body 'rope'");
  }
  d = Data();
  d.length = -1.0;
  EXPECT_THROW(AncfBeam2dBody("rope", d), InputError);
  d = Data();
  d.section.I = 0.0;
  EXPECT_THROW(AncfBeam2dBody("rope", d), InputError);
  d = Data();
  d.direction_W = d.normal_W;
  EXPECT_THROW(AncfBeam2dBody("rope", d), InputError);
  const AncfBeam2dBody b("rope", Data());
  VecX q(b.nq()), v(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  MarkerState ms;
  EXPECT_THROW(b.EvaluateMarker(q.data(), v.data(), NodeMarker(4), ms), InputError);
}

}  // namespace
}  // namespace flexmb::ancf
