// End-to-end test of beam fibre stresses through the command line
// (docs/cli.md "post"): a steel cantilever of 10 CBARs (L = 1 m, section
// 20 mm along y by 40 mm along z, PBAR with its four corners as C, D, E, F)
// reduced with "flexmb reduce" (interface: the root and the tip), clamped at
// the root in a model file, a tip force Fz = 100 N raised smoothly over
// 0.5 s (16 periods of the first bending mode, 33 Hz) and held; "flexmb
// post" recovers the stresses at the fibres. Reference: Euler-Bernoulli
// bending, sigma = Fz L c / Iy = 18.75 MPa at the root's corners (c = 20
// mm, Iy = 0.02 * 0.04^3 / 12), compression on the top (+z) fibres and
// tension on the bottom ones; the Craig-Bampton basis holds the tip's
// static constraint mode, so the quasi-static response is exact up to the
// ramp's residual vibration (about 1e-4 relative; tolerance 0.5 %).
// docs/validation.md, "Beam fibre stresses".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace beam_fibre_post_cli_test {

namespace fs = std::filesystem;
using flexmb::testing::CliResult;
using flexmb::testing::ReadFile;
using flexmb::testing::RunCli;
using flexmb::testing::WriteFile;

// a CSV file's header names and rows (text fields)
struct FibreCsv {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> rows;
  int Column(const std::string& name) const {
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return static_cast<int>(i);
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};

FibreCsv ReadFibreCsv(const fs::path& p) {
  FibreCsv c;
  std::istringstream in(ReadFile(p));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
    if (c.names.empty()) c.names = f;
    else c.rows.push_back(f);
  }
  return c;
}

// the deck: nodes 1 .. 11 along x, elements 1 .. 10; element 10 has a
// section without stress points
std::string FibreDeck() {
  std::string d = "BEGIN BULK\nMAT1,1,2.1+11,,.3,7850.\n"
                  "PBAR,1,1,8.-4,2.66666667-8,1.06666667-7,3.-8\n"
                  ",.01,.02,-.01,.02,-.01,-.02,.01,-.02\n"
                  "PBAR,2,1,8.-4,2.66666667-8,1.06666667-7,3.-8\n";
  for (int i = 0; i <= 10; ++i) d += "GRID," + std::to_string(i + 1) + ",,"+ std::to_string(0.1 * i) + ",0.,0.\n";
  for (int i = 1; i <= 10; ++i)
    d += "CBAR," + std::to_string(i) + "," + (i < 10 ? "1" : "2") + "," + std::to_string(i) + "," +
         std::to_string(i + 1) + ",0.,1.,0.\n";
  return d + "ENDDATA\n";
}

class BeamFibrePostCli : public flexmb::testing::CliTest {
 protected:
  BeamFibrePostCli() : CliTest("flexmb_beam_fibre_") {}
};

TEST_F(BeamFibrePostCli, RootFibreStressOfATipLoadedCantilever) {
  WriteFile(dir_ / "beam.bdf", FibreDeck());
  const CliResult red = RunCli(dir_, "reduce beam.bdf --interface 1,11 --modes 6 -o beam.h5");
  ASSERT_EQ(red.code, 0) << red.err;
  const CliResult info = RunCli(dir_, "body info beam.h5 --json");
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("\"beam_fibre\": {\"elements\": 9, \"locations\": 8, \"components\": 1}"),
            std::string::npos)
      << info.out;
  WriteFile(dir_ / "beam.yaml",
            "gravity: [0, 0, 0]\n"
            "ground:\n  markers:\n    - {name: root, position: [0, 0, 0]}\n"
            "bodies:\n  - name: beam\n    type: flexible\n    file: beam.h5\n"
            "    markers:\n      - {name: root, node: 1}\n      - {name: tip, node: 11}\n"
            "joints:\n  - {name: clamp, type: fixed, i: ground.root, j: beam.root}\n"
            "forces:\n  - {name: push, type: point_force, marker: beam.tip,\n"
            "     force: [0, 0, {expression: \"100*(t < 0.5 ? 0.5*(1 - cos(2*pi*t)) : 1)\"}]}\n"
            "solver: {t_end: 0.6, dt: 1.0e-3}\noutput: {interval: 5.0e-3}\n");
  const CliResult run = RunCli(dir_, "run beam.yaml --out res --quiet");
  ASSERT_EQ(run.code, 0) << run.err;
  const CliResult post = RunCli(dir_, "post res --body beam --element 1 --top 2");
  ASSERT_EQ(post.code, 0) << post.err;

  const double sigma = 100.0 * 1.0 * 0.02 / (0.02 * 0.04 * 0.04 * 0.04 / 12.0);  // 18.75 MPa
  // the root element is the hot spot, at its end A
  const FibreCsv hot = ReadFibreCsv(dir_ / "res" / "post_beam" / "hot_spots.csv");
  ASSERT_EQ(hot.rows.size(), 2u);
  EXPECT_EQ(hot.rows[0][hot.Column("element")], "1");
  EXPECT_EQ(hot.rows[0][hot.Column("point")].rfind("end_a_p", 0), 0u) << hot.rows[0][hot.Column("point")];
  // its history at t_end: top corners (p1, p2: z = +0.02) in compression, bottom in tension
  const FibreCsv h = ReadFibreCsv(dir_ / "res" / "post_beam" / "history_element_1.csv");
  ASSERT_GT(h.rows.size(), 100u);
  const std::vector<std::string>& last = h.rows.back();
  EXPECT_NEAR(std::stod(last[h.Column("t_s")]), 0.6, 1e-9);
  for (int p = 1; p <= 4; ++p) {
    const double s = std::stod(last[h.Column("end_a_p" + std::to_string(p) + "_sxx")]);
    EXPECT_NEAR(s, p <= 2 ? -sigma : sigma, 5e-3 * sigma) << "point " << p;
    const double vm = std::stod(last[h.Column("end_a_p" + std::to_string(p) + "_von_mises")]);
    EXPECT_NEAR(vm, std::abs(s), 1e-9 * sigma);
  }
  // end B of the root element: the moment Fz (L - 0.1)
  const double sb = std::stod(last[h.Column("end_b_p1_sxx")]);
  EXPECT_NEAR(sb, -0.9 * sigma, 5e-3 * sigma);
  // the element table lists the nine beams with stress points, not element 10
  const FibreCsv el = ReadFibreCsv(dir_ / "res" / "post_beam" / "elements.csv");
  EXPECT_EQ(el.rows.size(), 9u);
  for (const auto& row : el.rows) EXPECT_NE(row[0], "10");
  // element 10 has no fibre stresses: named in the error
  const CliResult bad = RunCli(dir_, "post res --body beam --element 10");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("element 10 has no stress modes"), std::string::npos) << bad.err;
}

}  // namespace beam_fibre_post_cli_test

namespace beam_fibre_post_cli_test {

// reduce --solid-corner-stress stores the solid_node table (8 corners of a
// CHEXA with 6 stress components each), reduce without it does not
TEST_F(BeamFibrePostCli, SolidCornerStressTableOnRequest) {
  std::string d = "BEGIN BULK\nMAT1,1,2.1+11,,.3,7850.\nPSOLID,1,1\n";
  const double xyz[8][3] = {{0, 0, 0}, {.2, 0, 0}, {.2, .1, 0}, {0, .1, 0},
                            {0, 0, .1}, {.2, 0, .1}, {.2, .1, .1}, {0, .1, .1}};
  for (int i = 0; i < 8; ++i)
    d += "GRID," + std::to_string(i + 1) + ",," + std::to_string(xyz[i][0]) + "," + std::to_string(xyz[i][1]) + "," +
         std::to_string(xyz[i][2]) + "\n";
  d += "CHEXA,1,1,1,2,3,4,5,6\n,7,8\nENDDATA\n";
  WriteFile(dir_ / "hex.bdf", d);
  for (bool corners : {false, true}) {
    const CliResult red = RunCli(dir_, std::string("reduce hex.bdf --interface 1,4,5,8 --modes 2 -o hex.h5") +
                                           (corners ? " --solid-corner-stress" : ""));
    ASSERT_EQ(red.code, 0) << red.err;
    const CliResult info = RunCli(dir_, "body info hex.h5 --json");
    ASSERT_EQ(info.code, 0) << info.err;
    const std::string want = corners ? "\"solid_node\": {\"elements\": 1, \"locations\": 8, \"components\": 6}"
                                     : "\"solid_node\": {\"elements\": 0, \"locations\": 0, \"components\": 0}";
    EXPECT_NE(info.out.find(want), std::string::npos) << info.out;
  }
}

}  // namespace beam_fibre_post_cli_test
