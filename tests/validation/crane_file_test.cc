// The crane template (docs/crane-file.md): examples/crane/crane.yaml, a
// crane file, against crane_model.yaml, the same crane written by hand as
// a plain model file (its numbers rounded by hand: the head's radius to
// 0.2 mm, the rope's free length to 0.8 mm, the pads' and the block's
// start in their contacts), the expanded file against the crane file, the
// luffing geometry against the boom's nodes, and bad crane data named by
// file, line and part (docs/validation.md, "Crane file").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include <Eigen/Dense>

#include "flexmb/body_file/body_file.h"
#include "results_csv.h"

namespace crane_file_test {

using flexmb::testing::ReadFile;
using flexmb::testing::ReadResultsCsv;
using flexmb::testing::ResultsCsv;
using flexmb::testing::RunCli;

class CraneFile : public flexmb::testing::CliTest {
 protected:
  CraneFile() : CliTest("crane_file_") {}
  // the boom of `make demo`, built once for the suite
  static std::filesystem::path Boom() {
    static const std::filesystem::path boom = [] {
      const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                        ("flexmb_crane_file_boom_" + std::to_string(::getpid()));
      std::filesystem::create_directories(dir);
      const std::string src = FLEXMB_SOURCE_DIR;
      const std::string gen = "cd '" + dir.string() + "' && /usr/bin/python3 '" + src +
                              "/examples/crane/make_boom.py' --out boom.bdf > make_boom.txt";
      EXPECT_EQ(std::system(gen.c_str()), 0);
      const auto r = RunCli(dir, "reduce boom.bdf --fix 1 --interface 1,2,3 --modes 20 --deformation-stiffening -o boom.h5");
      EXPECT_EQ(r.code, 0) << r.err;
      return dir / "boom.h5";
    }();
    return boom;
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(Boom().parent_path()); }

  void Prepare() {
    const std::string src = FLEXMB_SOURCE_DIR;
    for (const char* f : {"crane.yaml", "crane_model.yaml"})
      std::filesystem::copy_file(src + "/examples/crane/" + f, dir_ / f);
    std::filesystem::copy_file(Boom(), dir_ / "boom.h5");
  }
  // the crane file with `from` replaced by `to` (which must occur once); returns the line of `to`
  int Edit(const std::string& from, const std::string& to) {
    std::string text = ReadFile(dir_ / "crane.yaml");
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
    if (at == std::string::npos) return 0;
    text.replace(at, from.size(), to);
    std::ofstream(dir_ / "edited.yaml") << text;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
  }
};

// the largest |a - b| over a column's rows
double MaxDiff(const ResultsCsv& a, const ResultsCsv& b, const std::string& col) {
  const std::vector<double> x = a.Values(col), y = b.Values(col);
  EXPECT_EQ(x.size(), y.size()) << col;
  double d = 0;
  for (size_t k = 0; k < std::min(x.size(), y.size()); ++k) d = std::max(d, std::abs(x[k] - y[k]));
  return d;
}

double Max(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

TEST_F(CraneFile, BuildsTheCraneOfTheHandWrittenModelFile) {
  ASSERT_NO_FATAL_FAILURE(Prepare());
  // the static equilibrium, load on the ground: the vertical loads (the
  // horizontal pad forces are held by friction, statically indeterminate)
  for (const char* f : {"crane.yaml", "crane_model.yaml"}) {
    const auto r = RunCli(dir_, std::string("statics ") + f + " --out s_" + f + " --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const ResultsCsv a = ReadResultsCsv(dir_ / "s_crane.yaml" / "results.csv");
  const ResultsCsv b = ReadResultsCsv(dir_ / "s_crane_model.yaml" / "results.csv");
  ASSERT_EQ(a.header, b.header);
  for (const char* col : {"pad_fl.fz", "pad_fr.fz", "pad_rr.fz", "pad_rl.fz", "cylinder.fz", "foot_pin.fx", "foot_pin.fy"})
    EXPECT_LT(MaxDiff(a, b, col), 1e-5 * std::abs(b.Values(col).back())) << col;
  for (const char* col : {"top_flange.top_von_mises", "bottom_flange.bottom_von_mises"})
    EXPECT_LT(MaxDiff(a, b, col), 1e-5 * std::abs(b.Values(col).back())) << col;
  for (const char* col : {"head_on_platform.x", "head_on_platform.z"})
    EXPECT_LT(MaxDiff(a, b, col), 2e-5) << col;  // [m]; measured 5e-6 (the hand-written cylinder's place is rounded)

  // the lift-off (6 s): peak rope tension and lift-off time
  for (const char* f : {"crane.yaml", "crane_model.yaml"}) {
    const auto r = RunCli(dir_, std::string("run ") + f + " --out r_" + f + " --t-end 6 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const ResultsCsv ra = ReadResultsCsv(dir_ / "r_crane.yaml" / "results.csv");
  const ResultsCsv rb = ReadResultsCsv(dir_ / "r_crane_model.yaml" / "results.csv");
  ASSERT_EQ(ra.header, rb.header);
  const double peak_a = Max(ra.Values("rope.f")), peak_b = Max(rb.Values("rope.f"));
  EXPECT_NEAR(peak_a, peak_b, 2e-3 * peak_b);
  auto lift_off = [](const ResultsCsv& t) {
    const std::vector<double> time = t.Values("time"), hook = t.Values("hook.z");
    size_t k = 0;
    while (k < hook.size() && hook[k] < hook[0] + 1e-3) ++k;
    return k < hook.size() ? time[k] : -1.0;
  };
  EXPECT_GT(lift_off(rb), 1.0);
  EXPECT_NEAR(lift_off(ra), lift_off(rb), 0.021);  // one output row: 0.8 mm of rope at 0.3 m/s is 3 ms
}

TEST_F(CraneFile, ExpandedFileIsTheSameModelAndLuffsToTheBoomsGeometry) {
  ASSERT_NO_FATAL_FAILURE(Prepare());
  // `crane expand` writes the model the template makes: the same run, bit for bit
  auto r = RunCli(dir_, "crane expand crane.yaml --manoeuvre luffing -o expanded.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = RunCli(dir_, "run expanded.yaml --out e --t-end 13 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  r = RunCli(dir_, "run crane.yaml --manoeuvre luffing --out c --t-end 13 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(ReadFile(dir_ / "e" / "results.csv"), ReadFile(dir_ / "c" / "results.csv"));
  // a manoeuvre the file does not define is an error, as for `run`
  r = RunCli(dir_, "crane expand crane.yaml --manoeuvre nope -o x.yaml");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no manoeuvre named 'nope' in the file (defined: lift_and_slew, "), std::string::npos) << r.err;

  // luffed up to 50 degrees (6 s to 12 s): the cylinder between the platform's
  // pin (1.6, 0, 2.3) and the eye node of the boom turned 50 degrees about
  // the foot pin (1.0, 0, 3.2), from the body file's node coordinates
  const auto body = flexmb::io::ReadBody((dir_ / "boom.h5").string());
  const Eigen::Vector3d foot = body.mesh.nodes[body.mesh.NodeIndex(1)].x, eye = body.mesh.nodes[body.mesh.NodeIndex(3)].x;
  const double a = 50.0 * M_PI / 180.0;
  const Eigen::Vector3d d = eye - foot;
  const Eigen::Vector3d eye_W = Eigen::Vector3d(1.0, 0, 3.2) +
                                Eigen::Vector3d(std::cos(a) * d.x() - std::sin(a) * d.z(), d.y(),
                                                std::sin(a) * d.x() + std::cos(a) * d.z());
  const double length = (eye_W - Eigen::Vector3d(1.6, 0, 2.3)).norm();
  const ResultsCsv t = ReadResultsCsv(dir_ / "c" / "results.csv");
  const std::vector<double> time = t.Values("time"), cyl = t.Values("cylinder_length.value");
  size_t k = 0;
  while (k + 1 < time.size() && time[k] < 12.5) ++k;
  EXPECT_NEAR(cyl[k], length, 1e-6);
  EXPECT_GT(length - cyl[0], 0.1);  // it did luff
}

TEST_F(CraneFile, BadCraneDataNamesFileLineAndPart) {
  ASSERT_NO_FATAL_FAILURE(Prepare());
  struct Case {
    std::string from, to, message;
  };
  const std::vector<Case> cases = {
      {"drum_radius: 0.32", "drum_radius: 0", "crane.winch: 'drum_radius' must be positive"},
      {"slack: 0.05", "slak: 0.05", "unknown key 'slak'"},
      {"nodes: {foot: 1, head: 2, eye: 3}", "nodes: {foot: 1, head: 2, eye: 101}",
       "the eye node 101 is not an interface node"},
      {"luffing_angle_deg: 40", "luffing_angle_deg: 80", "outside its stroke [3.7, 4.7] m"},
      {"to_deg: 50", "to_deg: 78", "the boom at 78 deg needs the luffing cylinder at"},
      {"speed: 0.3, ramp: 0.5, distance: 1.2}\n    slew", "speed: 0.3, ramp: 0.5, distance: 30}\n    slew",
       "would run into the sheave"},
      {"width: 0.8}", "width: 0.8, rope_on_drum: 1.0}", ""},
      {"release_mass: 2000\n", "\n", ""},
      {"distance: 1.2}\n    slew", "distance: 0.1}\n    slew", "shorter than the ramps take"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.to);
    const int line = Edit(c.from, c.to);
    if (c.message.empty()) continue;  // set up below
    const auto r = RunCli(dir_, "check edited.yaml");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    // the line of the edited value, or (derived data) of the crane part holding it
    if (c.message.find("interface") == std::string::npos && c.message.find("stroke [") == std::string::npos)
      EXPECT_NE(r.err.find("edited.yaml:" + std::to_string(line) + ":"), std::string::npos) << r.err;
    else
      EXPECT_NE(r.err.find("edited.yaml:"), std::string::npos) << r.err;
  }
  // a winch paying out more rope than its drum holds: lowering 1.5 m with 1 m on the drum
  Edit("width: 0.8}", "width: 0.8, rope_on_drum: 1.0}");
  std::string text = ReadFile(dir_ / "edited.yaml");
  text.replace(text.find("speed: 0.15, ramp"), 11, "speed: -0.15");
  std::ofstream(dir_ / "edited.yaml") << text;
  auto r = RunCli(dir_, "check edited.yaml");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("more than the 1 m on the drum"), std::string::npos) << r.err;
  // a release time without a part to release
  const int line = Edit("release_mass: 2000\n", "\n");
  (void)line;
  r = RunCli(dir_, "check edited.yaml --manoeuvre release");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'release_time' opens the grab"), std::string::npos) << r.err;
}

// tests/data/crane/pedestal_crane.yaml: a crane on a fixed base (no
// carrier) with a rigid 12 m boom luffed 30 degrees, the 2 t load hanging
// 1 m above the ground on one fall. Its static equilibrium against the
// moment balance written here from the file's data: the rope carries m g;
// the hook hangs where the template put it (the free length is the path
// stretched by the load's weight, and the rigid boom does not give); the
// luffing cylinder's axial force balances, about the foot pin, the boom's
// weight, the rope at the head (the fall down, the lead span towards the
// drum's top) and the eye's transverse force from the cylinder's own
// weight (barrel and rod, pinned at both ends), plus the rod's weight
// along its axis.
// the pedestal crane (tests/data/crane/pedestal_crane.yaml) at rest: its
// luffing cylinder's axial force [N] and length [m] from the moments about
// the foot pin, with `W_head` [N] hanging from the head sheave and the lead
// span pulling the head towards the drum's top with `T_lead` [N]
struct Cylinder {
  double axial, length;
  Eigen::Vector2d u;  // its direction (x, z)
};
Cylinder PedestalCylinder(double W_head, double T_lead) {
  using V2 = Eigen::Vector2d;  // (x, z)
  const double g = 9.81;
  auto cross = [](const V2& r, const V2& f) { return r.x() * f.y() - r.y() * f.x(); };
  const double a = 30.0 * M_PI / 180.0;
  const V2 foot(0.8, 4.0), base(1.4, 3.2), drum_top(-1.5, 4.2 + 0.25);
  auto on_boom = [&](double x, double z) {
    return V2(foot.x() + std::cos(a) * x - std::sin(a) * z, foot.y() + std::sin(a) * x + std::cos(a) * z);
  };
  const V2 com = on_boom(6.0, 0), head = on_boom(12.0, 0), eye = on_boom(3.0, -0.4);
  double moment = cross(com - foot, V2(0, -1500 * g)) + cross(head - foot, V2(0, -W_head)) +
                  cross(head - foot, T_lead * (drum_top - head).normalized());
  const double length = (eye - base).norm();
  const V2 u = (eye - base) / length, n(-u.y(), u.x());
  // the cylinder's weight: barrel's centre 0.9 m from the base pin, rod's 0.9 m from the eye
  const double m_w = cross(0.9 * u, V2(0, -200 * g)) + cross((length - 0.9) * u, V2(0, -80 * g));
  const double q = m_w / length;  // on the boom at the eye, along n
  const double p = -(moment + q * cross(eye - foot, n)) / cross(eye - foot, u);
  return {p + 80 * g * u.y(), length, u};  // axial: in the cylinder's prismatic joint
}

TEST_F(CraneFile, RigidBoomOnAFixedBaseBalancesItsMomentsAboutTheFootPin) {
  const std::string src = FLEXMB_SOURCE_DIR;
  std::filesystem::copy_file(src + "/tests/data/crane/pedestal_crane.yaml", dir_ / "crane.yaml");
  const auto r = RunCli(dir_, "statics crane.yaml --out s --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const ResultsCsv t = ReadResultsCsv(dir_ / "s" / "results.csv");
  auto last = [&](const char* col) { return t.Values(col).back(); };
  const double g = 9.81, m = 2000, T = m * g;
  EXPECT_NEAR(last("rope.f"), T, 1e-9 * T);
  EXPECT_NEAR(last("hook.z"), 1.0 + 0.4 + 1.0, 1e-9);  // clearance + half height + hook height
  const Cylinder c = PedestalCylinder(T, T);
  EXPECT_NEAR(last("cylinder_length.value"), c.length, 1e-12);
  EXPECT_NEAR(std::hypot(last("cylinder.fx"), last("cylinder.fz")), c.axial, 1e-9 * c.axial);
  EXPECT_NEAR(std::atan2(last("cylinder.fz"), last("cylinder.fx")), std::atan2(c.u.y(), c.u.x()), 1e-12);
}

// The same crane with the ANCF rope (docs/crane-file.md, "The ANCF rope"):
// at rest the lead span's tension carries the load and the span's own
// weight on `falls` parts, the hook carries the load, and the cylinder
// balances the head's load plus the span; a grounded load is refused.
TEST_F(CraneFile, AncfRopeAtRestCarriesTheLoadAndItsOwnWeight) {
  const std::string src = FLEXMB_SOURCE_DIR;
  std::filesystem::copy_file(src + "/tests/data/crane/pedestal_crane.yaml", dir_ / "crane.yaml");
  const double g = 9.81, m = 2000, mu = 2.5;  // load [kg], rope [kg/m] (a heavy rope, to be seen)
  for (int falls : {1, 2}) {
    const std::string rope = "rope: {axial_stiffness: 1.0e7, damping_time: 0.002, falls: " + std::to_string(falls) +
                             ", model: ancf, elements: 6, mass_per_length: 2.5, bending_stiffness: 50}";
    Edit("rope: {axial_stiffness: 1.0e7, damping_time: 0.002, falls: 1, slack: 0.02}", rope);
    const auto r = RunCli(dir_, "statics edited.yaml --out s" + std::to_string(falls) + " --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const ResultsCsv t = ReadResultsCsv(dir_ / ("s" + std::to_string(falls)) / "results.csv");
    auto last = [&](const char* col) { return t.Values(col).back(); };
    const double L = last("span_length.x"), W = m * g + falls * mu * g * L;
    EXPECT_GT(L, 5.0);
    EXPECT_NEAR(falls * last("rope.f"), W, 1e-9 * W) << falls << " falls";
    EXPECT_NEAR(last("hook_force.fz"), m * g, 1e-9 * m * g) << falls << " falls";  // the joint holds the load up
    EXPECT_NEAR(last("hook_force.fx"), 0.0, 1e-9 * m * g);
    const Cylinder c = PedestalCylinder(W, last("rope.f"));
    EXPECT_NEAR(std::hypot(last("cylinder.fx"), last("cylinder.fz")), c.axial, 1e-9 * c.axial) << falls << " falls";
  }
  const int line = Edit("clearance: 1.0", "clearance: 0.0");
  std::string text = ReadFile(dir_ / "edited.yaml");
  ASSERT_NE(text.find("slack: 0.02"), std::string::npos);
  text.replace(text.find("slack: 0.02"), 11, "model: ancf, mass_per_length: 2.5, bending_stiffness: 50");
  std::ofstream(dir_ / "edited.yaml") << text;
  const auto r = RunCli(dir_, "statics edited.yaml --out g --quiet");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("edited.yaml:21: crane.rope: the ANCF rope needs the load hanging"), std::string::npos)
      << r.err << " (clearance on line " << line << ")";
}

// Slack and snap with the ANCF rope: the pedestal crane's grab drops 1600
// of its 2000 kg at 0.5 s, the rope rebounds slack and snaps taut again.
// The tension-only lead takes the slack while the span slides back over the
// sheave: no Newton failure at the file's step (5 ms), the first slack
// interval equals the massless rope's to 10 ms (measured 5 ms), the snap's
// peak exceeds twice the static load of what is left on the hook, converges
// with the step (5, 2.5, 1.25 ms: the last two within 0.5 %, measured
// 0.11 %) and equals the massless rope's to 1 % (measured 0.37 %: the
// span's 9 kg against the 400 kg left on the hook).
TEST_F(CraneFile, AncfRopeGoesSlackAndSnapsTautWithoutNewtonFailure) {
  const std::string src = FLEXMB_SOURCE_DIR;
  std::string text = ReadFile(src + "/tests/data/crane/pedestal_crane.yaml");
  auto replace = [&](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("    clearance: 1.0", "    clearance: 1.0\n    release_mass: 1600");
  replace("manoeuvre: slew", "  drop:\n    release_time: 0.5\nmanoeuvre: drop");
  replace("solver: {t_end: 3.0, dt: 0.005,", "output: {interval: DT}\nsolver: {t_end: 2.5, dt: DT,");
  struct Snap {
    double slack_from = -1, slack_to = -1, peak = 0;
  };
  auto run = [&](bool ancf, const char* dt) {
    std::string t = text;
    for (size_t at; (at = t.find("DT")) != std::string::npos;) t.replace(at, 2, dt);
    if (ancf) {
      const size_t at = t.find("slack: 0.02}");
      EXPECT_NE(at, std::string::npos);
      if (at == std::string::npos) return Snap{};
      t.replace(at, 12, "model: ancf, elements: 6, mass_per_length: 1.2, bending_stiffness: 50}");
    }
    const std::string name = std::string(ancf ? "ancf_" : "massless_") + dt;
    std::ofstream(dir_ / (name + ".yaml")) << t;
    const auto r = RunCli(dir_, "run " + name + ".yaml --out " + name + " --quiet");
    EXPECT_EQ(r.code, 0) << r.err;
    Snap s;
    if (r.code != 0) return s;
    const ResultsCsv c = ReadResultsCsv(dir_ / name / "results.csv");
    const std::vector<double> time = c.Values("time"), f = c.Values("rope.f");
    // the first slack interval, and the peak of the snap that ends it
    size_t k = 0;
    while (k < f.size() && f[k] > 0.0) ++k;
    if (k == f.size()) return s;
    s.slack_from = time[k];
    while (k < f.size() && f[k] <= 0.0) ++k;
    if (k == f.size()) return s;
    s.slack_to = time[k];
    for (; k < f.size() && time[k] < s.slack_to + 0.3; ++k) s.peak = std::max(s.peak, f[k]);
    return s;
  };
  const Snap m = run(false, "0.005"), a5 = run(true, "0.005"), a2 = run(true, "0.0025"), a1 = run(true, "0.00125");
  ASSERT_GT(m.slack_from, 0.5) << "the massless rope never went slack";
  ASSERT_GT(a5.slack_from, 0.5) << "the ANCF rope never went slack";
  EXPECT_NEAR(a5.slack_from, m.slack_from, 0.01);
  EXPECT_NEAR(a5.slack_to, m.slack_to, 0.01);
  const double g = 9.81;
  for (const Snap* s : {&a5, &a2, &a1}) EXPECT_GT(s->peak, 2 * 400 * g) << "no snap after the slack";
  EXPECT_NEAR(a2.peak, a1.peak, 0.005 * a1.peak);
  EXPECT_NEAR(a5.peak, m.peak, 0.01 * m.peak);
  std::printf("slack massless %.4f..%.4f s, ANCF %.4f..%.4f s; snap peak massless %.1f N, ANCF %.1f / %.1f / %.1f N\n",
              m.slack_from, m.slack_to, a5.slack_from, a5.slack_to, m.peak, a5.peak, a2.peak, a1.peak);
}

}  // namespace crane_file_test
