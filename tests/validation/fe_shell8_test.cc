// Second-order shells (Nastran CQUAD8 and CTRIA6; fe/elements/shell_quad8.h,
// shell_tria6.h) through the reader, the assembly and the modal solver,
// against the exact solution of the theory they discretize: the simply
// supported (hard) square steel plate a = 1 m, t = 10 mm, whose Mindlin
// Navier solution (S = 5/6 G t, mass rho t, rotary inertia rho t^3 / 12) is
// per mode (m, n) the lowest root of a 3 x 3 eigenproblem. The four lowest
// frequencies on 8 x 8 and 16 x 16 meshes of CQUAD8 (and of CTRIA6, two per
// cell) converge at second order and Richardson's extrapolation equals the
// Navier values; a laminated plate ([0/90]s PCOMP) of CQUAD8 with THETA =
// 90 has the frequencies of THETA = 0 (the square plate is symmetric under
// x <-> y) and a plate of curved CQUAD8 elements (mid nodes off the chords
// by a cylinder of radius 20 m) stays within its curvature's small effect.
// Numbers: docs/validation.md, "FE: second-order shells".

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace fe_shell8_test {

constexpr double kS8A = 1.0, kS8T = 0.01, kS8E = 2.1e11, kS8Nu = 0.3, kS8Rho = 7850.0;

// Mindlin Navier frequencies [Hz] of the simply supported isotropic plate
std::vector<double> NavierIsotropic(int count) {
  const double g = kS8E / (2 * (1 + kS8Nu)), d = kS8E * kS8T * kS8T * kS8T / (12 * (1 - kS8Nu * kS8Nu));
  const double s = 5.0 / 6.0 * g * kS8T, m0 = kS8Rho * kS8T, m2 = kS8Rho * kS8T * kS8T * kS8T / 12;
  std::vector<double> f;
  for (int m = 1; m <= 5; ++m)
    for (int n = 1; n <= 5; ++n) {
      const double a = m * M_PI / kS8A, b = n * M_PI / kS8A;
      Eigen::Matrix3d k;
      k << s * (a * a + b * b), s * a, s * b,  //
          s * a, d * a * a + (1 - kS8Nu) / 2 * d * b * b + s, (kS8Nu * d + (1 - kS8Nu) / 2 * d) * a * b,  //
          s * b, (kS8Nu * d + (1 - kS8Nu) / 2 * d) * a * b, (1 - kS8Nu) / 2 * d * a * a + d * b * b + s;
      const Eigen::Vector3d w = Eigen::Vector3d(m0, m2, m2).cwiseSqrt().cwiseInverse();
      const Eigen::Matrix3d kk = w.asDiagonal() * k * w.asDiagonal();
      f.push_back(std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(kk).eigenvalues()(0)) / (2 * M_PI));
    }
  std::sort(f.begin(), f.end());
  f.resize(static_cast<size_t>(count));
  return f;
}

// n x n cells of CQUAD8 (or two CTRIA6 per cell) on the plate, property 1;
// u, v, rz held everywhere, w and the rotation about each edge's normal on
// the edges; `sag` lifts every node by z = sag (x - x^2) (a shallow curve)
std::string Shell8Deck(int n, bool triangles, const std::string& property, const std::string& theta, double sag = 0.0) {
  std::ostringstream d;
  d.precision(17);
  d << "BEGIN BULK\n" << property;
  const int g = 2 * n;
  auto id = [&](int i, int j) { return j * (g + 1) + i + 1; };
  std::map<int, bool> used;
  std::ostringstream elements;
  int eid = 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = id(2 * i, 2 * j), b = id(2 * i + 2, 2 * j), c = id(2 * i + 2, 2 * j + 2), e = id(2 * i, 2 * j + 2);
      const int ab = id(2 * i + 1, 2 * j), bc = id(2 * i + 2, 2 * j + 1), ce = id(2 * i + 1, 2 * j + 2),
                ea = id(2 * i, 2 * j + 1), mid = id(2 * i + 1, 2 * j + 1);
      if (triangles) {
        elements << "CTRIA6," << eid++ << ",1," << a << "," << b << "," << c << "," << ab << "," << bc << "," << mid
                 << "\n," << theta << "\n";
        elements << "CTRIA6," << eid++ << ",1," << a << "," << c << "," << e << "," << mid << "," << ce << "," << ea
                 << "\n," << theta << "\n";
        for (int k : {a, b, c, e, ab, bc, ce, ea, mid}) used[k] = true;
      } else {
        elements << "CQUAD8," << eid++ << ",1," << a << "," << b << "," << c << "," << e << "," << ab << "," << bc
                 << "\n," << ce << "," << ea << ",,,,," << theta << "\n";
        for (int k : {a, b, c, e, ab, bc, ce, ea}) used[k] = true;
      }
    }
  for (int j = 0; j <= g; ++j)
    for (int i = 0; i <= g; ++i)
      if (used.count(id(i, j))) {
        const double x = kS8A * i / g, y = kS8A * j / g;
        d << "GRID," << id(i, j) << ",," << x << "," << y << "," << sag * (x - x * x) << "\n";
      }
  d << elements.str();
  for (const auto& [k, u] : used) d << "SPC1,1,126," << k << "\n";
  for (int k = 0; k <= g; ++k) {
    for (int node : {id(0, k), id(g, k)})
      if (used.count(node)) d << "SPC1,1,34," << node << "\n";
    for (int node : {id(k, 0), id(k, g)})
      if (used.count(node)) d << "SPC1,1,35," << node << "\n";
  }
  d << "ENDDATA\n";
  return d.str();
}

std::vector<double> Shell8Frequencies(const std::string& deck, const std::string& name, int count) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() /
                                  ("flexmb_shell8_" + std::to_string(getpid()) + "_" + name + ".bdf");
  std::ofstream(p) << deck;
  const Mesh m = io::ReadNastran(p.string());
  std::filesystem::remove(p);
  const ModalResult r = SolveMeshModes(m, count);
  return std::vector<double>(r.frequencies_hz.data(), r.frequencies_hz.data() + count);
}

const std::string kSteel = "PSHELL,1,20,0.01,20\nMAT1,20,2.1e11,,0.3,7850.\n";

TEST(SecondOrderShells, SimplySupportedPlateConvergesToNavier) {
  const std::vector<double> exact = NavierIsotropic(4);
  for (bool triangles : {false, true}) {
    std::vector<std::vector<double>> f;
    // the triangles reach the asymptotic range later: 16 and 32 cells a side
    for (int n : {8, 16}) f.push_back(Shell8Frequencies(Shell8Deck(triangles ? 2 * n : n, triangles, kSteel, ""), "plate", 4));
    for (size_t m = 0; m < 4; ++m) {
      const double extrapolated = (4 * f[1][m] - f[0][m]) / 3;
      std::printf("  %s mode %zu: Navier %.5f Hz, coarse/fine / exact %.6f %.6f, Richardson - 1 = %.2e\n",
                  triangles ? "CTRIA6" : "CQUAD8", m + 1, exact[m], f[0][m] / exact[m], f[1][m] / exact[m],
                  extrapolated / exact[m] - 1);
      EXPECT_LT(std::abs(f[1][m] / exact[m] - 1), 0.5 * std::abs(f[0][m] / exact[m] - 1) + 1e-6) << "mode " << m;
      EXPECT_LT(std::abs(extrapolated / exact[m] - 1), triangles ? 3e-3 : 3e-4) << "mode " << m;
    }
  }
}

TEST(SecondOrderShells, LaminateMaterialAngleAndCurvedElements) {
  const std::string pcomp = "PCOMP,1,,,,,,,SYM\n,10,0.0025,0.,YES,10,0.0025,90.\n"
                            "MAT8,10,138.e9,9.e9,0.3,7.1e9,7.1e9,7.1e9,1600.\n";
  const std::vector<double> base = Shell8Frequencies(Shell8Deck(6, false, pcomp, ""), "lam0", 4);
  const std::vector<double> turned = Shell8Frequencies(Shell8Deck(6, false, pcomp, "90."), "lam90", 4);
  const std::vector<double> skew = Shell8Frequencies(Shell8Deck(6, false, pcomp, "45."), "lam45", 4);
  for (size_t m = 0; m < 4; ++m) EXPECT_NEAR(turned[m], base[m], 1e-9 * base[m]) << "mode " << m;
  EXPECT_GT(std::abs(skew[0] / base[0] - 1), 1e-2);
  // a shallow cylinder z = s (x - x^2), s = 0.0125 (radius 1 / (2 s) = 40 m):
  // curved elements run and differ from the flat plate only a little
  const std::vector<double> flat = Shell8Frequencies(Shell8Deck(8, false, kSteel, ""), "flat", 2);
  const std::vector<double> curved = Shell8Frequencies(Shell8Deck(8, false, kSteel, "", 0.0125), "curved", 2);
  std::printf("  flat %.5f Hz, shallow cylinder (R = 40 m) %.5f Hz\n", flat[0], curved[0]);
  EXPECT_GT(curved[0], flat[0]);
  EXPECT_LT(curved[0], 1.5 * flat[0]);
}

}  // namespace fe_shell8_test
}  // namespace flexmb::fe::validation
