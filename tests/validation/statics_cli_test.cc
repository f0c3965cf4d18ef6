// Validation of `flexmb statics` and of solver.analysis (statics,
// statics_then_dynamics) through the command line
// (apps/flexmb/commands/statics_command.h; docs/validation.md, "Statics from
// the command line"): an ANCF cantilever under a small tip load against
// Euler-Bernoulli beam theory, the slender elastica PL^2/EI = 10 against
// Mattiasson (1981), a crane-like jib with a tie and a hanging payload
// against the hand calculation of its reactions, the run started from the
// equilibrium, and the failure message of a body without equilibrium.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "json_reader.h"
#include "results_csv.h"

namespace statics_cli_test {

namespace fs = std::filesystem;
using flexmb::testing::CliResult;
using flexmb::testing::Json;
using flexmb::testing::ReadFile;
using flexmb::testing::RunCli;
using flexmb::testing::WriteFile;

using StaticsCsv = flexmb::testing::ResultsCsv;
using flexmb::testing::ReadResultsCsv;

class StaticsCli : public flexmb::testing::CliTest {
 protected:
  StaticsCli() : CliTest("flexmb_statics_") {}
  // runs `flexmb statics` on `yaml`; the summary
  Json Statics(const std::string& yaml) {
    WriteFile(dir_ / "model.yaml", yaml);
    const CliResult r = RunCli(dir_, "statics model.yaml --out res");
    EXPECT_EQ(r.code, 0) << r.err;
    Json s;
    EXPECT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "res" / "summary.json"), s));
    EXPECT_EQ(s["status"].string, "ok") << s["message"].string;
    return s;
  }
};

// a planar ANCF cantilever along x clamped at the origin, tip load P along
// -y (N), length L, E, section A, I, `elements` elements, no gravity
std::string StaticsCantilever(double L, int elements, double A, double I, double E, double P) {
  std::ostringstream o;
  o.precision(17);
  o << "name: cantilever\ngravity: [0, 0, 0]\nground:\n  markers:\n    - {name: clamp}\nbodies:\n"
    << "  - name: beam\n    type: ancf_beam\n    length: " << L << "\n    elements: " << elements
    << "\n    section: {area: " << A << ", inertia: " << I << "}\n    material: {E: " << E << ", rho: 7850}\n"
    << "    markers:\n      - {name: root, end: start}\n      - {name: tip, end: end}\n"
    << "joints:\n  - {name: clamp, type: fixed, i: ground.clamp, j: beam.root}\n"
    << "forces:\n  - {name: load, type: point_force, marker: beam.tip, force: [0, " << -P << ", 0]}\n"
    << "sensors:\n  - {name: tip, type: marker_position, marker: beam.tip}\n";
  return o.str();
}

TEST_F(StaticsCli, CantileverSmallLoadMatchesBeamTheory) {
  // L = 1 m, EI = 1 N m^2, P = 1e-4 N: w = P L^3 / (3 EI); the geometric
  // nonlinearity changes it by O((P L^2 / EI)^2) = 1e-8 relative
  const double P = 1e-4;
  const Json s = Statics(StaticsCantilever(1.0, 8, 1e-2, 8.333333333333333e-6, 1.2e5, P));
  EXPECT_EQ(s["load_factor"].number, 1.0);
  const StaticsCsv t = ReadResultsCsv(dir_ / "res" / "results.csv");
  ASSERT_GE(t.rows.size(), 1u);
  ASSERT_EQ(t.header[0], "load_factor");
  const double w = -t.At(t.rows.size() - 1, "tip.y");
  std::printf("cantilever, P L^2/EI = 1e-4: w = %.10e m, beam theory %.10e m\n", w, P / 3.0);
  EXPECT_NEAR(w / (P / 3.0), 1.0, 1e-6);
}

TEST_F(StaticsCli, SlenderElasticaMatchesMattiasson) {
  // L = 2 m, EI = 1 N m^2, EA/EI = 3e6 1/m^2, P = 2.5 N: P L^2/EI = 10,
  // Mattiasson (1981): w/L = 0.81061, u/L = 0.55500
  const Json s = Statics(StaticsCantilever(2.0, 16, 4.0e-6, 1.3333333333333333e-12, 7.5e11, 2.5));
  EXPECT_EQ(s["load_factor"].number, 1.0);
  EXPECT_GT(s["newton_iterations"].number, 3);
  EXPECT_LT(s["residual"].number, 1e-6);
  const StaticsCsv t = ReadResultsCsv(dir_ / "res" / "results.csv");
  ASSERT_EQ(static_cast<double>(t.rows.size()), s["load_steps"].number);
  const size_t last = t.rows.size() - 1;
  EXPECT_EQ(t.At(last, "load_factor"), 1.0);
  EXPECT_NEAR(-t.At(last, "tip.y") / 2.0, 0.81061, 1e-4);
  EXPECT_NEAR(1.0 - t.At(last, "tip.x") / 2.0, 0.55500, 1e-4);
}

// the jib: a rigid boom of L = 4 m (mj = 100 kg, centre of mass at mid
// length) pinned at the origin about z, held horizontal by a tie (distance
// joint) from its tip to the mast top (0, H = 2, 0); a payload of mp = 50 kg
// hangs 1 m below the tip on a pin about z, released 0.3 rad off the
// vertical. Gravity -y.
std::string StaticsJib(const std::string& analysis) {
  const double a = 0.3;
  std::ostringstream o;
  o.precision(17);
  o << "name: jib\ngravity: [0, -9.81, 0]\nground:\n  markers:\n    - {name: pivot}\n"
    << "    - {name: mast, position: [0, 2, 0]}\nbodies:\n"
    << "  - {name: boom, mass: 100, inertia: [1, 140, 140], position: [2, 0, 0],\n"
    << "     markers: [{name: pivot, position: [-2, 0, 0]}, {name: tip, position: [2, 0, 0]}]}\n"
    << "  - {name: payload, mass: 50, inertia: [2, 2, 2], position: [" << 4.0 + std::sin(a) << ", " << -std::cos(a)
    << ", 0],\n     orientation: {roll_pitch_yaw: [0, 0, " << a << "]}, markers: [{name: hook, position: [0, 1, 0]}]}\n"
    << "joints:\n  - {name: pin, type: revolute, i: ground.pivot, j: boom.pivot}\n"
    << "  - {name: tie, type: distance, i: ground.mast, j: boom.tip}\n"
    << "  - {name: hook, type: revolute, i: boom.tip, j: payload.hook}\n"
    << "sensors:\n  - {name: tie, type: joint_reaction, joint: tie, frame: world}\n"
    << "  - {name: pin, type: joint_reaction, joint: pin, frame: world}\n"
    << "  - {name: load, type: body_position, body: payload}\n"
    << "solver: {analysis: " << analysis << ", t_end: 0.5, dt: 1.0e-3}\noutput: {interval: 0.05}\n";
  return o.str();
}

TEST_F(StaticsCli, JibWithHangingPayloadMatchesHandCalculation) {
  // moments about the pivot: T sin(alpha) L = (mj L/2 + mp L) g with
  // tan(alpha) = H / L; the pin carries (T cos(alpha), (mj + mp) g - T sin(alpha))
  const double g = 9.81, L = 4.0, H = 2.0, mj = 100.0, mp = 50.0;
  const double sa = H / std::hypot(L, H), ca = L / std::hypot(L, H);
  const double T = g * (0.5 * mj + mp) / sa;
  Statics(StaticsJib("dynamics"));
  const StaticsCsv t = ReadResultsCsv(dir_ / "res" / "results.csv");
  ASSERT_GE(t.rows.size(), 1u);
  const size_t last = t.rows.size() - 1;
  std::printf("jib: tie force (%.9f, %.9f) N, hand calculation (%.9f, %.9f) N\n", t.At(last, "tie.fx"),
              t.At(last, "tie.fy"), -T * ca, T * sa);
  EXPECT_NEAR(t.At(last, "tie.fx") / (-T * ca), 1.0, 1e-9);
  EXPECT_NEAR(t.At(last, "tie.fy") / (T * sa), 1.0, 1e-9);
  EXPECT_NEAR(t.At(last, "pin.fx") / (T * ca), 1.0, 1e-9);
  EXPECT_NEAR(t.At(last, "pin.fy") / ((mj + mp) * g - T * sa), 1.0, 1e-9);
  EXPECT_NEAR(t.At(last, "load.x"), L, 1e-9);
  EXPECT_NEAR(t.At(last, "load.y"), -1.0, 1e-9);
}

TEST_F(StaticsCli, AnalysisKeyOfTheModelFile) {
  // solver.analysis: statics makes `flexmb run` a static solve
  WriteFile(dir_ / "statics.yaml", StaticsJib("statics"));
  CliResult r = RunCli(dir_, "run statics.yaml --out a --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  StaticsCsv t = ReadResultsCsv(dir_ / "a" / "results.csv");
  ASSERT_FALSE(t.header.empty());
  EXPECT_EQ(t.header[0], "load_factor");
  EXPECT_NEAR(t.At(t.rows.size() - 1, "load.x"), 4.0, 1e-9);
  // statics_then_dynamics: the run starts at rest in the equilibrium and stays there
  WriteFile(dir_ / "settled.yaml", StaticsJib("statics_then_dynamics"));
  r = RunCli(dir_, "run settled.yaml --out b --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  t = ReadResultsCsv(dir_ / "b" / "results.csv");
  ASSERT_EQ(t.rows.size(), 11u);
  for (size_t k = 0; k < t.rows.size(); ++k) {
    EXPECT_NEAR(t.At(k, "load.x"), 4.0, 1e-8) << "t = " << t.At(k, "time");
    EXPECT_NEAR(t.At(k, "load.yaw"), 0.0, 1e-8) << "t = " << t.At(k, "time");
  }
  // without it the payload swings from its release angle
  WriteFile(dir_ / "swing.yaml", StaticsJib("dynamics"));
  r = RunCli(dir_, "run swing.yaml --out c --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  t = ReadResultsCsv(dir_ / "c" / "results.csv");
  EXPECT_NEAR(t.At(0, "load.yaw"), 0.3, 1e-9);
  // a bad value is an error naming the key
  WriteFile(dir_ / "bad.yaml", StaticsJib("quasistatics"));
  r = RunCli(dir_, "run bad.yaml --out d --quiet");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'analysis' must be"), std::string::npos) << r.err;
}

TEST_F(StaticsCli, NoEquilibriumNamesTheBodyAndTheLoadFactor) {
  WriteFile(dir_ / "falling.yaml",
            "name: falling\nbodies:\n  - {name: stone, mass: 1, inertia: [0.1, 0.1, 0.1]}\n");
  const CliResult r = RunCli(dir_, "statics falling.yaml --out res");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("'stone'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("load factor"), std::string::npos) << r.err;
  Json s;
  ASSERT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "res" / "summary.json"), s));
  EXPECT_EQ(s["status"].string, "failed");
  EXPECT_EQ(s["load_factor"].number, 0.0);
}

}  // namespace statics_cli_test
