// Validation of `flexmb linearize` (apps/flexmb/commands/linearize_command.h)
// through the command line: the step response of its state-space model
// (A, B, C, D read from the Matrix Market files, integrated by RK4) against
// the nonlinear simulation of the same model file started from its static
// equilibrium (analysis: statics_then_dynamics) with the same small step
// load, to 1e-3 of the response (docs/validation.md, "Linearized modes of
// the whole machine"); and the bad inputs.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "json_reader.h"

namespace statespace_cli_test {

namespace fs = std::filesystem;
using flexmb::testing::CliResult;
using flexmb::testing::Json;
using flexmb::testing::ReadFile;
using flexmb::testing::RunCli;
using flexmb::testing::WriteFile;

// a dense Matrix Market "array" file
Eigen::MatrixXd StateSpaceMatrix(const fs::path& p) {
  std::istringstream in(ReadFile(p));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "%%MatrixMarket matrix array real general") << p;
  int r = 0, c = 0;
  in >> r >> c;
  Eigen::MatrixXd A(r, c);
  for (int j = 0; j < c; ++j)
    for (int i = 0; i < r; ++i) in >> A(i, j);
  return A;
}

// the quarter car of system_modes_cli_test (ms 400 kg, mu 40 kg, ks 20 kN/m,
// cs 1.5 kN s/m, kt 200 kN/m) with a vertical step load `load` [N] on the
// body from t > 0
std::string StateSpaceQuarterCar(const std::string& solver) {
  return "name: quarter_car\ngravity: [0, 0, -9.81]\nground:\n  markers:\n    - {name: road}\nbodies:\n"
         "  - {name: body, mass: 400, inertia: [50, 50, 50], position: [0, 0, 1.0], markers: [{name: c}]}\n"
         "  - {name: wheel, mass: 40, inertia: [1, 1, 1], position: [0, 0, 0.4], markers: [{name: c}]}\n"
         "joints:\n  - {name: body_guide, type: prismatic, i: ground.road, j: body.c}\n"
         "  - {name: wheel_guide, type: prismatic, i: ground.road, j: wheel.c}\n"
         "forces:\n  - {name: suspension, type: spring_damper, i: wheel.c, j: body.c, stiffness: 20000, damping: 1500}\n"
         "  - {name: tire, type: spring_damper, i: ground.road, j: wheel.c, stiffness: 200000}\n"
         "  - {name: push, type: point_force, marker: body.c, force: [0, 0, {expression: \"100*(t>0)\"}]}\n"
         "sensors:\n  - {name: body, type: body_position, body: body}\n"
         "  - {name: wheel, type: body_position, body: wheel}\n" + solver;
}

class StateSpaceCli : public flexmb::testing::CliTest {
 protected:
  StateSpaceCli() : CliTest("flexmb_statespace_") {}
};

TEST_F(StateSpaceCli, StepResponseMatchesTheNonlinearSimulation) {
  WriteFile(dir_ / "qc.yaml", StateSpaceQuarterCar(""));
  CliResult r = RunCli(dir_, "linearize qc.yaml --inputs push --outputs body,wheel --out lin --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  Json idx;
  ASSERT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "lin" / "statespace.json"), idx));
  const Eigen::MatrixXd A = StateSpaceMatrix(dir_ / "lin" / "A.mtx"), B = StateSpaceMatrix(dir_ / "lin" / "B.mtx"),
                        C = StateSpaceMatrix(dir_ / "lin" / "C.mtx"), D = StateSpaceMatrix(dir_ / "lin" / "D.mtx");
  ASSERT_EQ(A.rows(), 4);  // two independent coordinates and their rates
  ASSERT_EQ(B.cols(), 3);  // push.fx, fy, fz
  ASSERT_EQ(C.rows(), 12);
  ASSERT_EQ(idx["inputs"].array.size(), 3u);
  EXPECT_EQ(idx["inputs"].array[2].string, "push.fz");
  EXPECT_EQ(idx["outputs"].array[2].string, "body.z");
  const std::vector<double> y0 = idx["output_values"].Numbers();

  // the nonlinear run from the static equilibrium, dt = 1e-4 s
  WriteFile(dir_ / "run.yaml", StateSpaceQuarterCar("solver: {analysis: statics_then_dynamics, t_end: 1.0, dt: 1.0e-4, "
                                                    "rho_inf: 1.0}\noutput: {interval: 0.01}\n"));
  r = RunCli(dir_, "run run.yaml --out run --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream in(ReadFile(dir_ / "run" / "results.csv"));
  std::string line;
  std::getline(in, line);
  // columns: time, body x y z roll pitch yaw, wheel x y z ...
  Eigen::VectorXd x = Eigen::VectorXd::Zero(A.rows());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3);
  u(2) = 100.0;
  const auto f = [&](const Eigen::VectorXd& s) -> Eigen::VectorXd { return A * s + B * u; };
  double t = 0.0, worst = 0.0, peak = 0.0;
  const double h = 1e-5;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, ',')) row.push_back(std::stod(cell));
    const double tr = row[0];
    while (t < tr - 1e-12) {
      const Eigen::VectorXd k1 = f(x), k2 = f(x + 0.5 * h * k1), k3 = f(x + 0.5 * h * k2), k4 = f(x + h * k3);
      x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      t += h;
    }
    const Eigen::VectorXd y = C * x + D * u;
    for (int k : {2, 8}) {  // body.z, wheel.z
      const double lin = y0[k] + y(k), nonlin = row[1 + k];
      worst = std::max(worst, std::abs(lin - nonlin));
      peak = std::max(peak, std::abs(nonlin - y0[k]));
    }
  }
  std::printf("quarter car step 100 N: peak response %.6e m, largest difference linear - nonlinear %.3e m\n", peak,
              worst);
  EXPECT_GT(peak, 1e-3);
  EXPECT_LT(worst, 1e-3 * peak);
}

TEST_F(StateSpaceCli, BadInputsAreNamed) {
  WriteFile(dir_ / "qc.yaml", StateSpaceQuarterCar(""));
  CliResult r = RunCli(dir_, "linearize qc.yaml --inputs nothing --out a --quiet");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no force element named 'nothing'"), std::string::npos) << r.err;
  r = RunCli(dir_, "linearize qc.yaml --inputs push --outputs nothing --out b --quiet");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no sensor named 'nothing'"), std::string::npos) << r.err;
}

}  // namespace statespace_cli_test
