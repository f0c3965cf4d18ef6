// Runs that never lose rows or hide the culprit (apps/flexmb/commands/run.h RunModel over
// solver/simulator.h): every output instant is in results.csv whatever path
// the step took (fixed steps cut into pieces by Newton failures, every-step
// output, adaptive steps); a failing run names the element with the largest
// share of the scaled Newton residual in the message and in summary.json,
// and prints dt_min as a number that means something; a fixed step far too
// large for the tolerance warns with the step that would be needed (and a
// rerun at that step meets the tolerance); a runaway stops with its own
// message; SIGTERM ends a run as "terminated" (exit 143).

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/flexmb/commands/run.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

namespace fs = std::filesystem;

// a pendulum (1 kg at 1 m on a revolute pin, gravity -y, released
// horizontal) and a free block 1 m below a ground marker (for springs);
// `extra` is appended (forces:, more bodies), `solver` and
// `output` are the maps of those sections
std::string PendulumYaml(const std::string& solver, const std::string& output, const std::string& extra = "") {
  return "name: robust\n"
         "gravity: [0, -9.81, 0]\n"
         "ground:\n"
         "  markers:\n"
         "    - {name: pivot, position: [0, 0, 0]}\n"
         "    - {name: anchor, position: [3, 0, 0]}\n"
         "bodies:\n"
         "  - name: bob\n"
         "    mass: 1.0\n"
         "    inertia: [0.01, 0.01, 0.01]\n"
         "    position: [-1, 0, 0]\n"
         "    markers:\n"
         "      - {name: p1, position: [0, 0, 0]}\n"
         "      - {name: pivot, position: [1, 0, 0]}\n"
         "  - name: block\n"
         "    mass: 0.5\n"
         "    inertia: [0.01, 0.01, 0.01]\n"
         "    position: [3, -1, 0]\n"
         "    markers:\n"
         "      - {name: top, position: [0, 0, 0]}\n"
         "joints:\n"
         "  - {name: pin, type: revolute, i: ground.pivot, j: bob.pivot}\n"
         "sensors:\n"
         "  - {name: p1, type: marker_position, marker: bob.p1}\n"
         "solver: " + solver + "\n"
         "output: " + output + "\n" + extra;
}

struct RunDir {
  fs::path dir;
  explicit RunDir(const std::string& name) {
    dir = fs::temp_directory_path() / ("flexmb_run_robust_" + std::to_string(getpid()) + "_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~RunDir() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string Read(const std::string& file) const {
    std::ifstream in(dir / "out" / file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  RunSummary Run(const std::string& yaml, const volatile std::sig_atomic_t* interrupt = nullptr) const {
    std::ofstream(dir / "model.yaml") << yaml;
    RunOptions opt;
    opt.model_path = (dir / "model.yaml").string();
    opt.out_dir = (dir / "out").string();
    opt.interrupt = interrupt;
    return RunModel(opt);
  }
  // first column (time) and the p1 columns of results.csv
  std::vector<std::vector<double>> Rows() const {
    std::vector<std::vector<double>> rows;
    std::istringstream in(Read("results.csv"));
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::vector<double> row;
      std::stringstream ls(line);
      std::string cell;
      while (std::getline(ls, cell, ',')) row.push_back(std::stod(cell));
      rows.push_back(row);
    }
    return rows;
  }
};

// every row at t = k * interval, k = 0..n, with the bob on its unit circle
void ExpectGridRows(const RunDir& d, double interval, int n, const std::string& label) {
  const auto rows = d.Rows();
  ASSERT_EQ(static_cast<int>(rows.size()), n + 1) << label << "\n" << d.Read("results.csv");
  for (int k = 0; k <= n; ++k) {
    ASSERT_GE(rows[k].size(), 4u) << label;
    EXPECT_NEAR(rows[k][0], k * interval, 1e-9) << label << " row " << k;
    EXPECT_NEAR(std::hypot(rows[k][1], rows[k][2]), 1.0, 1e-6) << label << " row " << k;
  }
}

TEST(RunRows, EveryOutputInstantIsWrittenWhenFixedStepsAreCut) {
  // 2 Newton iterations cannot converge a 50 ms step of the pendulum: every
  // step is cut into pieces that end on the step's time
  const RunDir d("cut");
  const RunSummary s = d.Run(PendulumYaml("{t_end: 1, dt: 0.05, max_newton: 2, rho_inf: 0.9}", "{interval: 0.05}"));
  ASSERT_EQ(s.status, RunStatus::kOk) << s.message;
  EXPECT_GT(s.rejected_steps, 5) << "the steps were not cut: the test does not test the cut path";
  EXPECT_EQ(s.rows, 21);
  ExpectGridRows(d, 0.05, 20, "interval 0.05");
  // every step (interval 0): one row per fixed step
  const RunSummary e = d.Run(PendulumYaml("{t_end: 1, dt: 0.05, max_newton: 2, rho_inf: 0.9}", "{interval: 0}"));
  ASSERT_EQ(e.status, RunStatus::kOk) << e.message;
  EXPECT_GT(e.rejected_steps, 5);
  ExpectGridRows(d, 0.05, 20, "interval 0");
  // rows on a coarser grid than the step
  const RunSummary c = d.Run(PendulumYaml("{t_end: 1, dt: 0.05, max_newton: 2, rho_inf: 0.9}", "{interval: 0.1}"));
  ASSERT_EQ(c.status, RunStatus::kOk) << c.message;
  ExpectGridRows(d, 0.1, 10, "interval 0.1");
}

TEST(RunRows, EveryOutputInstantIsWrittenWithAdaptiveSteps) {
  const RunDir d("adaptive");
  const RunSummary s =
      d.Run(PendulumYaml("{t_end: 1, dt: 0.05, adaptive: true, rtol: 1e-6, atol: 1e-8, rho_inf: 0.9}",
                         "{interval: 0.05}"));
  ASSERT_EQ(s.status, RunStatus::kOk) << s.message;
  EXPECT_GT(s.rejected_steps, 0);
  ExpectGridRows(d, 0.05, 20, "adaptive");
}

// a cubic spring of the block to the ground, far too stiff for the step
const std::string kStiffSpring =
    "forces:\n"
    "  - {name: hard_spring, type: spring_damper, i: ground.anchor, j: block.top,\n"
    "     force_deflection: {expression: \"1e12*x^3 + 1e6*x\"}, free_length: 0.2}\n";

TEST(RunFailure, NamesTheElementWithTheLargestResidualShare) {
  const RunDir d("culprit");
  const RunSummary s = d.Run(
      PendulumYaml("{t_end: 1, dt: 0.01, dt_min: 0.00025, max_newton: 6, rho_inf: 0.9}", "{interval: 0.01}",
                   kStiffSpring));
  ASSERT_EQ(s.status, RunStatus::kNumericalError) << s.message;
  EXPECT_NE(s.message.find("dt_min = 0.00025 s"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("largest share of the scaled Newton residual: force element 'hard_spring'"),
            std::string::npos)
      << s.message;
  EXPECT_EQ(s.culprit, "force element 'hard_spring'");
  EXPECT_GT(s.culprit_share, 0.3);
  EXPECT_LE(s.culprit_share, 1.0);
  const std::string json = d.Read("summary.json");
  EXPECT_NE(json.find("\"culprit\": \"force element 'hard_spring'\""), std::string::npos) << json;
}

TEST(RunFailure, NonFiniteForceAndTinyDtMinAreReadable) {
  // a force that becomes NaN at t = 0.5 s: the fixed step is cut down to
  // dt_min = 1e-10 s, printed as such (not as 0.000000)
  const RunDir d("nan");
  const RunSummary s = d.Run(PendulumYaml(
      "{t_end: 1, dt: 0.01, rho_inf: 0.9}", "{interval: 0.1}",
      "forces:\n  - {name: bad_force, type: point_force, marker: bob.p1,\n"
      "     force: [{expression: \"t < 0.5 ? 0 : sqrt(-1)\"}, 0, 0]}\n"));
  ASSERT_EQ(s.status, RunStatus::kNumericalError) << s.message;
  EXPECT_NE(s.message.find("dt_min = 1e-10 s"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("force element 'bad_force' (non-finite)"), std::string::npos) << s.message;
  EXPECT_EQ(s.culprit, "force element 'bad_force'");
  EXPECT_EQ(s.rows, 5) << "rows before the fault are kept";
}

TEST(RunFailure, AnAdaptiveRunCutByItsErrorControlNamesTheBody) {
  // the block on a 2e5 N/m spring (100 Hz): its local error keeps the
  // adaptive step far below dt_min = 1 ms while Newton converges
  const RunDir d("error_culprit");
  const RunSummary s = d.Run(PendulumYaml(
      "{t_end: 0.2, dt: 0.01, dt_min: 0.001, adaptive: true, rho_inf: 0.9}", "{interval: 0.01}",
      "forces:\n  - {name: spring, type: spring_damper, i: ground.anchor, j: block.top, stiffness: 2.0e5,\n"
      "     free_length: 0.9}\n"));
  ASSERT_EQ(s.status, RunStatus::kNumericalError) << s.message;
  EXPECT_NE(s.message.find("dt_min = 0.001 s"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("the local error estimate stays above the tolerance"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("largest share of the local error estimate: body 'block'"), std::string::npos)
      << s.message;
  EXPECT_EQ(s.culprit, "body 'block'");
  EXPECT_GT(s.culprit_share, 0.5);
}

TEST(RunFailure, ARunawayStopsWithItsOwnMessage) {
  // NaN from the first step on and a dt_min so small that the cuts of the
  // 1000 s step would go on for more than 1000 attempts (log2(1e303))
  const RunDir d("runaway");
  const RunSummary s = d.Run(PendulumYaml(
      "{t_end: 2000, dt: 1000, dt_min: 1.0e-300, rho_inf: 0.9}", "{interval: 1000}",
      "forces:\n  - {name: bad_force, type: point_force, marker: bob.p1,\n"
      "     force: [{expression: \"t > 0 ? sqrt(-1) : 0\"}, 0, 0]}\n"));
  ASSERT_EQ(s.status, RunStatus::kNumericalError) << s.message;
  EXPECT_NE(s.message.find("runaway: 1000 step attempts rejected for 0 accepted"), std::string::npos) << s.message;
  EXPECT_EQ(s.rejected_steps, kRunawayMinRejected);
  EXPECT_EQ(s.culprit, "force element 'bad_force'");
  EXPECT_FALSE(IsRunaway(999, 0));
  EXPECT_TRUE(IsRunaway(1000, 0));
  EXPECT_FALSE(IsRunaway(5000, 5));
  EXPECT_TRUE(IsRunaway(5001, 5));
}

TEST(RunAccuracy, AFixedStepFarTooLargeWarnsWithTheStepNeeded) {
  // the block on a linear spring of 2e5 N/m (100 Hz) at 10 ms steps
  const std::string spring =
      "forces:\n  - {name: spring, type: spring_damper, i: ground.anchor, j: block.top, stiffness: 2.0e5,\n"
      "     free_length: 0.9}\n";
  const RunDir d("accuracy");
  const RunSummary s = d.Run(PendulumYaml("{t_end: 0.2, dt: 0.01, rho_inf: 0.9}", "{interval: 0.01}", spring));
  ASSERT_EQ(s.status, RunStatus::kOk) << s.message;
  EXPECT_GT(s.max_error_estimate, 100.0);
  ASSERT_GT(s.dt_needed, 0.0);
  EXPECT_LT(s.dt_needed, 0.01);
  bool warned = false;
  for (const std::string& w : s.warnings) warned = warned || w.find("would be needed") != std::string::npos;
  EXPECT_TRUE(warned);
  const std::string json = d.Read("summary.json");
  EXPECT_NE(json.find("fixed step dt = 0.01 s is too large for the tolerance"), std::string::npos) << json;
  // at the step it names, the estimate meets the tolerance (measured 1.06)
  char dt[32];
  std::snprintf(dt, sizeof(dt), "%.6g", s.dt_needed);
  const RunSummary r =
      d.Run(PendulumYaml(std::string("{t_end: 0.2, dt: ") + dt + ", rho_inf: 0.9}", "{interval: 0.01}", spring));
  ASSERT_EQ(r.status, RunStatus::kOk) << r.message;
  EXPECT_LT(r.max_error_estimate, 1.5) << "dt " << dt;
  for (const std::string& w : r.warnings) EXPECT_EQ(w.find("would be needed"), std::string::npos) << w;
}

TEST(RunSignals, SigtermIsReportedAsTerminatedNotAsAnInterrupt) {
  const RunDir d("signal");
  volatile std::sig_atomic_t flag = SIGTERM;
  const RunSummary t = d.Run(PendulumYaml("{t_end: 1, dt: 0.01}", "{interval: 0.1}"), &flag);
  EXPECT_EQ(t.status, RunStatus::kTerminated);
  EXPECT_EQ(ExitCode(t.status), 143);
  EXPECT_STREQ(StatusName(t.status), "terminated");
  EXPECT_NE(t.message.find("SIGTERM"), std::string::npos) << t.message;
  EXPECT_NE(d.Read("summary.json").find("\"status\": \"terminated\""), std::string::npos);
  flag = SIGINT;
  const RunSummary i = d.Run(PendulumYaml("{t_end: 1, dt: 0.01}", "{interval: 0.1}"), &flag);
  EXPECT_EQ(i.status, RunStatus::kInterrupted);
  EXPECT_EQ(ExitCode(i.status), 130);
  EXPECT_EQ(i.message, "interrupted by the user");
}

}  // namespace
}  // namespace flexmb
