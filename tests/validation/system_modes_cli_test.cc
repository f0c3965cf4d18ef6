// Validation of `flexmb modes` (apps/flexmb/commands/modes_command.h)
// through the command line: the modes of model files linearized about their
// static equilibrium against closed forms (docs/validation.md, "Linearized
// modes of the whole machine"): a compound pendulum and a double pendulum of
// rigid bodies (small-oscillation frequencies, 1e-8 relative), a damped
// two-mass quarter car (its characteristic quartic), and the bad inputs: no
// degrees of freedom, no static equilibrium, a (nearly) massless body,
// redundant constraints.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>

#include "cli_runner.h"
#include "json_reader.h"

namespace system_modes_cli_test {

namespace fs = std::filesystem;
using flexmb::testing::CliResult;
using flexmb::testing::Json;
using flexmb::testing::ReadFile;
using flexmb::testing::RunCli;
using flexmb::testing::WriteFile;

constexpr double kG = 9.81;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

class SystemModesCli : public flexmb::testing::CliTest {
 protected:
  SystemModesCli() : CliTest("flexmb_modes_") {}

  // runs `flexmb modes` on `yaml` with `args`; the parsed modes.json
  Json Modes(const std::string& yaml, const std::string& args = "") {
    WriteFile(dir_ / "model.yaml", yaml);
    const CliResult r = RunCli(dir_, "modes model.yaml --out res --quiet " + args);
    EXPECT_EQ(r.code, 0) << r.err;
    Json j;
    EXPECT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "res" / "modes.json"), j));
    Json s;
    EXPECT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "res" / "summary.json"), s));
    EXPECT_EQ(s["status"].string, "ok") << s["message"].string;
    return j;
  }
};

// a body: mass m, principal inertia I about its centre of mass (the body
// origin), at `position`, turned by `yaw` about z, with markers (YAML list)
std::string SystemModesBody(const std::string& name, double m, double I, const std::string& position, double yaw,
                            const std::string& markers) {
  std::ostringstream o;
  o.precision(17);
  o << "  - name: " << name << "\n    mass: " << m << "\n    inertia: [" << I << ", " << I << ", " << I
    << "]\n    position: " << position << "\n    orientation: {roll_pitch_yaw: [0, 0, " << yaw
    << "]}\n    markers: " << markers << "\n";
  return o.str();
}

TEST_F(SystemModesCli, CompoundPendulumAtItsEquilibrium) {
  // m = 2 kg, I_c = 0.05 kg m^2, centre of mass d = 0.6 m below the pin
  // (gravity -y); released 0.2 rad off the vertical, so the static solve has
  // to find the hanging equilibrium: w^2 = m g d / (I_c + m d^2)
  const double m = 2.0, Ic = 0.05, d = 0.6, yaw = 0.2;
  const std::string pos = "[" + std::to_string(d * std::sin(yaw)) + ", " + std::to_string(-d * std::cos(yaw)) + ", 0]";
  const std::string yaml = "name: pendulum\ngravity: [0, -9.81, 0]\nground:\n  markers:\n    - {name: pin}\nbodies:\n" +
                           SystemModesBody("arm", m, Ic, pos, yaw, "[{name: pin, position: [0, 0.6, 0]}]") +
                           "joints:\n  - {name: pin, type: revolute, i: ground.pin, j: arm.pin}\n";
  const Json j = Modes(yaml);
  ASSERT_EQ(j["modes"].array.size(), 1u);
  EXPECT_EQ(j["dof"].number, 1);
  EXPECT_EQ(j["rigid_modes"].number, 0);
  const Json& md = j["modes"].array[0];
  const double f = std::sqrt(m * kG * d / (Ic + m * d * d)) / kTwoPi;
  EXPECT_EQ(md["kind"].string, "oscillatory");
  EXPECT_NEAR(md["frequency_hz"].number / f - 1.0, 0.0, 1e-8);
  EXPECT_EQ(md["damping_ratio"].number, 0.0);
  // the shape: the rotation about z of the arm (body axes = world z here)
  // and the velocity of its centre of mass, w x r with r = (0, -d, 0)
  const std::vector<double> x = md["shape"].Numbers();
  ASSERT_EQ(x.size(), 6u);
  EXPECT_NEAR(x[5], 1.0, 1e-9);
  EXPECT_NEAR(x[0], d, 1e-9);
  EXPECT_NEAR(x[1], 0.0, 1e-9);
  // the animation of the mode: one period, 25 frames
  const std::string pvd = ReadFile(dir_ / "res" / "mode_1" / "anim.pvd");
  EXPECT_NE(pvd.find("frame_00024.vtu"), std::string::npos) << pvd.substr(0, 400);
}

TEST_F(SystemModesCli, DoublePendulumOfRigidBodies) {
  // two rigid links: centres of mass d1, d2 below their pins, upper pin to
  // elbow l1; in the absolute angles M = [[I1 + m1 d1^2 + m2 l1^2, m2 l1 d2],
  // [m2 l1 d2, I2 + m2 d2^2]], K = diag((m1 d1 + m2 l1) g, m2 d2 g), and
  // det(K - w^2 M) = 0 is a quadratic in w^2
  const double m1 = 1.5, I1 = 0.04, d1 = 0.3, l1 = 0.7, m2 = 0.8, I2 = 0.01, d2 = 0.25;
  const std::string yaml =
      "name: double_pendulum\ngravity: [0, -9.81, 0]\nground:\n  markers:\n    - {name: pin}\nbodies:\n" +
      SystemModesBody("upper", m1, I1, "[0, -0.3, 0]", 0.0,
                      "[{name: pin, position: [0, 0.3, 0]}, {name: elbow, position: [0, -0.4, 0]}]") +
      SystemModesBody("lower", m2, I2, "[0.05, -0.95, 0]", 0.1, "[{name: elbow, position: [0, 0.25, 0]}]") +
      "joints:\n  - {name: pin, type: revolute, i: ground.pin, j: upper.pin}\n"
      "  - {name: elbow, type: revolute, i: upper.elbow, j: lower.elbow}\n";
  const Json j = Modes(yaml);
  ASSERT_EQ(j["modes"].array.size(), 2u);
  const double M11 = I1 + m1 * d1 * d1 + m2 * l1 * l1, M12 = m2 * l1 * d2, M22 = I2 + m2 * d2 * d2;
  const double K11 = (m1 * d1 + m2 * l1) * kG, K22 = m2 * d2 * kG;
  const double a = M11 * M22 - M12 * M12, b = M11 * K22 + M22 * K11, c = K11 * K22;
  const double disc = std::sqrt(b * b - 4.0 * a * c);
  const double w1 = std::sqrt((b - disc) / (2.0 * a)), w2 = std::sqrt(2.0 * c / (b - disc));
  EXPECT_NEAR(j["modes"].array[0]["frequency_hz"].number / (w1 / kTwoPi) - 1.0, 0.0, 1e-8);
  EXPECT_NEAR(j["modes"].array[1]["frequency_hz"].number / (w2 / kTwoPi) - 1.0, 0.0, 1e-8);
}

// the quarter car: sprung mass ms on the suspension (ks, cs) on the
// unsprung mass mu on the tire (kt), both guided vertically by prismatic
// joints, gravity -z
const double kQcMs = 400.0, kQcMu = 40.0, kQcKs = 20000.0, kQcCs = 1500.0, kQcKt = 200000.0;

std::string QuarterCar() {
  return "name: quarter_car\ngravity: [0, 0, -9.81]\nground:\n  markers:\n    - {name: road}\nbodies:\n" +
         SystemModesBody("body", kQcMs, 50.0, "[0, 0, 1.0]", 0.0, "[{name: c}]") +
         SystemModesBody("wheel", kQcMu, 1.0, "[0, 0, 0.4]", 0.0, "[{name: c}]") +
         "joints:\n  - {name: body_guide, type: prismatic, i: ground.road, j: body.c}\n"
         "  - {name: wheel_guide, type: prismatic, i: ground.road, j: wheel.c}\n"
         "forces:\n  - {name: suspension, type: spring_damper, i: wheel.c, j: body.c, stiffness: " +
         std::to_string(kQcKs) + ", damping: " + std::to_string(kQcCs) +
         "}\n  - {name: tire, type: spring_damper, i: ground.road, j: wheel.c, stiffness: " + std::to_string(kQcKt) +
         "}\n";
}

TEST_F(SystemModesCli, DampedQuarterCar) {
  // det(s^2 M + s C + K) = ms mu s^4 + cs (ms + mu) s^3 + (ms (ks + kt) + mu ks) s^2
  //                        + cs kt s + ks kt: each reported eigenvalue is a
  // root, and the two pairs satisfy Vieta's product and sum
  const Json j = Modes(QuarterCar());
  ASSERT_EQ(j["modes"].array.size(), 2u);
  const double p[5] = {kQcMs * kQcMu, kQcCs * (kQcMs + kQcMu), kQcMs * (kQcKs + kQcKt) + kQcMu * kQcKs, kQcCs * kQcKt,
                       kQcKs * kQcKt};
  std::complex<double> prod = 1.0, sum = 0.0;
  for (const Json& md : j["modes"].array) {
    ASSERT_EQ(md["kind"].string, "oscillatory");
    const std::complex<double> s(md["eigenvalue"].array[0].number, md["eigenvalue"].array[1].number);
    std::complex<double> val = 0.0;
    double scale = 0.0;
    for (int k = 0; k < 5; ++k) {
      val = val * s + p[k];
      scale += std::abs(p[k]) * std::pow(std::abs(s), 4 - k);
    }
    EXPECT_LT(std::abs(val) / scale, 1e-12);
    prod *= s * std::conj(s);
    sum += s + std::conj(s);
    EXPECT_NEAR(md["damping_ratio"].number, -s.real() / std::abs(s), 1e-12);
    EXPECT_NEAR(md["frequency_hz"].number, std::abs(s) / kTwoPi, 1e-9);
  }
  EXPECT_NEAR(prod.real() / (p[4] / p[0]) - 1.0, 0.0, 1e-10);
  EXPECT_NEAR(sum.real() / (-p[1] / p[0]) - 1.0, 0.0, 1e-10);
  // body bounce near sqrt(ks kt / (ks + kt) / ms), wheel hop near sqrt((ks + kt) / mu)
  const double f1 = std::sqrt(kQcKs * kQcKt / (kQcKs + kQcKt) / kQcMs) / kTwoPi;
  const double f2 = std::sqrt((kQcKs + kQcKt) / kQcMu) / kTwoPi;
  EXPECT_NEAR(j["modes"].array[0]["frequency_hz"].number / f1, 1.0, 0.03);
  EXPECT_NEAR(j["modes"].array[1]["frequency_hz"].number / f2, 1.0, 0.03);
}

TEST_F(SystemModesCli, FreeBodyHasSixRigidModes) {
  // a free rigid body without gravity: six rigid-body modes, no vibration;
  // --at initial (a free body has no static equilibrium to solve for)
  const std::string yaml = "name: free\ngravity: [0, 0, 0]\nbodies:\n" +
                           SystemModesBody("block", 3.0, 0.2, "[0, 0, 0]", 0.3, "[]");
  const Json j = Modes(yaml, "--at initial");
  EXPECT_EQ(j["rigid_modes"].number, 6);
  ASSERT_EQ(j["modes"].array.size(), 6u);
  for (const Json& md : j["modes"].array) EXPECT_EQ(md["kind"].string, "rigid");
}

TEST_F(SystemModesCli, BadInputsAreNamedWithoutNaN) {
  // no degrees of freedom: the arm welded to the ground
  WriteFile(dir_ / "fixed.yaml", "name: fixed\nbodies:\n" + SystemModesBody("arm", 1.0, 0.1, "[0, 0, 0]", 0.0,
                                                                             "[{name: m}]") +
                                     "ground:\n  markers:\n    - {name: m}\n"
                                     "joints:\n  - {name: weld, type: fixed, i: ground.m, j: arm.m}\n");
  CliResult r = RunCli(dir_, "modes fixed.yaml --out a --quiet");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no degrees of freedom"), std::string::npos) << r.err;
  Json s;
  ASSERT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "a" / "summary.json"), s));
  EXPECT_EQ(s["status"].string, "failed");

  // no static equilibrium: a free body falling under gravity
  WriteFile(dir_ / "falling.yaml",
            "name: falling\nbodies:\n" + SystemModesBody("stone", 1.0, 0.1, "[0, 0, 0]", 0.0, "[]"));
  r = RunCli(dir_, "modes falling.yaml --out b --quiet");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no static equilibrium"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'stone'"), std::string::npos) << r.err;
  EXPECT_EQ(ReadFile(dir_ / "b" / "summary.json").find("NaN"), std::string::npos);

  // a (nearly) massless body on a pendulum: named
  WriteFile(dir_ / "massless.yaml",
            "name: massless\ngravity: [0, -9.81, 0]\nground:\n  markers:\n    - {name: pin}\nbodies:\n" +
                SystemModesBody("arm", 1.0, 0.1, "[0, -0.5, 0]", 0.0, "[{name: pin, position: [0, 0.5, 0]}, {name: tip, position: [0, -0.5, 0]}]") +
                SystemModesBody("feather", 1e-20, 1e-20, "[0, -1.0, 0]", 0.0, "[{name: top}]") +
                "joints:\n  - {name: pin, type: revolute, i: ground.pin, j: arm.pin}\n"
                "  - {name: ball, type: spherical, i: arm.tip, j: feather.top}\n");
  r = RunCli(dir_, "modes massless.yaml --out c --quiet --at initial");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("singular mass matrix"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'feather'"), std::string::npos) << r.err;
}

// a hanging parallelogram four-bar: two cranks (mc, Ic about their centres
// of mass at dc = 0.4 m below the ground pivots (0, 0) and (1, 0)) of
// length l = 0.8 m and a coupler mp between their ends, all revolutes about
// z, gravity -y (4 revolutes on 3 planar bodies: redundant equations);
// initial crank rate w0 [rad/s]
const double kFbMc = 1.0, kFbIc = 0.05, kFbD = 0.4, kFbL = 0.8, kFbMp = 2.0;

std::string FourBar(double w0, const std::string& solver) {
  const std::string v = std::to_string(kFbD * w0), vp = std::to_string(kFbL * w0), w = std::to_string(w0);
  const auto crank = [&](const std::string& name, double x) {
    return "  - {name: " + name + ", mass: 1, inertia: [0.05, 0.05, 0.05], position: [" + std::to_string(x) +
           ", -0.4, 0], velocity: [" + v + ", 0, 0], angular_velocity: [0, 0, " + w +
           "],\n     markers: [{name: top, position: [0, 0.4, 0]}, {name: bottom, position: [0, -0.4, 0]}]}\n";
  };
  return "name: four_bar\ngravity: [0, -9.81, 0]\nground:\n  markers:\n    - {name: a}\n    - {name: b, position: [1, 0, "
         "0]}\nbodies:\n" +
         crank("left", 0.0) + crank("right", 1.0) +
         "  - {name: coupler, mass: 2, inertia: [0.3, 0.3, 0.3], position: [0.5, -0.8, 0], velocity: [" + vp +
         ", 0, 0],\n     markers: [{name: l, position: [-0.5, 0, 0]}, {name: r, position: [0.5, 0, 0]}]}\n"
         "joints:\n  - {name: a, type: revolute, i: ground.a, j: left.top}\n"
         "  - {name: b, type: revolute, i: ground.b, j: right.top}\n"
         "  - {name: l, type: revolute, i: left.bottom, j: coupler.l}\n"
         "  - {name: r, type: revolute, i: right.bottom, j: coupler.r}\n"
         "sensors:\n  - {name: crank, type: joint_coordinate, joint: a}\n" + solver;
}

TEST_F(SystemModesCli, FourBarAgainstClosedFormAndNonlinearPeriod) {
  // closed form of the parallelogram: the coupler translates on a circle of
  // radius l, w^2 = (2 mc g d + mp g l) / (2 (Ic + mc d^2) + mp l^2)
  const double w2 = (2.0 * kFbMc * kG * kFbD + kFbMp * kG * kFbL) / (2.0 * (kFbIc + kFbMc * kFbD * kFbD) + kFbMp * kFbL * kFbL);
  const Json j = Modes(FourBar(0.0, ""));
  ASSERT_EQ(j["modes"].array.size(), 1u);
  const double f = j["modes"].array[0]["frequency_hz"].number;
  EXPECT_NEAR(f / (std::sqrt(w2) / kTwoPi), 1.0, 1e-8);
  Json s;
  ASSERT_TRUE(flexmb::testing::ParseJsonObject(ReadFile(dir_ / "res" / "summary.json"), s));
  EXPECT_GT(s["redundant_constraints"].number, 0);
  ASSERT_FALSE(s["redundant"].array.empty());
  EXPECT_NE(s["redundant"].array[0].string.find("joint '"), std::string::npos);

  // the period of the nonlinear simulation at 0.01 rad amplitude (amplitude
  // shift theta0^2 / 16 ~ 6e-6, trapezoidal period error (w h)^2 / 12 ~ 1e-6):
  // upward zero crossings of the crank angle over 4 periods
  const double w0 = 0.01 * std::sqrt(w2);
  WriteFile(dir_ / "sim.yaml", FourBar(w0, "solver: {t_end: 7.5, dt: 1.0e-3, rho_inf: 1.0}\noutput: {interval: 1.0e-3}\n"));
  const CliResult r = RunCli(dir_, "run sim.yaml --out sim --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream in(ReadFile(dir_ / "sim" / "results.csv"));
  std::string line;
  std::getline(in, line);
  std::vector<double> up;
  double t0 = 0.0, a0 = 0.0;
  bool first = true;
  while (std::getline(in, line)) {
    const double t = std::stod(line), a = std::stod(line.substr(line.find(',') + 1));
    if (!first && a0 < 0.0 && a >= 0.0) up.push_back(t0 + (t - t0) * (-a0) / (a - a0));
    t0 = t, a0 = a, first = false;
  }
  ASSERT_GE(up.size(), 4u);
  const double period = (up.back() - up.front()) / (up.size() - 1);
  std::printf("four-bar: linearized %.9f Hz, nonlinear simulation %.9f Hz\n", f, 1.0 / period);
  EXPECT_NEAR(f * period, 1.0, 1e-4);
}

}  // namespace system_modes_cli_test
