// FlexibleBody (floating frame of reference): every analytic derivative
// against central finite differences, the inertial forces against the
// conservation laws of the kinetic energy they come from (power balance and
// momentum balance along the motion), the marker kinematics against finite
// differences of the marker pose.

#include "flexmb/bodies/flexible_body.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <functional>
#include <string>

#include "flexmb/common/error.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb {
namespace {

constexpr double kH = 1e-6;  // finite-difference step

struct Fixture {
  std::shared_ptr<reduction::ReducedBody> reduced;
  std::unique_ptr<FlexibleBody> body;
  VecX q, v;
  Vec3 g = Vec3(0.3, -1.2, -9.81);
};

// a moving, deformed, spinning state of the free bent bar with Rayleigh damping
Fixture Make(double amplitude = 1e-2) {
  Fixture f;
  f.reduced = testing::FreeBentBar(3, 3);
  const int n = f.reduced->invariants.n;
  f.reduced->damping = 1e-4 * f.reduced->stiffness + 0.5 * MatX::Identity(n, n);
  FlexibleBodyData d;
  d.reduced = f.reduced;
  d.p_WB = Vec3(0.3, -0.2, 1.1);
  d.R_WB = ExpSO3(Vec3(0.4, -0.7, 1.3));
  d.v_WB = Vec3(1.0, -2.0, 0.5);
  d.w_WB = Vec3(3.0, 1.5, -2.0);
  d.w0 = amplitude * VecX::LinSpaced(n, 1.0, -0.5);
  d.wd0 = 10.0 * amplitude * VecX::LinSpaced(n, -1.0, 2.0);
  f.body = std::make_unique<FlexibleBody>("bar", d);
  f.q.resize(f.body->nq());
  f.v.resize(f.body->nv());
  f.body->InitialCoordinates(f.q.data(), f.v.data());
  return f;
}

VecX Retracted(const Body& b, const VecX& q, const VecX& dx) {
  VecX out(q.size());
  b.Retract(q.data(), dx.data(), out.data());
  return out;
}

VecX Forces(const Fixture& f, const VecX& q, const VecX& v) {
  const int N = f.body->nv();
  VecX Q = VecX::Zero(N);
  MatX a = MatX::Zero(N, N), b = MatX::Zero(N, N);
  f.body->AddForces(q.data(), v.data(), f.g, Q, a, b);
  return Q;
}

// relative max-norm error
double RelErr(const MatX& a, const MatX& ref) {
  return (a - ref).cwiseAbs().maxCoeff() / std::max(1.0, ref.cwiseAbs().maxCoeff());
}

TEST(FlexibleBody, Sizes) {
  const Fixture f = Make();
  EXPECT_EQ(f.body->modes(), 9);
  EXPECT_EQ(f.body->nq(), 16);
  EXPECT_EQ(f.body->nv(), 15);
  EXPECT_FALSE(f.body->HasConstantMass());
}

TEST(FlexibleBody, ForceTangentsMatchFiniteDifferences) {
  const Fixture f = Make();
  const int N = f.body->nv();
  VecX Q = VecX::Zero(N);
  MatX dQdq = MatX::Zero(N, N), dQdv = MatX::Zero(N, N);
  f.body->AddForces(f.q.data(), f.v.data(), f.g, Q, dQdq, dQdv);
  MatX fq(N, N), fv(N, N);
  for (int k = 0; k < N; ++k) {
    VecX e = VecX::Zero(N);
    e(k) = kH;
    fq.col(k) = (Forces(f, Retracted(*f.body, f.q, e), f.v) - Forces(f, Retracted(*f.body, f.q, -e), f.v)) / (2 * kH);
    fv.col(k) = (Forces(f, f.q, f.v + e) - Forces(f, f.q, f.v - e)) / (2 * kH);
  }
  EXPECT_LT(RelErr(dQdq, fq), 1e-6) << "dQ/dx\n" << dQdq - fq;
  EXPECT_LT(RelErr(dQdv, fv), 1e-6) << "dQ/dv\n" << dQdv - fv;
  // the elastic, inertial and gravity terms are all present
  EXPECT_GT(dQdq.cwiseAbs().maxCoeff(), 1.0);
  EXPECT_GT(dQdv.block(0, 0, 6, 6).cwiseAbs().maxCoeff(), 1e-3);
}

TEST(FlexibleBody, MassMatrixSymmetricPositiveDefinite) {
  const Fixture f = Make();
  MatX M;
  f.body->MassMatrix(f.q.data(), M);
  EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-12 * M.cwiseAbs().maxCoeff());
  Eigen::SelfAdjointEigenSolver<MatX> es(M);
  EXPECT_GT(es.eigenvalues().minCoeff(), 0.0);
  // kinetic energy is 1/2 v^T M v
  EXPECT_NEAR(f.body->KineticEnergy(f.q.data(), f.v.data()), 0.5 * f.v.dot(M * f.v), 1e-12 * f.v.squaredNorm());
}

// along the free motion (Q from the body alone, vdot = M^-1 Q, no gravity)
// energy and momentum are conserved: their time derivatives, by central
// differences along (v, vdot), vanish (the damping dissipates exactly
// wd^T D wd). This checks the inertial forces against the mass matrix they
// are derived from.
void ExpectConservedAlongMotion(const Fixture& f) {
  const int N = f.body->nv();
  MatX M;
  f.body->MassMatrix(f.q.data(), M);
  const VecX a = M.ldlt().solve(Forces(f, f.q, f.v));
  const double h = 1e-6;
  const VecX qp = Retracted(*f.body, f.q, h * f.v), qm = Retracted(*f.body, f.q, -h * f.v);
  const VecX vp = f.v + h * a, vm = f.v - h * a;
  const auto energy = [&](const VecX& q, const VecX& v) {
    return f.body->KineticEnergy(q.data(), v.data()) + f.body->StrainEnergy(q.data());
  };
  const double dE = (energy(qp, vp) - energy(qm, vm)) / (2 * h);
  const double scale = std::abs(f.v.dot(M * a)) + f.v.norm() * M.norm() * f.v.norm();
  const VecX wd = f.v.tail(N - 6);
  EXPECT_NEAR(dE, -wd.dot(f.body->damping() * wd), 1e-7 * scale);
  const Vec6 dL = (f.body->Momentum(qp.data(), vp.data()) - f.body->Momentum(qm.data(), vm.data())) / (2 * h);
  const double pscale = f.body->Momentum(f.q.data(), f.v.data()).norm();
  EXPECT_LT(dL.norm(), 1e-7 * pscale) << dL.transpose();
}

Fixture WithoutGravity(Fixture f) {
  f.g.setZero();
  return f;
}

TEST(FlexibleBody, InertialForcesConserveEnergyAndMomentum) {
  ExpectConservedAlongMotion(WithoutGravity(Make(1e-2)));
  ExpectConservedAlongMotion(WithoutGravity(Make(0.0)));
  ExpectConservedAlongMotion(WithoutGravity(Make(5e-2)));
}

TEST(FlexibleBody, GravityIsTheConsistentMassLoad) {
  // THEORY section 5: Q_g = M (g; 0; 0) in the body's velocity coordinates
  const Fixture f = Make(2e-2);
  const int N = f.body->nv();
  MatX M;
  f.body->MassMatrix(f.q.data(), M);
  VecX g0 = VecX::Zero(N);
  g0.head<3>() = f.g;
  const VecX Qg = Forces(f, f.q, f.v) - Forces(WithoutGravity(Make(2e-2)), f.q, f.v);
  EXPECT_LT((Qg - M * g0).norm(), 1e-10 * (M * g0).norm());
  // in the undeformed state it is minus the gradient of the potential
  const Fixture u = Make(0.0);
  const VecX Qu = Forces(u, u.q, u.v) - Forces(WithoutGravity(Make(0.0)), u.q, u.v);
  VecX grad(N);
  for (int k = 0; k < N; ++k) {
    VecX e = VecX::Zero(N);
    e(k) = kH;
    grad(k) = (u.body->GravityPotential(Retracted(*u.body, u.q, e).data(), u.g) -
               u.body->GravityPotential(Retracted(*u.body, u.q, -e).data(), u.g)) / (2 * kH);
  }
  EXPECT_LT((Qu + grad).norm(), 1e-7 * Qu.norm()) << (Qu + grad).transpose();
}

TEST(FlexibleBody, RigidStateMatchesNewtonEuler) {
  // w = 0, wd = 0: the frame forces are Newton-Euler about the frame origin
  Fixture f = Make(0.0);
  const int N = f.body->nv();
  f.g.setZero();
  f.reduced->damping.setZero();
  const VecX Q = Forces(f, f.q, f.v);
  const Mat3& s0 = f.reduced->invariants.mvo0;
  const Mat3& J0 = f.reduced->invariants.moo0;
  const Vec3 S(-s0(2, 1), -s0(0, 2), -s0(1, 0));
  const Vec3 om = f.v.segment<3>(3);
  // rigid body about a reference point O off the centre of mass, with the
  // world acceleration a of O: m a + R (om_dot x S + om x (om x S)) = F and
  // J_O om_dot + om x J_O om + S x R^T a = M_O; the forces are the bias terms
  Mat3 R;
  Vec3 p;
  f.body->BodyFramePose(f.q.data(), p, R);
  EXPECT_LT((Q.head<3>() + R * om.cross(om.cross(S))).norm(), 1e-10 * (1.0 + Q.head<3>().norm()));
  const Vec3 moment = -om.cross(J0 * om);
  EXPECT_LT((Q.segment<3>(3) - moment).norm(), 1e-10 * (1.0 + moment.norm()));
  EXPECT_EQ(Q.tail(N - 6).size(), 9);
}

// marker helpers
MarkerState Eval(const Fixture& f, const Marker& m, const VecX& q, const VecX& v) {
  MarkerState s;
  f.body->EvaluateMarker(q.data(), v.data(), m, s);
  return s;
}

Marker FlexNodeMarker(int node) {
  Marker m;
  m.name = "bar.m";
  m.body = 1;
  m.node = node;
  m.p_BM = Vec3(0.03, -0.02, 0.04);
  m.R_BM = ExpSO3(Vec3(0.2, 0.1, -0.3));
  return m;
}

double RotationJacobianError(double amplitude, int node) {
  const Fixture f = Make(amplitude);
  const int N = f.body->nv();
  const Marker m = FlexNodeMarker(node);
  const MarkerState s = Eval(f, m, f.q, f.v);
  MatX fd(3, N);
  for (int k = 0; k < N; ++k) {
    VecX e = VecX::Zero(N);
    e(k) = kH;
    const MarkerState p = Eval(f, m, Retracted(*f.body, f.q, e), f.v);
    const MarkerState q = Eval(f, m, Retracted(*f.body, f.q, -e), f.v);
    fd.col(k) = LogSO3(p.R_WM * q.R_WM.transpose()) / (2 * kH);
  }
  return RelErr(s.J.bottomRows(3), fd);
}

TEST(FlexibleBody, MarkerRotationJacobianIsFirstOrderInTheElasticRotation) {
  // the elastic rotation's exponential is differentiated to first order:
  // the error of the rotation rows shrinks linearly with the deformation
  for (int node : {0, 6}) {
    const double e1 = RotationJacobianError(1e-3, node), e2 = RotationJacobianError(1e-4, node);
    EXPECT_LT(e1, 2e-2) << "node " << node;
    EXPECT_LT(e2, 0.12 * e1) << "node " << node;
    EXPECT_GT(e2, 0.08 * e1) << "node " << node;
  }
}

TEST(FlexibleBody, MarkerJacobianMatchesPose) {
  const Fixture f = Make(1e-2);
  const int N = f.body->nv();
  for (int node : {-1, 0, 3, 6}) {
    const Marker m = FlexNodeMarker(node);
    const MarkerState s = Eval(f, m, f.q, f.v);
    MatX fd(6, N);
    for (int k = 0; k < N; ++k) {
      VecX e = VecX::Zero(N);
      e(k) = kH;
      const MarkerState p = Eval(f, m, Retracted(*f.body, f.q, e), f.v);
      const MarkerState q = Eval(f, m, Retracted(*f.body, f.q, -e), f.v);
      fd.block<3, 1>(0, k) = (p.p_WM - q.p_WM) / (2 * kH);
      fd.block<3, 1>(3, k) = LogSO3(p.R_WM * q.R_WM.transpose()) / (2 * kH);
    }
    // positions exactly (rotations: see the test above)
    EXPECT_LT(RelErr(s.J.topRows(3), fd.topRows(3)), 1e-7) << "node " << node;
    if (node < 0) EXPECT_LT(RelErr(s.J.bottomRows(3), fd.bottomRows(3)), 1e-7);
    // and the twist is J v
    EXPECT_LT((s.J.topRows(3) * f.v - s.v_WM).norm(), 1e-12 * (1 + s.v_WM.norm()));
    EXPECT_LT((s.J.bottomRows(3) * f.v - s.w_WM).norm(), 1e-12 * (1 + s.w_WM.norm()));
  }
  // in the undeformed state the rotation Jacobian is exact as well
  const Fixture u = Make(0.0);
  const Marker m = FlexNodeMarker(5);
  const MarkerState s = Eval(u, m, u.q, u.v);
  for (int k = 0; k < N; ++k) {
    VecX e = VecX::Zero(N);
    e(k) = kH;
    const MarkerState p = Eval(u, m, Retracted(*u.body, u.q, e), u.v);
    const MarkerState q = Eval(u, m, Retracted(*u.body, u.q, -e), u.v);
    const Vec3 fd = LogSO3(p.R_WM * q.R_WM.transpose()) / (2 * kH);
    EXPECT_LT((s.J.block<3, 1>(3, k) - fd).norm(), 1e-7 * (1 + fd.norm())) << "column " << k;
  }
}

TEST(FlexibleBody, MarkerTangentsMatchFiniteDifferences) {
  const Fixture f = Make(2e-2);
  const int N = f.body->nv();
  Vec6 wrench;
  wrench << 30.0, -12.0, 7.0, 2.0, -5.0, 1.5;
  for (int node : {-1, 2, 6}) {
    const Marker m = FlexNodeMarker(node);
    MatX twist(6, N), wt = MatX::Zero(N, N), fd_twist(6, N), fd_wt(N, N), fd_bias(6, 1);
    f.body->MarkerTwistTangent(f.q.data(), f.v.data(), m, twist);
    f.body->AddMarkerWrenchTangent(f.q.data(), m, wrench, wt);
    for (int k = 0; k < N; ++k) {
      VecX e = VecX::Zero(N);
      e(k) = kH;
      const MarkerState p = Eval(f, m, Retracted(*f.body, f.q, e), f.v);
      const MarkerState q = Eval(f, m, Retracted(*f.body, f.q, -e), f.v);
      fd_twist.col(k) = (p.J - q.J) * f.v / (2 * kH);
      fd_wt.col(k) = (p.J - q.J).transpose() * wrench / (2 * kH);
    }
    EXPECT_LT(RelErr(twist, fd_twist), 1e-7) << "node " << node;
    EXPECT_LT(RelErr(wt, fd_wt), 1e-7) << "node " << node;
    // bias = d/dt(J) v along the motion
    const MarkerState p = Eval(f, m, Retracted(*f.body, f.q, kH * f.v), f.v);
    const MarkerState q = Eval(f, m, Retracted(*f.body, f.q, -kH * f.v), f.v);
    const Vec6 bias_fd = (p.J - q.J) * f.v / (2 * kH);
    const Vec6 bias = f.body->MarkerAccelerationBias(f.q.data(), f.v.data(), m);
    EXPECT_LT((bias - bias_fd).norm(), 1e-6 * (1 + bias.norm())) << "node " << node;
  }
}

TEST(FlexibleBody, NodeForceIsVirtualWork) {
  // J^T wrench of a node marker: the power of the wrench on the marker twist
  const Fixture f = Make(1e-2);
  const Marker m = FlexNodeMarker(4);
  const MarkerState s = Eval(f, m, f.q, f.v);
  Vec6 wrench;
  wrench << 1.0, 2.0, -3.0, 0.5, 0.1, -0.2;
  const VecX Q = s.J.transpose() * wrench;
  EXPECT_NEAR(Q.dot(f.v), wrench.head<3>().dot(s.v_WM) + wrench.tail<3>().dot(s.w_WM), 1e-10);
}

TEST(FlexibleBody, BadInputNamesTheBody) {
  FlexibleBodyData d;
  try {
    FlexibleBody b("frame", d);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("frame"), std::string::npos) << e.what();
  }
  Fixture f = Make();
  d.reduced = f.reduced;
  d.w0 = VecX::Zero(2);
  EXPECT_THROW(FlexibleBody("frame", d), InputError);
  const Marker m = FlexNodeMarker(1000);
  MarkerState s;
  EXPECT_THROW(f.body->EvaluateMarker(f.q.data(), f.v.data(), m, s), InputError);
}

TEST(FlexibleBody, StrainEnergyAndNodeDisplacement) {
  const Fixture f = Make(1e-2);
  const int n = f.body->modes();
  const VecX w = f.q.tail(n);
  EXPECT_NEAR(f.body->StrainEnergy(f.q.data()), 0.5 * w.dot(f.reduced->stiffness * w), 1e-12);
  const Vec3 u = f.reduced->modes.block(6 * 4, 0, 3, n) * w;
  EXPECT_LT((f.body->NodeDisplacement(f.q.data(), 4) - u).norm(), 1e-15);
}

}  // namespace
}  // namespace flexmb
