// End-to-end test of "flexmb reduce" and "flexmb body info" (the FLEXMB_CLI
// binary) on the free steel strip tests/data/fe/nastran/cli_strip.bdf
// (1 m x 50 mm x 5 mm, 20 x 2 CQUAD4, nu = 0). References:
// - the full FE model's own frequencies ("fe modes"): the Craig-Bampton
//   frequencies are Rayleigh-Ritz upper bounds of them; more normal modes
//   give nested bases, so the frequencies decrease from Guyan (--modes 0)
//   towards the full model's, which 200 normal modes reach to 1e-7;
// - the fixed-interface modes are the modes of the model with the interface
//   clamped ("fe modes --fix"), so --cutoff keeps exactly those below it;
// - mass, centre of mass and inertia from the body file's invariants equal
//   the hand values of the plate (as in fe_cli_test.cc);
// - damping from --rayleigh / --damping-ratio follows its definition on the
//   written frequencies;
// and the exit codes and messages of bad input (docs/cli.md).

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "flexmb/body_file/body_file.h"
#include "cli_strip.h"
#include "json_reader.h"

namespace reduce_cli_test {

namespace fs = std::filesystem;
using flexmb::testing::CliResult;
using flexmb::testing::Json;
using flexmb::testing::ParseJsonObject;
using flexmb::testing::RunCli;

constexpr double kPi = 3.14159265358979323846;
using flexmb::testing::kHinge;
using flexmb::testing::kStrip;
// both ends of the strip (x = 0 and x = 1 m)
const std::string kEnds = "1,22,43,21,42,63";

class ReduceCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("flexmb_reduce_cli_test_" + std::to_string(getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // a command with --json that must succeed, parsed
  Json Run(const std::string& args) {
    const CliResult r = RunCli(dir_, args + " --json");
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    EXPECT_EQ(r.err, "") << args;
    Json j;
    EXPECT_TRUE(ParseJsonObject(r.out, j)) << args;
    return j;
  }
  // "reduce" of the strip with these options, written to `body`
  Json Reduce(const std::string& options, const std::string& body = "body.h5") {
    return Run("reduce '" + kStrip + "' " + options + " -o " + body);
  }
  // a command that must fail with `code`, naming every one of `parts` on stderr
  void ExpectFailure(const std::string& args, int code, const std::vector<std::string>& parts) {
    const CliResult r = RunCli(dir_, args);
    EXPECT_EQ(r.code, code) << args << "\n" << r.err;
    EXPECT_EQ(r.out, "") << args;
    for (const std::string& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << args << "\n" << r.err;
  }

  fs::path dir_;
};

TEST_F(ReduceCli, FreeStripFrequenciesCountsAndTimings) {
  const Json j = Reduce("--interface " + kEnds + " --modes 10");
  EXPECT_EQ(j["file"].string, kStrip);
  EXPECT_EQ(j["output"].string, "body.h5");
  EXPECT_EQ(j["nodes"].number, 63.0);
  EXPECT_EQ(j["elements"].number, 40.0);
  EXPECT_EQ(j["interface_nodes"].number, 6.0);
  EXPECT_EQ(j["fixed_nodes"].number, 0.0);
  EXPECT_EQ(j["static_modes"].number, 36.0);
  EXPECT_EQ(j["normal_modes"].number, 10.0);
  EXPECT_EQ(j["rigid_modes_removed"].number, 6.0);
  EXPECT_EQ(j["flexible_modes"].number, 40.0);
  const std::vector<double> f = j["frequencies_hz"].Numbers();
  ASSERT_EQ(f.size(), 40u);
  EXPECT_GT(f[0], 1.0);
  for (size_t k = 1; k < f.size(); ++k) EXPECT_GE(f[k], f[k - 1]) << k;
  EXPECT_TRUE(fs::exists(dir_ / "body.h5"));
  EXPECT_FALSE(fs::exists(dir_ / "body.h5.tmp"));

  const Json& t = j["timings_s"];
  double steps = 0.0;
  for (const char* key : {"read", "assemble", "factorize", "static_modes", "normal_modes", "orthonormalize",
                          "invariants", "stress_modes", "write", "total"}) {
    ASSERT_TRUE(t.Has(key)) << key;
    EXPECT_GE(t[key].number, 0.0) << key;
  }
  for (const char* key : {"read", "assemble", "factorize", "orthonormalize", "invariants", "stress_modes", "write"}) {
    steps += t[key].number;
  }
  // steps that run one after the other: their sum is within the total (printed to 6 digits)
  EXPECT_LE(steps, t["total"].number * (1 + 1e-5) + 1e-5);

  // the full model: six rigid modes, then the flexible ones, which bound the
  // reduced frequencies from below (Rayleigh-Ritz)
  const std::vector<double> full = Run("fe modes '" + kStrip + "' --count 14")["frequencies_hz"].Numbers();
  ASSERT_EQ(full.size(), 14u);
  for (int k = 0; k < 8; ++k) EXPECT_GE(f[k], full[6 + k] * (1 - 1e-9)) << "mode " << k + 1;

  // more normal modes: nested bases, so every frequency decreases towards
  // the full model's (Guyan, K = 0, is the upper bound of them all); with
  // 200 of the 360 fixed-interface modes the lowest eight are converged
  std::vector<double> previous =
      Reduce("--interface " + kEnds + " --modes 0", "guyan.h5")["frequencies_hz"].Numbers();
  ASSERT_EQ(previous.size(), 30u);
  EXPECT_GT(previous[0], f[0] * (1 + 1e-6));
  for (int modes : {10, 40, 200}) {
    const std::vector<double> g =
        Reduce("--interface " + kEnds + " --modes " + std::to_string(modes), "k.h5")["frequencies_hz"].Numbers();
    ASSERT_EQ(g.size(), static_cast<size_t>(30 + modes));
    for (int k = 0; k < 8; ++k) {
      EXPECT_LE(g[k], previous[k] * (1 + 1e-9)) << modes << " modes, mode " << k + 1;
      EXPECT_GE(g[k], full[6 + k] * (1 - 1e-9)) << modes << " modes, mode " << k + 1;
      if (modes == 200) EXPECT_NEAR(g[k], full[6 + k], 1e-7 * full[6 + k]) << "mode " << k + 1;
    }
    previous = g;
  }
}

TEST_F(ReduceCli, BodyInfoGivesBackFrequenciesMassAndProvenance) {
  const Json r = Reduce("--interface " + kEnds + " --modes 4 --keep 6");
  EXPECT_EQ(r["flexible_modes"].number, 6.0);
  const Json j = Run("body info body.h5");
  EXPECT_EQ(j["file"].string, "body.h5");
  EXPECT_EQ(j["format_version"].number, 1.0);
  EXPECT_EQ(j["nodes"].number, 63.0);
  EXPECT_EQ(j["elements"].number, 40.0);
  EXPECT_EQ(j["interface_nodes"].Numbers(), (std::vector<double>{1, 22, 43, 21, 42, 63}));
  EXPECT_EQ(j["static_modes"].number, 36.0);
  EXPECT_EQ(j["normal_modes"].number, 4.0);
  EXPECT_EQ(j["rigid_modes_removed"].number, 6.0);
  EXPECT_EQ(j["flexible_modes"].number, 6.0);
  // 17 significant digits: the same doubles
  EXPECT_EQ(j["frequencies_hz"].Numbers(), r["frequencies_hz"].Numbers());

  // mass properties of the strip, in the body file's report and the mesh's
  flexmb::testing::ExpectStripMassProperties(j);
  flexmb::testing::ExpectStripMassProperties(r);

  EXPECT_EQ(j["stress"]["shell"]["elements"].number, 40.0);
  EXPECT_EQ(j["stress"]["beam"]["elements"].number, 0.0);
  const std::string source = j["provenance"]["source"].string;
  EXPECT_NE(source.find("cli_strip.bdf"), std::string::npos) << source;
  EXPECT_EQ(j["provenance"]["keep"].string, "6");

  const CliResult text = RunCli(dir_, "body info body.h5");
  ASSERT_EQ(text.code, 0) << text.err;
  for (const char* part : {"nodes: 63, elements: 40", "interface nodes: 6 (ids 1,22,43,21,42,63)",
                           "modes: 6 flexible (basis 36 static + 4 normal, 6 rigid-body modes removed)",
                           "mass: 1.9625 kg", "centre of mass: (0.5, 0.025, 0) m", "mode  frequency [Hz]\n   1  ",
                           "provenance:\n  source: "}) {
    EXPECT_NE(text.out.find(part), std::string::npos) << part << "\n" << text.out;
  }
}

TEST_F(ReduceCli, KeepCutoffSetsAndFix) {
  const std::vector<double> all = Reduce("--interface " + kEnds + " --modes 10")["frequencies_hz"].Numbers();
  const Json kept = Reduce("--interface " + kEnds + " --modes 10 --keep 5", "kept.h5");
  const std::vector<double> f = kept["frequencies_hz"].Numbers();
  ASSERT_EQ(f.size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(f[k], all[k], 1e-12 * all[k]) << k;

  // the fixed-interface modes are those of the strip clamped at both ends
  const std::vector<double> fixed =
      Run("fe modes '" + kStrip + "' --fix " + kEnds + " --count 30")["frequencies_hz"].Numbers();
  ASSERT_EQ(fixed.size(), 30u);
  const double cutoff = std::sqrt(fixed[11] * fixed[12]);  // between the 12th and 13th
  ASSERT_GT(fixed[12], fixed[11] * (1 + 1e-3));
  const Json c = Reduce("--interface " + kEnds + " --cutoff " + std::to_string(cutoff), "cutoff.h5");
  EXPECT_EQ(c["normal_modes"].number, 12.0);
  EXPECT_EQ(c["flexible_modes"].number, 36.0 + 12.0 - 6.0);

  // a node set as interface: the edge x = 0
  const Json s = Reduce("--interface SET1_1 --modes 3", "set.h5");
  EXPECT_EQ(s["interface_nodes"].number, 3.0);
  EXPECT_EQ(s["static_modes"].number, 18.0);

  // clamped at x = 0, interface at the tip: no rigid-body modes, and the
  // cantilever frequencies of the full model bound the reduced ones from below
  const Json cl = Reduce("--interface 21,42,63 --fix SET1_1 --modes 6", "clamped.h5");
  EXPECT_EQ(cl["fixed_nodes"].number, 3.0);
  EXPECT_EQ(cl["rigid_modes_removed"].number, 0.0);
  EXPECT_EQ(cl["flexible_modes"].number, 24.0);
  const std::vector<double> fc = cl["frequencies_hz"].Numbers();
  const std::vector<double> cantilever =
      Run("fe modes '" + kStrip + "' --fix SET1_1 --count 4")["frequencies_hz"].Numbers();
  ASSERT_EQ(cantilever.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_GE(fc[k], cantilever[k] * (1 - 1e-9)) << k;
  const std::vector<double> converged =
      Reduce("--interface 21,42,63 --fix SET1_1 --modes 200", "clamped200.h5")["frequencies_hz"].Numbers();
  for (int k = 0; k < 4; ++k) {
    EXPECT_LE(converged[k], fc[k] * (1 + 1e-9)) << k;
    EXPECT_NEAR(converged[k], cantilever[k], 1e-7 * cantilever[k]) << k;
  }
}

TEST_F(ReduceCli, DampingIsWrittenAsDefined) {
  Reduce("--interface " + kEnds + " --modes 4 --rayleigh 0.5,1e-4", "rayleigh.h5");
  const flexmb::reduction::ReducedBody r = flexmb::io::ReadBody((dir_ / "rayleigh.h5").string());
  const int n = static_cast<int>(r.frequencies_hz.size());
  ASSERT_EQ(n, 34);
  for (int i = 0; i < n; ++i) {
    const double w2 = std::pow(2 * kPi * r.frequencies_hz[i], 2);
    for (int k = 0; k < n; ++k) {
      const double want = i == k ? 0.5 + 1e-4 * w2 : 0.0;
      EXPECT_NEAR(r.damping(i, k), want, 1e-12 * (0.5 + 1e-4 * w2)) << i << "," << k;
    }
  }
  Reduce("--interface " + kEnds + " --modes 4 --damping-ratio 0.02,0.05", "ratios.h5");
  const flexmb::reduction::ReducedBody z = flexmb::io::ReadBody((dir_ / "ratios.h5").string());
  ASSERT_EQ(z.frequencies_hz.size(), n);
  for (int i = 0; i < n; ++i) {
    const double w = 2 * kPi * z.frequencies_hz[i];
    const double want = 2.0 * (i == 0 ? 0.02 : 0.05) * w;
    EXPECT_NEAR(z.damping(i, i), want, 1e-12 * want) << i;
  }
  EXPECT_EQ((z.damping - Eigen::MatrixXd(z.damping.diagonal().asDiagonal())).norm(), 0.0);
}

TEST_F(ReduceCli, TextReport) {
  const CliResult r = RunCli(dir_, "reduce '" + kStrip + "' --interface SET1_1 --modes 2 -o text.h5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  for (const char* part : {"cli_strip.bdf: 63 nodes, 40 elements; 3 interface nodes\n",
                           "Craig-Bampton basis: 18 static + 2 normal modes; 6 rigid-body modes removed; 14 flexible "
                           "modes kept\n",
                           "mass 1.9625 kg, centre of mass (0.5, 0.025, 0) m\n", "mode  frequency [Hz]\n   1  ",
                           "\n  14  ", "wrote text.h5\n", "read ", " s, total "}) {
    EXPECT_NE(r.out.find(part), std::string::npos) << part << "\n" << r.out;
  }
}

// The seed's path through the exchange set: the FE side writes M, K,
// geometry and the Craig-Bampton modes ("fe export --interface"), the body is
// built from those files ("reduce DIR --modes-file"). The modes file holds the
// basis bit for bit and the matrices are the same, so the body equals the one
// reduced from the mesh directly, up to the round-off of the reduced
// stiffness (formed from the static solve there, by the product H^T K H here).
TEST_F(ReduceCli, BodyFromExportedModesEqualsDirectReduction) {
  const CliResult ex = RunCli(dir_, "fe export '" + kStrip + "' --hb ex --interface " + kEnds + " --modes 6");
  ASSERT_EQ(ex.code, 0) << ex.err;
  EXPECT_NE(ex.out.find("modes.mtx: 36 static and 6 fixed-interface normal modes"), std::string::npos) << ex.out;
  const Json direct = Reduce("--interface " + kEnds + " --modes 6", "direct.h5");
  const Json imported = Run("reduce ex --modes-file ex/modes.mtx -o imported.h5");
  EXPECT_EQ(imported["static_modes"].number, 36);
  EXPECT_EQ(imported["normal_modes"].number, 6);
  const std::vector<double> fd = direct["frequencies_hz"].Numbers(), fi = imported["frequencies_hz"].Numbers();
  ASSERT_EQ(fd.size(), fi.size());
  for (size_t k = 0; k < fd.size(); ++k) EXPECT_NEAR(fi[k], fd[k], 1e-9 * fd[k]) << k;
  EXPECT_NEAR(imported["mass_kg"].number, direct["mass_kg"].number, 1e-12 * direct["mass_kg"].number);
  const flexmb::reduction::ReducedBody b = flexmb::io::ReadBody((dir_ / "imported.h5").string());
  EXPECT_EQ(b.interface_nodes.size(), 6u);

  // the file brings the interface: no --interface with it; a modes file of
  // another model is refused naming the file
  ExpectFailure("reduce ex --modes-file ex/modes.mtx --interface 1 -o b.h5", 2, {"--modes-file", "--interface"});
  ExpectFailure("reduce '" + kHinge + "' --modes-file ex/modes.mtx -o b.h5", 2, {"modes.mtx"});
  EXPECT_FALSE(fs::exists(dir_ / "b.h5"));
  // an FE model file that adds a node and a link to the exported matrices
  // renumbers their rows: the modes file no longer fits them
  std::ofstream(dir_ / "ex" / "links.yaml")
      << "matrices: {stiffness: K_CCS.hb, mass: M_CCS.hb, dof_map: dof_map.txt, geometry: geometry.vtk}\n"
         "nodes: [{id: 900001, x: [-0.1, 0.025, 0]}]\n"
         "rigid_links: [{independent: 900001, dependent: [2]}]\n";
  ExpectFailure("reduce ex/links.yaml --modes-file ex/modes.mtx -o b.h5", 2, {"modes.mtx", "renumbers"});
  // the acceleration modes need the model's factor
  ExpectFailure("reduce ex --modes-file ex/modes.mtx --acceleration-modes -o b.h5", 2,
                {"--acceleration-modes", "--modes-file"});
}

// --acceleration-modes: six more basis vectors, counted in the report, the
// JSON and the provenance
TEST_F(ReduceCli, AccelerationModes) {
  const Json plain = Reduce("--interface " + kEnds + " --modes 4", "plain.h5");
  const Json acc = Reduce("--interface " + kEnds + " --modes 4 --acceleration-modes", "acc.h5");
  EXPECT_EQ(acc["normal_modes"].number, 4);
  EXPECT_EQ(acc["frequencies_hz"].Numbers().size(), plain["frequencies_hz"].Numbers().size() + 6);
  EXPECT_EQ(acc["acceleration_modes"].number, 6);
  EXPECT_EQ(plain["acceleration_modes"].number, 0);
  const flexmb::reduction::ReducedBody b = flexmb::io::ReadBody((dir_ / "acc.h5").string());
  bool found = false;
  for (const auto& [key, value] : b.provenance)
    if (key == "acceleration_modes") found = value == "6";
  EXPECT_TRUE(found);
  const CliResult text = RunCli(dir_, "reduce '" + kStrip + "' --interface " + kEnds + " --modes 4 --acceleration-modes -o t.h5");
  EXPECT_NE(text.out.find("static + 4 normal + 6 acceleration modes"), std::string::npos) << text.out;
}

TEST_F(ReduceCli, FrameOption) {
  // the mean axes by default, by name, and by the names of the frames that
  // coincide with them to first order (Tisserand, Buckens): the same body
  const Json plain = Reduce("--interface " + kEnds + " --modes 4");
  EXPECT_NE(plain["frame"].string.find("mean axes"), std::string::npos) << plain["frame"].string;
  const std::vector<double> f = plain["frequencies_hz"].Numbers();
  for (const char* name : {"mean", "tisserand", "buckens"}) {
    const Json j = Reduce("--interface " + kEnds + " --modes 4 --frame " + name, std::string(name) + ".h5");
    EXPECT_EQ(j["frame"].string, plain["frame"].string) << name;
    EXPECT_EQ(j["frequencies_hz"].Numbers(), f) << name;
  }
  // attached to node 1: as --fix 1 with node 1 in the interface
  const Json fixed = Reduce("--interface " + kEnds + " --fix 1 --modes 4", "fix1.h5");
  const Json node = Reduce("--interface " + kEnds + " --frame node:1 --modes 4", "node1.h5");
  EXPECT_EQ(node["frame"].string, "attached to the clamped nodes 1");
  EXPECT_EQ(node["frame"].string, fixed["frame"].string);
  EXPECT_EQ(node["rigid_modes_removed"].number, 0.0);
  EXPECT_EQ(node["interface_nodes"].number, fixed["interface_nodes"].number);
  EXPECT_EQ(node["frequencies_hz"].Numbers(), fixed["frequencies_hz"].Numbers());
  // the frame is in the body file's provenance
  const CliResult info = RunCli(dir_, "body info node1.h5");
  EXPECT_NE(info.out.find("frame: attached to the clamped nodes 1"), std::string::npos) << info.out;

  const std::string strip = "reduce '" + kStrip + "' --interface " + kEnds + " --modes 2 -o b.h5 ";
  ExpectFailure(strip + "--frame mean --fix 1", 2, {"--frame mean asks for the mean axes", "--fix"});
  ExpectFailure(strip + "--frame nodes:1", 2, {"--frame expects mean, tisserand, buckens or node:ID", "nodes:1"});
  ExpectFailure(strip + "--frame node:", 2, {"--frame expects"});
  ExpectFailure(strip + "--frame node:999", 2, {"cli_strip.bdf", "999"});
  ExpectFailure(strip + "--frame node:SET1_1", 2, {"--frame node:ID takes one node", "3 nodes"});
}

TEST_F(ReduceCli, BadInput) {
  const std::string strip = "reduce '" + kStrip + "' ";
  ExpectFailure("reduce nope.bdf --interface 1 --modes 2 -o b.h5 --json", 2, {"error: nope.bdf"});
  ExpectFailure(strip + "--interface 1,999 --modes 2 -o b.h5 --json", 2, {"error: ", "cli_strip.bdf", "999"});
  ExpectFailure(strip + "--interface NOSET --modes 2 -o b.h5", 2, {"cli_strip.bdf", "NOSET"});
  ExpectFailure(strip + "--interface 1 -o b.h5 --json", 2, {"--modes K", "--cutoff HZ"});
  ExpectFailure(strip + "--interface 1 --modes 2 --rayleigh 1,2 --damping-ratio 0.1 -o b.h5", 2, {"excludes"});
  ExpectFailure(strip + "--interface 1 --modes 2 --rayleigh 1 -o b.h5", 2, {"--rayleigh expects ALPHA,BETA"});
  ExpectFailure(strip + "--interface 1 --modes 2 --damping-ratio 0.1,x -o b.h5", 2, {"--damping-ratio", "0.1,x"});
  ExpectFailure(strip + "--interface 1 --modes 2 --keep 100 -o b.h5 --json", 2,
                {"cli_strip.bdf", "keep = 100 flexible modes asked"});
  ExpectFailure(strip + "--interface 1 --modes 2 --cutoff=-3 -o b.h5", 2, {"--cutoff"});
  ExpectFailure(strip + "--interface 1 --modes 2 -o no/such/dir/b.h5 --json", 2, {"no/such/dir/b.h5.tmp"});
  EXPECT_FALSE(fs::exists(dir_ / "b.h5"));
  // a mechanism inside the body: the massless bar hinged to the tip turns
  // freely when the interface (node 2) is held
  ExpectFailure("reduce '" + kHinge + "' --interface 2 --modes 1 -o hinge.h5 --json", 1, {"error: ", "cli_hinge.bdf"});
  EXPECT_FALSE(fs::exists(dir_ / "hinge.h5"));

  // a deck written for statics: its material has no density
  {
    std::string deck = flexmb::testing::ReadFile(kStrip);
    const std::string mat = "MAT1,1,2.1+11,,0.,7850.";
    ASSERT_NE(deck.find(mat), std::string::npos);
    deck.replace(deck.find(mat), mat.size(), "MAT1,1,2.1+11,,0.");
    flexmb::testing::WriteFile(dir_ / "massless.bdf", deck);
    const CliResult r = RunCli(dir_, "reduce massless.bdf --interface " + kEnds + " --modes 2 -o m.h5");
    EXPECT_NE(r.code, 0);
    for (const char* part : {"massless.bdf", "no mass", "density", "--modes 0"})
      EXPECT_NE(r.err.find(part), std::string::npos) << part << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "m.h5"));
  }

  ExpectFailure("body info missing.h5 --json", 2, {"error: missing.h5: body file: does not exist"});
  flexmb::testing::WriteFile(dir_ / "text.h5", "not a body\n");
  ExpectFailure("body info text.h5", 2, {"error: text.h5: body file: not an HDF5 file"});
  ExpectFailure("body info", 2, {"file"});
}

}  // namespace reduce_cli_test
