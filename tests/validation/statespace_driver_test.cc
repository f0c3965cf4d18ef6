// Validation of motion drivers as inputs of `flexmb linearize`
// (apps/flexmb/commands/linearize_drivers.h; docs/validation.md, "Drivers
// as linearize inputs"): a base-excited mass-spring-damper whose base is a
// driven prismatic joint. The state-space model (input: the base's
// acceleration; the base's position and velocity appended as states) against
// the closed form of its matrices, and its response to a step of the base
// acceleration against a nonlinear run of the same model (the driver
// following a t^2 / 2) through the command line, to 1e-3 of the peak, and
// against the closed-form response.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "json_reader.h"

namespace statespace_driver_test {

namespace fs = std::filesystem;
using flexmb::testing::CliResult;
using flexmb::testing::Json;
using flexmb::testing::ReadFile;
using flexmb::testing::RunCli;
using flexmb::testing::WriteFile;

constexpr double kMass = 10.0, kStiffness = 4000.0, kDamping = 40.0, kAccel = 0.01;

// a dense Matrix Market "array" file
Eigen::MatrixXd DriverMatrix(const fs::path& p) {
  std::istringstream in(ReadFile(p));
  std::string line;
  std::getline(in, line);
  int r = 0, c = 0;
  in >> r >> c;
  Eigen::MatrixXd A(r, c);
  for (int j = 0; j < c; ++j)
    for (int i = 0; i < r; ++i) in >> A(i, j);
  return A;
}

// base (5 kg) on a prismatic joint driven along a t^2 / 2, the mass on its
// own prismatic joint, linked by a spring-damper; no gravity
std::string DriverModel(const std::string& solver) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%.17g", 0.5 * kAccel);
  return std::string("name: base_excited\ngravity: [0, 0, 0]\nground:\n  markers:\n    - {name: o}\nbodies:\n") +
         "  - {name: base, mass: 5, inertia: [1, 1, 1], position: [0, 0, 0], markers: [{name: c}]}\n"
         "  - {name: mass, mass: 10, inertia: [1, 1, 1], position: [0, 0, 1], markers: [{name: c}]}\n"
         "joints:\n  - {name: base_guide, type: prismatic, i: ground.o, j: base.c}\n"
         "  - {name: mass_guide, type: prismatic, i: ground.o, j: mass.c}\n"
         "drivers:\n  - {name: base_drive, joint: base_guide, function: {expression: \"" + buf + "*t^2\"}}\n"
         "forces:\n  - {name: link, type: spring_damper, i: base.c, j: mass.c, stiffness: 4000, damping: 40}\n"
         "sensors:\n  - {name: mass, type: body_position, body: mass}\n" + solver;
}

// closed form: x = b + y, b = a t^2 / 2, m y'' + c y' + k y = -m a
double DriverClosedForm(double t) {
  const double w = std::sqrt(kStiffness / kMass), z = kDamping / (2.0 * std::sqrt(kStiffness * kMass));
  const double wd = w * std::sqrt(1.0 - z * z);
  const double y = -kMass * kAccel / kStiffness *
                   (1.0 - std::exp(-z * w * t) * (std::cos(wd * t) + z / std::sqrt(1.0 - z * z) * std::sin(wd * t)));
  return 0.5 * kAccel * t * t + y;
}

class StateSpaceDriver : public flexmb::testing::CliTest {
 protected:
  StateSpaceDriver() : CliTest("flexmb_statespace_driver_") {}
};

TEST_F(StateSpaceDriver, BaseAccelerationStepMatchesNonlinearRunAndClosedForm) {
  WriteFile(dir_ / "bx.yaml", DriverModel(""));
  CliResult r = RunCli(dir_, "linearize bx.yaml --inputs base_drive --outputs mass --out lin --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  Json idx;
  ASSERT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "lin" / "statespace.json"), idx));
  const Eigen::MatrixXd A = DriverMatrix(dir_ / "lin" / "A.mtx"), B = DriverMatrix(dir_ / "lin" / "B.mtx"),
                        C = DriverMatrix(dir_ / "lin" / "C.mtx"), D = DriverMatrix(dir_ / "lin" / "D.mtx");
  // states (z, z', df, df'), one input: the base's acceleration
  ASSERT_EQ(A.rows(), 4);
  ASSERT_EQ(B.cols(), 1);
  ASSERT_EQ(idx["states"].array.size(), 4u);
  EXPECT_EQ(idx["states"].array[2].string, "driver base_drive.position");
  EXPECT_EQ(idx["states"].array[3].string, "driver base_drive.velocity");
  EXPECT_EQ(idx["inputs"].array[0].string, "base_drive.acceleration");
  // closed form of the matrices: z'' = -k/m (z - df) - c/m (z' - df'), df'' = u
  Eigen::MatrixXd Aref(4, 4), Bref(4, 1);
  Aref << 0, 1, 0, 0, -kStiffness / kMass, -kDamping / kMass, kStiffness / kMass, kDamping / kMass, 0, 0, 0, 1, 0, 0,
      0, 0;
  Bref << 0, 0, 0, 1;
  EXPECT_LT((A - Aref).cwiseAbs().maxCoeff(), 1e-9 * kStiffness / kMass) << A;
  EXPECT_LT((B - Bref).cwiseAbs().maxCoeff(), 1e-12) << B;
  const std::vector<double> y0 = idx["output_values"].Numbers();

  // the nonlinear run: the driver follows a t^2 / 2
  WriteFile(dir_ / "run.yaml", DriverModel("solver: {t_end: 1.0, dt: 1.0e-4, rho_inf: 1.0}\noutput: {interval: 0.01}\n"));
  r = RunCli(dir_, "run run.yaml --out run --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream in(ReadFile(dir_ / "run" / "results.csv"));
  std::string line;
  std::getline(in, line);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(4), u = Eigen::VectorXd::Constant(1, kAccel);
  const auto f = [&](const Eigen::VectorXd& s) -> Eigen::VectorXd { return A * s + B * u; };
  double t = 0.0, worst = 0.0, worst_closed = 0.0, peak = 0.0;
  const double h = 1e-5;
  int rows = 0;
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
    const double lin = y0[2] + y(2), nonlin = row[3];  // mass.z
    worst = std::max(worst, std::abs(lin - nonlin));
    // the closed form at the integrator's time t (within a step h of tr)
    worst_closed = std::max(worst_closed, std::abs(lin - (1.0 + DriverClosedForm(t))));
    peak = std::max(peak, std::abs(nonlin - y0[2]));
    ++rows;
  }
  std::printf("base acceleration step %.3g m/s^2: peak response %.6e m, linear - nonlinear %.3e m, "
              "linear - closed form %.3e m\n", kAccel, peak, worst, worst_closed);
  EXPECT_GT(rows, 90);
  EXPECT_GT(peak, 1e-3);
  EXPECT_LT(worst, 1e-3 * peak);
  EXPECT_LT(worst_closed, 1e-6 * peak);
}

TEST_F(StateSpaceDriver, ADriverAndAForceTogetherKeepTheNamedOrder) {
  WriteFile(dir_ / "bx.yaml", DriverModel(""));
  CliResult r = RunCli(dir_, "linearize bx.yaml --inputs link,base_drive --outputs mass --out lin --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  Json idx;
  ASSERT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "lin" / "statespace.json"), idx));
  ASSERT_EQ(idx["inputs"].array.size(), 2u);
  EXPECT_EQ(idx["inputs"].array[0].string, "link.tension");
  EXPECT_EQ(idx["inputs"].array[1].string, "base_drive.acceleration");
  const Eigen::MatrixXd B = DriverMatrix(dir_ / "lin" / "B.mtx");
  // a unit tension pulls the mass (at +z) towards the base: z'' = -1/m
  EXPECT_NEAR(B(1, 0), -1.0 / kMass, 1e-12);
  EXPECT_NEAR(B(3, 1), 1.0, 1e-12);
}

}  // namespace statespace_driver_test
