// Nastran scalar masses CMASS1 (with PMASS) and CMASS2 (issue 17): on one
// grid component (to ground), between two components of one grid, along
// the axes of a grid's displacement system (GRID CD); each against a hand
// computation: with a CELAS spring k on the same component the one mode is
// at omega^2 = k / m, the mass matrix is m a a^T with a the component's
// axis, and the total mass (fe::ComputeMassProperties, what `flexmb fe
// info` reports) of three masses m on the three translations is m.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace nastran_masses_test {

// the dense K and M of a deck's unconstrained assembly
struct CmassDense {
  fe::AssembledModel model;
  Eigen::MatrixXd K, M;
};

CmassDense CmassAssemble(const fe::Mesh& mesh) {
  CmassDense d;
  fe::AssemblyOptions options;
  options.apply_constraints = false;
  d.model = fe::Assemble(mesh, options);
  d.K = Eigen::MatrixXd(d.model.K);
  d.M = Eigen::MatrixXd(d.model.M);
  return d;
}

// "CORD2R,5" turned by `deg` degrees about z (its x' = (cos, sin, 0))
std::string CmassTurnedSystem(double deg) {
  const double a = deg * M_PI / 180.0;
  char buf[160];
  std::snprintf(buf, sizeof buf, "CORD2R,5,,0.,0.,0.,0.,0.,1.\n,%.15f,%.15f,0.\n", std::cos(a), std::sin(a));
  return buf;
}

// CMASS2 m = 2.5 kg and CELAS2 k = 1000 N/m on ux of one grid, both to
// ground: one DOF, omega^2 = k / m = 400 rad^2/s^2
TEST(NastranMasses, GroundedCmass2WithCelas2) {
  const std::string path = testing::WriteScratch("cmass2_grounded.bdf",
                                                 "GRID,1,,0.,0.,0.\n"
                                                 "CELAS2,21,1000.,1,1\n"
                                                 "CMASS2,22,2.5,1,1\n");
  const fe::Mesh mesh = ReadNastran(path);
  ASSERT_EQ(mesh.point_masses.size(), 1u);
  EXPECT_EQ(mesh.point_masses[0].id, 22);
  EXPECT_EQ(mesh.point_masses[0].origin.line, 3);
  const CmassDense d = CmassAssemble(mesh);
  ASSERT_EQ(d.model.dofs.n_free, 1);
  EXPECT_DOUBLE_EQ(d.M(0, 0), 2.5);
  EXPECT_NEAR(d.K(0, 0) / d.M(0, 0), 400.0, 1e-12);
}

// CMASS1 with PMASS (the second of two properties on the card), grid 2 blank
// and grid 1 given in field G2: the same single DOF on a rotation (rz)
TEST(NastranMasses, Cmass1PmassOnARotation) {
  const std::string path = testing::WriteScratch("cmass1_pmass.bdf",
                                                 "GRID,1,,0.,0.,0.\n"
                                                 "PMASS,7,1.,8,.04\n"
                                                 "CELAS2,21,9.,1,6\n"
                                                 "CMASS1,22,8,,,1,6\n");
  const fe::Mesh mesh = ReadNastran(path);
  const CmassDense d = CmassAssemble(mesh);
  ASSERT_EQ(d.model.dofs.n_free, 1);
  ASSERT_GE(d.model.dofs.free[0][5], 0);
  EXPECT_DOUBLE_EQ(d.M(0, 0), 0.04);
  EXPECT_NEAR(d.K(0, 0) / d.M(0, 0), 9.0 / 0.04, 1e-10);
}

// on a grid with a displacement system turned 30 degrees about z: CELAS2 and
// CMASS2 on component 1 act along x' = (cos 30, sin 30, 0): K = k a a^T,
// M = m a a^T on (ux, uy), and the mode along a has omega^2 = k / m
TEST(NastranMasses, CmassAlongADisplacementSystemAxis) {
  const std::string path = testing::WriteScratch("cmass_cd.bdf", CmassTurnedSystem(30.0) +
                                                                     "GRID,1,,0.,0.,0.,5\n"
                                                                     "CELAS2,21,1000.,1,1\n"
                                                                     "CMASS2,22,4.,1,1\n");
  const fe::Mesh mesh = ReadNastran(path);
  const CmassDense d = CmassAssemble(mesh);
  ASSERT_EQ(d.model.dofs.n_free, 2);
  const int x = d.model.dofs.free[0][0], y = d.model.dofs.free[0][1];
  ASSERT_GE(x, 0);
  ASSERT_GE(y, 0);
  const Eigen::Vector2d a(std::cos(M_PI / 6.0), std::sin(M_PI / 6.0));
  Eigen::Vector2d ap;
  ap(x) = a(0);
  ap(y) = a(1);
  EXPECT_LT((d.M - 4.0 * ap * ap.transpose()).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(ap.dot(d.K * ap) / ap.dot(d.M * ap), 250.0, 1e-10);
}

// between components 1 and 2 of one grid: M = m [1 -1; -1 1] on (ux, uy)
TEST(NastranMasses, Cmass2BetweenTwoComponentsOfOneGrid) {
  const std::string path = testing::WriteScratch("cmass_two_components.bdf",
                                                 "GRID,1,,0.,0.,0.\n"
                                                 "CMASS2,22,3.,1,1,1,2\n");
  const CmassDense d = CmassAssemble(ReadNastran(path));
  ASSERT_EQ(d.model.dofs.n_free, 2);
  const int x = d.model.dofs.free[0][0], y = d.model.dofs.free[0][1];
  EXPECT_DOUBLE_EQ(d.M(x, x), 3.0);
  EXPECT_DOUBLE_EQ(d.M(y, y), 3.0);
  EXPECT_DOUBLE_EQ(d.M(x, y), -3.0);
}

// three CMASS2 of m = 4 kg on the three translations of a grid in a turned
// CD system: the total mass is 4 kg, as for a CONM2 of 4 kg (the trace of
// the translational block is invariant under the rotation)
TEST(NastranMasses, TotalMassOfThreeScalarMasses) {
  const std::string path = testing::WriteScratch("cmass_total.bdf", CmassTurnedSystem(40.0) +
                                                                        "GRID,1,,1.,2.,3.,5\n"
                                                                        "PMASS,7,4.\n"
                                                                        "CMASS2,21,4.,1,1\n"
                                                                        "CMASS1,22,7,1,2\n"
                                                                        "CMASS2,23,4.,1,3\n");
  const fe::Mesh mesh = ReadNastran(path);
  fe::AssemblyOptions options;
  options.apply_constraints = false;
  const fe::MassProperties p = fe::ComputeMassProperties(mesh, fe::Assemble(mesh, options));
  EXPECT_NEAR(p.mass, 4.0, 1e-13);
  EXPECT_LT((p.center - fe::Vec3(1.0, 2.0, 3.0)).norm(), 1e-12);
}

struct CmassBadCase {
  const char* name;
  const char* deck;
  std::vector<std::string> parts;
};

TEST(NastranMasses, BadCardsAreErrorsNamingTheCard) {
  const CmassBadCase cases[] = {
      {"negative_M", "GRID,1,,0.,0.,0.\nCMASS2,22,-1.,1,1\n", {":2", "CMASS2", "must not be negative"}},
      {"negative_PMASS", "GRID,1,,0.,0.,0.\nPMASS,7,-2.\nCMASS1,22,7,1,1\n", {":2", "PMASS", "must not be negative"}},
      {"missing_PMASS", "GRID,1,,0.,0.,0.\nCMASS1,22,7,1,1\n", {":2", "CMASS1", "7"}},
      {"component_7", "GRID,1,,0.,0.,0.\nCMASS2,22,1.,1,7\n", {":2", "CMASS2", "C1", "not a single digit"}},
      {"nothing", "GRID,1,,0.,0.,0.\nCMASS2,22,1.\n", {":2", "CMASS2", "connects nothing"}},
      {"itself", "GRID,1,,0.,0.,0.\nCMASS2,22,1.,1,2,1,2\n", {":2", "CMASS2", "to itself"}},
      {"two_grids", "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nCMASS2,22,1.,1,1,2,1\n",
       {":3", "CMASS2", "two different grids (1 and 2)", "not supported"}},
      {"CMASS3", "GRID,1,,0.,0.,0.\nCMASS3,22,7,1,2\n", {"CMASS3"}},
  };
  for (const CmassBadCase& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = testing::WriteScratch(std::string("cmass_bad_") + c.name + ".bdf", c.deck);
    const std::string message = testing::InputErrorOf([&] { ReadNastran(path); });
    ASSERT_FALSE(message.empty());
    testing::ExpectContains(message, c.parts, c.name);
  }
}

}  // namespace nastran_masses_test
}  // namespace flexmb::io
