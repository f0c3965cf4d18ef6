// 2-node Timoshenko beam: symmetry and rigid-body modes (rotated, offset,
// unsymmetric section), the closed-form Timoshenko stiffness (Przemieniecki
// 1968, phi = 12 E I / (k G A L^2)), cantilever tip displacements against
// beam theory (exact with one element), a patch test of unequal elements
// (exact at every node), unsymmetric bending, rigid offsets,
// the Euler-Bernoulli consistent mass (Przemieniecki 1968: 156/22/54/13 and
// the rotary-inertia matrix), exact rigid-body mass and inertia, lumped
// mass, and errors for bad input.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/beam2.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace {

using testing::ExpectInputErrorWith;
using testing::ExpectSixRigidModes;
using testing::RigidModes;
using testing::Skew;
using testing::RandomRotation;

// the section of the tests: A, Iy, Iz, J and shear factors, all different
BeamSection TestSection() {
  BeamSection s;
  s.A = 3.0e-3;
  s.Iy = 4.0e-6;
  s.Iz = 9.0e-6;
  s.J = 2.5e-6;
  s.ky = 0.8;
  s.kz = 0.6;
  return s;
}

// a beam element with its section and material
struct Beam {
  Element element;
  Material material;
  BeamSection section;
  std::vector<Vec3> x = std::vector<Vec3>(2);

  Beam(const Vec3& a, const Vec3& b, const Vec3& v) {
    element.id = 31;
    element.type = ElementType::kBeam2;
    element.nodes = {0, 1};
    element.orientation = v;
    element.origin = {"frame.bdf", 42};
    material.E = 2.1e11;
    material.nu = 0.3;
    material.rho = 7850.0;
    section = TestSection();
    x[0] = a;
    x[1] = b;
  }
  double G() const { return material.E / (2.0 * (1.0 + material.nu)); }
  void Compute(MatX& K, MatX& M, MassForm form = MassForm::kConsistent) const {
    ElementInput in;
    in.element = &element;
    in.x = x.data();
    in.material = &material;
    in.beam = &section;
    in.mass_form = form;
    Beam2Matrices(in, K, M);
  }
};

// clamps node A and solves for node B under the load f (basic frame)
Eigen::Matrix<double, 6, 1> Cantilever(const MatX& K, const Eigen::Matrix<double, 6, 1>& f) {
  const Eigen::Matrix<double, 6, 6> kbb = K.block<6, 6>(6, 6);
  return kbb.ldlt().solve(f);
}

Eigen::Matrix3d Frame(const Vec3& a, const Vec3& b, const Vec3& v) {
  Eigen::Matrix3d R;
  R.col(0) = (b - a).normalized();
  R.col(1) = (v - R.col(0) * R.col(0).dot(v)).normalized();
  R.col(2) = R.col(0).cross(R.col(1));
  return R;
}

TEST(Beam2, RigidBodyModesRotatedOffsetUnsymmetric) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::Matrix3d R = RandomRotation(seed);
    const Vec3 a = Vec3::Random() * 3.0;
    const Vec3 b = a + R * Vec3(1.7, 0.2, -0.1);
    Beam beam(a, b, R * Vec3(0.3, 1.0, 0.5));
    beam.section.Iyz = 2.0e-6;
    beam.element.offset_a = Vec3(0.05, -0.1, 0.2);
    beam.element.offset_b = Vec3(-0.15, 0.07, 0.01);
    MatX K, M;
    beam.Compute(K, M);
    ExpectSixRigidModes(K, beam.x, 6);
    EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
  }
}

TEST(Beam2, EulerBernoulliHasSixRigidModesToo) {
  Beam beam(Vec3(1.0, 2.0, 3.0), Vec3(1.5, 2.0, 4.0), Vec3(0.0, 1.0, 0.0));
  beam.section.ky = beam.section.kz = 0.0;
  MatX K, M;
  beam.Compute(K, M);
  ExpectSixRigidModes(K, beam.x, 6);
}

// classical closed-form Timoshenko stiffness in the local frame (axis x,
// orientation y), Przemieniecki, Theory of Matrix Structural Analysis, 1968
TEST(Beam2, MatchesClosedFormTimoshenkoStiffness) {
  const double L = 1.3;
  Beam beam(Vec3::Zero(), Vec3(L, 0.0, 0.0), Vec3(0.0, 1.0, 0.0));
  MatX K, M;
  beam.Compute(K, M);
  const BeamSection& s = beam.section;
  const double E = beam.material.E, G = beam.G();
  MatX k = MatX::Zero(12, 12);
  auto sym = [&](int i, int j, double v) { k(i, j) = k(j, i) = v; };
  sym(0, 0, E * s.A / L); sym(6, 6, E * s.A / L); sym(0, 6, -E * s.A / L);
  sym(3, 3, G * s.J / L); sym(9, 9, G * s.J / L); sym(3, 9, -G * s.J / L);
  // x-y plane: v (1, 7), theta_z (5, 11)
  const double py = 12.0 * E * s.Iz / (s.ky * G * s.A * L * L);
  const double cy = E * s.Iz / (1.0 + py);
  sym(1, 1, 12 * cy / (L * L * L)); sym(7, 7, 12 * cy / (L * L * L)); sym(1, 7, -12 * cy / (L * L * L));
  sym(1, 5, 6 * cy / (L * L)); sym(1, 11, 6 * cy / (L * L));
  sym(7, 5, -6 * cy / (L * L)); sym(7, 11, -6 * cy / (L * L));
  sym(5, 5, (4 + py) * cy / L); sym(11, 11, (4 + py) * cy / L); sym(5, 11, (2 - py) * cy / L);
  // x-z plane: w (2, 8), theta_y (4, 10), theta_y = -w'
  const double pz = 12.0 * E * s.Iy / (s.kz * G * s.A * L * L);
  const double cz = E * s.Iy / (1.0 + pz);
  sym(2, 2, 12 * cz / (L * L * L)); sym(8, 8, 12 * cz / (L * L * L)); sym(2, 8, -12 * cz / (L * L * L));
  sym(2, 4, -6 * cz / (L * L)); sym(2, 10, -6 * cz / (L * L));
  sym(8, 4, 6 * cz / (L * L)); sym(8, 10, 6 * cz / (L * L));
  sym(4, 4, (4 + pz) * cz / L); sym(10, 10, (4 + pz) * cz / L); sym(4, 10, (2 - pz) * cz / L);
  EXPECT_LT((K - k).norm(), 1e-12 * k.norm());
}

// one element reproduces beam theory at the tip of a cantilever exactly:
// bending P L^3 / (3 E I) + P L / (k G A) in both planes, axial, torsion
TEST(Beam2, CantileverTipDisplacementsAreExact) {
  const Eigen::Matrix3d R = RandomRotation(7);
  const double L = 2.2, P = 1.0e3, T = 150.0;
  const Vec3 a(0.4, -0.3, 1.0);
  const Vec3 b = a + R * Vec3(L, 0.0, 0.0);
  const Vec3 v = R * Vec3(0.5, 2.0, 0.0);  // local y = R e_y
  Beam beam(a, b, v);
  MatX K, M;
  beam.Compute(K, M);
  const Eigen::Matrix3d F = Frame(a, b, v);
  EXPECT_LT((F - R).norm(), 1e-12);
  const BeamSection& s = beam.section;
  const double E = beam.material.E, G = beam.G();
  Eigen::Matrix<double, 6, 1> f;
  // load along local y: v = P L^3/(3 E Iz) + P L/(ky G A), theta_z = P L^2/(2 E Iz)
  f << P * R.col(1), Vec3::Zero();
  Eigen::Matrix<double, 6, 1> u = Cantilever(K, f);
  EXPECT_NEAR(R.col(1).dot(u.head<3>()), P * L * L * L / (3 * E * s.Iz) + P * L / (s.ky * G * s.A),
              1e-10 * P * L * L * L / (E * s.Iz));
  EXPECT_NEAR(R.col(2).dot(u.tail<3>()), P * L * L / (2 * E * s.Iz), 1e-10 * P * L * L / (E * s.Iz));
  EXPECT_NEAR(R.col(0).dot(u.head<3>()), 0.0, 1e-12);
  // load along local z: w = P L^3/(3 E Iy) + P L/(kz G A), theta_y = -P L^2/(2 E Iy)
  f << P * R.col(2), Vec3::Zero();
  u = Cantilever(K, f);
  EXPECT_NEAR(R.col(2).dot(u.head<3>()), P * L * L * L / (3 * E * s.Iy) + P * L / (s.kz * G * s.A),
              1e-10 * P * L * L * L / (E * s.Iy));
  EXPECT_NEAR(R.col(1).dot(u.tail<3>()), -P * L * L / (2 * E * s.Iy), 1e-10 * P * L * L / (E * s.Iy));
  // axial and torsion
  f << P * R.col(0), T * R.col(0);
  u = Cantilever(K, f);
  EXPECT_NEAR(R.col(0).dot(u.head<3>()), P * L / (E * s.A), 1e-10 * P * L / (E * s.A));
  EXPECT_NEAR(R.col(0).dot(u.tail<3>()), T * L / (G * s.J), 1e-10 * T * L / (G * s.J));
  // end moment about local z: v = M L^2/(2 E Iz), theta_z = M L/(E Iz) (no shear)
  f << Vec3::Zero(), T * R.col(2);
  u = Cantilever(K, f);
  EXPECT_NEAR(R.col(1).dot(u.head<3>()), T * L * L / (2 * E * s.Iz), 1e-10 * T * L * L / (E * s.Iz));
  EXPECT_NEAR(R.col(2).dot(u.tail<3>()), T * L / (E * s.Iz), 1e-10 * T * L / (E * s.Iz));
}

// unsymmetric bending (Iyz != 0): a tip load along y gives
// v = P L^3 Iy / (3 E (Iy Iz - Iyz^2)) + P L / (ky G A),
// w = -P L^3 Iyz / (3 E (Iy Iz - Iyz^2))
TEST(Beam2, UnsymmetricSectionBendsOutOfPlane) {
  const double L = 1.5, P = 500.0;
  Beam beam(Vec3::Zero(), Vec3(L, 0.0, 0.0), Vec3(0.0, 1.0, 0.0));
  beam.section.Iyz = 3.0e-6;
  MatX K, M;
  beam.Compute(K, M);
  const BeamSection& s = beam.section;
  const double E = beam.material.E, G = beam.G();
  const double det = s.Iy * s.Iz - s.Iyz * s.Iyz;
  Eigen::Matrix<double, 6, 1> f;
  f << 0.0, P, 0.0, 0.0, 0.0, 0.0;
  const Eigen::Matrix<double, 6, 1> u = Cantilever(K, f);
  const double scale = P * L * L * L / (E * det);
  EXPECT_NEAR(u(1), P * L * L * L * s.Iy / (3 * E * det) + P * L / (s.ky * G * s.A), 1e-10 * scale);
  EXPECT_NEAR(u(2), -P * L * L * L * s.Iyz / (3 * E * det), 1e-10 * scale);
}

// patch test: a cantilever of four unequal elements along a rotated axis,
// loaded at its tip by a force and a moment in every direction, reproduces
// the Timoshenko beam solution at every node exactly (the states a beam
// without span loads is made of: constant axial strain and twist, constant
// shear, linear bending moment). Local coordinate s from the clamp, L the
// length, (N, P, Q) the tip force and (T, My, Mz) the tip moment in element
// axes:
//   u = N s / (E A), phi = T s / (G J),
//   v = P (L s^2 / 2 - s^3 / 6) / (E Iz) + P s / (ky G A) + Mz s^2 / (2 E Iz),
//   theta_z = P (L s - s^2 / 2) / (E Iz) + Mz s / (E Iz),
//   w = Q (L s^2 / 2 - s^3 / 6) / (E Iy) + Q s / (kz G A) - My s^2 / (2 E Iy),
//   theta_y = -Q (L s - s^2 / 2) / (E Iy) + My s / (E Iy).
TEST(Beam2, PatchTestOfUnequalElementsIsExactAtEveryNode) {
  const Eigen::Matrix3d R = RandomRotation(21);
  const std::vector<double> s = {0.0, 0.3, 1.1, 1.6, 2.4};
  const double L = s.back();
  const Vec3 a(0.5, -0.2, 1.0);
  Mesh mesh;
  const int mat = testing::AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  BeamSection sec = TestSection();
  sec.material = mat;
  mesh.beam_sections.push_back(sec);
  for (double si : s) testing::AddNode(mesh, a + R * Vec3(si, 0.0, 0.0));
  for (int e = 0; e + 1 < static_cast<int>(s.size()); ++e)
    testing::AddBeam(mesh, 0, e, e + 1, R * Vec3(0.2, 1.0, 0.0));
  testing::AddConstraint(mesh, 0, 0b111111);
  const AssembledModel model = Assemble(mesh);
  const double E = mesh.materials[mat].E, G = mesh.materials[mat].G;
  const double N = 2.0e4, P = 1.5e3, Q = -2.5e3, T = 300.0, My = 450.0, Mz = -600.0;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.dofs.n_free);
  const int tip = static_cast<int>(s.size()) - 1;
  const Vec3 force = R * Vec3(N, P, Q), moment = R * Vec3(T, My, Mz);
  for (int c = 0; c < 3; ++c) {
    f(model.dofs.free[tip][c]) = force(c);
    f(model.dofs.free[tip][3 + c]) = moment(c);
  }
  const Eigen::VectorXd u = Eigen::MatrixXd(model.K).ldlt().solve(f);
  const double scale = std::abs(P) * L * L * L / (E * sec.Iy);
  for (int n = 1; n <= tip; ++n) {
    const double x = s[n];
    const Vec3 disp(N * x / (E * sec.A),
                    P * (L * x * x / 2 - x * x * x / 6) / (E * sec.Iz) + P * x / (sec.ky * G * sec.A) +
                        Mz * x * x / (2 * E * sec.Iz),
                    Q * (L * x * x / 2 - x * x * x / 6) / (E * sec.Iy) + Q * x / (sec.kz * G * sec.A) -
                        My * x * x / (2 * E * sec.Iy));
    const Vec3 rot(T * x / (G * sec.J), -Q * (L * x - x * x / 2) / (E * sec.Iy) + My * x / (E * sec.Iy),
                   P * (L * x - x * x / 2) / (E * sec.Iz) + Mz * x / (E * sec.Iz));
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(u(model.dofs.free[n][c]), (R * disp)(c), 1e-10 * scale) << "node " << n;
      EXPECT_NEAR(u(model.dofs.free[n][3 + c]) * L, (R * rot)(c) * L, 1e-10 * scale) << "node " << n;
    }
  }
}

// offsets are rigid links: node B offset from end B by -offset_b; an axial
// force at node B is an axial force plus a moment (node - end) x F at end B
TEST(Beam2, OffsetsActAsRigidLinks) {
  const double L = 2.0, P = 1.0e4, h = 0.3;
  Beam beam(Vec3(0.0, 0.0, -0.2), Vec3(L, 0.0, h), Vec3(0.0, 1.0, 0.0));
  beam.element.offset_a = Vec3(0.0, 0.0, 0.2);
  beam.element.offset_b = Vec3(0.0, 0.0, -h);
  beam.section.ky = beam.section.kz = 0.0;
  MatX K, M;
  beam.Compute(K, M);
  ExpectSixRigidModes(K, beam.x, 6);
  const BeamSection& s = beam.section;
  const double E = beam.material.E;
  Eigen::Matrix<double, 6, 1> f;
  f << P, 0.0, 0.0, 0.0, 0.0, 0.0;
  const Eigen::Matrix<double, 6, 1> u = Cantilever(K, f);
  const double my = h * P;                    // moment at end B
  const double theta_y = my * L / (E * s.Iy);  // end rotation
  const double w_end = -my * L * L / (2 * E * s.Iy);
  EXPECT_NEAR(u(4), theta_y, 1e-10 * theta_y);
  EXPECT_NEAR(u(0), P * L / (E * s.A) + h * theta_y, 1e-10 * h * theta_y);
  EXPECT_NEAR(u(2), w_end, 1e-10 * std::abs(w_end));
}

// Euler-Bernoulli consistent mass: Przemieniecki's translational matrix
// (m L / 420) [156 22L 54 -13L ...] plus the rotary-inertia matrix
// (rho I / (30 L)) [36 3L -36 3L ...], axial and torsion (m L / 6) [2 1; 1 2]
TEST(Beam2, EulerBernoulliConsistentMassIsTheClassicalOne) {
  const double L = 0.8;
  Beam beam(Vec3::Zero(), Vec3(L, 0.0, 0.0), Vec3(0.0, 1.0, 0.0));
  beam.section.ky = beam.section.kz = 0.0;
  beam.section.nsm = 3.0;
  MatX K, M;
  beam.Compute(K, M);
  const BeamSection& s = beam.section;
  const double rho = beam.material.rho;
  const double m = rho * s.A + s.nsm;
  MatX ref = MatX::Zero(12, 12);
  const double ax[2][2] = {{2, 1}, {1, 2}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      ref(6 * i, 6 * j) = m * L / 6.0 * ax[i][j];
      ref(6 * i + 3, 6 * j + 3) = rho * (s.Iy + s.Iz) * L / 6.0 * ax[i][j];
    }
  const double t[4][4] = {{156, 22 * L, 54, -13 * L},
                          {22 * L, 4 * L * L, 13 * L, -3 * L * L},
                          {54, 13 * L, 156, -22 * L},
                          {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
  const double r[4][4] = {{36, 3 * L, -36, 3 * L},
                          {3 * L, 4 * L * L, -3 * L, -L * L},
                          {-36, -3 * L, 36, -3 * L},
                          {3 * L, -L * L, -3 * L, 4 * L * L}};
  const int xy[4] = {1, 5, 7, 11}, xz[4] = {2, 4, 8, 10};
  const double sg[4] = {1, -1, 1, -1};  // theta_y = -w'
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      ref(xy[i], xy[j]) = m * L / 420.0 * t[i][j] + rho * s.Iz / (30.0 * L) * r[i][j];
      ref(xz[i], xz[j]) = sg[i] * sg[j] * (m * L / 420.0 * t[i][j] + rho * s.Iy / (30.0 * L) * r[i][j]);
    }
  EXPECT_LT((M - ref).norm(), 1e-12 * ref.norm());
}

// R^T M R of a rotated, offset beam with an unsymmetric section against the
// rigid-body mass of a bar: mass (rho A + nsm) L at the midpoint of the ends,
// inertia about it m L^2 / 12 (transverse) plus the section's rotary inertia
void CheckRigidMass(unsigned seed, double ky) {
  const Eigen::Matrix3d R = RandomRotation(seed);
  const double L = 1.9;
  const Vec3 a(0.3, 1.0, -0.5);
  const Vec3 oa(0.02, 0.1, -0.05), ob(-0.1, 0.03, 0.2);
  const Vec3 ea = a + oa, eb = ea + R * Vec3(L, 0.0, 0.0);
  Beam beam(a, eb - ob, R * Vec3(0.0, 1.0, 0.0));
  beam.element.offset_a = oa;
  beam.element.offset_b = ob;
  beam.section.Iyz = 1.5e-6;
  beam.section.ky = beam.section.kz = ky;
  beam.section.nsm = 2.0;
  MatX K, M;
  beam.Compute(K, M);
  const BeamSection& s = beam.section;
  const double rho = beam.material.rho;
  const double m = (rho * s.A + s.nsm) * L;
  const Vec3 c = 0.5 * (ea + eb);
  Eigen::Matrix3d jl;  // about the centre, element axes
  jl << rho * (s.Iy + s.Iz) * L, 0.0, 0.0, 0.0, rho * s.Iy * L + m * L * L / 12.0,
      -rho * s.Iyz * L, 0.0, -rho * s.Iyz * L, rho * s.Iz * L + m * L * L / 12.0;
  const Eigen::Matrix3d jo =
      R * jl * R.transpose() + m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  Eigen::Matrix<double, 6, 6> ref;
  ref << m * Eigen::Matrix3d::Identity(), -m * Skew(c), m * Skew(c), jo;
  const MatX rm = RigidModes(beam.x, 6);
  const MatX got = rm.transpose() * M * rm;
  EXPECT_LT((got - ref).norm(), 1e-12 * ref.norm()) << got << "\n\n" << ref;
}

TEST(Beam2, ConsistentMassGivesExactRigidBodyInertia) {
  CheckRigidMass(11, 0.0);
  CheckRigidMass(12, 0.7);
}

TEST(Beam2, LumpedMassIsBlockDiagonalWithExactMassAndPolarInertia) {
  const double L = 1.2;
  const Eigen::Matrix3d R = RandomRotation(5);
  Beam beam(Vec3(1.0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0) + R * Vec3(L, 0.0, 0.0), R * Vec3(0.0, 1.0, 0.0));
  MatX K, M;
  beam.Compute(K, M, MassForm::kLumped);
  const BeamSection& s = beam.section;
  const double rho = beam.material.rho;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      if (i / 3 != j / 3) EXPECT_EQ(M(i, j), 0.0) << i << " " << j;
  const double m = rho * s.A * L;
  const double trace = M.topLeftCorner(3, 3).trace() + M.block(6, 6, 3, 3).trace();
  EXPECT_NEAR(trace, 3.0 * m, 1e-12 * m);
  const Vec3 ex = R.col(0);
  const Eigen::Matrix3d rot = M.block(3, 3, 3, 3) + M.block(9, 9, 3, 3);
  const double polar = ex.dot(rot * ex);
  EXPECT_NEAR(polar, rho * (s.Iy + s.Iz) * L, 1e-12 * polar);
}

void ExpectInputError(Beam& beam, const std::string& what) {
  MatX K, M;
  ExpectInputErrorWith([&] { beam.Compute(K, M); }, {"frame.bdf:42", "2-node beam 31", what});
}

TEST(Beam2, BadInputIsAnInputErrorNamingTheElement) {
  const Vec3 a(0.0, 0.0, 0.0), b(1.0, 1.0, 0.0);
  {
    Beam beam(a, a, Vec3(0.0, 0.0, 1.0));
    ExpectInputError(beam, "zero length");
  }
  {
    // offsets that bring the ends together
    Beam beam(a, b, Vec3(0.0, 0.0, 1.0));
    beam.element.offset_b = a - b;
    ExpectInputError(beam, "zero length");
  }
  {
    Beam beam(a, b, Vec3(2.0, 2.0, 0.0));
    ExpectInputError(beam, "parallel");
  }
  {
    Beam beam(a, b, Vec3::Zero());
    ExpectInputError(beam, "zero orientation");
  }
  {
    Beam beam(a, b, Vec3(0.0, 0.0, 1.0));
    beam.section.A = 0.0;
    ExpectInputError(beam, "area");
  }
  {
    Beam beam(a, b, Vec3(0.0, 0.0, 1.0));
    beam.section.Iy = -1.0e-6;
    ExpectInputError(beam, "Iy");
  }
  {
    Beam beam(a, b, Vec3(0.0, 0.0, 1.0));
    beam.section.Iz = 0.0;
    ExpectInputError(beam, "Iz");
  }
  {
    Beam beam(a, b, Vec3(0.0, 0.0, 1.0));
    beam.section.J = 0.0;
    ExpectInputError(beam, "torsion");
  }
  {
    Beam beam(a, b, Vec3(0.0, 0.0, 1.0));
    beam.section.Iyz = 7.0e-6;
    ExpectInputError(beam, "Iyz");
  }
  {
    Beam beam(a, b, Vec3(0.0, 0.0, 1.0));
    beam.section.ky = -1.0;
    ExpectInputError(beam, "shear factor");
  }
  {
    Beam beam(a, b, Vec3(0.0, 0.0, 1.0));
    ElementInput in;
    in.element = &beam.element;
    in.x = beam.x.data();
    in.beam = &beam.section;
    MatX K, M;
    ExpectInputErrorWith([&] { Beam2Matrices(in, K, M); },
                         {"frame.bdf:42: 2-node beam 31: missing material"});
  }
}

}  // namespace
}  // namespace flexmb::fe
