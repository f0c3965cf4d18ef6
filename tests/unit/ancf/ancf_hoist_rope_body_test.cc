// Unit tests of the hoisting rope of changing length: force tangents (and
// the force-only path) and the mass tangent against finite differences,
// forces against the potentials, the kinetic energy against the integral
// of the material points'
// velocities (taken by finite differences of their positions, independent
// of the body's matrices), the velocity terms against Lagrange's equations
// of that kinetic energy, the payout marker, mass bookkeeping, bad input.
#include "flexmb/ancf/ancf_hoist_rope_body.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/common/error.h"
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb::ancf {
namespace {

HoistRopeData RopeData() {
  HoistRopeData d;
  d.free_length = 6.0;
  d.stored_length = 30.0;
  d.elements = 4;
  d.section = test_util::MakeSection(1e9, 2e-4, 3e-9, 7800.0, 0.002);
  d.start_W = Vec3(1.0, 0.5, 10.0);
  d.direction_W = Vec3(0.2, 0.1, -1.0);
  d.drum_W = Vec3(-3.0, 0.0, 2.0);
  d.drum_radius = 0.25;
  d.drum_inertia = 4.0;
  d.payout_speed = 0.7;
  return d;
}

void State(const AncfHoistRopeBody& b, VecX& q, VecX& v) { test_util::PerturbedBodyState(b, 0.05, q, v); }

// the rope of RopeData without damping
HoistRopeData UndampedRopeData() {
  HoistRopeData d = RopeData();
  d.section.damping = 0.0;
  return d;
}

TEST(AncfHoistRopeBody, ForceTangentsMatchCentralDifferences) {
  for (auto measure : {AxialStrainMeasure::kEngineering, AxialStrainMeasure::kGreenLagrange}) {
    HoistRopeData d = RopeData();
    d.section.axial_strain = measure;
    const AncfHoistRopeBody b("rope", d);
    VecX q, v;
    State(b, q, v);
    test_util::ExpectBodyForceTangentsMatchCentralDifferences(b, q, v, Vec3(0.0, 0.0, -9.81));
  }
}

// A stiff bending section (EI = 1e6 N m^2, as large as the axial terms of
// the 1.5 m elements): with a rope's EI the bending tangents are below the
// axial ones' tolerance, so this case checks them (a 10 % error in one of
// their terms fails it).
TEST(AncfHoistRopeBody, BendingTangentsMatchCentralDifferences) {
  HoistRopeData d = RopeData();
  d.section = test_util::MakeSection(1e9, 2e-4, 1e-3, 7800.0, 0.002);
  const AncfHoistRopeBody b("rope", d);
  VecX q, v;
  State(b, q, v);
  test_util::ExpectBodyForceTangentsMatchCentralDifferences(b, q, v, Vec3(0.0, 0.0, -9.81));
}

TEST(AncfHoistRopeBody, ForcesArePotentialGradients) {
  const HoistRopeData d = UndampedRopeData();
  const AncfHoistRopeBody b("rope", d);
  VecX q, v;
  State(b, q, v);
  test_util::ExpectBodyForcesArePotentialGradients(b, q, Vec3(0.3, -0.2, -9.81));
  // the straight, unstretched rope stores no strain energy
  VecX q0(b.nq()), v0(b.nv());
  b.InitialCoordinates(q0.data(), v0.data());
  EXPECT_LT(b.ElasticEnergy(q0.data()), 1e-18 * d.section.E * d.section.A * d.free_length);
}

TEST(AncfHoistRopeBody, MassTangentMatchesCentralDifferences) {
  const AncfHoistRopeBody b("rope", RopeData());
  VecX q, v;
  State(b, q, v);
  const VecX a = test_util::TestAcceleration(b);
  const int n = b.nv();
  MatX K = MatX::Zero(n, n);
  b.AddMassTangent(q.data(), a.data(), 1.0, K);
  const double h = 1e-6;
  MatX Mp, Mm;
  for (int j = 0; j < n; ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    b.MassMatrix(qp.data(), Mp);
    b.MassMatrix(qm.data(), Mm);
    EXPECT_LT(((Mp - Mm) * a / (2 * h) - K.col(j)).norm(), 1e-6 * K.norm()) << j;
  }
  MatX M;
  b.MassMatrix(q.data(), M);
  EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
}

// kinetic energy of the span by quadrature of rho A |v|^2 over the material
// arc length, with the material points' velocities taken as central
// differences of MaterialPoint along (q + t v): independent of Mb, Cb, Db
double SpanKineticEnergyFromMaterialPoints(const AncfHoistRopeBody& b, const HoistRopeData& d, const VecX& q,
                                           const VecX& v) {
  const double L = b.FreeLength(q.data()), N = d.elements, h = 1e-6;
  const double *xs = nullptr, *ws = nullptr;
  GaussPoints01(5, xs, ws);
  const VecX qp = q + h * v, qm = q - h * v;
  double T = 0.0;
  for (int e = 0; e < d.elements; ++e)
    for (int g = 0; g < 5; ++g) {
      const double sigma = (N - e - xs[g]) * L / N;
      const Vec3 u = (b.MaterialPoint(qp.data(), sigma) - b.MaterialPoint(qm.data(), sigma)) / (2 * h);
      T += 0.5 * d.section.rho * d.section.A * u.squaredNorm() * ws[g] * L / N;
    }
  return T;
}

TEST(AncfHoistRopeBody, KineticEnergyIsThatOfTheMaterialPointsDrumAndStoredRope) {
  const HoistRopeData d = RopeData();
  const AncfHoistRopeBody b("rope", d);
  VecX q, v;
  State(b, q, v);
  const double L = b.FreeLength(q.data()), Ld = v(b.LengthIndex());
  const double stored = 0.5 * (d.section.rho * d.section.A * (d.free_length + d.stored_length - L) +
                               d.drum_inertia / (d.drum_radius * d.drum_radius)) *
                        Ld * Ld;
  const double T = SpanKineticEnergyFromMaterialPoints(b, d, q, v) + stored;
  EXPECT_NEAR(b.KineticEnergy(q.data(), v.data()), T, 1e-7 * T);
  // the straight rope paid out uniformly: every material point moves with L'
  VecX q0(b.nq()), v0(b.nv());
  b.InitialCoordinates(q0.data(), v0.data());
  const double m_all = d.section.rho * d.section.A * (d.free_length + d.stored_length) +
                       d.drum_inertia / (d.drum_radius * d.drum_radius);
  EXPECT_NEAR(b.KineticEnergy(q0.data(), v0.data()), 0.5 * m_all * d.payout_speed * d.payout_speed,
              1e-12 * m_all);
  const Vec6 p = b.Momentum(q0.data(), v0.data());
  const Vec3 t0 = d.direction_W.normalized();
  EXPECT_LT((p.head<3>() - d.section.rho * d.section.A * d.free_length * d.payout_speed * t0).norm(), 1e-12);
}

// M(q) vdot = Q: the velocity part of Q (no gravity, no damping in b) must
// be dT/dq - (dM/dq v) v
void ExpectVelocityTermsAreLagrangesEquations(const AncfHoistRopeBody& b, const VecX& q, const VecX& v) {
  const int n = b.nv();
  auto forces = [&](const VecX& vv) {
    VecX Q = VecX::Zero(n);
    MatX K = MatX::Zero(n, n), C = MatX::Zero(n, n);
    b.AddForces(q.data(), vv.data(), Vec3::Zero(), Q, K, C);
    return Q;
  };
  const VecX Qv = forces(v) - forces(VecX::Zero(n));
  const double h = 1e-6;
  VecX expected(n);
  MatX Mp, Mm;
  b.MassMatrix((q + h * v).eval().data(), Mp);
  b.MassMatrix((q - h * v).eval().data(), Mm);
  const VecX Mdot_v = (Mp - Mm) * v / (2 * h);
  for (int j = 0; j < n; ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    expected(j) = (b.KineticEnergy(qp.data(), v.data()) - b.KineticEnergy(qm.data(), v.data())) / (2 * h) -
                  Mdot_v(j);
  }
  EXPECT_LT((Qv - expected).norm(), 1e-6 * expected.norm());
}

TEST(AncfHoistRopeBody, VelocityTermsAreLagrangesEquations) {
  const AncfHoistRopeBody b("rope", UndampedRopeData());
  VecX q, v;
  State(b, q, v);
  ExpectVelocityTermsAreLagrangesEquations(b, q, v);
}

// Without the drum in the body (fed over the sheave by a rope's span): no
// drum, no stored rope; the rope enters at node 0's height.
HoistRopeData FedRopeData() {
  HoistRopeData d = RopeData();
  d.drum_in_body = false;
  d.drum_radius = 0.0;  // not used
  d.drum_inertia = 0.0;
  return d;
}

TEST(AncfHoistRopeBody, FedSpanTangentsMassAndVelocityTerms) {
  const HoistRopeData d = FedRopeData();
  const AncfHoistRopeBody b("rope", d);
  VecX q, v;
  State(b, q, v);
  test_util::ExpectBodyForceTangentsMatchCentralDifferences(b, q, v, Vec3(0.3, -0.2, -9.81));
  // the mass: that of the span alone (drum and stored rope take no part)
  const int n = b.nv();
  MatX M, Mdrum;
  b.MassMatrix(q.data(), M);
  const AncfHoistRopeBody with_drum("drum", RopeData());
  with_drum.MassMatrix(q.data(), Mdrum);
  const double L = b.FreeLength(q.data());
  const double m_stored = d.section.rho * d.section.A * (d.free_length + d.stored_length - L);
  EXPECT_NEAR(Mdrum(n - 1, n - 1) - M(n - 1, n - 1), m_stored + 4.0 / (0.25 * 0.25), 1e-9 * M.norm());
  EXPECT_LT((Mdrum.topLeftCorner(n - 1, n) - M.topLeftCorner(n - 1, n)).norm(), 1e-14 * M.norm());
  const auto [span, stored] = b.RopeMasses(q.data());
  EXPECT_NEAR(span, d.section.rho * d.section.A * L, 1e-12);
  EXPECT_EQ(stored, 0.0);
  // the velocity terms: Lagrange's equations of its kinetic energy
  HoistRopeData u = d;
  u.section.damping = 0.0;
  ExpectVelocityTermsAreLagrangesEquations(AncfHoistRopeBody("rope", u), q, v);
}

// The fed span's gravity: the span's weight relative to node 0 is the
// potential of every applied force but node 0's (the rope's mass appears at
// the sheave, so the span's weight carried with a moving sheave is not
// applied there: exactly rho A L g is missing at node 0, documented).
TEST(AncfHoistRopeBody, FedSpanGravityIsTheSpansWeightRelativeToNodeZero) {
  HoistRopeData d = FedRopeData();
  d.section.damping = 0.0;
  const AncfHoistRopeBody b("rope", d);
  VecX q, v;
  State(b, q, v);
  const int n = b.nv();
  const Vec3 g(0.3, -0.2, -9.81);
  VecX Qg = VecX::Zero(n), Q0 = VecX::Zero(n);
  MatX K = MatX::Zero(n, n), C = MatX::Zero(n, n);
  const VecX v0 = VecX::Zero(n);
  b.AddForces(q.data(), v0.data(), g, Qg, K, C);
  b.AddForces(q.data(), v0.data(), Vec3::Zero(), Q0, K, C);
  const double h = 1e-6, L = b.FreeLength(q.data());
  for (int j = 0; j < n; ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    const double dV = (b.GravityPotential(qp.data(), g) - b.GravityPotential(qm.data(), g)) / (2 * h);
    const double missing = j < 3 ? d.section.rho * d.section.A * L * g(j) : 0.0;
    EXPECT_NEAR(Qg(j) - Q0(j), -dV + missing, 1e-6 * (1.0 + Qg.norm())) << j;
  }
  // at the free length's coordinate: the weight of the span relative to the
  // sheave pulls rope in, rho A g . (r_0 - mean r) per metre in the mesh
  EXPECT_GT(std::abs(Qg(n - 1) - Q0(n - 1)), 1.0);
}

TEST(AncfHoistRopeBody, InitialLengthStartsTheSpanStretched) {
  HoistRopeData d = FedRopeData();
  d.initial_length = 6.3;  // 5 % stretch
  const AncfHoistRopeBody b("rope", d);
  VecX q(b.nq()), v(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  const Vec3 t0 = d.direction_W.normalized();
  EXPECT_LT((q.segment<3>(6 * d.elements) - (d.start_W + 6.3 * t0)).norm(), 1e-14);
  EXPECT_EQ(b.FreeLength(q.data()), 6.0);
  EXPECT_NEAR(b.AxialForce(q.data(), 1), d.section.E * d.section.A * 0.05, 1e-9 * d.section.E * d.section.A);
  d.initial_length = -1.0;
  EXPECT_THROW(AncfHoistRopeBody("bad", d), InputError);
}

TEST(AncfHoistRopeBody, MarkersAndMassBookkeeping) {
  const HoistRopeData d = RopeData();
  const AncfHoistRopeBody b("rope", d);
  VecX q, v;
  State(b, q, v);
  for (int node : {0, 2, 4, 5}) {
    Marker m;
    m.name = "rope.m";
    m.node = node;
    test_util::ExpectMarkerJacobianMatchesCentralDifferences(b, q, v, m);
    test_util::ExpectMarkerTangentsMatchCentralDifferences(b, q, v, m, test_util::TestWrench());
  }
  Marker payout;
  payout.name = "rope.payout";
  payout.node = b.PayoutNode();
  MarkerState ms;
  b.EvaluateMarker(q.data(), v.data(), payout, ms);
  EXPECT_EQ(ms.p_WM.x(), b.FreeLength(q.data()));
  EXPECT_EQ(ms.v_WM.x(), v(b.LengthIndex()));
  // the hook end (node N) is the material end sigma = 0; node 0 is sigma = L
  EXPECT_LT((b.MaterialPoint(q.data(), 0.0) - q.segment<3>(6 * d.elements)).norm(), 1e-14);
  EXPECT_LT((b.MaterialPoint(q.data(), b.FreeLength(q.data())) - q.head<3>()).norm(), 1e-14);
  const auto [span, stored] = b.RopeMasses(q.data());
  EXPECT_NEAR(span + stored, d.section.rho * d.section.A * (d.free_length + d.stored_length), 1e-12);
  // a marker with an offset or on a missing node is an error naming it
  Marker bad = payout;
  bad.node = d.elements + 2;
  EXPECT_THROW(b.EvaluateMarker(q.data(), v.data(), bad, ms), InputError);
  bad.node = 1;
  bad.p_BM = Vec3(0.1, 0.0, 0.0);
  EXPECT_THROW(b.EvaluateMarker(q.data(), v.data(), bad, ms), InputError);
}

TEST(AncfHoistRopeBody, RunningOutOfRopeIsANumericalErrorNamingTheBody) {
  const HoistRopeData d = RopeData();
  const AncfHoistRopeBody b("rope", d);
  VecX q, v;
  State(b, q, v);
  const int n = b.nv();
  VecX Q = VecX::Zero(n);
  MatX K = MatX::Zero(n, n), C = MatX::Zero(n, n);
  for (double L : {0.0, d.free_length + d.stored_length + 1.0}) {
    q(b.LengthIndex()) = L;
    try {
      b.AddForces(q.data(), v.data(), Vec3::Zero(), Q, K, C);
      ADD_FAILURE() << "no error at L = " << L;
    } catch (const NumericalError& e) {
      EXPECT_EQ(e.context().entity, "body 'rope'");
    }
  }
}

TEST(AncfHoistRopeBody, BadInputThrowsNamingTheBody) {
  auto expect_named = [](const HoistRopeData& bad) {
    try {
      AncfHoistRopeBody("rope", bad);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.context().entity, "body 'rope'");
    }
  };
  for (double x : {0.0, -1.0}) {
    HoistRopeData d = RopeData();
    d.free_length = x;
    expect_named(d);
    d = RopeData();
    d.drum_radius = x;
    expect_named(d);
    d = RopeData();
    d.section.A = x;
    expect_named(d);
  }
  HoistRopeData d = RopeData();
  d.elements = 0;
  expect_named(d);
  d = RopeData();
  d.stored_length = -1.0;
  expect_named(d);
  d = RopeData();
  d.stored_length = 0.0;
  d.drum_inertia = 0.0;
  expect_named(d);
  d = RopeData();
  d.direction_W.setZero();
  expect_named(d);
}

}  // namespace
}  // namespace flexmb::ancf
