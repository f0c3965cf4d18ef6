// The model checks after reading (flexmb/fe/mesh_checks.h) against the
// free-free modes they predict: two CBAR beams that nothing joins are two
// parts, and `flexmb fe modes` finds 12 zero frequencies (6 per free part)
// before the first elastic one; joined by an RBE2 they are one part with
// 6; with one beam clamped by an SPC1 the other alone moves freely: 6.
// Unused nodes (a GRID no element uses) are reported by id. References:
// docs/validation.md, "FE model checks".
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "cli_runner.h"
#include "json_reader.h"

namespace fe_mesh_checks_test {

using flexmb::testing::Json;
using flexmb::testing::ParseJsonObject;
using flexmb::testing::RunCli;

class FeMeshChecks : public flexmb::testing::CliTest {
 protected:
  FeMeshChecks() : CliTest("flexmb_fe_mesh_checks_test_") {}
  void Deck(const std::string& extra) {
    std::ofstream(dir_ / "two.bdf") << "BEGIN BULK\nMAT1,1,2.1+11,,0.3,7850.\nPBAR,1,1,1.-3,8.-7,2.-7,5.-7\n"
                                       "GRID,1,,0.,0.,0.\nGRID,2,,0.5,0.,0.\nGRID,3,,1.0,0.,0.\n"
                                       "GRID,11,,0.,1.,0.\nGRID,12,,0.5,1.,0.\nGRID,13,,1.0,1.,0.\n"
                                       "CBAR,1,1,1,2,0.,0.,1.\nCBAR,2,1,2,3,0.,0.,1.\n"
                                       "CBAR,11,1,11,12,0.,0.,1.\nCBAR,12,1,12,13,0.,0.,1.\n"
                                    << extra << "ENDDATA\n";
  }
  // zero frequencies (below 1e-3 Hz) among the 14 lowest, and stderr
  int ZeroModes(std::string& err) {
    const auto r = RunCli(dir_, "fe modes two.bdf --count 14 --json");
    EXPECT_EQ(r.code, 0) << r.err;
    err = r.err;
    Json j;
    EXPECT_TRUE(ParseJsonObject(r.out, j)) << r.out;
    int zeros = 0;
    for (double f : j["frequencies_hz"].Numbers()) zeros += std::abs(f) < 1e-3;
    EXPECT_GT(j["frequencies_hz"].Numbers().at(12), 100.0);  // the first elastic mode is far above
    return zeros;
  }
};

TEST_F(FeMeshChecks, DisconnectedPartsAddTheRigidBodyModesTheWarningCounts) {
  std::string err;
  Deck("");
  EXPECT_EQ(ZeroModes(err), 12);
  EXPECT_NE(err.find("falls into 2 parts"), std::string::npos) << err;
  EXPECT_NE(err.find("from element 1 (two.bdf:10)"), std::string::npos) << err;
  EXPECT_NE(err.find("from element 11 (two.bdf:12)"), std::string::npos) << err;
  EXPECT_NE(err.find("up to 12 rigid-body"), std::string::npos) << err;

  Deck("RBE2,100,3,123456,11\n");
  EXPECT_EQ(ZeroModes(err), 6);
  EXPECT_EQ(err.find("parts that no element"), std::string::npos) << err;

  // part 1 held: the warning still names two parts, of which one is free
  Deck("SPC1,1,123456,1\n");
  const auto r = RunCli(dir_, "fe modes two.bdf --count 8 --json");
  EXPECT_EQ(r.code, 0) << r.err;
  Json j;
  ASSERT_TRUE(ParseJsonObject(r.out, j)) << r.out;
  int zeros = 0;
  for (double f : j["frequencies_hz"].Numbers()) zeros += std::abs(f) < 1e-3;
  EXPECT_EQ(zeros, 6);
  EXPECT_NE(r.err.find("supported"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("up to 6 rigid-body"), std::string::npos) << r.err;
}

TEST_F(FeMeshChecks, UnusedNodesAreNamed) {
  Deck("RBE2,100,3,123456,11\nGRID,50,,9.,9.,9.\nGRID,51,,9.,9.,8.\n");
  const auto r = RunCli(dir_, "fe info two.bdf --json");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("2 nodes are used by no element, spring, link, constraint or mass (ids 50 51)"),
            std::string::npos)
      << r.err;
  Json j;
  ASSERT_TRUE(ParseJsonObject(r.out, j)) << r.out;
  EXPECT_EQ(j["parts"].number, 1);
  EXPECT_EQ(j["unused_nodes"].number, 2);
}

}  // namespace fe_mesh_checks_test

namespace fe_mesh_checks_test {

// `fe export` of a model with a support: the exchange set holds the free DOF
// only. Massless bars (rho 0) with a 10 kg CONM2 on the clamped grid 1
// (x = 0) and 5 kg on grid 3 (x = 1 m): M_CCS.hb carries 5 of the 15 kg,
// and about the nodes' mean x0 = 0.5 m a rotational inertia trace of
// 2 x 5 x 0.25 = 2.5 of 2 x 15 x 0.25 = 7.5 kg m^2: 66.67 % of both missing.
TEST_F(FeMeshChecks, ExportSaysWhichMassTheExchangeSetLacks) {
  std::ofstream(dir_ / "spc.bdf") << "BEGIN BULK\nMAT1,1,2.1+11,,0.3,0.\nPBAR,1,1,1.-3,8.-7,2.-7,5.-7\n"
                                     "GRID,1,,0.,0.,0.\nGRID,2,,0.5,0.,0.\nGRID,3,,1.0,0.,0.\n"
                                     "CBAR,1,1,1,2,0.,0.,1.\nCBAR,2,1,2,3,0.,0.,1.\n"
                                     "CONM2,9,1,,10.0\nCONM2,10,3,,5.0\nSPC1,1,123456,1\nENDDATA\n";
  auto r = RunCli(dir_, "fe export spc.bdf --hb ex");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("M_CCS.hb: 5 kg of the model's 15 kg (66.6667 % missing; of the rotational inertia 66.6667 %)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("no stress modes"), std::string::npos) << r.err;
  // the same model without the support: nothing is missing, only the note on stresses
  std::string text = flexmb::testing::ReadFile(dir_ / "spc.bdf");
  text.erase(text.find("SPC1"), std::string("SPC1,1,123456,1\n").size());
  std::ofstream(dir_ / "free.bdf") << text;
  r = RunCli(dir_, "fe export free.bdf --hb ex2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("missing"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no stress modes"), std::string::npos) << r.err;
}

}  // namespace fe_mesh_checks_test
