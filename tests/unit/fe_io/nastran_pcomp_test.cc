// Nastran laminated shells read into fe::ShellLaminate: PCOMP with LAM = SYM
// (the listed half mirrored), a blank MID or T repeating the ply before,
// PCOMPG, MAT1 and MAT8 plies, NSM, the element's THETA; each against the
// hand-computed laminate; and the errors that name the card and field
// (LAM options, a MAT2 ply, no plies, a missing MCID system).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "flexmb/fe/laminate.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

const std::string kQuad =
    "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n"
    "MAT8,10,138.e9,9.e9,0.3,7.1e9,5.e9,4.e9,1600.\nMAT1,20,2.1e11,,0.3,7850.\n";

TEST(NastranPcomp, SymmetricStackWithRepeatedPliesIsTheHandLaminate) {
  const fe::Mesh m = ReadNastran(testing::WriteScratch(
      "pcomp_sym.bdf", kQuad + "CQUAD4,1,1,1,2,3,4,30.\n"
                               "PCOMP,1,,0.5,,,,,SYM\n,10,0.001,45.,YES,,,-45.,NO\n,20,0.002,0.\n"));
  ASSERT_EQ(m.shell_sections.size(), 1u);
  const fe::ShellSection& s = m.shell_sections[0];
  ASSERT_TRUE(s.laminate);
  EXPECT_EQ(s.material, -1);
  EXPECT_NEAR(s.thickness, 0.008, 1e-15);
  EXPECT_EQ(s.nsm, 0.5);
  EXPECT_NEAR(m.elements[0].shell_theta, M_PI / 6, 1e-15);
  // by hand: 45, -45 (MAT8, 1 mm), steel 2 mm, mirrored; from z = -4 mm
  std::vector<fe::LaminatePly> plies;
  auto ply = [&](bool mat8, double t, double deg) {
    fe::LaminatePly p;
    p.q = mat8 ? fe::OrthotropicPlaneStress(138e9, 9e9, 0.3, 7.1e9) : fe::IsotropicPlaneStress(2.1e11, 0.3);
    p.g13 = mat8 ? 5e9 : 2.1e11 / 2.6;
    p.g23 = mat8 ? 4e9 : 2.1e11 / 2.6;
    p.rho = mat8 ? 1600 : 7850;
    p.t = t;
    p.theta = deg * M_PI / 180;
    plies.push_back(p);
  };
  ply(true, 0.001, 45);
  ply(true, 0.001, -45);
  ply(false, 0.002, 0);
  ply(false, 0.002, 0);
  ply(true, 0.001, -45);
  ply(true, 0.001, 45);
  const fe::ShellLaminate l = fe::StackPlies(plies, -0.004);
  EXPECT_LT((s.laminate->A - l.A).cwiseAbs().maxCoeff(), 1e-12 * l.A(0, 0));
  EXPECT_LT((s.laminate->D - l.D).cwiseAbs().maxCoeff(), 1e-12 * l.D(0, 0));
  EXPECT_LT((s.laminate->S - l.S).cwiseAbs().maxCoeff(), 1e-12 * l.S(0, 0));
  EXPECT_NEAR(s.laminate->mass, 2 * (2 * 1600 * 0.001 + 7850 * 0.002), 1e-12);
  EXPECT_EQ(s.laminate->card, "PCOMP 1");
}

TEST(NastranPcomp, PcompgIsReadPlyByPly) {
  const fe::Mesh m = ReadNastran(testing::WriteScratch(
      "pcompg.bdf", kQuad + "CTRIA3,1,7,1,2,3\nPCOMPG,7\n,101,10,0.001,0.\n,102,20,0.003,0.\n,103,10,0.001,0.\n"));
  const fe::ShellLaminate& l = *m.shell_sections[0].laminate;
  EXPECT_NEAR(l.thickness, 0.005, 1e-15);
  EXPECT_NEAR(l.mass, 2 * 1600 * 0.001 + 7850 * 0.003, 1e-12);
  EXPECT_EQ(l.card, "PCOMPG 7");
}

TEST(NastranPcomp, BadLaminatesNameCardAndField) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"CQUAD4,1,1,1,2,3,4\nPCOMP,1,,,,,,,MEM\n,10,0.001,0.\n", {"PCOMP 1", "LAM = MEM is not supported"}},
      {"CQUAD4,1,1,1,2,3,4\nPCOMP,1\n", {"PCOMP 1", "no plies"}},
      {"CQUAD4,1,1,1,2,3,4\nPCOMP,1\n,30,0.001,0.\n", {"PCOMP 1", "material 30 does not exist"}},
      {"CQUAD4,1,1,1,2,3,4\nPCOMP,1,,,,,,,SYM\n,10,-0.001,0.\n", {"PCOMP 1", "ply thickness T"}},
      {"CQUAD4,1,1,1,2,3,4\nPCOMP,1\n,30,0.001,0.\nMAT2,30,1.e9,,,1.e9,,1.e8\n", {"PCOMP 1", "MAT2", "ply"}},
      {"CQUAD4,1,1,1,2,3,4,5\nPCOMP,1,,,,,,,SYM\n,10,0.001,0.\n", {"CQUAD4 1", "coordinate system 5 does not exist"}},
  };
  int k = 0;
  for (const auto& [cards, parts] : cases) {
    const std::string path = testing::WriteScratch("pcomp_bad" + std::to_string(k++) + ".bdf", kQuad + cards);
    std::vector<std::string> with_file = parts;
    with_file.push_back(path + ":");
    testing::ExpectContains(testing::InputErrorOf([&] { ReadNastran(path); }), with_file, cards);
  }
}

}  // namespace
}  // namespace flexmb::io
