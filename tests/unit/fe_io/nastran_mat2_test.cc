// Nastran PSHELL with other materials than one MAT1: MAT2 (anisotropic
// shell material) and MAT8 as MID1, MID2 and MID3, MID2 differing from
// MID1. Independent references: a MAT2 whose matrix is the isotropic
// plane-stress matrix written out by hand (E / (1 - nu^2) [1 nu 0; nu 1 0;
// 0 0 (1 - nu) / 2]) gives the element matrices of the MAT1 plate; a MAT2
// with the orthotropic matrix of a MAT8 written out by hand (q11 = E1 / (1
// - nu12 nu21), ...) gives those of the MAT8 plate, also with a material
// angle; the section of MID1 != MID2 is A = T q1, D = T^3 / 12 q2, S = 5/6
// T of MID2's shear or TS/T T of MID3's; the bending stresses of a plate
// whose MID2 is twice as stiff are twice as large at the same curvature
// (sigma = z q2 kappa, Nastran's M z / I) and the membrane stresses equal;
// and the errors that name card and field.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/laminate.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace nastran_mat2_test {

const std::string kMat2Quad = "GRID,1,,0.,0.,0.\nGRID,2,,1.2,0.1,0.\nGRID,3,,1.1,0.9,0.\nGRID,4,,0.,1.,0.\n";
constexpr double kMat2E = 2.1e11, kMat2Nu = 0.3, kMat2Rho = 7850.0;

std::string Num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// the element's K and M of a one-CQUAD4 deck
void QuadMatrices(const std::string& name, const std::string& cards, fe::MatX& K, fe::MatX& M) {
  const fe::Mesh m = ReadNastran(testing::WriteScratch(name, kMat2Quad + cards));
  const fe::AssembledModel a = fe::Assemble(m);
  K = fe::MatX(a.K);
  M = fe::MatX(a.M);
}

double RelDiff(const fe::MatX& a, const fe::MatX& b) { return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff(); }

TEST(NastranMat2, IsotropicMat2EqualsMat1) {
  const double c = kMat2E / (1 - kMat2Nu * kMat2Nu), g = kMat2E / (2 * (1 + kMat2Nu));
  fe::MatX K1, M1, K2, M2;
  QuadMatrices("mat1.bdf", "CQUAD4,1,1,1,2,3,4\nPSHELL,1,10,0.01,10\nMAT1,10,2.1e11,,0.3,7850.\n", K1, M1);
  QuadMatrices("mat2.bdf",
               "CQUAD4,1,1,1,2,3,4\nPSHELL,1,20,0.01,20\nMAT2,20," + Num(c) + "," + Num(kMat2Nu * c) + ",0.," + Num(c) +
                   ",0.," + Num(g) + "," + Num(kMat2Rho) + "\n",
               K2, M2);
  EXPECT_LT(RelDiff(K2, K1), 1e-12);
  EXPECT_LT(RelDiff(M2, M1), 1e-12);
}

TEST(NastranMat2, OrthotropicMat2EqualsMat8AtAMaterialAngle) {
  const double e1 = 138e9, e2 = 9e9, nu12 = 0.3, g12 = 7.1e9;
  const double nu21 = nu12 * e2 / e1, d = 1 - nu12 * nu21;
  fe::MatX K8, M8, K2, M2;
  QuadMatrices("mat8_pshell.bdf",
               "CQUAD4,1,1,1,2,3,4,30.\nPSHELL,1,10,0.01,10\nMAT8,10,138.e9,9.e9,0.3,7.1e9,7.1e9,7.1e9,1600.\n", K8, M8);
  QuadMatrices("mat2_pshell.bdf",
               "CQUAD4,1,1,1,2,3,4,30.\nPSHELL,1,20,0.01,20\nMAT2,20," + Num(e1 / d) + "," + Num(nu12 * e2 / d) + ",," +
                   Num(e2 / d) + ",," + Num(g12) + ",1600.\n",
               K2, M2);
  EXPECT_LT(RelDiff(K2, K8), 1e-12);
  EXPECT_LT(RelDiff(M2, M8), 1e-12);
  // the angle matters: the comparison sees it
  fe::MatX K0, M0;
  QuadMatrices("mat2_pshell0.bdf",
               "CQUAD4,1,1,1,2,3,4\nPSHELL,1,20,0.01,20\nMAT2,20," + Num(e1 / d) + "," + Num(nu12 * e2 / d) + ",," +
                   Num(e2 / d) + ",," + Num(g12) + ",1600.\n",
               K0, M0);
  EXPECT_GT(RelDiff(K0, K8), 1e-2);
}

TEST(NastranMat2, Mid2AndMid3GiveTheBendingAndShearOfTheirMaterials) {
  const std::string mats = "MAT1,10,2.1e11,,0.3,7850.\nMAT1,11,7.e10,,0.33,2700.\nMAT2,12,3.e9,1.e9,,2.e9,,0.8e9\n"
                           "MAT8,13,138.e9,9.e9,0.3,7.1e9,5.e9,4.e9,1600.\n";
  const double t = 0.02;
  {
    const fe::Mesh m = ReadNastran(testing::WriteScratch("mid2.bdf", kMat2Quad + mats + "CQUAD4,1,1,1,2,3,4\nPSHELL,1,10,0.02,11\n"));
    const fe::ShellLaminate& l = *m.shell_sections[0].laminate;
    const Eigen::Matrix3d q1 = fe::IsotropicPlaneStress(2.1e11, 0.3), q2 = fe::IsotropicPlaneStress(7e10, 0.33);
    EXPECT_LT((l.A - t * q1).cwiseAbs().maxCoeff(), 1e-12 * t * q1(0, 0));
    EXPECT_LT((l.D - t * t * t / 12 * q2).cwiseAbs().maxCoeff(), 1e-12 * t * t * t * q2(0, 0));
    EXPECT_LT((l.S - Eigen::Matrix2d::Identity() * (5.0 / 6.0 * t * 7e10 / 2.66)).cwiseAbs().maxCoeff(), 1e-6 * t * 7e10);
    EXPECT_TRUE(l.B.isZero(0.0));
    EXPECT_NEAR(l.mass, 7850 * t, 1e-12);
    EXPECT_LT((l.qb_top - q2).cwiseAbs().maxCoeff(), 1e-6 * q2(0, 0));
    EXPECT_LT((l.q_top - q1).cwiseAbs().maxCoeff(), 1e-6 * q1(0, 0));
    EXPECT_EQ(m.shell_sections[0].material, 0);  // MID1 is a MAT1
  }
  {  // MID3 a MAT2: its [G11 G12; G12 G22] times TS/T T; a bending ratio
    const fe::Mesh m =
        ReadNastran(testing::WriteScratch("mid3.bdf", kMat2Quad + mats + "CQUAD4,1,1,1,2,3,4\nPSHELL,1,10,0.02,10,1.5,12,0.9\n"));
    const fe::ShellLaminate& l = *m.shell_sections[0].laminate;
    Eigen::Matrix2d s;
    s << 3e9, 1e9, 1e9, 2e9;
    EXPECT_LT((l.S - 0.9 * t * s).cwiseAbs().maxCoeff(), 1e-12 * t * 3e9);
    EXPECT_LT((l.D - 1.5 * t * t * t / 12 * fe::IsotropicPlaneStress(2.1e11, 0.3)).cwiseAbs().maxCoeff(), 1e-12 * t * t * t * 2.1e11);
  }
  {  // MID3 a MAT8: diag(G1Z, G2Z); MID1 a MAT8: no MAT1 index
    const fe::Mesh m =
        ReadNastran(testing::WriteScratch("mid3_mat8.bdf", kMat2Quad + mats + "CQUAD4,1,1,1,2,3,4\nPSHELL,1,13,0.02,13,,13\n"));
    const fe::ShellLaminate& l = *m.shell_sections[0].laminate;
    EXPECT_NEAR(l.S(0, 0), 5.0 / 6.0 * t * 5e9, 1e-6 * t * 5e9);
    EXPECT_NEAR(l.S(1, 1), 5.0 / 6.0 * t * 4e9, 1e-6 * t * 5e9);
    EXPECT_EQ(l.S(0, 1), 0.0);
    EXPECT_EQ(m.shell_sections[0].material, -1);
    EXPECT_NEAR(l.mass, 1600 * t, 1e-12);
  }
}

// the surface stresses of a one-element plate: a membrane state and a
// bending state (rotations only), MID2 = MID1 against MID2 twice as stiff
TEST(NastranMat2, BendingStressesFollowMid2AndMembraneStressesMid1) {
  const std::string mats = "MAT1,10,2.1e11,,0.3,7850.\nMAT1,11,4.2e11,,0.3,7850.\n";
  const fe::Mesh plain = ReadNastran(testing::WriteScratch("stress_plain.bdf", kMat2Quad + mats + "CQUAD4,1,1,1,2,3,4\nPSHELL,1,10,0.01,10\n"));
  const fe::Mesh stiff = ReadNastran(testing::WriteScratch("stress_mid2.bdf", kMat2Quad + mats + "CQUAD4,1,1,1,2,3,4\nPSHELL,1,10,0.01,11\n"));
  auto stress = [](const fe::Mesh& m, const Eigen::VectorXd& u) {
    std::vector<fe::Vec3> x;
    for (int n : m.elements[0].nodes) x.push_back(m.nodes[n].x);
    fe::ElementInput in;
    in.element = &m.elements[0];
    in.x = x.data();
    in.shell = &m.shell_sections[0];
    in.material = m.shell_sections[0].material >= 0 ? &m.materials[m.shell_sections[0].material] : nullptr;
    fe::MatX S;
    Eigen::Matrix3d axes;
    fe::Traits(fe::ElementType::kQuad4).stress(in, S, axes);
    return Eigen::VectorXd(S * u);
  };
  Eigen::VectorXd membrane = Eigen::VectorXd::Zero(24), bending = Eigen::VectorXd::Zero(24);
  for (int i = 0; i < 4; ++i) {
    const fe::Vec3 x = plain.nodes[plain.elements[0].nodes[i]].x;
    membrane(6 * i) = 1e-4 * x.x();  // stretch along x
    bending(6 * i + 4) = 1e-3 * x.x();  // ry linear in x: a curvature
  }
  const Eigen::VectorXd m0 = stress(plain, membrane), m1 = stress(stiff, membrane);
  const Eigen::VectorXd b0 = stress(plain, bending), b1 = stress(stiff, bending);
  EXPECT_GT(m0.norm(), 1e6);
  EXPECT_GT(b0.norm(), 1e6);
  EXPECT_LT((m1 - m0).norm(), 1e-12 * m0.norm());
  EXPECT_LT((b1 - 2.0 * b0).norm(), 1e-12 * b0.norm());
}

TEST(NastranMat2, BadShellMaterialsNameCardAndField) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"CQUAD4,1,1,1,2,3,4\nPSHELL,1,20,0.01,20\nMAT2,20,1.e9,,,1.e9,,1.e8,\n,,,,,,,,\n,5\n", {"MAT2 20", "MCSID"}},
      {"CQUAD4,1,1,1,2,3,4\nPSHELL,1,20,0.01,20\nMAT2,20,-1.e9,,,1.e9,,1.e8\n", {"PSHELL 1", "MID1 = 20", "positive definite"}},
      {"CQUAD4,1,1,1,2,3,4\nPSHELL,1,10,0.01,10,,20\nMAT1,10,2.1e11,,0.3\nMAT2,20,1.e9,2.e9,,1.e9,,1.e8\n",
       {"PSHELL 1", "MID3 = 20", "positive definite"}},
      {"CQUAD4,1,1,1,2,3,4\nPSHELL,1,10,0.01,-1\nMAT1,10,2.1e11,,0.3\n", {"PSHELL 1", "plane strain"}},
      {"CTETRA,1,1,1,2,3,4\nPSOLID,1,20\nMAT2,20,1.e9,,,1.e9,,1.e8\n", {"PSOLID 1", "MAT2"}},
  };
  int k = 0;
  for (const auto& [cards, parts] : cases) {
    const std::string path = testing::WriteScratch("mat2_bad" + std::to_string(k++) + ".bdf", kMat2Quad + cards);
    std::vector<std::string> with_file = parts;
    with_file.push_back(path + ":");
    testing::ExpectContains(testing::InputErrorOf([&] { ReadNastran(path); }), with_file, cards);
  }
}

}  // namespace nastran_mat2_test
}  // namespace flexmb::io
