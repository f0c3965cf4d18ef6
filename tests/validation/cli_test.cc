// End-to-end test of the flexmb command line (FLEXMB_CLI): "run" on a small
// pendulum model file, checked against the linearized pendulum solution
// theta0 cos(sqrt(g/L) t); "check" on a planar four-bar, whose redundant
// equations follow from the Gruebler count; exit codes and messages of bad
// models; rows kept by an interrupted or failing run.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "cli_runner.h"

namespace cli_test {

namespace fs = std::filesystem;
constexpr const char* kPython = "/usr/bin/python3";

using flexmb::testing::CliResult;
using flexmb::testing::ReadFile;
using flexmb::testing::RunCli;
using flexmb::testing::WriteFile;

std::vector<std::vector<std::string>> ReadCsv(const fs::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(ReadFile(p));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// summary.json parsed by Python's json module, flattened to "key value" lines
std::map<std::string, std::string> ReadSummary(const fs::path& p) {
  const std::string cmd = std::string(kPython) +
                          " -c 'import json,sys; d=json.load(open(sys.argv[1]));"
                          " [print(k, v) for k, v in d.items()]' '" + p.string() + "'";
  std::map<std::string, std::string> m;
  std::FILE* f = popen(cmd.c_str(), "r");
  if (!f) return m;
  char line[4096];
  while (std::fgets(line, sizeof(line), f)) {
    std::string s(line);
    if (!s.empty() && s.back() == '\n') s.pop_back();
    const auto sp = s.find(' ');
    m[s.substr(0, sp)] = sp == std::string::npos ? "" : s.substr(sp + 1);
  }
  if (pclose(f) != 0) m.clear();
  return m;
}

// a 1 m point pendulum about z, hanging along -y (gravity -y), released
// at rest at theta0 = 0.05 rad from the vertical
const char* kPendulum = R"yaml(name: pendulum
gravity: [0, -9.81, 0]
ground:
  markers:
    - {name: pin}
bodies:
  - name: bob
    mass: 1.0
    inertia: [1e-8, 1e-8, 1e-8]
    position: [0.04997916927067833, -0.9987502603949663, 0]
    orientation: {roll_pitch_yaw: [0, 0, 0.05]}
    shape: {type: box, size: [0.1, 0.1, 0.1]}
    markers:
      - {name: pin, position: [0, 1, 0]}
joints:
  - {name: pin, type: revolute, i: ground.pin, j: bob.pin}
sensors:
  - {name: swing, type: joint_coordinate, joint: pin}
  - {name: energy, type: system_energy}
solver: {t_end: 2.0, dt: 1e-3, rho_inf: 1.0}
output: {interval: 0.01, animation: false, animation_interval: 0.1}
)yaml";

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    if (access(kPython, X_OK) != 0) GTEST_SKIP() << "no " << kPython << " to parse the JSON";
    dir_ = fs::temp_directory_path() / ("flexmb_cli_test_" + std::to_string(getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    WriteFile(dir_ / "pendulum.yaml", kPendulum);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(Cli, Version) {
  const CliResult r = RunCli(dir_, "--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("flexmb 0."), std::string::npos) << r.out;
}

TEST_F(Cli, RunWritesResultsSummaryAndAnimation) {
  const CliResult r = RunCli(dir_, "run pendulum.yaml --out res --t-end 1.5 --animation --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << "--quiet prints nothing: " << r.out;

  // columns: time, then <sensor>.<component>
  const auto rows = ReadCsv(dir_ / "res" / "results.csv");
  ASSERT_GE(rows.size(), 2u);
  const std::vector<std::string> header = {"time", "swing.value", "swing.rate", "energy.kinetic",
                                           "energy.potential", "energy.total"};
  ASSERT_EQ(rows[0], header);
  // --t-end overrides the file's 2 s; one row per 0.01 s including t = 0
  ASSERT_EQ(rows.size(), 152u);
  const double g = 9.81, theta0 = 0.05, omega = std::sqrt(g / 1.0);
  // the joint angle is that of marker j (body axes) about marker i's z axis
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), header.size());
    const double t = std::stod(rows[i][0]);
    EXPECT_NEAR(t, 0.01 * (i - 1), 1e-12);
    // linearized pendulum; the amplitude error is ~theta0^3/16 * omega t
    const double theta = theta0 * std::cos(omega * t);
    EXPECT_NEAR(std::stod(rows[i][1]), theta, 1e-4) << "t = " << t;
    EXPECT_NEAR(std::stod(rows[i][2]), -theta0 * omega * std::sin(omega * t), 5e-4) << "t = " << t;
  }

  const auto s = ReadSummary(dir_ / "res" / "summary.json");
  ASSERT_FALSE(s.empty()) << "summary.json does not parse as JSON";
  EXPECT_EQ(s.at("status"), "ok");
  EXPECT_EQ(s.at("message"), "");
  EXPECT_NEAR(std::stod(s.at("t_end")), 1.5, 1e-12);
  EXPECT_EQ(s.at("steps"), "1500");  // fixed step 1e-3, output times on the step grid
  EXPECT_EQ(s.at("dof"), "1");
  EXPECT_EQ(s.at("redundant_constraints"), "0");
  EXPECT_EQ(s.at("rejected_steps"), "0");
  for (const char* key : {"model", "newton_iterations", "factorizations", "wall_time_s",
                          "max_constraint_violation", "steps_per_second"})
    EXPECT_EQ(s.count(key), 1u) << key;
  EXPECT_GE(std::stol(s.at("newton_iterations")), 1500);
  EXPECT_LT(std::stod(s.at("max_constraint_violation")), 1e-8);
  EXPECT_GT(std::stod(s.at("steps_per_second")), 0.0);

  // --animation: one frame per 0.1 s, listed in a valid anim.pvd
  const std::string pvd = (dir_ / "res" / "anim.pvd").string();
  const std::string cmd = std::string(kPython) +
                          " -c 'import sys,xml.etree.ElementTree as E;"
                          " print(len(E.parse(sys.argv[1]).findall(\"Collection/DataSet\")))' '" +
                          pvd + "' > '" + (dir_ / "frames.txt").string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(ReadFile(dir_ / "frames.txt"), "16\n");
  EXPECT_TRUE(fs::exists(dir_ / "res" / "frames" / "frame_00015.vtu"));
  EXPECT_FALSE(fs::exists(dir_ / "res" / "frames" / "frame_00016.vtu"));
}

TEST_F(Cli, RunPrintsDegreesOfFreedom) {
  const CliResult r = RunCli(dir_, "run pendulum.yaml --out res --t-end 0.1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1 degrees of freedom"), std::string::npos) << r.out;
  // not a terminal: no progress bar
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "res" / "anim.pvd"));
}

// planar four-bar (parallelogram) from revolute joints: 3 bodies x 6 = 18
// coordinates, 4 x 5 = 20 equations, 1 degree of freedom (Gruebler for the
// planar linkage: 3 (4 - 1) - 2 x 4 = 1), so rank 17 and 3 redundant
const char* kFourBar = R"yaml(name: four_bar
ground:
  markers:
    - {name: a}
    - {name: d, position: [2, 0, 0]}
bodies:
  - name: crank
    mass: 1
    inertia: [0.1, 0.1, 0.1]
    position: [0, 0.5, 0]
    markers:
      - {name: a, position: [0, -0.5, 0]}
      - {name: b, position: [0, 0.5, 0]}
  - name: coupler
    mass: 1
    inertia: [0.1, 0.1, 0.1]
    position: [1, 1, 0]
    markers:
      - {name: b, position: [-1, 0, 0]}
      - {name: c, position: [1, 0, 0]}
  - name: rocker
    mass: 1
    inertia: [0.1, 0.1, 0.1]
    position: [2, 0.5, 0]
    markers:
      - {name: c, position: [0, 0.5, 0]}
      - {name: d, position: [0, -0.5, 0]}
joints:
  - {name: ja, type: revolute, i: ground.a, j: crank.a}
  - {name: jb, type: revolute, i: crank.b, j: coupler.b}
  - {name: jc, type: revolute, i: coupler.c, j: rocker.c}
  - {name: jd, type: revolute, i: rocker.d, j: ground.d}
)yaml";

TEST_F(Cli, CheckReportsDofAndRedundantEquations) {
  CliResult r = RunCli(dir_, "check pendulum.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("degrees of freedom: 1\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("constraint equations: 5 (0 redundant)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bodies: 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("revolute 'pin': 5 equations"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sensors: 2"), std::string::npos) << r.out;

  WriteFile(dir_ / "four_bar.yaml", kFourBar);
  r = RunCli(dir_, "check four_bar.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("degrees of freedom: 1\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("constraint equations: 20 (3 redundant)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("joints: 4 (20 equations)"), std::string::npos) << r.out;
  // one warning for the joint that closes the loop, naming its 3 removed
  // equations in one line
  size_t warnings = 0;
  for (size_t p = r.out.find("warning:"); p != std::string::npos; p = r.out.find("warning:", p + 1))
    ++warnings;
  EXPECT_EQ(warnings, 1u) << r.out;
  EXPECT_NE(r.out.find("3 redundant constraint equations removed ("), std::string::npos) << r.out;
}

// check --manoeuvre: the manoeuvre's values are checked without a run (a
// negative release time is an error naming the joint and the manoeuvre)
TEST_F(Cli, CheckAppliesAManoeuvre) {
  WriteFile(dir_ / "manoeuvres.yaml", std::string(kPendulum) +
                                          "manoeuvres:\n"
                                          "  drop: {joints: {pin: {release_time: 0.5}}}\n"
                                          "  broken: {joints: {pin: {release_time: -1}}}\n");
  CliResult r = RunCli(dir_, "check manoeuvres.yaml --manoeuvre drop");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("degrees of freedom: 1\n"), std::string::npos) << r.out;
  r = RunCli(dir_, "check manoeuvres.yaml");
  EXPECT_EQ(r.code, 0) << r.err;
  r = RunCli(dir_, "check manoeuvres.yaml --manoeuvre broken");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("joint 'pin': 'release_time' must be positive, got -1 (manoeuvre 'broken')"), std::string::npos)
      << r.err;
  r = RunCli(dir_, "check manoeuvres.yaml --manoeuvre nosuch");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("drop"), std::string::npos) << r.err;
}

TEST_F(Cli, BadModelIsAnInputErrorWithFileAndLine) {
  // line 8 has the misspelled key
  std::string text = kPendulum;
  text.replace(text.find("    mass: 1.0"), 13, "    mas: 1.0");
  WriteFile(dir_ / "bad.yaml", text);
  CliResult r = RunCli(dir_, "check bad.yaml");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.yaml:8:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("mas"), std::string::npos) << r.err;

  r = RunCli(dir_, "run bad.yaml --out res");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.yaml:8:"), std::string::npos) << r.err;
  const auto s = ReadSummary(dir_ / "res" / "summary.json");
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.at("status"), "failed");
  EXPECT_NE(s.at("message").find("bad.yaml:8:"), std::string::npos);

  r = RunCli(dir_, "run missing.yaml --out res2");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("missing.yaml"), std::string::npos) << r.err;

  r = RunCli(dir_, "run pendulum.yaml --out res3 --dt -1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--dt"), std::string::npos) << r.err;
}

// a free body pushed by sqrt(0.25 - t) N: the force is not finite after
// t = 0.25 s, so the solve fails there with a numerical error
const char* kBlowUp = R"yaml(name: blowup
gravity: [0, 0, 0]
bodies:
  - name: bob
    mass: 2.0
    inertia: [1e-3, 1e-3, 1e-3]
    markers:
      - {name: c}
forces:
  - {name: push, type: point_force, marker: bob.c, force: [{expression: "sqrt(0.25 - t)"}, 0, 0]}
sensors:
  - {name: pos, type: body_position, body: bob}
solver: {t_end: 1.0, dt: 1e-3}
output: {interval: 0.01}
)yaml";

TEST_F(Cli, NumericalFailureKeepsRowsAndReportsFailure) {
  WriteFile(dir_ / "blowup.yaml", kBlowUp);
  const CliResult r = RunCli(dir_, "run blowup.yaml --out res");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("error:"), std::string::npos) << r.err;
  const auto s = ReadSummary(dir_ / "res" / "summary.json");
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.at("status"), "failed");
  EXPECT_FALSE(s.at("message").empty());
  EXPECT_NEAR(std::stod(s.at("t_end")), 0.25, 1e-3);
  // rows up to the failure, x(t) = (1/m) * double integral of sqrt(0.25 - s)
  const auto rows = ReadCsv(dir_ / "res" / "results.csv");
  ASSERT_EQ(rows.size(), 27u);  // header + t = 0, 0.01, ..., 0.25
  for (size_t i = 1; i < rows.size(); ++i) {
    const double t = std::stod(rows[i][0]);
    const double x = (4.0 / 15.0 * (std::pow(0.25 - t, 2.5) - std::pow(0.25, 2.5)) +
                      2.0 / 3.0 * std::pow(0.25, 1.5) * t) / 2.0;
    EXPECT_NEAR(std::stod(rows[i][1]), x, 1e-5) << "t = " << t;
  }
}

TEST_F(Cli, InterruptedRunKeepsFlushedRows) {
  // a long run in the background; rows must appear while it runs
  const fs::path csv = dir_ / "res" / "results.csv";
  const std::string cmd = "cd '" + dir_.string() + "' && exec '" FLEXMB_CLI
                          "' run pendulum.yaml --out res --t-end 1e6 --quiet > /dev/null 2>&1";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  size_t seen = 0;
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::seconds(30)) {
    seen = ReadCsv(csv).size();
    if (seen > 20) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_GT(seen, 20u) << "no rows appeared while running";
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const auto rows = ReadCsv(csv);
  EXPECT_GE(rows.size(), seen);
  for (size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i].size(), 6u) << "row " << i;
  const auto s = ReadSummary(dir_ / "res" / "summary.json");
  ASSERT_FALSE(s.empty());
  EXPECT_EQ(s.at("status"), "interrupted");
  EXPECT_EQ(std::stol(s.at("rows")), static_cast<long>(rows.size()) - 1);
}

}  // namespace cli_test
