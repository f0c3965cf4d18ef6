// 2-node rod: the stiffness of an oblique rod against the hand-built axial
// and torsional pattern (E A / L and G J / L times e e^T in [k -k; -k k]),
// rigid-body motions storing no energy and the rank of K (2 with torsion,
// 1 for a truss), the consistent (m / 6 [2 1; 1 2] per direction) and
// lumped (m / 2) mass with non-structural mass, the section forces N and T
// of a stretch and a twist, the rod stresses sigma = N / A and tau = C T /
// J, the string geometric stiffness N / L (I - e e^T), the assembly (a
// rod's nodes activate translations only; its torsion counts only between
// nodes whose rotations other elements activate) and errors for bad input.

#include "flexmb/fe/elements/rod2.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/element_traits.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace {

using testing::ExpectInputErrorWith;
using testing::RigidModes;

// a rod element with its section and material: axis (1, 2, 2) / 3, L = 1.2
struct RodCase {
  Element element;
  Material material;
  BeamSection section;
  std::vector<Vec3> x = {Vec3(0.5, -1.0, 2.0), Vec3(0.5, -1.0, 2.0) + 0.4 * Vec3(1.0, 2.0, 2.0)};

  RodCase() {
    element.id = 77;
    element.type = kRod2;
    element.nodes = {0, 1};
    element.origin = {"truss.bdf", 12};
    material.E = 7.0e10;
    material.nu = 0.25;  // G = 2.8e10
    material.rho = 2700.0;
    section.id = 5;
    section.A = 2.0e-4;
    section.J = 3.0e-8;
    section.nsm = 0.1;
    section.stress_points = {{0.01, 0.0}};
  }
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

TEST(Rod2, ObliqueStiffnessIsTheAxialAndTorsionalPattern) {
  RodCase r;
  MatX K, M;
  Rod2Matrices(r.Input(), K, M);
  ASSERT_EQ(K.rows(), 12);
  // hand values: L = 1.2, e = (1, 2, 2) / 3, EA/L = 7e10 * 2e-4 / 1.2, GJ/L = 2.8e10 * 3e-8 / 1.2
  const double ka = 7.0e10 * 2.0e-4 / 1.2, kt = 2.8e10 * 3.0e-8 / 1.2;
  const double e[3] = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  MatX ref = MatX::Zero(12, 12);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double s = a == b ? 1.0 : -1.0;
          ref(6 * a + i, 6 * b + j) = s * ka * e[i] * e[j];
          ref(6 * a + 3 + i, 6 * b + 3 + j) = s * kt * e[i] * e[j];
        }
  EXPECT_LT((K - ref).norm(), 1e-12 * ref.norm());
  EXPECT_NEAR(K(1, 8), -ka * 4.0 / 9.0, 1e-6);  // uy of node 1 with uz of node 2
  EXPECT_NEAR(K(3, 3), kt / 9.0, 1e-9);
}

TEST(Rod2, RigidMotionsStoreNoEnergyAndTheRankIsTheRods) {
  RodCase r;
  MatX K, M;
  Rod2Matrices(r.Input(), K, M);
  const MatX R = RigidModes(r.x, 6);
  EXPECT_LT((K * R).norm(), 1e-12 * K.norm());
  Eigen::SelfAdjointEigenSolver<MatX> eig(K);
  const Eigen::VectorXd ev = eig.eigenvalues();
  const double top = ev.maxCoeff();
  int positive = 0;
  for (int i = 0; i < 12; ++i) {
    EXPECT_GT(ev(i), -1e-12 * top);
    if (ev(i) > 1e-9 * top) ++positive;
  }
  EXPECT_EQ(positive, 2);  // stretch and twist
  // the truss (J = 0): stretch only
  r.section.J = 0.0;
  Rod2Matrices(r.Input(), K, M);
  EXPECT_EQ((Eigen::SelfAdjointEigenSolver<MatX>(K).eigenvalues().array() > 1e-9 * top).count(), 1);
  EXPECT_EQ((K.bottomRightCorner(3, 3).norm()), 0.0);
}

TEST(Rod2, ConsistentAndLumpedMass) {
  RodCase r;
  MatX K, M, Ml;
  Rod2Matrices(r.Input(), K, M);
  Rod2Matrices(r.Input(MassForm::kLumped), K, Ml);
  const double m = (2700.0 * 2.0e-4 + 0.1) * 1.2;  // 0.768 kg
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(M(c, c), m / 3.0, 1e-15);
    EXPECT_NEAR(M(c, 6 + c), m / 6.0, 1e-15);
    EXPECT_NEAR(M(6 + c, 6 + c), m / 3.0, 1e-15);
    EXPECT_NEAR(Ml(c, c), m / 2.0, 1e-15);
    EXPECT_EQ(Ml(c, 6 + c), 0.0);
  }
  // no coupling between directions, no rotational inertia
  EXPECT_EQ(M(0, 1), 0.0);
  EXPECT_EQ(M(0, 7), 0.0);
  EXPECT_EQ((M.block(3, 3, 3, 3).norm()), 0.0);
  // rigid translation: total mass m in each direction, both forms
  const MatX R = RigidModes(r.x, 6);
  for (const MatX* mm : {&M, &Ml}) {
    const MatX rm = R.leftCols(3).transpose() * (*mm) * R.leftCols(3);
    EXPECT_LT((rm - m * MatX::Identity(3, 3)).norm(), 1e-14);
  }
}

TEST(Rod2, SectionForcesOfStretchAndTwist) {
  RodCase r;
  MatX S;
  Mat3 axes;
  Rod2SectionForces(r.Input(), S, axes);
  const Vec3 e = Vec3(1.0, 2.0, 2.0) / 3.0;
  EXPECT_LT((axes.col(0) - e).norm(), 1e-15);
  EXPECT_LT((axes.transpose() * axes - Mat3::Identity()).norm(), 1e-14);
  EXPECT_NEAR(axes.determinant(), 1.0, 1e-14);
  // stretch by d along e plus a transverse motion, twist by phi
  const double d = 1.0e-4, phi = 2.0e-3;
  const Vec3 perp = e.cross(Vec3::UnitX()).normalized();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  u.segment<3>(6) = d * e + 0.05 * perp;
  u.segment<3>(9) = phi * e + 0.01 * perp;
  const Eigen::VectorXd f = S * u;
  const double N = 7.0e10 * 2.0e-4 * d / 1.2, T = 2.8e10 * 3.0e-8 * phi / 1.2;
  for (int end = 0; end < 2; ++end) {
    EXPECT_NEAR(f(6 * end), N, 1e-9 * N);
    EXPECT_NEAR(f(6 * end + 3), T, 1e-9 * T);
    for (int c : {1, 2, 4, 5}) EXPECT_EQ(f(6 * end + c), 0.0);
  }
  // sigma = N / A = E d / L, tau = C T / J = C G phi / L
  const Eigen::Vector2d st = RodStresses(r.section, N, T);
  EXPECT_NEAR(st(0), 7.0e10 * d / 1.2, 1e-6);
  EXPECT_NEAR(st(1), 0.01 * 2.8e10 * phi / 1.2, 1e-6);
  r.section.stress_points.clear();
  EXPECT_EQ(RodStresses(r.section, N, T)(1), 0.0);
}

TEST(Rod2, GeometricStiffnessIsTheStrings) {
  RodCase r;
  MatX KG;
  const double N = 500.0;
  Rod2GeometricStiffness(r.Input(), N, KG);
  const Vec3 e = Vec3(1.0, 2.0, 2.0) / 3.0;
  const Vec3 perp = e.cross(Vec3::UnitY()).normalized();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  u.segment<3>(6) = perp;  // end 2 moves across: energy N / L
  EXPECT_NEAR(u.dot(KG * u), N / 1.2, 1e-10);
  u.segment<3>(6) = e;  // along the axis: none
  EXPECT_NEAR(u.dot(KG * u), 0.0, 1e-10);
  EXPECT_LT((KG * RigidModes(r.x, 6).leftCols(3)).norm(), 1e-10);
  // the table's kernel takes N from the element displacements
  Eigen::VectorXd stretch = Eigen::VectorXd::Zero(12);
  stretch.segment<3>(6) = 1.0e-5 * e;
  double axial = 0.0;
  Traits(kRod2).geometric_stiffness(r.Input(), stretch, KG, &axial);
  EXPECT_NEAR(axial, 7.0e10 * 2.0e-4 * 1.0e-5 / 1.2, 1e-9);
}

TEST(Rod2, AssemblyActivatesTranslationsAndTorsionOnlyBetweenActiveRotations) {
  // three collinear nodes on x: a rod 0-1 and a rod 1-2, plus (second mesh) a beam 0-1
  Mesh mesh;
  const int n0 = testing::AddNode(mesh, Vec3(0.0, 0.0, 0.0));
  const int n1 = testing::AddNode(mesh, Vec3(1.0, 0.0, 0.0));
  const int n2 = testing::AddNode(mesh, Vec3(2.0, 0.0, 0.0));
  const int mat = testing::AddMaterial(mesh, 2.0e11, 0.3, 7800.0);
  BeamSection rod;
  rod.id = 9;
  rod.material = mat;
  rod.A = 1.0e-4;
  rod.J = 2.0e-8;
  mesh.beam_sections.push_back(rod);
  testing::AddElement(mesh, kRod2, 0, {n0, n1});
  testing::AddElement(mesh, kRod2, 0, {n1, n2});
  const AssembledModel rods = Assemble(mesh);
  EXPECT_EQ(rods.dofs.n_full, 9);  // translations only
  for (int n = 0; n < 3; ++n)
    for (int c = 3; c < 6; ++c) EXPECT_EQ(rods.dofs.full[n][c], -1);

  // a beam 0-1 activates the rotations of nodes 0 and 1: rod 0-1 adds its
  // torsion G J / L there, rod 1-2 (node 2 without rotations) none
  const int bar = testing::AddRoundBar(mesh, mat, 0.01);
  testing::AddBeam(mesh, bar, n0, n1, Vec3(0.0, 1.0, 0.0));
  const AssembledModel both = Assemble(mesh);
  Mesh beam_only = mesh;
  beam_only.elements.erase(beam_only.elements.begin(), beam_only.elements.begin() + 2);
  const AssembledModel beam = Assemble(beam_only);
  ASSERT_EQ(both.dofs.n_free, 15);
  const double G = 2.0e11 / 2.6, kt = G * 2.0e-8 / 1.0, ka = 2.0e11 * 1.0e-4;
  const Eigen::MatrixXd kb = Eigen::MatrixXd(both.K), kbeam = Eigen::MatrixXd(beam.K);
  auto at = [&](const AssembledModel& m, int n, int c) { return m.dofs.free[n][c]; };
  // rotations about x of nodes 0, 1: the rod's torsion added to the beam's
  const int r0 = at(both, n0, 3), r1 = at(both, n1, 3);
  EXPECT_NEAR(kb(r0, r0) - kbeam(at(beam, n0, 3), at(beam, n0, 3)), kt, 1e-9 * kt);
  EXPECT_NEAR(kb(r1, r1) - kbeam(at(beam, n1, 3), at(beam, n1, 3)), kt, 1e-9 * kt);
  EXPECT_NEAR(kb(r0, r1) - kbeam(at(beam, n0, 3), at(beam, n1, 3)), -kt, 1e-9 * kt);
  // axial: both rods at node 1
  EXPECT_NEAR(kb(at(both, n2, 0), at(both, n2, 0)), ka, 1e-9 * ka);
  EXPECT_NEAR(kb(at(both, n1, 0), at(both, n2, 0)), -ka, 1e-9 * ka);
}

TEST(Rod2, BadInputNamesTheElement) {
  MatX K, M;
  RodCase zero;
  zero.x[1] = zero.x[0];
  ExpectInputErrorWith([&] { Rod2Matrices(zero.Input(), K, M); }, {"truss.bdf:12", "2-node rod 77", "zero length"});
  RodCase area;
  area.section.A = 0.0;
  ExpectInputErrorWith([&] { Rod2Matrices(area.Input(), K, M); }, {"2-node rod 77", "area A must be positive"});
  RodCase bending;
  bending.section.Iy = 1.0e-8;
  ExpectInputErrorWith([&] { Rod2Matrices(bending.Input(), K, M); }, {"not a rod section"});
  RodCase torsion;
  torsion.section.J = -1.0;
  ExpectInputErrorWith([&] { Rod2Matrices(torsion.Input(), K, M); }, {"torsion constant J"});
  RodCase nosec;
  ElementInput in = nosec.Input();
  in.beam = nullptr;
  ExpectInputErrorWith([&] { Rod2Matrices(in, K, M); }, {"missing rod section"});
}

}  // namespace
}  // namespace flexmb::fe
