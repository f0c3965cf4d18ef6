// 3-node beams (B32R) against CalculiX (ccx 2.20) and beam theory: a steel
// cantilever 2 m long with a rectangular 0.05 m x 0.08 m section whose
// local 1-axis is the global y (n1 = (0, 1, 0)), n B32R elements, clamped
// at x = 0. The same deck goes to ccx, which expands each beam into C3D20R
// bricks (CalculiX manual, "Three-node 3D beam element"), and to flexmb's
// Abaqus reader (fe/elements/beam3.h, two exact Timoshenko halves):
// - static, tip loads of 100 N along y and 200 N along z: flexmb equals the
//   Timoshenko cantilever F L^3 / (3 E I) + F L / (k G A) (k = Cowper's
//   10 (1 + nu) / (12 + 11 nu), the reader's) to 1e-9 at every n; ccx's
//   expanded bricks are stiffer and converge towards it (the CalculiX
//   manual's own cantilever, "Cantilever beam using beam elements": 5 B32R
//   2.4 % short of beam theory): from n = 20 to n = 80 its difference
//   must fall by half and end below 0.3 % (what is left is 3-D elasticity
//   at the clamped end);
// - modes: the four lowest bending frequencies, two per plane, the same way;
// - contrast: the section turned by 90 degrees (n1 = (0, 0, 1)) moves the
//   tip along y far more, so the comparison sees the section's orientation.
// Sources: docs/validation.md, "FE: 3-node beam".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/beam3.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"

namespace flexmb::fe {
namespace fe_beam3_calculix_test {

using flexmb::testing::CcxScratchDir;
using flexmb::testing::HaveCcx;
using flexmb::testing::kCcxE;
using flexmb::testing::kCcxNu;
using flexmb::testing::kCcxRho;
using flexmb::testing::MaxRelDiff;
using flexmb::testing::ParseCcxDisplacements;
using flexmb::testing::ParseCcxFrequencies;
using flexmb::testing::RunCcx;

constexpr double kL = 2.0, kA = 0.05, kB = 0.08, kFy = 100.0, kFz = 200.0;

// the deck of n elements: `n1` the section's local 1-axis, `step` the step's cards
std::string Deck(int n, const std::string& n1, const std::string& step, const std::string& section = "") {
  std::ostringstream d;
  d.precision(17);
  d << "*NODE, NSET=NALL\n";
  for (int i = 0; i <= 2 * n; ++i) d << i + 1 << ", " << kL * i / (2 * n) << ", 0., 0.\n";
  d << "*ELEMENT, TYPE=B32R, ELSET=EBEAM\n";
  for (int e = 0; e < n; ++e) d << e + 1 << ", " << 2 * e + 1 << ", " << 2 * e + 2 << ", " << 2 * e + 3 << "\n";
  d << "*NSET, NSET=TIP\n" << 2 * n + 1 << "\n*BOUNDARY\n1, 1, 6\n"
    << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << kCcxE << ", " << kCcxNu << "\n*DENSITY\n" << kCcxRho << "\n"
    << "*BEAM SECTION, ELSET=EBEAM, MATERIAL=STEEL, SECTION="
    << (section.empty() ? "RECT\n" + std::to_string(kA) + ", " + std::to_string(kB) : section) << "\n" << n1 << "\n"
    << "*STEP\n" << step << "*END STEP\n";
  return d.str();
}

const char* const kStatic = "*STATIC\n*CLOAD\nTIP, 2, 100.\nTIP, 3, 200.\n*NODE PRINT, NSET=TIP\nU\n";

// flexmb's tip displacement under the deck's loads
Vec3 FlexmbTip(const Mesh& m) {
  const AssembledModel a = Assemble(m);
  const int tip = m.node_sets.at("TIP").front();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(a.dofs.n_full);
  f[a.dofs.full[tip][1]] = kFy;
  f[a.dofs.full[tip][2]] = kFz;
  const Eigen::MatrixXd k(a.K);
  const Eigen::VectorXd u = a.T * k.ldlt().solve(a.T.transpose() * f);
  return Vec3(u[a.dofs.full[tip][0]], u[a.dofs.full[tip][1]], u[a.dofs.full[tip][2]]);
}

// |a - b| / |b|
double Rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(Beam3Calculix, CantileverTipDeflectionConvergesToBeamTheory) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const double G = kCcxE / (2.0 * (1.0 + kCcxNu)), area = kA * kB, k = 10.0 * (1.0 + kCcxNu) / (12.0 + 11.0 * kCcxNu);
  // local 1 = y (width a), local 2 = z (height b): bending along y uses b a^3 / 12
  const double uy = kFy * std::pow(kL, 3) / (3.0 * kCcxE * kB * std::pow(kA, 3) / 12.0) + kFy * kL / (k * G * area);
  const double uz = kFz * std::pow(kL, 3) / (3.0 * kCcxE * kA * std::pow(kB, 3) / 12.0) + kFz * kL / (k * G * area);
  std::vector<double> diff_y, diff_z;
  for (int n : {20, 80}) {
    CcxScratchDir dir("beam3_static_" + std::to_string(n));
    ASSERT_TRUE(RunCcx(dir.path, "job", Deck(n, "0., 1., 0.", kStatic)));
    const Vec3 ccx = ParseCcxDisplacements(dir.path / "job.dat", "TIP").at(2 * n + 1);
    const Mesh mesh = io::ReadAbaqus((dir.path / "job.inp").string());
    ASSERT_EQ(mesh.elements.front().type, kBeam3);
    const Vec3 ours = FlexmbTip(mesh);
    std::printf("  n = %d: tip uy ccx %.7e, flexmb %.7e, Timoshenko %.7e\n", n, ccx.y(), ours.y(), uy);
    std::printf("  n = %d: tip uz ccx %.7e, flexmb %.7e, Timoshenko %.7e\n", n, ccx.z(), ours.z(), uz);
    EXPECT_NEAR(ours.y(), uy, 1e-9 * uy);  // exact elements under end loads
    EXPECT_NEAR(ours.z(), uz, 1e-9 * uz);
    diff_y.push_back(Rel(ccx.y(), ours.y()));
    diff_z.push_back(Rel(ccx.z(), ours.z()));
  }
  std::printf("  ccx - flexmb: uy %.2e -> %.2e, uz %.2e -> %.2e\n", diff_y[0], diff_y[1], diff_z[0], diff_z[1]);
  EXPECT_LT(diff_y[1], 0.5 * diff_y[0]);
  EXPECT_LT(diff_z[1], 0.5 * diff_z[0]);
  EXPECT_LT(diff_y[1], 3e-3);
  EXPECT_LT(diff_z[1], 3e-3);
  // the section turned: the comparison sees the orientation
  CcxScratchDir turned("beam3_turned");
  std::ofstream(turned.path / "job.inp") << Deck(20, "0., 0., 1.", kStatic);
  const Vec3 swapped = FlexmbTip(io::ReadAbaqus((turned.path / "job.inp").string()));
  EXPECT_GT(Rel(swapped.y(), uy), 0.5);
}

TEST(Beam3Calculix, BendingFrequenciesConvergeToFlexmbs) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  // the four lowest are bending modes (about 10, 17, 65 and 104 Hz: the first
  // and second in y, the first and second in z); torsion lies near 330 Hz
  std::vector<double> diff;
  for (int n : {20, 80}) {
    CcxScratchDir dir("beam3_modes_" + std::to_string(n));
    ASSERT_TRUE(RunCcx(dir.path, "job", Deck(n, "0., 1., 0.", "*FREQUENCY\n4\n")));
    const std::vector<double> all = ParseCcxFrequencies(dir.path / "job.dat");
    ASSERT_GE(all.size(), 4u);
    const std::vector<double> ccx(all.begin(), all.begin() + 4);
    const std::vector<double> ours = flexmb::testing::FlexmbFrequencies(Assemble(io::ReadAbaqus((dir.path / "job.inp").string())), 4);
    flexmb::testing::PrintFrequencies(("ccx B32R, n = " + std::to_string(n)).c_str(), ccx);
    flexmb::testing::PrintFrequencies(("flexmb beam3, n = " + std::to_string(n)).c_str(), ours);
    diff.push_back(MaxRelDiff(ccx, ours));
  }
  std::printf("  ccx - flexmb, largest of the four: %.2e -> %.2e\n", diff[0], diff[1]);
  EXPECT_LT(diff[1], 0.5 * diff[0]);
  EXPECT_LT(diff[1], 3e-3);
}

// CalculiX's SECTION=CIRC value is the diameter (the CalculiX manual: "the
// thickness of a section is the distance between the free surfaces, i.e.
// for a circular section it is the diameter"); Abaqus's is the radius, and
// flexmb reads it so, with a warning. The workaround the warning names, a
// PIPE with the radius and a wall as thick as the radius, gives ccx's beam:
// tip deflection of a CIRC 0.02 m cantilever (80 B32R) against flexmb's
// PIPE 0.01, 0.01 within 1 % (measured 0.57 %: ccx expands a round section
// into a covering brick with its own integration points), and 16 times off
// with CIRC 0.02 read as the radius
TEST(Beam3Calculix, CalculixCircIsADiameterAndPipeGivesItsBeam) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const int n = 80;
  CcxScratchDir dir("beam3_circ");
  ASSERT_TRUE(RunCcx(dir.path, "job", Deck(n, "0., 1., 0.", kStatic, "CIRC\n0.02")));
  const Vec3 ccx = ParseCcxDisplacements(dir.path / "job.dat", "TIP").at(2 * n + 1);
  std::ofstream(dir.path / "pipe.inp") << Deck(n, "0., 1., 0.", kStatic, "PIPE\n0.01, 0.01");
  const Vec3 pipe = FlexmbTip(io::ReadAbaqus((dir.path / "pipe.inp").string()));
  const Vec3 radius = FlexmbTip(io::ReadAbaqus((dir.path / "job.inp").string()));
  std::printf("  CIRC 0.02 tip uy: ccx %.7e, flexmb PIPE 0.01, 0.01 %.7e, flexmb CIRC as radius %.7e\n", ccx.y(),
              pipe.y(), radius.y());
  EXPECT_LT(Rel(pipe.y(), ccx.y()), 1e-2);
  EXPECT_NEAR(ccx.y() / radius.y(), 16.0, 0.2);
}

}  // namespace fe_beam3_calculix_test
}  // namespace flexmb::fe
