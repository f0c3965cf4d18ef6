// Nastran MPC (flexmb/fe_io/nastran/nastran_constraints.cc) through `flexmb
// fe static`: rods (CROD, EA = 2e7 N) tied by MPCs, against the closed
// form of the constrained springs (the stationary point of the potential
// with the dependent DOF eliminated):
// - a lever, u4 = 2 u2 (rod 1-2 of stiffness k1 = EA / 1 m, rod 3-4 of
//   k2 = EA / 2 m, force F on grid 4): u2 = 2 F / (k1 + 4 k2), u4 = 2 u2;
// - the same with grid 2 in a displacement system rotated 90 degrees about
//   z (its component 2 is basic -x): u2 changes sign, u4 stays;
// - three terms over a continuation line, u4 = u2 + u6 (a third rod 5-6
//   of stiffness k1): u2 = u6 = F / (k1 + 2 k2), u4 = 2 u2;
// and bad MPCs named by file and line (docs/validation.md, "Nastran MPC").
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "json_reader.h"

namespace nastran_mpc_test {

using flexmb::testing::Json;
using flexmb::testing::ParseJsonObject;
using flexmb::testing::RunCli;

constexpr double kEA = 2.0e11 * 1.0e-4, kF = 1000.0;

class NastranMpc : public flexmb::testing::CliTest {
 protected:
  NastranMpc() : CliTest("flexmb_nastran_mpc_test_") {}
  // rods 1-2 (1 m) and 3-4 (2 m) along x, grids 1 and 3 clamped; `extra` cards
  void Deck(const std::string& extra, const std::string& grid2 = "GRID,2,,1.,0.,0.,,23456\n") {
    std::ofstream(dir_ / "mpc.bdf") << "BEGIN BULK\nMAT1,1,2.0+11,,0.3,7850.\nPROD,1,1,1.0-4\n"
                                       "CORD2R,5,,0.,0.,0.,0.,0.,1.,\n,0.,1.,0.\n"
                                       "GRID,1,,0.,0.,0.,,123456\n"
                                    << grid2
                                    << "GRID,3,,0.,1.,0.,,123456\nGRID,4,,2.,1.,0.,,23456\n"
                                       "CROD,1,1,1,2\nCROD,2,1,3,4\n"
                                    << extra << "ENDDATA\n";
  }
  // the x displacement of grids 2, 4 (and 6) under F along x at grid 4
  std::vector<double> Solve(int nodes) {
    const auto r = RunCli(dir_, "fe static mpc.bdf --force 4:1000,0,0 --json --nodes " +
                                    std::string(nodes == 3 ? "2,4,6" : "2,4"));
    EXPECT_EQ(r.code, 0) << r.err;
    Json j;
    EXPECT_TRUE(ParseJsonObject(r.out, j)) << r.out;
    std::vector<double> ux;
    for (const Json& n : j["nodes"].array) ux.push_back(n["displacement_m"].Numbers().at(0));
    return ux;
  }
};

TEST_F(NastranMpc, LeverAgainstTheConstrainedSprings) {
  const double k1 = kEA / 1.0, k2 = kEA / 2.0, u2 = 2 * kF / (k1 + 4 * k2);
  Deck("MPC,7,4,1,1.0,2,1,-2.0\n");
  std::vector<double> u = Solve(2);
  ASSERT_EQ(u.size(), 2u);
  EXPECT_NEAR(u[0], u2, 1e-12 * u2);
  EXPECT_NEAR(u[1], 2 * u2, 1e-12 * u2);

  // grid 2 in CD 5 (x_CD = basic y, y_CD = basic -x): component 2 is -x
  Deck("MPC,7,4,1,1.0,2,2,-2.0\n", "GRID,2,,1.,0.,0.,5,13456\n");
  u = Solve(2);
  ASSERT_EQ(u.size(), 2u);
  EXPECT_NEAR(u[0], -u2, 1e-12 * u2);
  EXPECT_NEAR(u[1], 2 * u2, 1e-12 * u2);
}

TEST_F(NastranMpc, ThreeTermsOverAContinuation) {
  const double k1 = kEA / 1.0, k2 = kEA / 2.0, u2 = kF / (k1 + 2 * k2);
  Deck("GRID,5,,0.,2.,0.,,123456\nGRID,6,,1.,2.,0.,,23456\nCROD,3,1,5,6\n"
       "MPC,7,4,1,1.0,2,1,-1.0\n,,6,1,-1.0\n");
  const std::vector<double> u = Solve(3);
  ASSERT_EQ(u.size(), 3u);
  EXPECT_NEAR(u[0], u2, 1e-12 * u2);
  EXPECT_NEAR(u[1], 2 * u2, 1e-12 * u2);
  EXPECT_NEAR(u[2], u2, 1e-12 * u2);
}

TEST_F(NastranMpc, BadMpcIsNamedByFileAndLine) {
  struct Case {
    std::string card, message;
  };
  const std::vector<Case> cases = {
      {"MPC,7,4,7,1.0,2,1,-2.0\n", "component C must be one of 1 to 6 (7"},
      {"MPC,7,4,1,0.0,2,1,-2.0\n", "A1, the coefficient of the dependent DOF, must not be 0"},
      {"MPC,7,4,1,1.0\n", "at least two terms"},
      {"MPC,7,4,1,1.0,4,1,-2.0\n", "the dependent DOF (G1, C1) appears again"},
      {"MPC,7,4,1,1.0,2,1,-2.0\n,3,6,1,-1.0\n", "field 2 of an MPC continuation must be blank"},
      {"MPC,7,2,1,1.0,4,1,-2.0\n", "has a displacement coordinate system (CD)"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.card);
    Deck(c.card, "GRID,2,,1.,0.,0.,5,13456\n");
    const auto r = RunCli(dir_, "fe info mpc.bdf");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("mpc.bdf:1"), std::string::npos) << r.err;  // the MPC's line (11 or 12)
    EXPECT_NE(r.err.find("MPC 7"), std::string::npos) << r.err;
  }
}

}  // namespace nastran_mpc_test
