// Nastran cards beyond elements with a section: CONM1 (general nodal mass
// matrix), CELAS1 / PELAS and CELAS2 (scalar springs), each checked against
// a hand-computed reference; INCLUDE resolution as Nastran searches.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"
#include "flexmb/fe/point_mass.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using fe::Mat3;
using fe::Mat6;
using fe::Vec3;

// ---- CONM1 ---------------------------------------------------------------------

// the rigid mass m = 2 kg at d = (0, 0, 0.5) m from node (1, 0, 0), inertia
// diag(0.1, 0.2, 0.3) kg m^2 about its centre, written by hand as the 6 x 6
// matrix [[m I, -m S], [m S, Ic - m S^2]], S = skew(d) = [[0, -.5, 0], [.5,
// 0, 0], [0, 0, 0]]: m S = [[0, -1, 0], [1, 0, 0], 0] (M42 = -1, M51 = 1),
// -m S^2 = diag(.5, .5, 0) (M44 = .6, M55 = .7, M66 = .3)
TEST(NastranCards, Conm1RigidMassHasItsMassCentreAndInertia) {
  const std::string path = testing::WriteScratch("conm1_rigid.bdf",
                                                 "GRID,1,,1.,0.,0.\n"
                                                 "CONM1,7,1,,2.,0.,2.,0.,0.\n"
                                                 ",2.,0.,-1.,0.,.6,1.,0.,0.\n"
                                                 ",0.,.7,0.,0.,0.,0.,0.,.3\n");
  const fe::Mesh mesh = ReadNastran(path);
  ASSERT_EQ(mesh.point_masses.size(), 1u);
  const fe::PointMass& pm = mesh.point_masses[0];
  EXPECT_TRUE(pm.general);
  EXPECT_EQ(pm.id, 7);
  EXPECT_EQ(pm.origin.line, 2);

  // the same mass as CONM2's rigid-body matrix
  fe::PointMass rigid;
  rigid.node = 0;
  rigid.mass = 2.0;
  rigid.offset = Vec3(0.0, 0.0, 0.5);
  rigid.inertia = Vec3(0.1, 0.2, 0.3).asDiagonal();
  EXPECT_LT((fe::PointMassMatrix(pm) - fe::PointMassMatrix(rigid)).cwiseAbs().maxCoeff(), 1e-15);

  fe::AssemblyOptions options;
  options.apply_constraints = false;
  const fe::MassProperties p = fe::ComputeMassProperties(mesh, fe::Assemble(mesh, options));
  EXPECT_NEAR(p.mass, 2.0, 1e-14);
  EXPECT_LT((p.center - Vec3(1.0, 0.0, 0.5)).norm(), 1e-14);
  const Mat3 inertia = Vec3(0.1, 0.2, 0.3).asDiagonal();
  EXPECT_LT((p.inertia - inertia).cwiseAbs().maxCoeff(), 1e-14) << p.inertia;
}

// CORD2R 1 (origin 0, z = Z, x-z plane through (0, 1, 0)): x = Y, y = -X,
// so diag(1, 2, 3) in it is diag(2, 1, 3) in basic, and diag(4, 5, 6) on
// the rotations diag(5, 4, 6)
TEST(NastranCards, Conm1InARectangularSystem) {
  const std::string path = testing::WriteScratch("conm1_cid.bdf",
                                                 "CORD2R,1,,0.,0.,0.,0.,0.,1.\n"
                                                 ",0.,1.,0.\n"
                                                 "GRID,3,,0.,0.,2.\n"
                                                 "CONM1,8,3,1,1.,,2.,,\n"
                                                 ",3.,,,,4.,,,\n"
                                                 ",,5.,,,,,,6.\n");
  const fe::Mesh mesh = ReadNastran(path);
  ASSERT_EQ(mesh.point_masses.size(), 1u);
  Mat6 expected = Mat6::Zero();
  expected.diagonal() << 2.0, 1.0, 3.0, 5.0, 4.0, 6.0;
  EXPECT_LT((mesh.point_masses[0].matrix - expected).cwiseAbs().maxCoeff(), 1e-15) << mesh.point_masses[0].matrix;
}

TEST(NastranCards, Conm1BadInputNamesFileLineAndCard) {
  testing::WarningCapture quiet;
  testing::ExpectBadFiles(
      {
          {"conm1_no_grid.bdf", "GRID,1,,0.,0.,0.\nCONM1,7,99,,1.\n", ":2: CONM1 7: node 99 does not exist", {}},
          {"conm1_negative_diagonal.bdf", "GRID,1,,0.,0.,0.\nCONM1,7,1,,1.,,-2.\n",
           ":2: CONM1 7: M22 must not be negative", {}},
          {"conm1_no_system.bdf", "GRID,1,,0.,0.,0.\nCONM1,7,1,4,1.\n",
           ":2: CONM1 7: coordinate system 4 does not exist", {}},
          {"conm1_too_many_fields.bdf", "GRID,1,,0.,0.,0.\nCONM1,7,1,,1.\n,,,,,,,,\n,,,,,,,,\n,1.\n",
           ":5: CONM1 7: unexpected field", {}},
      },
      [](const std::string& path) { ReadNastran(path); });
  // not positive semi-definite: found when the matrices are built, named by file and line
  const std::string indefinite =
      testing::WriteScratch("conm1_indefinite.bdf", "GRID,1,,0.,0.,0.\n$\nCONM1,7,1,,1.,5.,1.\n");
  const fe::Mesh mesh = ReadNastran(indefinite);
  testing::ExpectContains(testing::InputErrorOf([&] { fe::Assemble(mesh); }),
                          {indefinite + ":3", "point mass 7", "not positive semi-definite"}, "indefinite");
}

// ---- CELAS1, CELAS2 ---------------------------------------------------------------

// the dense K and M of a deck's unconstrained assembly
struct NastranCardsDense {
  fe::AssembledModel model;
  Eigen::MatrixXd K, M;
};

NastranCardsDense NastranCardsAssemble(const fe::Mesh& mesh) {
  NastranCardsDense d;
  fe::AssemblyOptions options;
  options.apply_constraints = false;
  d.model = fe::Assemble(mesh, options);
  d.K = Eigen::MatrixXd(d.model.K);
  d.M = Eigen::MatrixXd(d.model.M);
  return d;
}

// two CONM2 masses m1 = 2 kg and m2 = 3 kg joined in x by CELAS2 k = 1000 N/m:
// the one elastic mode is at sqrt(k / m_eff) / (2 pi), m_eff = m1 m2 / (m1 + m2)
// = 1.2 kg, i.e. 4.5944 Hz; the five other DOF (y, z) carry mass only
TEST(NastranCards, Celas2BetweenTwoMassesHasTheTwoMassFrequency) {
  const std::string path = testing::WriteScratch("celas2_two_masses.bdf",
                                                 "GRID,1,,0.,0.,0.\n"
                                                 "GRID,2,,1.,0.,0.\n"
                                                 "CONM2,11,1,,2.\n"
                                                 "CONM2,12,2,,3.\n"
                                                 "CELAS2,21,1000.,1,1,2,1\n");
  const fe::Mesh mesh = ReadNastran(path);
  ASSERT_EQ(mesh.springs.size(), 1u);
  EXPECT_EQ(mesh.springs[0].id, 21);
  EXPECT_EQ(mesh.springs[0].component_a, 0);
  EXPECT_EQ(mesh.springs[0].node_b, 1);
  EXPECT_TRUE(mesh.elements.empty());
  const NastranCardsDense d = NastranCardsAssemble(mesh);
  ASSERT_EQ(d.model.dofs.n_free, 6);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(d.K, d.M);
  const Eigen::VectorXd w2 = eig.eigenvalues();
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(w2[k], 0.0, 1e-9);
  const double f = std::sqrt(w2[5]) / (2.0 * M_PI);
  const double f_ref = std::sqrt(1000.0 / 1.2) / (2.0 * M_PI);
  EXPECT_NEAR(f, f_ref, 1e-12 * f_ref);
}

// CELAS1 with PELAS to ground (G2 blank), on G2 with G1 blank, and on a
// rotation: K holds k on the diagonal and -k between the two DOF
TEST(NastranCards, Celas1PelasGroundedAndRotationalSprings) {
  testing::WarningCapture capture;
  const std::string path = testing::WriteScratch("celas1_pelas.bdf",
                                                 "GRID,1,,0.,0.,0.\n"
                                                 "GRID,2,,1.,0.,0.\n"
                                                 "PELAS,5,800.,.02,,6,40.\n"
                                                 "CELAS1,31,5,1,3\n"
                                                 "CELAS1,32,6,,,2,2\n"
                                                 "CELAS2,33,7.,1,4,2,6\n"
                                                 "CELAS2,34,3.,1,4,,,.01\n");
  const fe::Mesh mesh = ReadNastran(path);
  ASSERT_EQ(mesh.springs.size(), 4u);
  // one note per card type for the damping GE that is ignored
  EXPECT_EQ(capture.Count("GE of PELAS is ignored"), 1);
  EXPECT_EQ(capture.Count("GE of CELAS2 is ignored"), 1);
  const NastranCardsDense d = NastranCardsAssemble(mesh);
  const auto& free = d.model.dofs.free;
  // active: node 1 uz, rx; node 2 uy, rz
  ASSERT_EQ(d.model.dofs.n_free, 4);
  const int z1 = free[0][2], rx1 = free[0][3], y2 = free[1][1], rz2 = free[1][5];
  ASSERT_GE(std::min({z1, rx1, y2, rz2}), 0);
  EXPECT_EQ(free[0][0], -1);
  Eigen::MatrixXd K_ref = Eigen::MatrixXd::Zero(4, 4);
  K_ref(z1, z1) = 800.0;
  K_ref(y2, y2) = 40.0;
  K_ref(rx1, rx1) = 7.0 + 3.0;
  K_ref(rz2, rz2) = 7.0;
  K_ref(rx1, rz2) = K_ref(rz2, rx1) = -7.0;
  EXPECT_LT((d.K - K_ref).cwiseAbs().maxCoeff(), 1e-12) << d.K;
  EXPECT_EQ(d.M.cwiseAbs().maxCoeff(), 0.0);
}

TEST(NastranCards, CelasBadInputNamesFileLineAndCard) {
  testing::WarningCapture quiet;
  const std::string base = "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n";  // lines 1-2
  testing::ExpectBadFiles(
      {
          {"celas1_no_pelas.bdf", base + "CELAS1,7,5,1,1,2,1\n",
           ":3: CELAS1 7: property 5 does not exist (CELAS1 needs a PELAS)", {}},
          {"celas1_not_pelas.bdf", base + "MAT1,1,2.1+11,,.3\nPSHELL,5,1,.01,1\nCELAS1,7,5,1,1,2,1\n",
           ":5: CELAS1 7: property 5 is a PSHELL; CELAS1 needs a PELAS", {}},
          {"celas2_component_7.bdf", base + "CELAS2,7,1.,1,7,2,1\n",
           ":3: CELAS2 7: C1: component '7' is not a single digit 1 to 6", {}},
          {"celas2_component_12.bdf", base + "CELAS2,7,1.,1,1,2,12\n",
           ":3: CELAS2 7: C2: component '12' is not a single digit 1 to 6", {}},
          {"celas2_no_grid.bdf", base + "CELAS2,7,1.,1,1,99,1\n", ":3: CELAS2 7: node 99 does not exist", {}},
          {"celas2_itself.bdf", base + "CELAS2,7,1.,2,3,2,3\n",
           ":3: CELAS2 7: the spring connects component 3 of node 2 to itself", {}},
          {"celas2_nothing.bdf", base + "CELAS2,7,1.\n", ":3: CELAS2 7: both grids are blank", {}},
          {"celas2_negative.bdf", base + "CELAS2,7,-1.,1,1\n", ":3: CELAS2 7: spring stiffness K must not be negative",
           {}},
          {"pelas_negative.bdf", base + "PELAS,5,-2.\n", ":3: PELAS 5: spring stiffness K must not be negative", {}},
          {"celas_duplicate.bdf", base + "CONM2,7,1,,1.\nCELAS2,7,1.,1,1\n", ":4: CELAS2 7: duplicate element id 7",
           {}},
      },
      [](const std::string& path) { ReadNastran(path); });
}

// the Abaqus writer cannot carry springs yet: it refuses them by name
TEST(NastranCards, AbaqusWriterRefusesSprings) {
  const std::string path =
      testing::WriteScratch("celas_to_abaqus.bdf", "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n$\nCELAS2,7,1.,1,1,2,1\n");
  const fe::Mesh mesh = ReadNastran(path);
  testing::ExpectContains(
      testing::InputErrorOf([&] { WriteAbaqus(mesh, testing::ScratchPath("celas_to_abaqus.inp")); }),
      {path + ":4", "scalar spring 7", "cannot be written to an Abaqus deck"}, "abaqus");
}

// ---- INCLUDE ------------------------------------------------------------------------

// a relative INCLUDE is searched in the including file's folder, then the
// main deck's folder, then the current directory
TEST(NastranInclude, SearchesIncludingFolderThenMainDeckFolderThenCurrentDirectory) {
  namespace fs = std::filesystem;
  const std::string main = testing::WriteScratch("include_search/main.bdf",
                                                 "GRID,1,,0.,0.,0.\n"
                                                 "INCLUDE 'sub/a.bdf'\n");
  // sub/a.bdf includes b.bdf (in sub/ and in the main folder: sub/ wins),
  // c.bdf (only in the main folder) and d.bdf (only in the current directory)
  testing::WriteScratch("include_search/sub/a.bdf", "INCLUDE 'b.bdf'\nINCLUDE 'c.bdf'\nINCLUDE 'd.bdf'\n");
  testing::WriteScratch("include_search/sub/b.bdf", "GRID,2,,2.,0.,0.\n");
  testing::WriteScratch("include_search/b.bdf", "GRID,2,,-2.,0.,0.\n");
  testing::WriteScratch("include_search/c.bdf", "GRID,3,,3.,0.,0.\n");
  testing::WriteScratch("include_search_cwd/d.bdf", "GRID,4,,4.,0.,0.\n");
  const fs::path before = fs::current_path();
  fs::current_path(testing::ScratchPath("include_search_cwd"));
  fe::Mesh mesh;
  std::string missing;
  try {
    mesh = ReadNastran(main);
    testing::WriteScratch("include_search/sub/e.bdf", "INCLUDE 'nowhere.bdf'\n");
    const std::string e_main = testing::WriteScratch("include_search/e_main.bdf", "INCLUDE 'sub/e.bdf'\n");
    missing = testing::InputErrorOf([&] { ReadNastran(e_main); });
  } catch (...) {
    fs::current_path(before);
    throw;
  }
  fs::current_path(before);
  ASSERT_EQ(mesh.nodes.size(), 4u);
  for (int id = 1; id <= 4; ++id) {
    const int n = mesh.NodeIndex(id);
    ASSERT_GE(n, 0) << id;
    EXPECT_EQ(mesh.nodes[n].x, Vec3((id == 1 ? 0.0 : id), 0.0, 0.0)) << id;
  }
  // the error names the including file's line and every folder tried
  const std::string root = testing::ScratchPath("include_search");
  testing::ExpectContains(missing,
                          {"sub/e.bdf:1: INCLUDE: cannot open 'nowhere.bdf'", "'" + root + "/sub' (including file)",
                           "'" + root + "' (main deck)", testing::ScratchPath("include_search_cwd") + "' (current directory)"},
                          "missing include");
}

}  // namespace
}  // namespace flexmb::io

// ---- stress recovery points of beam sections -------------------------------------

namespace flexmb::io {
namespace {

// PBAR with C1 ... F2 keeps them as (y, z) = (Ci, Di ...) pairs; a PBAR
// without them has none (Nastran: the axial stress only); PBARL BAR has its
// four corners about the centroid (DIM1 along z, DIM2 along y); PBEAM takes
// end A's points
TEST(NastranCards, BeamSectionStressPoints) {
  const std::string path = testing::WriteScratch("stress_points.bdf",
                                                 "MAT1,1,2.1+11,,.3,7850.\n"
                                                 "PBAR,1,1,1.-3,2.-7,3.-7,1.-7\n"
                                                 ",.01,.02,-.01,.02,-.01,-.02,.01,-.02\n"
                                                 "PBAR,2,1,1.-3,2.-7,3.-7,1.-7\n"
                                                 "PBARL,3,1,,BAR\n"
                                                 ",.04,.06\n"
                                                 "PBEAM,4,1,1.-3,2.-7,3.-7,,1.-7\n"
                                                 ",.03,.01,-.03,.01,,,,\n"
                                                 "GRID,1,,0.,0.,0.\n"
                                                 "GRID,2,,1.,0.,0.\n"
                                                 "CBAR,1,1,1,2,0.,1.,0.\n"
                                                 "CBAR,2,2,1,2,0.,1.,0.\n"
                                                 "CBAR,3,3,1,2,0.,1.,0.\n"
                                                 "CBEAM,4,4,1,2,0.,1.,0.\n");
  const fe::Mesh mesh = ReadNastran(path);
  ASSERT_EQ(mesh.beam_sections.size(), 4u);
  using P = std::array<double, 2>;
  EXPECT_EQ(mesh.beam_sections[0].stress_points,
            (std::vector<P>{{.01, .02}, {-.01, .02}, {-.01, -.02}, {.01, -.02}}));
  EXPECT_TRUE(mesh.beam_sections[1].stress_points.empty());
  std::vector<P> bar = mesh.beam_sections[2].stress_points;
  std::sort(bar.begin(), bar.end());
  EXPECT_EQ(bar, (std::vector<P>{{-.03, -.02}, {-.03, .02}, {.03, -.02}, {.03, .02}}));
  EXPECT_EQ(mesh.beam_sections[3].stress_points, (std::vector<P>{{.03, .01}, {-.03, .01}, {0, 0}, {0, 0}}));
}

}  // namespace
}  // namespace flexmb::io
