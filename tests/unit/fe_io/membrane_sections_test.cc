// Membranes: a Nastran PSHELL without MID2 and an Abaqus/CalculiX
// *MEMBRANE SECTION (M3D3, M3D4, M3D4R) are read as a
// membrane section (fe::ShellLaminate::membrane_only). Checked here: the
// section is the hand-computed one (A = T q1, mass rho T, nothing else);
// the elements activate their nodes' translations only (3 DOF per node
// where nothing else uses the rotations), their matrices have no rotational
// stiffness or inertia, and their translational mass is rho T times the
// area; the same membrane written as Nastran and as Abaqus assembles to the
// same K and M; a membrane's element stiffness equals the plane-stress
// membrane energy of a homogeneous strain; a PSHELL's MID4 is the coupling
// B = T^2 G4; and every misuse is an error naming file, line and card.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "flexmb/body_file/body_file.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/laminate.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/element_input.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace membrane_sections_test {

// two CQUAD4 on a 2 x 1 m strip, skewed out of the x-y plane by a fold along
// x = 1 (so that the membrane has stiffness in every direction at the fold)
const std::string kGrids =
    "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n"
    "GRID,5,,2.,0.,0.5\nGRID,6,,2.,1.,0.5\n";
const std::string kMembrane = "MAT1,1,2.1+11,,0.3,7850.\nPSHELL,1,1,0.002\n";

TEST(MembraneSection, PshellWithoutMid2IsTheHandMembrane) {
  const fe::Mesh m =
      ReadNastran(testing::WriteScratch("membrane.bdf", kGrids + kMembrane + "CQUAD4,1,1,1,2,3,4\n"));
  ASSERT_EQ(m.shell_sections.size(), 1u);
  const fe::ShellSection& s = m.shell_sections[0];
  ASSERT_TRUE(s.laminate);
  const fe::ShellLaminate& l = *s.laminate;
  EXPECT_TRUE(l.membrane_only);
  const Eigen::Matrix3d q = fe::IsotropicPlaneStress(2.1e11, 0.3);
  EXPECT_LT((l.A - q * 0.002).cwiseAbs().maxCoeff(), 1e-12 * l.A(0, 0));
  EXPECT_EQ(l.B.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(l.D.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(l.S.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_NEAR(l.mass, 7850 * 0.002, 1e-12);
  EXPECT_EQ(l.rotary, 0.0);
  EXPECT_EQ(l.card, "PSHELL 1");
}

TEST(MembraneSection, MembranesActOnTranslationsOnly) {
  const fe::Mesh m = ReadNastran(testing::WriteScratch(
      "membrane_dofs.bdf", kGrids + kMembrane + "CQUAD4,1,1,1,2,3,4\nCQUAD4,2,1,2,5,6,3\n"));
  const fe::AssembledModel a = fe::Assemble(m);
  EXPECT_EQ(a.dofs.n_full, 3 * 6);
  for (size_t n = 0; n < m.nodes.size(); ++n)
    for (int c = 3; c < 6; ++c) EXPECT_LT(a.dofs.full[n][c], 0) << "node " << m.nodes[n].id << " rotation " << c;
  // the element's own matrices: no rotational stiffness or inertia, and the
  // translational mass of each direction is rho T times the area
  std::vector<fe::Vec3> x;
  for (const fe::Element& e : m.elements) {
    fe::MatX K, M;
    fe::ElementMatrices(reduction::ResolveElementInput(m, e, x), K, M);
    for (int node = 0; node < 4; ++node) {
      EXPECT_EQ(K.middleRows(6 * node + 3, 3).cwiseAbs().maxCoeff(), 0.0) << "element " << e.id;
      EXPECT_EQ(M.middleRows(6 * node + 3, 3).cwiseAbs().maxCoeff(), 0.0) << "element " << e.id;
    }
    const double area = e.id == 1 ? 1.0 : std::sqrt(1.25);
    for (int d = 0; d < 3; ++d) {
      double total = 0.0;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) total += M(6 * i + d, 6 * j + d);
      EXPECT_NEAR(total, 7850 * 0.002 * area, 1e-9) << "element " << e.id << " direction " << d;
    }
  }
  // a beam on nodes 1 and 2 activates their rotations; the membrane's
  // rotational terms stay zero there
  const fe::Mesh mb = ReadNastran(testing::WriteScratch(
      "membrane_beam.bdf", kGrids + kMembrane + "CQUAD4,1,1,1,2,3,4\nCBAR,9,2,1,2,0.,0.,1.\nPBAR,2,1,1.e-4,1.e-8,1.e-8,2.e-8\n"));
  const fe::AssembledModel ab = fe::Assemble(mb);
  EXPECT_EQ(ab.dofs.n_full, 4 * 3 + 2 * 3);
}

// a homogeneous membrane strain (u = E x) of a flat element stores the
// plane-stress energy T/2 eps^T q eps times the area
TEST(MembraneSection, HomogeneousStrainStoresThePlaneStressEnergy) {
  const fe::Mesh m = ReadNastran(testing::WriteScratch(
      "membrane_energy.bdf", "GRID,1,,0.,0.,0.\nGRID,2,,1.2,0.1,0.\nGRID,3,,1.,0.9,0.\nGRID,4,,-0.1,1.,0.\n" +
                                 kMembrane + "CQUAD4,1,1,1,2,3,4\nCTRIA3,2,1,1,2,3\n"));
  const double exx = 1e-3, eyy = -4e-4, gxy = 6e-4;
  Eigen::Matrix2d grad;  // u = grad x, symmetric part the strain
  grad << exx, gxy / 2, gxy / 2, eyy;
  const Eigen::Vector3d eps(exx, eyy, gxy);
  std::vector<fe::Vec3> x;
  for (const fe::Element& e : m.elements) {
    fe::MatX K, M;
    fe::ElementMatrices(reduction::ResolveElementInput(m, e, x), K, M);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(K.rows());
    for (size_t k = 0; k < e.nodes.size(); ++k)
      u.segment<2>(6 * static_cast<Eigen::Index>(k)) = grad * m.nodes[e.nodes[k]].x.head<2>();
    // shoelace area of the element's polygon
    double area = 0.0;
    for (size_t k = 0; k < e.nodes.size(); ++k) {
      const fe::Vec3 &p = m.nodes[e.nodes[k]].x, &r = m.nodes[e.nodes[(k + 1) % e.nodes.size()]].x;
      area += 0.5 * (p.x() * r.y() - r.x() * p.y());
    }
    const double expected = 0.5 * 0.002 * eps.dot(fe::IsotropicPlaneStress(2.1e11, 0.3) * eps) * area;
    EXPECT_NEAR(0.5 * u.dot(K * u), expected, 1e-9 * expected) << "element " << e.id;
  }
}

// the same folded strip as an Abaqus deck of M3D4: the same K and M
TEST(MembraneSection, AbaqusMembraneSectionEqualsTheNastranMembrane) {
  const fe::Mesh nas = ReadNastran(testing::WriteScratch(
      "fold.bdf", kGrids + kMembrane + "CQUAD4,1,1,1,2,3,4\nCQUAD4,2,1,2,5,6,3\n"));
  const fe::Mesh abq = ReadAbaqus(testing::WriteScratch(
      "fold.inp",
      "*NODE\n1,0.,0.,0.\n2,1.,0.,0.\n3,1.,1.,0.\n4,0.,1.,0.\n5,2.,0.,0.5\n6,2.,1.,0.5\n"
      "*ELEMENT, TYPE=M3D4, ELSET=E1\n1,1,2,3,4\n*ELEMENT, TYPE=M3D4R, ELSET=E1\n2,2,5,6,3\n"
      "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n"
      "*MEMBRANE SECTION, ELSET=E1, MATERIAL=STEEL, OFFSET=0.\n0.002\n"));
  const fe::AssembledModel a = fe::Assemble(nas), b = fe::Assemble(abq);
  ASSERT_EQ(a.dofs.n_free, b.dofs.n_free);
  EXPECT_LT((fe::MatX(a.K) - fe::MatX(b.K)).cwiseAbs().maxCoeff(), 1e-12 * fe::MatX(a.K).cwiseAbs().maxCoeff());
  EXPECT_LT((fe::MatX(a.M) - fe::MatX(b.M)).cwiseAbs().maxCoeff(), 1e-12 * fe::MatX(a.M).cwiseAbs().maxCoeff());
}

// a body file does not hold the membrane section: its mesh comes back with
// material -1, so re-assembling it is an error naming the element, never a
// bending shell of the same material
TEST(MembraneSection, BodyFileMeshOfAMembraneCannotBeReassembledAsAShell) {
  // one bay of a square tube of M3D4 walls closed by diaphragms at both
  // ends (an open end racks), its root corners the interface
  fe::FeModel model;
  model.mesh = ReadAbaqus(testing::WriteScratch(
      "tube.inp",
      "*NODE\n1,0.,0.,0.\n2,0.,1.,0.\n3,0.,1.,1.\n4,0.,0.,1.\n5,2.,0.,0.\n6,2.,1.,0.\n7,2.,1.,1.\n8,2.,0.,1.\n"
      "*ELEMENT, TYPE=M3D4, ELSET=WALLS\n1,1,5,6,2\n2,2,6,7,3\n3,3,7,8,4\n4,4,8,5,1\n5,5,6,7,8\n6,1,4,3,2\n"
      "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n"
      "*MEMBRANE SECTION, ELSET=WALLS, MATERIAL=STEEL\n0.002\n"));
  ASSERT_GE(model.mesh.shell_sections[0].material, 0);
  reduction::ReductionOptions options;
  options.interface_nodes = {0, 1, 2, 3};
  options.normal_modes = 2;
  const reduction::ReducedBody body = reduction::ReduceCraigBampton(model, options);
  const std::string path = testing::ScratchPath("tube.h5");
  WriteBody(body, path);
  const reduction::ReducedBody back = ReadBody(path);
  EXPECT_EQ(back.mesh.shell_sections[0].material, -1);
  testing::ExpectContains(testing::InputErrorOf([&] { fe::Assemble(back.mesh); }),
                          {"shell", "1", "no material", "body file"}, "reassembly");
}

TEST(MembraneSection, MisusedMembranesAreErrorsNamingTheCard) {
  const std::string quad = "CQUAD4,1,1,1,2,3,4\n";
  testing::ExpectBadFiles(
      {{"mem_mid3.bdf", kGrids + "MAT1,1,2.1+11,,0.3,7850.\nPSHELL,1,1,0.002,,,1\n" + quad, ":8: PSHELL 1: ",
        {"MID3 is given but MID2 is blank"}},
       {"mem_mid4.bdf", kGrids + "MAT1,1,2.1+11,,0.3,7850.\nPSHELL,1,1,0.002\n,,,1\n" + quad, ":9: PSHELL 1: ",
        {"MID4 is given but MID2 is blank"}},
       {"mem_offset.bdf", kGrids + kMembrane + "CQUAD4,1,1,1,2,3,4,,0.001\n", "",
        {"4-node shell 1", "offset membrane", "PSHELL 1"}},
       {"mem_quad8.bdf",
        kGrids + kMembrane +
            "GRID,11,,0.5,0.,0.\nGRID,12,,1.,0.5,0.\nGRID,13,,0.5,1.,0.\nGRID,14,,0.,0.5,0.\n"
            "CQUAD8,1,1,1,2,3,4,11,12\n,13,14\n",
        "", {"8-node shell 1", "second-order membrane", "PSHELL 1"}}},
      [](const std::string& p) { fe::Assemble(ReadNastran(p)); });
  const std::string nodes = "*NODE\n1,0.,0.,0.\n2,1.,0.,0.\n3,1.,1.,0.\n4,0.,1.,0.\n";
  const std::string material = "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n";
  testing::ExpectBadFiles(
      {{"m3d4_shell.inp", nodes + "*ELEMENT, TYPE=M3D4, ELSET=E1\n1,1,2,3,4\n" + material +
                              "*SHELL SECTION, ELSET=E1, MATERIAL=STEEL\n0.002\n",
        ":11: ", {"element 1 is a membrane element: give it a *MEMBRANE SECTION"}},
       {"s4_membrane.inp", nodes + "*ELEMENT, TYPE=S4, ELSET=E1\n1,1,2,3,4\n" + material +
                               "*MEMBRANE SECTION, ELSET=E1, MATERIAL=STEEL\n0.002\n",
        ":11: ", {"element 1 is a shell, not a membrane element", "*SHELL SECTION"}},
       {"membrane_offset.inp", nodes + "*ELEMENT, TYPE=M3D4, ELSET=E1\n1,1,2,3,4\n" + material +
                                   "*MEMBRANE SECTION, ELSET=E1, MATERIAL=STEEL, OFFSET=SPOS\n0.002\n",
        ":11: ", {"OFFSET must be 0"}},
       {"m3d8.inp", nodes + "*ELEMENT, TYPE=M3D8R, ELSET=E1\n1,1,2,3,4\n", ":6: ", {"M3D8R", "unsupported"}},
       {"membrane_param.inp", nodes + "*ELEMENT, TYPE=M3D4, ELSET=E1\n1,1,2,3,4\n" + material +
                                  "*MEMBRANE SECTION, ELSET=E1, MATERIAL=STEEL, THICK=2\n0.002\n",
        ":11: ", {"THICK"}}},
      [](const std::string& p) { ReadAbaqus(p); });
}

// MID4: the coupling B = T^2 G4 of Nastran's stress resultants (N = T G1
// eps + T^2 G4 kappa), and an indefinite section is an error
TEST(MembraneSection, Mid4IsTheCouplingTimesTSquared) {
  const std::string mats = "MAT2,1,2.e11,5.e10,0.,2.e11,0.,7.e10,7850.\nMAT2,4,3.e10,0.,0.,-3.e10,0.,0.\n";
  const fe::Mesh m = ReadNastran(testing::WriteScratch(
      "mid4.bdf", kGrids + mats + "MAT1,3,2.1e11,,0.3\nPSHELL,1,1,0.01,1,,3\n,,,4\nCQUAD4,1,1,1,2,3,4\n"));
  const fe::ShellLaminate& l = *m.shell_sections[0].laminate;
  Eigen::Matrix3d g4;
  g4 << 3e10, 0, 0, 0, -3e10, 0, 0, 0, 0;
  EXPECT_LT((l.B - g4 * 1e-4).cwiseAbs().maxCoeff(), 1e-12 * 3e6);
  EXPECT_FALSE(l.membrane_only);
  testing::ExpectBadFiles(
      {{"mid4_indefinite.bdf",
        kGrids + "MAT2,1,2.e11,5.e10,0.,2.e11,0.,7.e10,7850.\nMAT2,4,3.e13,0.,0.,0.,0.,0.\nMAT1,3,2.1e11,,0.3\n"
                 "PSHELL,1,1,0.01,1,,3\n,,,4\nCQUAD4,1,1,1,2,3,4\n",
        ":11: PSHELL 1: ", {"MID4 = 4", "indefinite"}}},
      [](const std::string& p) { ReadNastran(p); });
}

}  // namespace membrane_sections_test
}  // namespace flexmb::io
