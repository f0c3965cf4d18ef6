// 3-node beam (B32): rigid-body modes on a skew axis with an off-centre mid
// node, the cantilever's tip and mid-node displacements against Timoshenko
// beam theory (exact under end loads: P x^2 (3 L - x) / (6 E I) + P x / (k G
// A)), a tip load on a cantilever whose span is loaded at the mid node
// (superposition, exact), the section forces at both ends against statics,
// the rigid-body mass and inertia of the consistent and lumped mass, the
// Euler buckling load of a cantilever column from the geometric stiffness,
// an offset of the axis as a rigid link (an eccentric axial load bends it
// by P e), and errors for curved elements, mid nodes at an end and
// different end offsets.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/beam3.h"
#include "flexmb/fe/element_traits.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace beam3_test {

using testing::ExpectInputErrorWith;
using testing::ExpectSixRigidModes;
using testing::RandomRotation;
using testing::RigidModes;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// a 3-node beam from a to b with its mid node at the fraction s of the chord
struct Beam3Fixture {
  Element element;
  Material material;
  BeamSection section;
  std::vector<Vec3> x;

  Beam3Fixture(const Vec3& a, const Vec3& b, const Vec3& v, double s = 0.5) {
    element.id = 77;
    element.type = kBeam3;
    element.nodes = {0, 1, 2};
    element.orientation = v;
    element.origin = {"boom.inp", 12};
    material.E = 2.1e11;
    material.nu = 0.3;
    material.rho = 7850.0;
    section.A = 3.0e-3;
    section.Iy = 4.0e-6;
    section.Iz = 9.0e-6;
    section.J = 2.5e-6;
    section.ky = 0.8;
    section.kz = 0.6;
    section.nsm = 1.5;
    x = {a, a + s * (b - a), b};
  }
  double G() const { return material.E / (2.0 * (1.0 + material.nu)); }
  ElementInput Input(MassForm form = MassForm::kConsistent) const {
    ElementInput in;
    in.element = &element;
    in.x = x.data();
    in.material = &material;
    in.beam = &section;
    in.mass_form = form;
    return in;
  }
};

// clamps node A and solves for the mid node and B under the load f (12)
Eigen::VectorXd Clamped(const MatX& K, const Eigen::VectorXd& f) {
  return K.bottomRightCorner(12, 12).ldlt().solve(f);
}

TEST(Beam3, RigidBodyModesOnASkewAxis) {
  const Eigen::Matrix3d R = RandomRotation(3);
  for (double s : {0.5, 0.3}) {
    Beam3Fixture b(Vec3(0.2, 1.0, -0.5), Vec3(0.2, 1.0, -0.5) + R * Vec3(1.7, 0.0, 0.0), R * Vec3(0.3, 1.0, 0.0), s);
    MatX K, M;
    Beam3Matrices(b.Input(), K, M);
    ASSERT_EQ(K.rows(), 18);
    ExpectSixRigidModes(K, b.x, 6);
    EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
  }
}

// a tip load P along local y: v(x) = P x^2 (3 L - x) / (6 E Iz) + P x / (ky G A),
// theta_z(x) = P x (2 L - x) / (2 E Iz); along local z the same with Iy, kz
// and theta_y = -w'; at the mid node (x = s L) and the tip
TEST(Beam3, CantileverDisplacementsAreExactAtTheMidNodeAndTheTip) {
  const Eigen::Matrix3d R = RandomRotation(11);
  const double L = 2.4, P = 1.0e3;
  for (double s : {0.5, 0.35}) {
    const Vec3 a(0.4, -0.3, 1.0);
    Beam3Fixture b(a, a + R * Vec3(L, 0.0, 0.0), R * Vec3(0.5, 2.0, 0.0), s);
    MatX K, M;
    Beam3Matrices(b.Input(), K, M);
    const double E = b.material.E, G = b.G();
    const BeamSection& sec = b.section;
    for (int dir : {1, 2}) {
      const double I = dir == 1 ? sec.Iz : sec.Iy, k = dir == 1 ? sec.ky : sec.kz;
      const double sign = dir == 1 ? 1.0 : -1.0;  // theta_z = v', theta_y = -w'
      Eigen::VectorXd f = Eigen::VectorXd::Zero(12);
      f.segment<3>(6) = P * R.col(dir);
      const Eigen::VectorXd u = Clamped(K, f);
      const double scale = P * L * L * L / (E * I);
      for (int node = 0; node < 2; ++node) {
        const double xn = node == 0 ? s * L : L;
        const double defl = P * xn * xn * (3 * L - xn) / (6 * E * I) + P * xn / (k * G * sec.A);
        const double rot = P * xn * (2 * L - xn) / (2 * E * I);
        EXPECT_NEAR(R.col(dir).dot(u.segment<3>(6 * node)), defl, 1e-10 * scale) << dir << " " << node;
        EXPECT_NEAR(R.col(3 - dir).dot(u.segment<3>(6 * node + 3)), sign * rot, 1e-10 * scale / L);
        EXPECT_NEAR(R.col(0).dot(u.segment<3>(6 * node)), 0.0, 1e-12 * scale);
      }
    }
    // axial force and torque at the tip: u = P L / (E A), phi = T L / (G J), linear along x
    Eigen::VectorXd f = Eigen::VectorXd::Zero(12);
    f.segment<3>(6) = P * R.col(0);
    f.segment<3>(9) = 0.1 * P * R.col(0);
    const Eigen::VectorXd u = Clamped(K, f);
    for (int node = 0; node < 2; ++node) {
      const double xn = node == 0 ? s * L : L;
      EXPECT_NEAR(R.col(0).dot(u.segment<3>(6 * node)), P * xn / (E * sec.A), 1e-10 * P * L / (E * sec.A));
      EXPECT_NEAR(R.col(0).dot(u.segment<3>(6 * node + 3)), 0.1 * P * xn / (G * sec.J),
                  1e-10 * 0.1 * P * L / (G * sec.J));
    }
  }
}

// a load Q at the mid node (x = L / 2) of a cantilever: the tip moves
// Q a^2 (3 L - a) / (6 E I) + Q a / (k G A) with a = L / 2 (Maxwell-Betti:
// the mid node's deflection under a tip load)
TEST(Beam3, MidNodeLoadGivesTheExactTipDeflection) {
  const double L = 1.8, Q = 500.0, a = 0.5 * L;
  Beam3Fixture b(Vec3::Zero(), Vec3(L, 0.0, 0.0), Vec3::UnitY());
  MatX K, M;
  Beam3Matrices(b.Input(), K, M);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(12);
  f(1) = Q;
  const Eigen::VectorXd u = Clamped(K, f);
  const double E = b.material.E, I = b.section.Iz;
  const double ref = Q * a * a * (3 * L - a) / (6 * E * I) + Q * a / (b.section.ky * b.G() * b.section.A);
  EXPECT_NEAR(u(7), ref, 1e-10 * ref);
}

// section forces at the ends of a cantilever under a tip wrench (F, Mo):
// both ends carry F; the moment is Mo plus F's moment about the end
TEST(Beam3, SectionForcesAtBothEndsFromStatics) {
  const Eigen::Matrix3d R = RandomRotation(5);
  const Vec3 a(1.0, 0.5, -0.2);
  Beam3Fixture b(a, a + R * Vec3(2.0, 0.0, 0.0), R * Vec3(0.0, 1.0, 0.4), 0.45);
  MatX K, M, S;
  Eigen::Matrix3d axes;
  Beam3Matrices(b.Input(), K, M);
  Beam3SectionForces(b.Input(), S, axes);
  ASSERT_EQ(S.rows(), 12);
  ASSERT_EQ(S.cols(), 18);
  const Vec3 F(120.0, -340.0, 75.0), Mo(-20.0, 15.0, 40.0);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(12);
  f.segment<3>(6) = F;
  f.segment<3>(9) = Mo;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(18);
  u.tail(12) = Clamped(K, f);
  const Eigen::VectorXd sf = S * u;
  EXPECT_LT((axes.col(0) - R.col(0)).norm(), 1e-14);
  Vec6 ref_a, ref_b;
  ref_a << axes.transpose() * F, axes.transpose() * (Mo + (b.x[2] - b.x[0]).cross(F));
  ref_b << axes.transpose() * F, axes.transpose() * Mo;
  EXPECT_LT((sf.head<6>() - ref_a).norm(), 1e-9 * ref_a.norm()) << sf.head<6>().transpose();
  EXPECT_LT((sf.tail<6>() - ref_b).norm(), 1e-9 * ref_b.norm()) << sf.tail<6>().transpose();
  // a rigid motion has no section forces
  const MatX r = RigidModes(b.x, 6);
  EXPECT_LT((S * r).norm(), 1e-6 * S.norm());
}

// rigid-body mass m = (rho A + nsm) L and, about the centre, the inertia of
// a slender rod m L^2 / 12 across the axis plus the section's rotary inertia
// rho L (Iy + Iz) about it
TEST(Beam3, MassGivesTheExactRigidBodyInertia) {
  const double L = 3.0;
  for (MassForm form : {MassForm::kConsistent, MassForm::kLumped}) {
    Beam3Fixture b(Vec3(-0.5 * L, 0.0, 0.0), Vec3(0.5 * L, 0.0, 0.0), Vec3::UnitY());
    MatX K, M;
    Beam3Matrices(b.Input(form), K, M);
    const MatX r = RigidModes(b.x, 6);  // about the origin = the centre
    const MatX mr = r.transpose() * M * r;
    const double m = (b.material.rho * b.section.A + b.section.nsm) * L;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(mr(k, k), m, 1e-12 * m);
    EXPECT_NEAR(mr(3, 3), b.material.rho * L * (b.section.Iy + b.section.Iz), 1e-12 * m * L * L);
    if (form == MassForm::kConsistent) {
      EXPECT_NEAR(mr(4, 4), m * L * L / 12.0 + b.material.rho * L * b.section.Iy, 1e-12 * m * L * L);
      EXPECT_NEAR(mr(5, 5), m * L * L / 12.0 + b.material.rho * L * b.section.Iz, 1e-12 * m * L * L);
    } else {  // lumped: m/4, m/2, m/4 at -L/2, 0, L/2
      EXPECT_NEAR(mr(4, 4), m * L * L / 8.0 + b.material.rho * L * b.section.Iy, 1e-12 * m * L * L);
    }
  }
}

// a cantilever column of 4 elements under compression P: K - P KG(1) turns
// singular at P_cr = pi^2 E I / (4 L^2) (Euler); the cubic bending fields of
// the halves converge fast, 8 halves give it to 1e-4
TEST(Beam3, GeometricStiffnessGivesTheEulerLoad) {
  const double L = 3.0;
  const int n = 4;
  Beam3Fixture proto(Vec3::Zero(), Vec3(L / n, 0.0, 0.0), Vec3::UnitY());
  proto.section.ky = proto.section.kz = 0.0;  // Euler-Bernoulli
  const int nodes = 2 * n + 1;
  MatX K = MatX::Zero(6 * nodes, 6 * nodes), KG = K;
  for (int e = 0; e < n; ++e) {
    Beam3Fixture b = proto;
    for (int k = 0; k < 3; ++k) b.x[k] = Vec3((2 * e + k) * L / (2 * n), 0.0, 0.0);
    MatX k, m, kg;
    Beam3Matrices(b.Input(), k, m);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(18);  // a unit compression N = -1: shorten by L_e / (E A)
    const double le = L / n;
    u(6) = -0.5 * le / (b.material.E * b.section.A);
    u(12) = -le / (b.material.E * b.section.A);
    double N = 0.0;
    Beam3GeometricStiffness(b.Input(), u, kg, &N);
    EXPECT_NEAR(N, -1.0, 1e-9);
    K.block(12 * e, 12 * e, 18, 18) += k;
    KG.block(12 * e, 12 * e, 18, 18) += kg;
  }
  // bending in x-y only: keep uy and rz of nodes 1.. (node 0 clamped)
  std::vector<int> keep;
  for (int i = 1; i < nodes; ++i) keep.insert(keep.end(), {6 * i + 1, 6 * i + 5});
  const int nk = static_cast<int>(keep.size());
  MatX k(nk, nk), g(nk, nk);
  for (int i = 0; i < nk; ++i)
    for (int j = 0; j < nk; ++j) k(i, j) = K(keep[i], keep[j]), g(i, j) = -KG(keep[i], keep[j]);
  // K phi = P (-KG(N=-1)) phi: the smallest P
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> eig(g, k);  // g phi = mu k phi, P = 1 / mu_max
  const double P = 1.0 / eig.eigenvalues().maxCoeff();
  const double ref = M_PI * M_PI * proto.material.E * proto.section.Iz / (4.0 * L * L);
  EXPECT_NEAR(P, ref, 1e-4 * ref);
}

// the axis offset e below the node line (offset -e z): an axial load P on
// the tip node bends the cantilever by the moment P e, uz = -P e L^2 / (2 E
// Iy), and moves the node along x by P L / (E A) + e theta_y, theta_y = P e L
// / (E Iy); rigid motions stay free of energy
TEST(Beam3, AxisOffsetIsARigidLinkAtEveryNode) {
  const double L = 2.0, P = 1.0e4, e = 0.05;
  Beam3Fixture b(Vec3::Zero(), Vec3(L, 0.0, 0.0), Vec3::UnitY());
  b.element.offset_a = b.element.offset_b = Vec3(0.0, 0.0, -e);
  MatX K, M;
  Beam3Matrices(b.Input(), K, M);
  ExpectSixRigidModes(K, b.x, 6);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(12);
  f(6) = P;
  const Eigen::VectorXd u = Clamped(K, f);
  const double E = b.material.E, Iy = b.section.Iy, A = b.section.A;
  const double uz = -P * e * L * L / (2 * E * Iy), ux = P * L / (E * A) + e * P * e * L / (E * Iy);
  EXPECT_NEAR(u(8), uz, 1e-10 * std::abs(uz));
  EXPECT_NEAR(u(6), ux, 1e-10 * ux);
}

TEST(Beam3, BadGeometryIsAnInputErrorNamingTheElement) {
  Beam3Fixture curved(Vec3::Zero(), Vec3(2.0, 0.0, 0.0), Vec3::UnitY());
  curved.x[1].y() = 0.01;
  MatX K, M;
  ExpectInputErrorWith([&] { Beam3Matrices(curved.Input(), K, M); },
                       {"curved", "3-node beam 77", "boom.inp:12", "straight"});
  Beam3Fixture end(Vec3::Zero(), Vec3(2.0, 0.0, 0.0), Vec3::UnitY(), 0.0);
  ExpectInputErrorWith([&] { Beam3Matrices(end.Input(), K, M); }, {"mid node", "3-node beam 77"});
  Beam3Fixture offset(Vec3::Zero(), Vec3(2.0, 0.0, 0.0), Vec3::UnitY());
  offset.element.offset_b = Vec3(0.0, 0.1, 0.0);
  ExpectInputErrorWith([&] { Beam3Matrices(offset.Input(), K, M); }, {"offsets", "3-node beam 77"});
  Beam3Fixture parallel(Vec3::Zero(), Vec3(2.0, 0.0, 0.0), Vec3::UnitX());
  ExpectInputErrorWith([&] { Beam3Matrices(parallel.Input(), K, M); }, {"orientation", "3-node beam 77"});
  EXPECT_STREQ(Traits(kBeam3).abaqus.front().name, "B32");
}

}  // namespace beam3_test
}  // namespace flexmb::fe
