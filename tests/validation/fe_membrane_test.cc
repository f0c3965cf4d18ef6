// Membranes (a Nastran PSHELL without MID2, an Abaqus *MEMBRANE SECTION)
// through the reader, the assembly and a static solve, against beam
// theory: a thin-walled square box cantilever (a = 0.2 m, t = 2 mm, L = 2
// m, steel) whose four walls are membranes, one element across each wall,
// so that every node sits at a corner where two walls meet and the
// structure carries the tip load by membrane action alone (flanges in
// tension and compression, webs in shear). Its tip deflection under a
// vertical load P at the four tip corners is Timoshenko's P L^3 / (3 E I)
// + P L / (G A_web), with I = 2 a t (a/2)^2 + 2 t a^3 / 12 of the walls'
// mid-lines and A_web = 2 a t. The deflection on 10, 20 and 40 elements
// along converges to it (at about first order: the clamped root's shear
// lag), and Aitken's extrapolation of the three is within 0.1 %. CalculiX's own M3D4 gives 1.0838e-3 m on the 10-element
// box, 11 % stiffer than beam theory (its membranes are expanded into
// hinged volume elements), so it is not used as the reference here
// (docs/validation.md, "Membranes").

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace fe_membrane_test {

constexpr double kA = 0.2, kT = 0.002, kL = 2.0, kE = 2.1e11, kNu = 0.3, kP = 1000.0;

// corner c (0..3, counter-clockwise in y-z) of section i: node id
int Id(int i, int c) { return 4 * i + c + 1; }

// the box as Nastran bulk data, n elements along x, clamped (123) at x = 0
std::string BoxDeck(int n, const std::string& pshell) {
  const double y[4] = {-kA / 2, kA / 2, kA / 2, -kA / 2}, z[4] = {-kA / 2, -kA / 2, kA / 2, kA / 2};
  std::ostringstream d;
  d.precision(17);
  d << "BEGIN BULK\nMAT1,1," << kE << ",," << kNu << ",7850.\n" << pshell;
  for (int i = 0; i <= n; ++i)
    for (int c = 0; c < 4; ++c) d << "GRID," << Id(i, c) << ",," << kL * i / n << "," << y[c] << "," << z[c] << "\n";
  int e = 0;
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 4; ++c)
      d << "CQUAD4," << ++e << ",1," << Id(i, c) << "," << Id(i + 1, c) << "," << Id(i + 1, (c + 1) % 4) << ","
        << Id(i, (c + 1) % 4) << "\n";
  d << "SPC1,1,123,1,2,3,4\nENDDATA\n";
  return d.str();
}

// the tip's mean vertical deflection under P shared by the four tip corners [m]
double TipDeflection(const Mesh& m, int n) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * static_cast<Eigen::Index>(m.nodes.size()));
  for (int c = 0; c < 4; ++c) f(6 * m.NodeIndex(Id(n, c)) + 2) = -kP / 4;
  const Eigen::VectorXd u = SolveStatic(m, f);
  double w = 0.0;
  for (int c = 0; c < 4; ++c) w -= u(6 * m.NodeIndex(Id(n, c)) + 2) / 4;
  return w;
}

TEST(Membranes, ThinWalledBoxOfMembranesBendsAsTimoshenkoBeam) {
  const double g = kE / (2 * (1 + kNu));
  const double inertia = 2 * kA * kT * (kA / 2) * (kA / 2) + 2 * kT * kA * kA * kA / 12;
  const double exact = kP * kL * kL * kL / (3 * kE * inertia) + kP * kL / (g * 2 * kA * kT);
  const std::string membrane = "PSHELL,1,1," + std::to_string(kT) + "\n";
  double w[3];
  int k = 0;
  for (int n : {10, 20, 40}) {
    const Mesh m = ReadDeckText(BoxDeck(n, membrane), "box.bdf");
    // membranes only: three DOF per node
    EXPECT_EQ(Assemble(m).dofs.n_full, 3 * 4 * (n + 1));
    w[k] = TipDeflection(m, n);
    std::printf("  %2d elements along: tip %.7e m, / Timoshenko %.6f\n", n, w[k], w[k] / exact);
    ++k;
  }
  // the error falls with the mesh
  EXPECT_LT(std::abs(w[1] / exact - 1), std::abs(w[0] / exact - 1));
  EXPECT_LT(std::abs(w[2] / exact - 1), std::abs(w[1] / exact - 1));
  // and the limit is beam theory: Aitken's delta-squared extrapolation,
  // which needs no assumed order (the ratios of the differences are 2.2-2.5)
  const double d1 = w[1] - w[0], d2 = w[2] - w[1];
  EXPECT_GT(d1 / d2, 2.0);
  const double extrapolated = w[2] - d2 * d2 / (d2 - d1);
  std::printf("  Timoshenko %.7e m, Aitken's extrapolation / exact - 1 = %.2e\n", exact, extrapolated / exact - 1);
  EXPECT_LT(std::abs(extrapolated / exact - 1), 1e-3);
}

// the 10-element box as an Abaqus deck of M3D4 under *MEMBRANE SECTION:
// the same deflection to round-off; and the box of bending shells (the
// PSHELL with MID2) is not the same model
TEST(Membranes, AbaqusM3D4BoxEqualsTheNastranMembraneBox) {
  const int n = 10;
  const Mesh nas = ReadDeckText(BoxDeck(n, "PSHELL,1,1," + std::to_string(kT) + "\n"), "box10.bdf");
  std::ostringstream d;
  d.precision(17);
  d << "*NODE\n";
  for (const Node& node : nas.nodes) d << node.id << "," << node.x.x() << "," << node.x.y() << "," << node.x.z() << "\n";
  d << "*ELEMENT, TYPE=M3D4, ELSET=WALLS\n";
  for (const Element& e : nas.elements)
    d << e.id << "," << nas.nodes[e.nodes[0]].id << "," << nas.nodes[e.nodes[1]].id << ","
      << nas.nodes[e.nodes[2]].id << "," << nas.nodes[e.nodes[3]].id << "\n";
  d << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << kE << "," << kNu << "\n*DENSITY\n7850.\n"
    << "*MEMBRANE SECTION, ELSET=WALLS, MATERIAL=STEEL\n" << kT << "\n*BOUNDARY\n1,1,3\n2,1,3\n3,1,3\n4,1,3\n";
  const Mesh abq = ReadDeckText(d.str(), "box10.inp", true);
  const double w_nas = TipDeflection(nas, n), w_abq = TipDeflection(abq, n);
  EXPECT_NEAR(w_abq, w_nas, 1e-12 * w_nas);
  const Mesh shells = ReadDeckText(BoxDeck(n, "PSHELL,1,1," + std::to_string(kT) + ",1\n"), "box10s.bdf");
  const double w_shell = TipDeflection(shells, n);
  std::printf("  10 along: membranes %.7e m, bending shells %.7e m\n", w_nas, w_shell);
  EXPECT_GT(std::abs(w_shell / w_nas - 1), 1e-3);
}

}  // namespace fe_membrane_test
}  // namespace flexmb::fe::validation
