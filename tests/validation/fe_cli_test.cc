// End-to-end test of "flexmb fe modes | info | export" (the FLEXMB_CLI
// binary) on the free steel strip tests/data/fe/nastran/cli_strip.bdf
// (1 m x 50 mm x 5 mm, 20 x 2 CQUAD4, nu = 0): the first bending frequency
// clamped at x = 0 against Euler-Bernoulli (cantilever, beta L = 1.8751;
// free-free, beta L = 4.7300), mass, centre of mass and inertia against the
// hand computation for a thin rectangular plate, --fix by ids and by set,
// the six rigid-body modes of the free strip, the exchange-set round trip
// (fe export, then fe modes on the directory), and the error messages of
// bad input (missing file, unknown set or node, a zero-mass mechanism).
// References: docs/validation.md, "FE: command line".

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "cli_strip.h"
#include "json_reader.h"

namespace fe_cli_test {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

const std::string kMass = FLEXMB_SOURCE_DIR "/tests/data/fe/nastran/mass.bdf";

using flexmb::testing::kHinge;
using flexmb::testing::kStrip;
constexpr double kE = flexmb::testing::kStripE, kRho = flexmb::testing::kStripRho, kL = flexmb::testing::kStripL,
                 kB = flexmb::testing::kStripB, kT = flexmb::testing::kStripT;

using flexmb::testing::CliResult;
using flexmb::testing::Json;
using flexmb::testing::ParseJsonObject;
using flexmb::testing::RunCli;

// Euler-Bernoulli bending frequency of the strip for the root beta L [Hz]
double EulerBernoulli(double beta_l) {
  const double I = kB * kT * kT * kT / 12.0, A = kB * kT;
  return beta_l * beta_l / (2.0 * kPi * kL * kL) * std::sqrt(kE * I / (kRho * A));
}

class FeCli : public flexmb::testing::CliTest {
 protected:
  FeCli() : CliTest("flexmb_fe_cli_test_") {}

  // "fe modes ARGS --json" that must succeed, parsed
  Json Modes(const std::string& args) {
    const CliResult r = RunCli(dir_, "fe modes " + args + " --json");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "") << "nothing on stderr for a clean model";
    Json j;
    EXPECT_TRUE(ParseJsonObject(r.out, j));
    return j;
  }
};

TEST_F(FeCli, CantileverStripFirstBendingAgainstEulerBernoulli) {
  const Json j = Modes("'" + kStrip + "' --fix SET1_1 --count 3");
  const std::vector<double> f = j["frequencies_hz"].Numbers();
  ASSERT_EQ(f.size(), 3u);
  const double f1 = EulerBernoulli(1.87510406871196);
  EXPECT_NEAR(f[0], f1, 0.01 * f1);
  EXPECT_LT(f[0], f[1]);
  EXPECT_EQ(j["dofs"].number, 6.0 * (63 - 3));  // three clamped nodes
  EXPECT_EQ(j["nodes"].number, 63.0);
  EXPECT_EQ(j["elements"].number, 40.0);
  EXPECT_EQ(j["fixed_nodes"].number, 3.0);
  EXPECT_EQ(j["mass_form"].string, "consistent");

  // mass properties of the whole (unconstrained) strip
  flexmb::testing::ExpectStripMassProperties(j);

  const Json& t = j["timings_s"];
  for (const char* key : {"read", "assemble", "solve"}) {
    ASSERT_TRUE(t.Has(key)) << key;
    EXPECT_GE(t[key].number, 0.0) << key;
  }

  // the same nodes by id give the same model and frequencies
  const std::vector<double> g = Modes("'" + kStrip + "' --fix 1,22,43 --count 3")["frequencies_hz"].Numbers();
  ASSERT_EQ(g.size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(g[k], f[k], 1e-9 * f[k]) << "mode " << k + 1;
}

TEST_F(FeCli, FreeStripListsSixRigidModesFirst) {
  const Json j = Modes("'" + kStrip + "' --count 8");
  const std::vector<double> f = j["frequencies_hz"].Numbers();
  ASSERT_EQ(f.size(), 8u);
  EXPECT_EQ(j["dofs"].number, 6.0 * 63);
  EXPECT_EQ(j["fixed_nodes"].number, 0.0);
  const double f7 = EulerBernoulli(4.73004074486270);  // free-free first bending
  for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(f[k]), 1e-3 * f7) << "rigid mode " << k + 1;
  EXPECT_NEAR(f[6], f7, 0.01 * f7);
}

TEST_F(FeCli, LumpedMassKeepsMassPropertiesAndFrequency) {
  const Json j = Modes("'" + kStrip + "' --fix SET1_1 --count 1 --lumped");
  const double m = kRho * kL * kB * kT, f1 = EulerBernoulli(1.87510406871196);
  EXPECT_EQ(j["mass_form"].string, "lumped");
  EXPECT_NEAR(j["mass_kg"].number, m, 1e-12 * m);
  EXPECT_NEAR(j["center_of_mass_m"].array[0].number, 0.5 * kL, 1e-12);
  ASSERT_EQ(j["frequencies_hz"].array.size(), 1u);
  EXPECT_NEAR(j["frequencies_hz"].array[0].number, f1, 0.01 * f1);
}

TEST_F(FeCli, ModesTable) {
  const CliResult r = RunCli(dir_, "fe modes '" + kStrip + "' --fix SET1_1 --count 2");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("cli_strip.bdf: 63 nodes, 40 elements, 360 free DOF (3 nodes fixed by --fix)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("mass 1.9625 kg, centre of mass (0.5, 0.025, 0) m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mode  frequency [Hz]\n   1  "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n   2  "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\n   3  "), std::string::npos) << r.out;
  // the first frequency as printed
  const size_t p = r.out.find("\n   1  ") + 7;
  const double f1 = EulerBernoulli(1.87510406871196);
  EXPECT_NEAR(std::stod(r.out.substr(p)), f1, 0.01 * f1) << r.out;
}

TEST_F(FeCli, InfoCountsMassAndBoundingBox) {
  CliResult r = RunCli(dir_, "fe info '" + kStrip + "' --json");
  ASSERT_EQ(r.code, 0) << r.err;
  Json j;
  ASSERT_TRUE(ParseJsonObject(r.out, j));
  EXPECT_EQ(j["nodes"].number, 63.0);
  ASSERT_TRUE(j["elements"].Has("4-node shell")) << r.out;
  EXPECT_EQ(j["elements"]["4-node shell"].number, 40.0);
  EXPECT_EQ(j["elements"].object.size(), 1u);
  EXPECT_EQ(j["materials"].number, 1.0);
  EXPECT_EQ(j["sections"]["shell"].number, 1.0);
  EXPECT_EQ(j["node_sets"]["SET1_1"].number, 3.0);
  EXPECT_EQ(j["constraints"].number, 0.0);
  EXPECT_EQ(j["rigid_links"].number, 0.0);
  EXPECT_FALSE(j.Has("matrices"));
  const std::vector<double> lo = j["bounding_box_m"]["min"].Numbers(), hi = j["bounding_box_m"]["max"].Numbers();
  ASSERT_EQ(lo.size(), 3u);
  ASSERT_EQ(hi.size(), 3u);
  EXPECT_EQ(lo, (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_EQ(hi, (std::vector<double>{kL, kB, 0.0}));
  const double m = kRho * kL * kB * kT;
  EXPECT_NEAR(j["mass_kg"].number, m, 1e-12 * m);
  EXPECT_NEAR(j["center_of_mass_m"].array[1].number, 0.5 * kB, 1e-12);

  r = RunCli(dir_, "fe info '" + kStrip + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* line : {"nodes: 63\n", "elements: 40\n  4-node shell: 40\n", "node sets: 1\n  SET1_1: 3 nodes\n",
                           "bounding box: (0, 0, 0) to (1, 0.05, 0) m\n", "mass: 1.9625 kg\n",
                           "centre of mass: (0.5, 0.025, 0) m\n"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << " in:\n" << r.out;
}

// a gmsh mesh before its FE model file assigns sections: counts, and the
// mass reported as not available with the reason, still exit code 0
TEST_F(FeCli, InfoOfAMeshWithoutSections) {
  const std::string msh = FLEXMB_SOURCE_DIR "/tests/data/fe/gmsh/strip_v41.msh";
  CliResult r = RunCli(dir_, "fe info '" + msh + "' --json");
  ASSERT_EQ(r.code, 0) << r.err;
  Json j;
  ASSERT_TRUE(ParseJsonObject(r.out, j));
  EXPECT_EQ(j["node_sets"]["clamp"].number, 3.0);
  EXPECT_EQ(j["element_sets"]["strip"].number, 80.0);
  EXPECT_EQ(j["mass_kg"].kind, Json::kNull);
  EXPECT_EQ(j["center_of_mass_m"].kind, Json::kNull);
  EXPECT_NE(j["mass_error"].string.find("strip_v41.msh:"), std::string::npos) << r.out;
  r = RunCli(dir_, "fe info '" + msh + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("  tip: 1 node\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mass: not available: "), std::string::npos) << r.out;
}

// mass.bdf: four CONM2 on nodes tied by one RBE2 (values as in
// nastran_reader_test.cc): total mass and centre of mass by hand
TEST_F(FeCli, InfoPointMassesOnRigidLink) {
  const CliResult r = RunCli(dir_, "fe info '" + kMass + "' --json");
  ASSERT_EQ(r.code, 0) << r.err;
  Json j;
  ASSERT_TRUE(ParseJsonObject(r.out, j));
  EXPECT_EQ(j["point_masses"].number, 4.0);
  EXPECT_EQ(j["rigid_links"].number, 1.0);
  EXPECT_EQ(j["elements"].object.size(), 0u);
  // CONM2 21: 2 kg at (0.1, 0, 0); 22: 1 kg at (1, 1, 0); 23: 3 kg at node 3
  // (0, 2, 0) offset 0.2 along system 1's x = basic Y; 24: 0.5 kg at (0, 0, 3)
  const double m = 2.0 + 1.0 + 3.0 + 0.5;
  const double cx = (2.0 * 0.1 + 1.0 * 1.0) / m, cy = (1.0 * 1.0 + 3.0 * 2.2) / m, cz = (0.5 * 3.0) / m;
  EXPECT_NEAR(j["mass_kg"].number, m, 1e-12);
  const std::vector<double> c = j["center_of_mass_m"].Numbers();
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(c[0], cx, 1e-12);
  EXPECT_NEAR(c[1], cy, 1e-12);
  EXPECT_NEAR(c[2], cz, 1e-12);
}

TEST_F(FeCli, ExportThenModesOfTheExchangeSetGiveTheSameFrequencies) {
  CliResult r = RunCli(dir_, "fe export '" + kStrip + "' --hb set --fix SET1_1");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"K_CCS.hb", "M_CCS.hb", "geometry.vtk", "dof_map.txt"}) {
    EXPECT_TRUE(fs::exists(dir_ / "set" / f)) << f;
    EXPECT_NE(r.out.find(f), std::string::npos) << r.out;
  }
  EXPECT_NE(r.out.find("360 x 360"), std::string::npos) << r.out;

  const std::vector<double> direct = Modes("'" + kStrip + "' --fix SET1_1 --count 5")["frequencies_hz"].Numbers();
  const Json j = Modes("set --count 5");
  const std::vector<double> imported = j["frequencies_hz"].Numbers();
  ASSERT_EQ(direct.size(), 5u);
  ASSERT_EQ(imported.size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(imported[k], direct[k], 1e-9 * direct[k]) << "mode " << k + 1;
  EXPECT_EQ(j["dofs"].number, 360.0);
  EXPECT_EQ(j["mass_form"].string, "imported");
  // the exchange set holds the free DOF only: the clamped nodes' mass is gone
  EXPECT_LT(j["mass_kg"].number, kRho * kL * kB * kT);

  r = RunCli(dir_, "fe info set --json");
  ASSERT_EQ(r.code, 0) << r.err;
  Json info;
  ASSERT_TRUE(ParseJsonObject(r.out, info));
  EXPECT_EQ(info["matrices"]["dofs"].number, 360.0);
  EXPECT_GT(info["matrices"]["k_nonzeros"].number, 360.0);

  // the imported mass matrix cannot be lumped
  r = RunCli(dir_, "fe modes set --lumped --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("set: --lumped needs a mesh with elements"), std::string::npos) << r.err;
}

// ---- bad input: exit code 2 (input) or 1 (numerical), message on stderr naming the file and entity,
// nothing on stdout even with --json ----

TEST_F(FeCli, MissingFile) {
  const CliResult r = RunCli(dir_, "fe modes nothere.bdf --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("error: nothere.bdf"), std::string::npos) << r.err;
  EXPECT_EQ(RunCli(dir_, "fe info nothere.bdf").code, 2);
  EXPECT_EQ(RunCli(dir_, "fe export nothere.bdf --hb out").code, 2);
}

TEST_F(FeCli, UnknownSetOrNode) {
  CliResult r = RunCli(dir_, "fe modes '" + kStrip + "' --fix clamp --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("cli_strip.bdf: node set 'clamp': there is no node set named 'clamp' (node sets: SET1_1)"),
            std::string::npos)
      << r.err;

  r = RunCli(dir_, "fe modes '" + kStrip + "' --fix 1,22,999 --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("cli_strip.bdf: node 999: does not exist"), std::string::npos) << r.err;

  r = RunCli(dir_, "fe export '" + kStrip + "' --hb out --fix 999");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("cli_strip.bdf: node 999"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(FeCli, BadOptions) {
  CliResult r = RunCli(dir_, "fe modes '" + kStrip + "' --count 0 --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("--count must be at least 1"), std::string::npos) << r.err;

  r = RunCli(dir_, "fe modes '" + kStrip + "' --shift 5");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--shift must be a negative number"), std::string::npos) << r.err;

  // more modes than DOF
  r = RunCli(dir_, "fe modes '" + kStrip + "' --fix SET1_1 --count 400 --json");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("cli_strip.bdf: modal analysis: 400 modes asked, but the model has only 360 free DOF"),
            std::string::npos)
      << r.err;

  // --hb is required; a file where the directory should be
  EXPECT_EQ(RunCli(dir_, "fe export '" + kStrip + "'").code, 2);
  std::ofstream(dir_ / "afile") << "x";
  r = RunCli(dir_, "fe export '" + kStrip + "' --hb afile");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("afile"), std::string::npos) << r.err;
}

// a massless bar hinged (RBE2 on translations) to a clamped steel bar: its
// swing and spin have neither stiffness nor mass, K - sigma M is singular
TEST_F(FeCli, ZeroMassMechanismIsANumericalError) {
  const CliResult r = RunCli(dir_, "fe modes '" + kHinge + "' --count 2 --json");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("error: " + kHinge + ": modal analysis: K - sigma M"), std::string::npos) << r.err;
  // the DOF at fault is one of the massless bar's nodes, named by id
  EXPECT_TRUE(r.err.find("(node 3, ") != std::string::npos || r.err.find("(node 4, ") != std::string::npos)
      << r.err;
}

}  // namespace fe_cli_test
