// The force elements inside the engine: the top-left block of the assembled
// iteration matrix against central differences of the generalized forces
// ws.Q of a model of two free rigid bodies (and the ground) connected by
// force elements whose markers sit off the centres of mass.

#include <gtest/gtest.h>

#include <random>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/forces/bushing.h"
#include "flexmb/forces/point_force.h"
#include "flexmb/forces/point_torque.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/solver/assembler.h"

namespace flexmb {
namespace {

struct Bench {
  std::unique_ptr<Model> model = std::make_unique<Model>();
  State state;
  Workspace ws;
};

Bench TwoBodies(bool all_elements) {
  Bench b;
  Model& m = *b.model;
  RigidBodyData a;
  a.mass = 2.0;
  a.inertia_C << 0.3, 0.02, -0.01, 0.02, 0.5, 0.03, -0.01, 0.03, 0.4;
  a.c_B = Vec3(0.1, -0.05, 0.2);
  a.p_WB = Vec3(0.1, 0.2, 0.3);
  a.R_WB = ExpSO3(Vec3(0.3, -0.5, 0.8));
  RigidBodyData c = a;
  c.mass = 1.3;
  c.c_B = Vec3(-0.2, 0.1, 0.05);
  c.p_WB = Vec3(0.9, 0.1, 0.4);
  c.R_WB = ExpSO3(Vec3(-0.6, 0.2, 0.1));
  const int ba = m.AddBody(std::make_unique<RigidBody>("a", a));
  const int bc = m.AddBody(std::make_unique<RigidBody>("c", c));
  const int a1 = m.AddMarker(ba, "m1", Vec3(0.4, 0.1, -0.2), ExpSO3(Vec3(0.2, 0.1, -0.3)));
  const int c1 = m.AddMarker(bc, "m1", Vec3(-0.3, 0.2, 0.1), ExpSO3(Vec3(-0.1, 0.4, 0.2)));
  const int a2 = m.AddMarker(ba, "m2", Vec3(-0.2, 0.3, 0.1), Mat3::Identity());
  const int c2 = m.AddMarker(bc, "m2", Vec3(0.25, -0.1, 0.3), Mat3::Identity());
  BushingData bd;
  bd.translational_stiffness = Vec3(1e3, 2e3, 1.5e3);
  bd.rotational_stiffness = Vec3(50, 80, 30);
  bd.translational_damping = Vec3(10, 20, 15);
  bd.rotational_damping = Vec3(1, 2, 3);
  bd.preload_force = Vec3(5, -3, 2);
  bd.preload_torque = Vec3(0.5, 0.2, -0.4);
  m.AddForce(std::make_unique<Bushing>("bushing", bd), a1, c1);
  SpringDamperLaw sl;
  sl.stiffness = 800.0;
  sl.damping = 12.0;
  sl.free_length = 0.5;
  sl.preload = 20.0;
  m.AddForce(std::make_unique<SpringDamper>("spring", sl), a2, c2);
  if (all_elements) {
    // a spring to the ground and follower loads
    const int g = m.AddMarker(0, "anchor", Vec3(-0.5, 0.4, 1.0), Mat3::Identity());
    m.AddForce(std::make_unique<SpringDamper>("hang", sl), g, a1);
    std::array<std::shared_ptr<const ScalarFunction>, 3> f = {
        std::make_shared<ConstantFunction>(3.0), std::make_shared<ConstantFunction>(-7.0),
        std::make_shared<ConstantFunction>(4.0)};
    m.AddForce(std::make_unique<PointForce>("push", f, LoadFrame::kMarker), c1, -1);
    m.AddForce(std::make_unique<PointTorque>("twist", f, LoadFrame::kMarker), a2, -1);
  }
  m.Finalize();
  b.state = m.InitialState();
  // move both bodies off their initial poses so nothing is at rest
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  VecX dx(m.nv);
  for (int k = 0; k < m.nv; ++k) dx(k) = u(rng);
  VecX q = b.state.q;
  RetractAll(m, q, dx, b.state.q);
  InitWorkspace(m, b.ws);
  return b;
}

VecX Forces(const Model& m, const State& s, Workspace& ws) {
  EvaluateMarkers(m, s, ws);
  EvaluateForces(m, s, ws, false);
  return ws.Q;
}

MatX TopLeft(Bench& b, const MatrixCoefficients& c) {
  const Model& m = *b.model;
  EvaluateMarkers(m, b.state, b.ws);
  EvaluateConstraints(m, b.state, b.ws);
  EvaluateForces(m, b.state, b.ws, true);
  AssembleIterationMatrix(m, b.state, b.ws, c);
  return MatX(b.ws.S).topLeftCorner(m.nv, m.nv);
}

// central differences of Q under q (+) +-h e_k (stiffness) or v +- h e_k
MatX FiniteDifference(Bench& b, bool velocity) {
  const Model& m = *b.model;
  const double h = 1e-6;
  MatX D(m.nv, m.nv);
  for (int k = 0; k < m.nv; ++k) {
    State sp = b.state, sm = b.state;
    if (velocity) {
      sp.v(k) += h;
      sm.v(k) -= h;
    } else {
      VecX dx = VecX::Zero(m.nv);
      dx(k) = h;
      RetractAll(m, b.state.q, dx, sp.q);
      RetractAll(m, b.state.q, -dx, sm.q);
    }
    D.col(k) = (Forces(m, sp, b.ws) - Forces(m, sm, b.ws)) / (2 * h);
  }
  return D;
}

double RelErr(const MatX& a, const MatX& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

TEST(AssembledForces, StiffnessBlockAtRest) {
  for (bool all : {false, true}) {
    Bench b = TwoBodies(all);
    b.state.v.setZero();
    const MatX A = TopLeft(b, MatrixCoefficients{0, 0, 1, false});
    const MatX fd = FiniteDifference(b, false);
    EXPECT_LT(RelErr(A, -fd), 1e-6) << "assembled\n" << A << "\n-dQ/dq fd\n" << -fd;
  }
}

// d(J v)/dq of a rigid-body marker at fixed v: with twist = (v_C + R (w x s),
// R w) and R <- R exp(dth_B), the columns dth_B are (-R skew(w x s), -R skew(w)).
Eigen::Matrix<double, 6, 6> TwistTangent(const Model& m, const State& s, int marker) {
  const Body& body = *m.bodies[m.markers[marker].body];
  const double* q = s.q.data() + body.q_offset;
  const double* v = s.v.data() + body.v_offset;
  const Mat3 R = Quat(q[3], q[4], q[5], q[6]).toRotationMatrix();
  const Vec3 w(v[3], v[4], v[5]), p = m.markers[marker].p_BM;
  Eigen::Matrix<double, 6, 6> G = Eigen::Matrix<double, 6, 6>::Zero();
  G.block<3, 3>(0, 3) = -R * Skew(w.cross(p));
  G.block<3, 3>(3, 3) = -R * Skew(w);
  return G;
}

// With the bodies moving, the marker twists depend on q at fixed v, so
// dQ/dq holds sum J_a^T C_ab d(J_b v_b)/dq_b besides J^T K J and
// d(J^T)/dq w. The test checks the assembled block against finite
// differences and that this damping term (computed here independently) is
// large enough for the check to notice it missing.
TEST(AssembledForces, StiffnessBlockMoving) {
  Bench b = TwoBodies(true);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < b.model->nv; ++k) b.state.v(k) = u(rng);
  const Model& m = *b.model;
  const MatX A = TopLeft(b, MatrixCoefficients{0, 0, 1, false});
  MatX twist_term = MatX::Zero(m.nv, m.nv);
  for (size_t k = 0; k < m.forces.size(); ++k) {
    const ForceElement& f = *m.forces[k];
    const int mk[2] = {f.marker_i, f.marker_j};
    const int nm = f.marker_j >= 0 ? 2 : 1;
    for (int a = 0; a < nm; ++a)
      for (int c = 0; c < nm; ++c) {
        const MarkerState& ma = b.ws.markers[mk[a]];
        const MarkerState& mc = b.ws.markers[mk[c]];
        if (ma.nv == 0 || mc.nv == 0) continue;
        twist_term.block(ma.v_offset, mc.v_offset, ma.nv, mc.nv) +=
            ma.J.transpose() * b.ws.forces[k].C.block<6, 6>(6 * a, 6 * c) * TwistTangent(m, b.state, mk[c]);
      }
  }
  const MatX fd = FiniteDifference(b, false);
  EXPECT_GT(twist_term.cwiseAbs().maxCoeff(), 1.0);
  EXPECT_GT(RelErr(A + twist_term, -fd), 1e-3);  // without the term the check fails
  EXPECT_LT(RelErr(A, -fd), 1e-6) << "assembled\n" << A << "\n-dQ/dq fd\n" << -fd;
}

TEST(AssembledForces, DampingBlock) {
  Bench b = TwoBodies(true);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < b.model->nv; ++k) b.state.v(k) = u(rng);
  const MatX A = TopLeft(b, MatrixCoefficients{0, 1, 0, false});
  const MatX fd = FiniteDifference(b, true);
  EXPECT_LT(RelErr(A, -fd), 1e-6) << "assembled\n" << A << "\n-dQ/dv fd\n" << -fd;
}

}  // namespace
}  // namespace flexmb
