// Nastran CSHEAR / PSHEAR (fe/elements/shear4.h) in the classic idealized
// structure it is made for: a rectangular bay a x b of four pin-jointed
// CRODs (area A) stiffened by one shear panel (thickness t), node 1 pinned,
// node 2 on a roller, a horizontal load H at the top-left node 4. Without
// the panel the frame is a mechanism (racking); with it, statics gives the
// panel's shear force H (shear flow H / a, strain H / (G t a)) and the rods'
// end forces, and the virtual work of the discrete structure gives, by hand:
//   u4 = H b / (G t a) + H a / (2 E A) + H b^3 / (2 a^2 E A),
//   u2 = H a / (2 E A), v4 = -v3 = H b^2 / (2 a E A).
// flexmb's static solution of the Nastran deck equals them to 1e-12. The
// same bay with a membrane CQUAD4 (PSHELL without MID2) instead of the
// panel is a different structure (it also carries normal stress): its u4
// differs by more than 1 %. Sources: docs/validation.md, "Shear panels".

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace nastran_shear_panel_test {

constexpr double kA = 0.6, kB = 0.4, kT = 0.002, kRod = 1e-4, kE = 7e10, kNu = 0.33, kH = 1000.0;

std::string Bay(const std::string& panel) {
  char b[1200];
  std::snprintf(b, sizeof b,
                "BEGIN BULK\nMAT1,1,%.17g,,%.17g,2700.\nPROD,2,1,%.17g\n"
                "GRID,1,,0.,0.,0.\nGRID,2,,%.17g,0.,0.\nGRID,3,,%.17g,%.17g,0.\nGRID,4,,0.,%.17g,0.\n"
                "CROD,1,2,1,2\nCROD,2,2,2,3\nCROD,3,2,3,4\nCROD,4,2,4,1\n%s"
                "SPC1,1,123,1\nSPC1,1,23,2\nSPC1,1,3,3,4\nENDDATA\n",
                kE, kNu, kRod, kA, kA, kB, kB, panel.c_str());
  return b;
}

Eigen::VectorXd Solve(const Mesh& m) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * static_cast<Eigen::Index>(m.nodes.size()));
  f(6 * m.NodeIndex(4)) = kH;
  return SolveStatic(m, f);
}

TEST(ShearPanel, RackedBayOfRodsEqualsTheHandSolution) {
  const Mesh m = ReadDeckText(Bay("PSHEAR,5,1," + std::to_string(kT) + "\nCSHEAR,5,5,1,2,3,4\n"), "bay");
  const Eigen::VectorXd u = Solve(m);
  const double g = kE / (2 * (1 + kNu)), ea = kE * kRod;
  const double u4 = kH * kB / (g * kT * kA) + kH * kA / (2 * ea) + kH * kB * kB * kB / (2 * kA * kA * ea);
  const double u2 = kH * kA / (2 * ea), v4 = kH * kB * kB / (2 * kA * ea);
  const int n2 = m.NodeIndex(2), n3 = m.NodeIndex(3), n4 = m.NodeIndex(4);
  std::printf("  u4 %.12e m (hand %.12e), u2 %.6e (%.6e), v4 %.6e (%.6e), v3 %.6e\n", u(6 * n4), u4, u(6 * n2), u2,
              u(6 * n4 + 1), v4, u(6 * n3 + 1));
  EXPECT_NEAR(u(6 * n4), u4, 1e-12 * u4);
  EXPECT_NEAR(u(6 * n2), u2, 1e-12 * u4);
  EXPECT_NEAR(u(6 * n4 + 1), v4, 1e-12 * u4);
  EXPECT_NEAR(u(6 * n3 + 1), -v4, 1e-12 * u4);
  EXPECT_NEAR(u(6 * n3) - u(6 * n4), -kH / (2 * ea / kA), 1e-12 * u4);
  // a membrane in place of the panel: another structure
  const Mesh mem = ReadDeckText(Bay("PSHELL,5,1," + std::to_string(kT) + "\nCQUAD4,5,5,1,2,3,4\n"), "membrane");
  const double u4_membrane = Solve(mem)(6 * mem.NodeIndex(4));
  std::printf("  the bay with a membrane CQUAD4: u4 %.6e m\n", u4_membrane);
  EXPECT_GT(std::abs(u4_membrane / u4 - 1), 0.01);
}

}  // namespace nastran_shear_panel_test
}  // namespace flexmb::fe::validation
