// The iteration matrix S and the constraint Jacobian B as the assembler
// writes them through its precomputed value positions (Workspace::slots,
// skipping zero force-element blocks), against a reference assembled
// densely here from the same ingredients (body blocks, marker Jacobians,
// force and joint evaluations, body tangents), the formulas of
// assembler.h: a model with a floating-frame flexible body, a rigid body
// and the ground, a bushing and two spring-dampers (with damping, so the twist
// tangent term is present) and a spherical joint with non-zero multipliers.

#include <gtest/gtest.h>

#include <memory>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/forces/bushing.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/assembler.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb {
namespace {

// marker mk's Jacobian in the global velocity columns (6 x nv)
MatX SlotAsmJacobian(const Model& m, const Workspace& ws, int mk) {
  MatX J = MatX::Zero(6, m.nv);
  const MarkerState& ms = ws.markers[mk];
  if (ms.nv > 0) J.middleCols(ms.v_offset, ms.nv) = ms.J;
  return J;
}

// d(J^T w)/dx of marker mk's body at fixed world wrench w (nv x nv)
MatX SlotAsmWrenchTangent(const Model& m, const State& s, int mk, const Vec6& w) {
  MatX T = MatX::Zero(m.nv, m.nv);
  const Marker& marker = m.markers[mk];
  const Body& b = *m.bodies[marker.body];
  if (b.nv() == 0) return T;
  MatX Tb = MatX::Zero(b.nv(), b.nv());
  b.AddMarkerWrenchTangent(s.q.data() + b.q_offset, marker, w, Tb);
  T.block(b.v_offset, b.v_offset, b.nv(), b.nv()) = Tb;
  return T;
}

// d(J v)/dx of marker mk at fixed v (6 x nv)
MatX SlotAsmTwistTangent(const Model& m, const State& s, int mk) {
  MatX T = MatX::Zero(6, m.nv);
  const Marker& marker = m.markers[mk];
  const Body& b = *m.bodies[marker.body];
  if (b.nv() == 0) return T;
  MatX Tb = MatX::Zero(6, b.nv());
  b.MarkerTwistTangent(s.q.data() + b.q_offset, s.v.data() + b.v_offset, marker, Tb);
  T.middleCols(b.v_offset, b.nv()) = Tb;
  return T;
}

// dense S = [[A, B^T], [B, 0]] after the evaluations of the assembler
MatX SlotAsmReference(const Model& m, const State& s, const Workspace& ws, const MatrixCoefficients& c) {
  const int nv = m.nv;
  MatX S = MatX::Zero(nv + ws.n_active, nv + ws.n_active);
  auto A = S.topLeftCorner(nv, nv);
  for (size_t k = 0; k < m.bodies.size(); ++k) {
    const Body& b = *m.bodies[k];
    if (b.nv() == 0) continue;
    A.block(b.v_offset, b.v_offset, b.nv(), b.nv()) +=
        c.mass * ws.mass[k] - c.damping * ws.dQdv[k] - c.stiffness * ws.dQdq[k];
  }
  for (size_t k = 0; k < m.forces.size(); ++k) {
    const ForceElement& f = *m.forces[k];
    const ForceEval& e = ws.forces[k];
    const int nm = f.marker_j >= 0 ? 2 : 1;
    const int mk[2] = {f.marker_i, f.marker_j};
    for (int a = 0; a < nm; ++a) {
      const MatX Ja = SlotAsmJacobian(m, ws, mk[a]);
      A -= c.stiffness * SlotAsmWrenchTangent(m, s, mk[a], e.wrench.segment<6>(6 * a));
      for (int b = 0; b < nm; ++b) {
        const MatX Jb = SlotAsmJacobian(m, ws, mk[b]);
        const Eigen::Matrix<double, 6, 6> K = e.K.block<6, 6>(6 * a, 6 * b), C = e.C.block<6, 6>(6 * a, 6 * b);
        A -= Ja.transpose() * (c.stiffness * K + c.damping * C) * Jb;
        A -= c.stiffness * Ja.transpose() * C * SlotAsmTwistTangent(m, s, mk[b]);
      }
    }
  }
  for (size_t k = 0; k < m.joints.size(); ++k) {
    const Joint& j = *m.joints[k];
    const JointEval& e = ws.joints[k];
    const int mk[2] = {j.marker_i, j.marker_j};
    const MatX J[2] = {SlotAsmJacobian(m, ws, mk[0]), SlotAsmJacobian(m, ws, mk[1])};
    double lam[16] = {0};
    Vec12 w = Vec12::Zero();
    for (int q = 0; q < j.NumEquations(); ++q) {
      const int r = ws.row_of_eq[j.lambda_offset + q];
      if (r < 0) continue;
      lam[q] = s.lambda(j.lambda_offset + q);
      w += lam[q] * e.D.row(q).transpose();
      const MatX row = e.D.block(q, 0, 1, 6) * J[0] + e.D.block(q, 6, 1, 6) * J[1];
      S.block(nv + r, 0, 1, nv) += row;
      S.block(0, nv + r, nv, 1) += row.transpose();
    }
    Mat12 H = Mat12::Zero();
    j.AddGeometricStiffness(ws.markers[mk[0]], ws.markers[mk[1]], lam, H);
    for (int a = 0; a < 2; ++a) {
      A += c.stiffness * SlotAsmWrenchTangent(m, s, mk[a], w.segment<6>(6 * a));
      for (int b = 0; b < 2; ++b) A += c.stiffness * J[a].transpose() * H.block<6, 6>(6 * a, 6 * b) * J[b];
    }
  }
  return S;
}

TEST(SlotAssembly, IterationMatrixEqualsDenseReference) {
  Model m;
  const FlexibleBodyData d = testing::SpinningDeformedBentBar();
  const int bar = m.AddBody(std::make_unique<FlexibleBody>("bar", d));
  RigidBodyData r;
  r.mass = 2.0;
  r.inertia_C << 0.3, 0.02, -0.01, 0.02, 0.5, 0.03, -0.01, 0.03, 0.4;
  r.c_B = Vec3(0.1, -0.05, 0.2);
  r.p_WB = Vec3(0.3, 0.4, 0.1);
  r.R_WB = ExpSO3(Vec3(0.3, -0.5, 0.8));
  r.w_WB = Vec3(-0.4, 0.9, 0.2);
  r.v_WB = Vec3(0.1, -0.2, 0.5);
  const int rb = m.AddBody(std::make_unique<RigidBody>("a", r));
  const int f0 = m.AddMarker(bar, "end0", Vec3(0.01, 0.02, -0.01), Mat3::Identity(), 0);
  const int f6 = m.AddMarker(bar, "end6", Vec3(-0.02, 0.0, 0.03), ExpSO3(Vec3(0.1, 0.2, -0.1)), 6);
  const int fc = m.AddMarker(bar, "frame", Vec3(0.2, -0.1, 0.05), Mat3::Identity());
  const int a1 = m.AddMarker(rb, "a1", Vec3(0.4, 0.1, -0.2), ExpSO3(Vec3(0.2, 0.1, -0.3)));
  const int a2 = m.AddMarker(rb, "a2", Vec3(-0.2, 0.3, 0.1), Mat3::Identity());
  const int g = m.AddMarker(0, "anchor", Vec3(-0.5, 0.4, 1.0), Mat3::Identity());
  BushingData bd;
  bd.translational_stiffness = Vec3(1e3, 2e3, 1.5e3);
  bd.rotational_stiffness = Vec3(50, 80, 30);
  bd.translational_damping = Vec3(10, 20, 15);
  bd.rotational_damping = Vec3(1, 2, 3);
  bd.preload_force = Vec3(5, -3, 2);
  m.AddForce(std::make_unique<Bushing>("bushing", bd), f0, a1);
  SpringDamperLaw sl;
  sl.stiffness = 800.0;
  sl.damping = 12.0;
  sl.free_length = 0.5;
  m.AddForce(std::make_unique<SpringDamper>("hang", sl), g, f6);
  m.AddForce(std::make_unique<SpringDamper>("tie", sl), fc, a2);
  m.AddJoint(std::make_unique<SphericalJoint>("ball"), f6, a2);
  m.Finalize();
  Workspace ws;
  InitWorkspace(m, ws);
  State s = m.InitialState();
  s.lambda = VecX::LinSpaced(m.nc, 40.0, -25.0);

  const MatrixCoefficients c{1.3, 0.7, 0.4, true};
  EvaluateMarkers(m, s, ws);
  EvaluateConstraints(m, s, ws);
  EvaluateForces(m, s, ws, true);
  AssembleIterationMatrix(m, s, ws, c);
  const MatX ref = SlotAsmReference(m, s, ws, c);
  const MatX S(ws.S);
  ASSERT_EQ(S.rows(), ref.rows());
  const double scale = ref.cwiseAbs().maxCoeff();
  EXPECT_LT((S - ref).cwiseAbs().maxCoeff(), 1e-12 * scale) << "largest |S| " << scale;
  // B is the bottom-left of S
  EXPECT_LT((MatX(ws.B) - ref.bottomLeftCorner(ws.n_active, m.nv)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  // assembling again (values zeroed and rewritten in place) gives the same S
  AssembleIterationMatrix(m, s, ws, c);
  EXPECT_EQ((MatX(ws.S) - S).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace flexmb
