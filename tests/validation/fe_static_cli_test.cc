// End-to-end test of "flexmb fe static" (the FLEXMB_CLI binary) on a CBAR
// cantilever (4 elements, L = 2 m, I1 != I2, no shear flexibility: the
// Euler-Bernoulli Hermite element is exact at the nodes under end loads and
// under a uniform load with its consistent load vector): tip deflection
// P L^3 / (3 E I) in both bending planes, twist T L / (G J), self weight
// q L^4 / (8 E I1) with q = rho A g, the load resultant and the strain energy
// 1/2 u.f against the closed forms; a simply supported beam by --support
// (P L^3 / (48 E I)); errors for bad options, a missing node,
// a moment on a node without rotations and a free (singular) model. With
// --second-order: the beam column under an axial force of 0.3 and 0.9 of the
// Euler load and a small lateral tip load against Timoshenko and Gere's
// closed form (compression and tension), and beyond the Euler load a clear
// error.
// References: docs/validation.md, "FE: command line".

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "json_reader.h"

namespace fe_static_cli_test {

using flexmb::testing::CliResult;
using flexmb::testing::Json;
using flexmb::testing::ParseJsonObject;
using flexmb::testing::RunCli;

constexpr double kE = 2.1e11, kNu = 0.3, kRho = 7850.0, kL = 2.0;
constexpr double kA = 1e-3, kI1 = 8e-7, kI2 = 2e-7, kJ = 5e-7;

class FeStaticCli : public flexmb::testing::CliTest {
 protected:
  FeStaticCli() : CliTest("flexmb_fe_static_cli_test_") {}
  void SetUp() override {
    CliTest::SetUp();
    // CBAR along x, v = z: plane 1 = x-z (I1, uz), plane 2 = x-y (I2, uy)
    std::ofstream f(dir_ / "cantilever.bdf");
    f << "BEGIN BULK\nMAT1,1,2.1+11,,0.3,7850.\nPBAR,1,1,1.-3,8.-7,2.-7,5.-7\n";
    for (int k = 0; k <= 4; ++k) f << "GRID," << k + 1 << ",," << 0.5 * k << ",0.,0.\n";
    for (int e = 1; e <= 4; ++e) f << "CBAR," << e << ",1," << e << "," << e + 1 << ",0.,0.,1.\n";
    f << "ENDDATA\n";
  }

  Json Static(const std::string& args) {
    const CliResult r = RunCli(dir_, "fe static cantilever.bdf --fix 1 " + args + " --json");
    EXPECT_EQ(r.code, 0) << r.err;
    Json j;
    EXPECT_TRUE(ParseJsonObject(r.out, j)) << r.out;
    return j;
  }
};

TEST_F(FeStaticCli, CantileverTipLoadsTwistAndWeightAgainstBeamTheory) {
  const double Py = 300.0, Pz = -500.0, T = 40.0, G = kE / (2.0 * (1.0 + kNu));
  Json j = Static("--force 5:0,300,-500,40,0,0");
  ASSERT_EQ(j["nodes"].array.size(), 1u);
  const Json& tip = j["nodes"].array[0];
  EXPECT_EQ(tip["id"].number, 5.0);
  const std::vector<double> u = tip["displacement_m"].Numbers(), r = tip["rotation_rad"].Numbers();
  const double uy = Py * kL * kL * kL / (3.0 * kE * kI2), uz = Pz * kL * kL * kL / (3.0 * kE * kI1);
  EXPECT_NEAR(u[0], 0.0, 1e-15);
  EXPECT_NEAR(u[1], uy, 1e-9 * std::abs(uy));
  EXPECT_NEAR(u[2], uz, 1e-9 * std::abs(uz));
  EXPECT_NEAR(r[0], T * kL / (G * kJ), 1e-9 * T * kL / (G * kJ));
  // slopes P L^2 / (2 E I): rz = duy/dx, ry = -duz/dx
  EXPECT_NEAR(r[2], Py * kL * kL / (2.0 * kE * kI2), 1e-9 * Py * kL * kL / (2.0 * kE * kI2));
  EXPECT_NEAR(r[1], -Pz * kL * kL / (2.0 * kE * kI1), 1e-9 * std::abs(Pz) * kL * kL / (2.0 * kE * kI1));
  const double energy = 0.5 * (Py * uy + Pz * uz + T * T * kL / (G * kJ));
  EXPECT_NEAR(j["strain_energy_j"].number, energy, 1e-9 * energy);
  EXPECT_EQ(j["max_displacement_node"].number, 5.0);
  EXPECT_NEAR(j["max_displacement_m"].number, std::hypot(uy, uz), 1e-9 * std::hypot(uy, uz));
  const std::vector<double> R = j["load_resultant_n"].Numbers();
  EXPECT_NEAR(R[1], Py, 1e-9);
  EXPECT_NEAR(R[2], Pz, 1e-9);

  // self weight, reported at the tip and mid-span: w(x) = q x^2 (6 L^2 - 4 L x + x^2) / (24 E I1)
  j = Static("--gravity 0,0,-9.81 --nodes 3,5");
  const double q = -kRho * kA * 9.81;
  auto w = [&](double x) { return q * x * x * (6.0 * kL * kL - 4.0 * kL * x + x * x) / (24.0 * kE * kI1); };
  ASSERT_EQ(j["nodes"].array.size(), 2u);
  EXPECT_NEAR(j["nodes"].array[0]["displacement_m"].Numbers()[2], w(1.0), 1e-9 * std::abs(w(1.0)));
  EXPECT_NEAR(j["nodes"].array[1]["displacement_m"].Numbers()[2], w(kL), 1e-9 * std::abs(w(kL)));
  EXPECT_NEAR(w(kL), q * kL * kL * kL * kL / (8.0 * kE * kI1), 1e-12);
  EXPECT_NEAR(j["load_resultant_n"].Numbers()[2], q * kL, 1e-9 * std::abs(q * kL));
}

// simply supported: a pin at node 1 (ux uy uz rx), a roller at node 5 (uy uz):
// a mid-span force P gives P L^3 / (48 E I), end slopes P L^2 / (16 E I)
TEST_F(FeStaticCli, SupportsOfSingleComponentsMakeASimplySupportedBeam) {
  const CliResult r = RunCli(dir_, "fe static cantilever.bdf --support 1:1234 --support 5:23 --force 3:0,0,-800 "
                                   "--nodes 3,5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  Json j;
  ASSERT_TRUE(ParseJsonObject(r.out, j)) << r.out;
  EXPECT_EQ(j["supports"].number, 2.0);
  const double P = -800.0, w = P * kL * kL * kL / (48.0 * kE * kI1), slope = -P * kL * kL / (16.0 * kE * kI1);
  EXPECT_NEAR(j["nodes"].array[0]["displacement_m"].Numbers()[2], w, 1e-9 * std::abs(w));
  EXPECT_NEAR(j["nodes"].array[1]["rotation_rad"].Numbers()[1], -slope, 1e-9 * std::abs(slope));
  EXPECT_NEAR(j["nodes"].array[1]["displacement_m"].Numbers()[2], 0.0, 1e-15);
  const CliResult bad = RunCli(dir_, "fe static cantilever.bdf --support 1:1237 --force 3:0,0,-800");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--support '1:1237': components are the digits 1 to 6"), std::string::npos) << bad.err;
}

TEST_F(FeStaticCli, SecondOrderBeamColumnAgainstTimoshenko) {
  // plane 2 (x-y, I2 < I1, the weaker one): Euler load pi^2 E I2 / (4 L^2)
  const double EI = kE * kI2, euler = M_PI * M_PI * EI / (4.0 * kL * kL), H = -50.0;
  const double linear = H * kL * kL * kL / (3.0 * EI);
  for (double f : {-0.9, -0.3, 0.3, 0.9}) {
    const double P = f * euler, k = std::sqrt(std::abs(P) / EI), kl = k * kL;
    const double ref = f < 0 ? H * (std::tan(kl) - kl) / (k * k * k * EI) : H * (kl - std::tanh(kl)) / (k * k * k * EI);
    char load[80];
    std::snprintf(load, sizeof load, "--force 5:%.17g,%.17g,0 --second-order", P, H);
    Json j = Static(load);
    EXPECT_TRUE(j["second_order"].boolean);
    const double uz = j["nodes"].array[0]["displacement_m"].Numbers()[1];
    std::printf("fe static --second-order, P = %+.1f P_Euler: tip %.6e m, Timoshenko %.6e m (x%.3f of linear)\n", f,
                uz, ref, ref / linear);
    EXPECT_NEAR(uz / ref, 1.0, 1e-3) << f;
  }
  // at the Euler load K + K_G is singular or indefinite
  char load[80];
  std::snprintf(load, sizeof load, "--force 5:%.17g,-50,0 --second-order", -1.2 * euler);
  const CliResult r = RunCli(dir_, std::string("fe static cantilever.bdf --fix 1 ") + load);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("beyond the part's first buckling load"), std::string::npos) << r.err;
}

TEST_F(FeStaticCli, TableAndErrors) {
  CliResult r = RunCli(dir_, "fe static cantilever.bdf --fix 1 --force 5:0,0,-500");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("largest displacement"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("5 "), std::string::npos) << r.out;

  // no load; bad numbers; a missing node
  r = RunCli(dir_, "fe static cantilever.bdf --fix 1");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no load"), std::string::npos) << r.err;
  r = RunCli(dir_, "fe static cantilever.bdf --fix 1 --gravity 0,-9.81");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--gravity '0,-9.81': expected 3 numbers, got 2"), std::string::npos) << r.err;
  r = RunCli(dir_, "fe static cantilever.bdf --fix 1 --force 5:1,x,3");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'x' is not a number"), std::string::npos) << r.err;
  r = RunCli(dir_, "fe static cantilever.bdf --fix 1 --force 9:1,2,3");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("cantilever.bdf: node 9"), std::string::npos) << r.err;
  // without support the bar is a mechanism: a numerical error naming a DOF
  r = RunCli(dir_, "fe static cantilever.bdf --force 5:0,0,-500");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("fe static: K with the supports"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(node "), std::string::npos) << r.err;
}

}  // namespace fe_static_cli_test
