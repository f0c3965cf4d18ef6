// End-to-end test of "flexmb post" (docs/cli.md): the steel strip of
// tests/data/fe/nastran/cli_strip.bdf reduced with "flexmb reduce",
// clamped at the middle node of one end in a model file, gravity switched
// on at t = 0 (it vibrates about its static sag); "flexmb run" keeps its modal coordinates, and
// "flexmb post" recovers the stresses afterwards. Reference: the run's own
// element_stress sensor in results.csv (the stress modes applied during the
// run, an independent code path): the element history of post must give
// the same stresses at every output row. Also the hot-spot list, the
// element table and the ParaView file are consistent with the history, and
// bad input is named (docs/validation.md, "Durability").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "cli_strip.h"

namespace durability_post_cli_test {

namespace fs = std::filesystem;
using flexmb::testing::CliResult;
using flexmb::testing::ReadFile;
using flexmb::testing::RunCli;
using flexmb::testing::WriteFile;

// a CSV file as header names and rows of numbers (empty fields as NaN)
struct PostCsv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  int Column(const std::string& name) const {
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return static_cast<int>(i);
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};

PostCsv ReadPostCsv(const fs::path& p) {
  PostCsv c;
  std::istringstream in(ReadFile(p));
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
    if (first) {
      c.names = f;
      first = false;
      continue;
    }
    std::vector<double> v;
    for (const std::string& x : f) v.push_back(x.empty() ? NAN : std::atof(x.c_str()));
    c.rows.push_back(v);
  }
  return c;
}

class DurabilityPostCli : public flexmb::testing::CliTest {
 protected:
  DurabilityPostCli() : CliTest("flexmb_post_cli_") {}
  void RunStrip() {
    const CliResult red = RunCli(dir_, "reduce '" + flexmb::testing::kStrip + "' --interface 1,22,43 --modes 6 -o strip.h5");
    ASSERT_EQ(red.code, 0) << red.err;
    WriteFile(dir_ / "strip.yaml",
              "gravity: [0, 0, -9.81]\n"
              "ground:\n  markers:\n    - {name: root, position: [0, 0.025, 0]}\n"
              "bodies:\n  - name: strip\n    type: flexible\n    file: strip.h5\n"
              "    markers:\n      - {name: root, node: 22}\n"
              "joints:\n  - {name: clamp, type: fixed, i: ground.root, j: strip.root}\n"
              "sensors:\n  - {name: s, type: element_stress, body: strip, element: 1}\n"
              "solver: {t_end: 0.2, dt: 1.0e-3}\noutput: {interval: 2.0e-3}\n");
    const CliResult run = RunCli(dir_, "run strip.yaml --out res --quiet");
    ASSERT_EQ(run.code, 0) << run.err;
  }
};

TEST_F(DurabilityPostCli, HistoriesEqualTheRunsStressSensorAndFilesAgree) {
  RunStrip();
  ASSERT_TRUE(fs::exists(dir_ / "res" / "modal_coordinates.bin"));
  const CliResult r = RunCli(dir_, "post res --body strip --element 1 --node 21 --sn en1993-71 --distance-km 0.002 --top 3");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("hot spots"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("EN 1993-1-9 detail category 71"), std::string::npos) << r.out;
  const PostCsv results = ReadPostCsv(dir_ / "res" / "results.csv");
  const PostCsv hist = ReadPostCsv(dir_ / "res" / "post_strip" / "history_element_1.csv");
  ASSERT_EQ(results.rows.size(), hist.rows.size());
  ASSERT_GT(hist.rows.size(), 50u);
  double peak = 0, err = 0;
  for (const char* c : {"top_sxx", "bottom_syy", "top_sxy", "top_von_mises", "bottom_von_mises"}) {
    const int a = results.Column(std::string("s.") + c), b = hist.Column(c);
    for (size_t i = 0; i < hist.rows.size(); ++i) {
      peak = std::max(peak, std::abs(results.rows[i][a]));
      err = std::max(err, std::abs(results.rows[i][a] - hist.rows[i][b]));
    }
  }
  EXPECT_GT(peak, 1e6);  // the strip is stressed
  EXPECT_LT(err, 1e-7 * peak);
  // the middle surface is the mean of bottom and top
  const int m = hist.Column("middle_sxx"), bo = hist.Column("bottom_sxx"), to = hist.Column("top_sxx");
  for (const auto& row : hist.rows) EXPECT_NEAR(row[m], 0.5 * (row[bo] + row[to]), 1e-9 * peak);
  // the element table's maximum is the history's
  const PostCsv el = ReadPostCsv(dir_ / "res" / "post_strip" / "elements.csv");
  double hist_max = 0;
  for (const char* c : {"top_von_mises", "middle_von_mises", "bottom_von_mises"})
    for (const auto& row : hist.rows) hist_max = std::max(hist_max, row[hist.Column(c)]);
  bool found = false;
  for (const auto& row : el.rows)
    if (row[0] == 1) {
      found = true;
      EXPECT_NEAR(row[el.Column("max_von_mises_Pa")], hist_max, 1e-7 * hist_max);
      EXPECT_GE(row[el.Column("damage")], 0.0);
      EXPECT_NEAR(row[el.Column("damage_per_1000km")], row[el.Column("damage")] * 1000.0 / 0.002,
                  1e-6 * row[el.Column("damage_per_1000km")] + 1e-300);
    }
  EXPECT_TRUE(found);
  // hot spots: 3 rows, the largest first, at the clamped end of the strip
  const PostCsv hot = ReadPostCsv(dir_ / "res" / "post_strip" / "hot_spots.csv");
  ASSERT_EQ(hot.rows.size(), 3u);
  EXPECT_GE(hot.rows[0][2], hot.rows[1][2]);
  EXPECT_LT(hot.rows[0][hot.Column("x_m")], 0.2);
  // node history and the ParaView file
  EXPECT_EQ(ReadPostCsv(dir_ / "res" / "post_strip" / "history_node_21.csv").rows.size(), hist.rows.size());
  const std::string vtu = ReadFile(dir_ / "res" / "post_strip" / "strip_post.vtu");
  EXPECT_NE(vtu.find("Name=\"damage_per_1000km\""), std::string::npos);
  EXPECT_NE(vtu.find("NumberOfCells=\"40\""), std::string::npos);
}

// S-N options against each other, element by element: the Basquin line
// m = 3 through the category's point (no knee, no cut-off) lies below the
// EN 1993-1-9 curve everywhere, so it does at least its damage; Goodman never
// lowers a range (compressive means are left as they are), so it does at
// least the uncorrected damage, and more where means are tensile
TEST_F(DurabilityPostCli, SnOptionsOrderTheDamage) {
  RunStrip();
  auto damage = [&](const std::string& options, const std::string& out) {
    const CliResult r = RunCli(dir_, "post res --body strip -o " + out + " " + options);
    EXPECT_EQ(r.code, 0) << options << "\n" << r.err;
    const PostCsv c = ReadPostCsv(dir_ / out / "elements.csv");
    std::vector<double> d;
    for (const auto& row : c.rows) d.push_back(row[c.Column("damage")]);
    return d;
  };
  const std::vector<double> en = damage("--sn en1993-71", "en");
  const std::vector<double> basquin = damage("--sn-basquin 71e6,2e6,3", "basquin");
  const std::vector<double> goodman = damage("--sn en1993-71 --mean-stress goodman --ultimate 400e6", "goodman");
  ASSERT_EQ(en.size(), 40u);
  ASSERT_EQ(basquin.size(), en.size());
  ASSERT_EQ(goodman.size(), en.size());
  int more = 0;
  for (size_t i = 0; i < en.size(); ++i) {
    EXPECT_GE(basquin[i], en[i] * (1 - 1e-12)) << i;
    EXPECT_GE(goodman[i], en[i] * (1 - 1e-12)) << i;
    more += goodman[i] > en[i] * (1 + 1e-6);
  }
  EXPECT_GT(*std::max_element(en.begin(), en.end()), 0.0);
  EXPECT_GT(more, 0);
}

TEST_F(DurabilityPostCli, BadInputIsNamed) {
  RunStrip();
  auto fails = [&](const std::string& args, const std::vector<std::string>& parts) {
    const CliResult r = RunCli(dir_, args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    for (const std::string& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << args << "\n" << r.err;
  };
  fails("post res --body frame", {"no flexible body 'frame'", "'strip'", "modal_coordinates.bin"});
  fails("post res --body strip --element 9999", {"element 9999 does not exist", "strip.h5"});
  fails("post res --body strip --node 9999", {"node 9999 does not exist"});
  fails("post . --body strip", {"no modal coordinates"});
  WriteFile(dir_ / "sn.csv", "1e4, 300e6\n1e5, 310e6\n");
  fails("post res --body strip --sn-file sn.csv", {"sn.csv:2", "not monotonic"});
  fails("post res --body strip --sn en1993-99", {"unknown S-N curve preset 'en1993-99'", "en1993-71"});
  fails("post res --body strip --measure tresca", {"unknown stress measure 'tresca'"});
  fails("post res --body strip --mean-stress goodman", {"ultimate strength"});
  fails("post res --body strip --sn en1993-71 --sn-basquin 71e6,2e6,3", {"give one S-N curve"});
}

}  // namespace durability_post_cli_test
