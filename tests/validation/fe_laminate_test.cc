// Laminated shells (Nastran PCOMP / PCOMPG with MAT8 plies) through the
// reader, the assembly and the modal solver, against the exact solution of
// the theory the shells discretize: a simply supported (hard support)
// square cross-ply plate [0/90/90/0] (graphite-epoxy, a = 1 m, t = 10 mm),
// whose Mindlin (first-order shear) Navier solution with the closed-form
// D of a cross-ply and S = 5/6 G t is, per mode (m, n), the lowest root of
// a 3 x 3 eigenproblem (amplitudes of w, psi_x, psi_y; mass rho t and rho
// t^3 / 12). The four lowest frequencies on 10 x 10, 20 x 20 and 40 x 40
// CQUAD4 meshes converge to it at second order, and Richardson's
// extrapolation of the two finest meshes equals it. The same for the
// unsymmetric [0/90] (membrane-bending coupling B != 0) under the S2
// support, whose Navier problem is 5 x 5 (u, v, w, psi_x, psi_y), also on
// CTRIA3 meshes. The material axis turned by THETA = 90 on
// the elements, by an MCID system turned 90 degrees, or the plies given
// at 90/0/0/90 on a PCOMPG swap the plate's x and y: the same frequencies.
// Numbers: docs/validation.md, "Laminated shells".

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "flexmb/fe/laminate.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace fe_laminate_test {

constexpr double kA = 1.0, kT = 0.01, kE1 = 138e9, kE2 = 9e9, kNu12 = 0.3, kG = 7.1e9, kRho = 1600.0;

// the Mindlin Navier frequencies [Hz] of a simply supported (hard) square
// plate of bending stiffness d11, d22, d12, d66 [N m], shear stiffness s
// [N/m], mass m0 [kg/m^2] and rotary inertia m2 [kg], lowest `count`
std::vector<double> NavierFrequencies(double d11, double d22, double d12, double d66, double s, double m0, double m2,
                                      int count) {
  std::vector<double> f;
  for (int m = 1; m <= 5; ++m)
    for (int n = 1; n <= 5; ++n) {
      const double a = m * M_PI / kA, b = n * M_PI / kA;
      Eigen::Matrix3d k;
      k << s * (a * a + b * b), s * a, s * b,  //
          s * a, d11 * a * a + d66 * b * b + s, (d12 + d66) * a * b,  //
          s * b, (d12 + d66) * a * b, d66 * a * a + d22 * b * b + s;
      const Eigen::Vector3d mass(m0, m2, m2);
      const Eigen::Matrix3d kk = mass.cwiseSqrt().cwiseInverse().asDiagonal() * k *
                                 mass.cwiseSqrt().cwiseInverse().asDiagonal();
      const double w2 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(kk).eigenvalues()(0);
      f.push_back(std::sqrt(w2) / (2 * M_PI));
    }
  std::sort(f.begin(), f.end());
  f.resize(static_cast<size_t>(count));
  return f;
}

// the same for the [0/90]s plate (the closed-form D of a cross-ply)
std::vector<double> NavierFrequencies(int count) {
  const Eigen::Matrix3d q = OrthotropicPlaneStress(kE1, kE2, kNu12, kG);
  const double t3 = kT * kT * kT;
  return NavierFrequencies(t3 * (7 * q(0, 0) + q(1, 1)) / 96, t3 * (q(0, 0) + 7 * q(1, 1)) / 96, t3 * q(0, 1) / 12,
                           t3 * q(2, 2) / 12, 5.0 / 6.0 * kG * kT, kRho * kT, kRho * t3 / 12, count);
}

// the Mindlin Navier frequencies [Hz] of the antisymmetric [0/90] plate
// under the S2 support (x edges: v = w = psi_y = 0, y edges: u = w = psi_x
// = 0), lowest `count`: per (m, n) the lowest root of the 5 x 5 problem in
// the amplitudes (U, V, W, X, Y) of u = U cos(ax) sin(by), v = V sin(ax)
// cos(by), w = W sin sin, psi_x = X cos sin, psi_y = Y sin cos; A, B, D by
// hand (A11 = A22 = (Q11 + Q22) t / 2, B11 = -B22 = (Q22 - Q11) t^2 / 8,
// D11 = D22 = (Q11 + Q22) t^3 / 24, A12 = Q12 t, A66 = Q66 t, D12 = Q12
// t^3 / 12, D66 = Q66 t^3 / 12, B12 = B66 = 0)
std::vector<double> AntisymmetricNavierFrequencies(int count) {
  const Eigen::Matrix3d q = OrthotropicPlaneStress(kE1, kE2, kNu12, kG);
  const double t = kT, t2 = t * t, t3 = t2 * t;
  const double a11 = (q(0, 0) + q(1, 1)) * t / 2, a12 = q(0, 1) * t, a66 = q(2, 2) * t;
  const double b11 = (q(1, 1) - q(0, 0)) * t2 / 8, b22 = -b11;
  const double d11 = (q(0, 0) + q(1, 1)) * t3 / 24, d12 = q(0, 1) * t3 / 12, d66 = q(2, 2) * t3 / 12;
  const double s = 5.0 / 6.0 * kG * t;
  Eigen::Matrix4d cn;  // (eps_x, eps_y, kappa_x, kappa_y)
  cn << a11, a12, b11, 0, a12, a11, 0, b22, b11, 0, d11, d12, 0, b22, d12, d11;
  std::vector<double> f;
  for (int m = 1; m <= 5; ++m)
    for (int n = 1; n <= 5; ++n) {
      const double al = m * M_PI / kA, be = n * M_PI / kA;
      Eigen::Matrix<double, 4, 5> en = Eigen::Matrix<double, 4, 5>::Zero();  // sin sin parts
      en(0, 0) = -al;
      en(1, 1) = -be;
      en(2, 3) = -al;
      en(3, 4) = -be;
      Eigen::Matrix<double, 2, 5> es = Eigen::Matrix<double, 2, 5>::Zero();  // cos cos: gamma_xy, kappa_xy
      es(0, 0) = be;
      es(0, 1) = al;
      es(1, 3) = be;
      es(1, 4) = al;
      Eigen::Matrix<double, 2, 5> eq = Eigen::Matrix<double, 2, 5>::Zero();  // transverse shear
      eq(0, 2) = al;
      eq(0, 3) = 1;
      eq(1, 2) = be;
      eq(1, 4) = 1;
      Eigen::Matrix2d cs;
      cs << a66, 0, 0, d66;
      const Eigen::Matrix<double, 5, 5> k =
          en.transpose() * cn * en + es.transpose() * cs * es + s * eq.transpose() * eq;
      Eigen::Matrix<double, 5, 1> mass;
      mass << kRho * t, kRho * t, kRho * t, kRho * t3 / 12, kRho * t3 / 12;
      const Eigen::Matrix<double, 5, 1> w = mass.cwiseSqrt().cwiseInverse();
      const Eigen::Matrix<double, 5, 5> kk = w.asDiagonal() * k * w.asDiagonal();
      const double w2 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 5, 5>>(kk).eigenvalues()(0);
      f.push_back(std::sqrt(w2) / (2 * M_PI));
    }
  std::sort(f.begin(), f.end());
  f.resize(static_cast<size_t>(count));
  return f;
}

// the plate as a Nastran deck: n x n CQUAD4 on PCOMP 1 (or PCOMPG), MAT8
// plies; u, v, rz held everywhere (B = 0: the membrane is decoupled), w and
// the rotation about each edge's normal held on the edges (hard support).
// `theta` is the elements' THETA field ("" for none, or the MCID "2"),
// `property` the PCOMP or PCOMPG card
std::string PlateDeck(int n, const std::string& theta, const std::string& property, bool s2 = false,
                      bool triangles = false) {
  std::ostringstream d;
  d << "BEGIN BULK\nMAT8,10," << kE1 << "," << kE2 << "," << kNu12 << "," << kG << "," << kG << "," << kG << ","
    << kRho << "\n" << property << "CORD2R,2,,0.,0.,0.,0.,0.,1.,\n,0.,1.,0.\n";
  auto id = [&](int i, int j) { return j * (n + 1) + i + 1; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) d << "GRID," << id(i, j) << ",," << kA * i / n << "," << kA * j / n << ",0.\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (triangles)
        d << "CTRIA3," << 2 * (j * n + i) + 1 << ",1," << id(i, j) << "," << id(i + 1, j) << "," << id(i + 1, j + 1)
          << "," << theta << "\nCTRIA3," << 2 * (j * n + i) + 2 << ",1," << id(i, j) << "," << id(i + 1, j + 1)
          << "," << id(i, j + 1) << "," << theta << "\n";
      else
        d << "CQUAD4," << j * n + i + 1 << ",1," << id(i, j) << "," << id(i + 1, j) << "," << id(i + 1, j + 1)
          << "," << id(i, j + 1) << "," << theta << "\n";
  // S2: the membrane takes part and rz is free (held, the drilling tie
  // would hold the membrane's in-plane rotation too)
  if (!s2) d << "SPC1,1,126," << 1 << ",THRU," << id(n, n) << "\n";
  for (int k = 0; k <= n; ++k) {
    d << "SPC1,1," << (s2 ? "234" : "34") << "," << id(0, k) << "," << id(n, k) << "\n";  // x = 0, a: (v), w, rx
    d << "SPC1,1," << (s2 ? "135" : "35") << "," << id(k, 0) << "," << id(k, n) << "\n";  // y = 0, a: (u), w, ry
  }
  d << "ENDDATA\n";
  return d.str();
}

const std::string kPcomp = "PCOMP,1,,,,,,,SYM\n,10,0.0025,0.,YES,10,0.0025,90.,YES\n";

std::vector<double> DeckFrequencies(const std::string& deck, const std::string& name, int count) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() /
                                  ("flexmb_laminate_" + std::to_string(getpid()) + "_" + name + ".bdf");
  std::ofstream(p) << deck;
  const Mesh m = io::ReadNastran(p.string());
  std::filesystem::remove(p);
  const ModalResult r = SolveMeshModes(m, count);
  return std::vector<double>(r.frequencies_hz.data(), r.frequencies_hz.data() + count);
}

TEST(LaminatedPlate, CrossPlyConvergesToTheNavierSolution) {
  const std::vector<double> exact = NavierFrequencies(4);
  std::vector<std::vector<double>> meshes;
  for (int n : {10, 20, 40}) meshes.push_back(DeckFrequencies(PlateDeck(n, "", kPcomp), "n", 4));
  std::printf("  Navier [Hz]      ");
  for (double f : exact) std::printf(" %10.5f", f);
  std::printf("\n");
  for (size_t k = 0; k < meshes.size(); ++k) {
    std::printf("  %2d x %-2d  / exact", 10 << k, 10 << k);
    for (size_t m = 0; m < 4; ++m) std::printf(" %10.6f", meshes[k][m] / exact[m]);
    std::printf("\n");
  }
  for (size_t m = 0; m < 4; ++m) {
    const double e10 = meshes[0][m] / exact[m] - 1, e20 = meshes[1][m] / exact[m] - 1, e40 = meshes[2][m] / exact[m] - 1;
    // second order: the error falls fourfold per halving of the elements
    EXPECT_GT(e10 / e20, 3.5) << "mode " << m;
    EXPECT_GT(e20 / e40, 3.5) << "mode " << m;
    // so that Richardson's extrapolation of the two finest meshes is the
    // exact solution of the theory
    const double extrapolated = (4 * meshes[2][m] - meshes[1][m]) / 3;
    std::printf("  mode %zu: Richardson (4 f40 - f20) / 3 / exact - 1 = %.2e\n", m + 1, extrapolated / exact[m] - 1);
    EXPECT_LT(std::abs(extrapolated / exact[m] - 1), 3e-4) << "mode " << m;
  }
}

// the distinct values of the sorted `f` (a pair within 1e-6 counted once),
// the first `count`: the [0/90] plate's modes (1, 2) and (2, 1) have the
// same frequency, and a single-vector Lanczos run may return that pair
// once (docs/validation.md, "Laminated shells")
std::vector<double> Distinct(const std::vector<double>& f, size_t count) {
  std::vector<double> out;
  for (double v : f)
    if (out.empty() || std::abs(v / out.back() - 1) > 1e-6) out.push_back(v);
  EXPECT_GE(out.size(), count);
  out.resize(count);
  return out;
}

TEST(LaminatedPlate, UnsymmetricCrossPlyConvergesToTheNavierSolution) {
  // [0/90]: B != 0, the membrane and the bending are coupled
  const std::string pcomp = "PCOMP,1\n,10,0.005,0.,,10,0.005,90.\n";
  const std::vector<double> exact = Distinct(AntisymmetricNavierFrequencies(6), 3);
  std::vector<std::vector<double>> meshes;
  for (int n : {10, 20, 40}) meshes.push_back(Distinct(DeckFrequencies(PlateDeck(n, "", pcomp, true), "u", 6), 3));
  std::printf("  Navier [0/90] [Hz]");
  for (double f : exact) std::printf(" %10.5f", f);
  std::printf("\n");
  for (size_t m = 0; m < 3; ++m) {
    const double e20 = meshes[1][m] / exact[m] - 1, e40 = meshes[2][m] / exact[m] - 1;
    const double extrapolated = (4 * meshes[2][m] - meshes[1][m]) / 3;
    std::printf("  mode %zu: 10/20/40 / exact %.6f %.6f %.6f, Richardson - 1 = %.2e\n", m + 1,
                meshes[0][m] / exact[m], meshes[1][m] / exact[m], meshes[2][m] / exact[m],
                extrapolated / exact[m] - 1);
    EXPECT_GT(e20 / e40, 3.5) << "mode " << m;
    EXPECT_LT(std::abs(extrapolated / exact[m] - 1), 3e-4) << "mode " << m;
  }
  // 3-node shells (each cell halved): the same limit
  std::vector<double> tri;
  // (MCID 0: the material axis is the basic x axis; a blank THETA would
  // measure it from each triangle's G1-G2 edge, half of them diagonal)
  for (int n : {20, 40}) tri.push_back(DeckFrequencies(PlateDeck(n, "0", pcomp, true, true), "t", 4)[0]);
  const double tri_extrapolated = (4 * tri[1] - tri[0]) / 3;
  std::printf("  CTRIA3 mode 1: 20/40 / exact %.6f %.6f, Richardson - 1 = %.2e\n", tri[0] / exact[0],
              tri[1] / exact[0], tri_extrapolated / exact[0] - 1);
  EXPECT_LT(std::abs(tri_extrapolated / exact[0] - 1), 3e-3);
  // the symmetric [0/90]s of the same plies under the same support: clearly
  // different (the coupling lowers the first frequency)
  const std::vector<double> sym = DeckFrequencies(PlateDeck(20, "", kPcomp, true), "s", 4);
  std::printf("  [0/90]s under S2, 20 x 20: f1 %.5f Hz, %.4f times the [0/90]'s\n", sym[0], sym[0] / meshes[1][0]);
  EXPECT_GT(sym[0] / meshes[1][0], 1.1);
}

// the [0/90] plate's section written as Nastran's generalized PSHELL: MAT2
// cards from the hand formulas of AntisymmetricNavierFrequencies, MID1 =
// A / T, MID2 = 12 D / T^3 (the same matrix here), MID4 = B / T^2 (Nastran:
// N = T G1 eps + T^2 G4 kappa), MID3 a MAT1 of shear modulus G12 (TS/T
// 5/6): the same frequencies as the PCOMP plate on the same mesh, and the
// Navier limit
TEST(LaminatedPlate, PshellWithMid4EqualsTheUnsymmetricLaminate) {
  const Eigen::Matrix3d q = OrthotropicPlaneStress(kE1, kE2, kNu12, kG);
  const double g11 = (q(0, 0) + q(1, 1)) / 2, b11 = (q(1, 1) - q(0, 0)) / 8;
  std::ostringstream p;
  p.precision(17);
  p << "PSHELL,1,1," << kT << ",1,,3\n,,,4\n"
    << "MAT2,1," << g11 << "," << q(0, 1) << ",0.," << g11 << ",0.," << q(2, 2) << "," << kRho << "\n"
    << "MAT2,4," << b11 << ",0.,0.," << -b11 << ",0.,0.\n"
    << "MAT1,3," << 2 * kG * 1.3 << "," << kG << "\n";
  const std::string pcomp = "PCOMP,1\n,10,0.005,0.,,10,0.005,90.\n";
  // the assembled stiffness, entry by entry: the frequencies cannot see the
  // sign of B (B -> -B mirrors the plate through its thickness), K can
  auto stiffness = [](const std::string& deck, const std::string& name) {
    const std::filesystem::path p = std::filesystem::temp_directory_path() /
                                    ("flexmb_laminate_" + std::to_string(getpid()) + "_" + name + ".bdf");
    std::ofstream(p) << deck;
    const Mesh m = io::ReadNastran(p.string());
    std::filesystem::remove(p);
    return Eigen::MatrixXd(Assemble(m).K);
  };
  const Eigen::MatrixXd k_pcomp = stiffness(PlateDeck(4, "", pcomp, true), "kl"),
                        k_pshell = stiffness(PlateDeck(4, "", p.str(), true), "km");
  ASSERT_EQ(k_pcomp.rows(), k_pshell.rows());
  EXPECT_LT((k_pcomp - k_pshell).cwiseAbs().maxCoeff(), 1e-9 * k_pcomp.cwiseAbs().maxCoeff());
  const std::vector<double> laminate = DeckFrequencies(PlateDeck(10, "", pcomp, true), "l", 6);
  const std::vector<double> pshell = DeckFrequencies(PlateDeck(10, "", p.str(), true), "m", 6);
  for (size_t m = 0; m < 6; ++m) {
    std::printf("  10 x 10 mode %zu: PCOMP [0/90] %.9f Hz, PSHELL with MID4 %.9f Hz\n", m + 1, laminate[m], pshell[m]);
    EXPECT_NEAR(pshell[m], laminate[m], 1e-9 * laminate[m]) << "mode " << m;
  }
  const std::vector<double> exact = Distinct(AntisymmetricNavierFrequencies(6), 3);
  std::vector<std::vector<double>> meshes;
  for (int n : {20, 40}) meshes.push_back(Distinct(DeckFrequencies(PlateDeck(n, "", p.str(), true), "r", 6), 3));
  for (size_t m = 0; m < 3; ++m) {
    const double extrapolated = (4 * meshes[1][m] - meshes[0][m]) / 3;
    EXPECT_LT(std::abs(extrapolated / exact[m] - 1), 3e-4) << "mode " << m;
  }
  // without MID4 (no coupling) the plate is clearly another one
  std::string uncoupled = p.str();
  uncoupled.replace(uncoupled.find(",,,4\n"), 5, "");
  const std::vector<double> plain = DeckFrequencies(PlateDeck(10, "", uncoupled, true), "n", 6);
  EXPECT_GT(plain[0] / laminate[0], 1.1);
}

TEST(LaminatedPlate, PshellBendingRatioAndShearThicknessFollowTheirNavierSolution) {
  // steel, t = 10 mm, 12I/T^3 = 2 (D doubled), MID3 = MID1 with TS/T = 1
  // (S = G t instead of 5/6 G t): Nastran's generalized PSHELL
  const double e = 2.1e11, nu = 0.3, g = e / (2 * (1 + nu)), rho = 7850, d = 2 * e * kT * kT * kT / (12 * (1 - nu * nu));
  const std::vector<double> exact =
      NavierFrequencies(d, d, nu * d, (1 - nu) / 2 * d, g * kT, rho * kT, rho * kT * kT * kT / 12, 4);
  const std::string pshell = "PSHELL,1,20,0.01,20,2.,20,1.\nMAT1,20,2.1e11,,0.3,7850.\n";
  std::vector<std::vector<double>> meshes;
  for (int n : {20, 40}) meshes.push_back(Distinct(DeckFrequencies(PlateDeck(n, "", pshell), "p", 6), 3));
  const std::vector<double> ex = Distinct(exact, 3);
  for (size_t m = 0; m < 3; ++m) {
    const double extrapolated = (4 * meshes[1][m] - meshes[0][m]) / 3;
    std::printf("  PSHELL 12I/T^3 = 2, TS/T = 1, mode %zu: Navier %.5f Hz, 20/40 / exact %.6f %.6f, Richardson - 1 "
                "= %.2e\n", m + 1, ex[m], meshes[0][m] / ex[m], meshes[1][m] / ex[m], extrapolated / ex[m] - 1);
    EXPECT_LT(std::abs(extrapolated / ex[m] - 1), 3e-4) << "mode " << m;
  }
  // a plain PSHELL of the same plate: the ratio matters (about sqrt 2)
  const std::vector<double> plain = DeckFrequencies(PlateDeck(20, "", "PSHELL,1,20,0.01,20\nMAT1,20,2.1e11,,0.3,7850.\n"), "q", 4);
  EXPECT_GT(meshes[0][0] / plain[0], 1.35);
}

TEST(LaminatedPlate, PshellWithAnAnisotropicMid2FollowsItsNavierSolution) {
  // t = 10 mm; MID1 steel (membrane, mass), MID2 a MAT2 of its own
  // (bending D = t^3 / 12 G: specially orthotropic, G11 != G22), MID3 steel
  // (shear 5/6 G t): Nastran's PSHELL with three materials
  const double e = 2.1e11, nu = 0.3, g = e / (2 * (1 + nu)), rho = 7850, c = kT * kT * kT / 12;
  const double g11 = 2.3e11, g12 = 0.5e11, g22 = 1.2e11, g33 = 0.6e11;
  const std::vector<double> exact = NavierFrequencies(c * g11, c * g22, c * g12, c * g33, 5.0 / 6.0 * g * kT, rho * kT,
                                                      rho * kT * kT * kT / 12, 4);
  const std::string pshell = "PSHELL,1,20,0.01,21,,20\nMAT1,20,2.1e11,,0.3,7850.\nMAT2,21,2.3e11,0.5e11,,1.2e11,,0.6e11\n";
  std::vector<std::vector<double>> meshes;
  for (int n : {20, 40}) meshes.push_back(DeckFrequencies(PlateDeck(n, "", pshell), "mat2", 4));
  for (size_t m = 0; m < 4; ++m) {
    const double extrapolated = (4 * meshes[1][m] - meshes[0][m]) / 3;
    std::printf("  PSHELL MID2 = MAT2, mode %zu: Navier %.5f Hz, 20/40 / exact %.6f %.6f, Richardson - 1 = %.2e\n", m + 1,
                exact[m], meshes[0][m] / exact[m], meshes[1][m] / exact[m], extrapolated / exact[m] - 1);
    EXPECT_LT(std::abs(extrapolated / exact[m] - 1), 3e-4) << "mode " << m;
  }
  // the same plate with MID2 = MID1 (steel bending): G11 and G22 matter
  const std::vector<double> plain = DeckFrequencies(PlateDeck(20, "", "PSHELL,1,20,0.01,20\nMAT1,20,2.1e11,,0.3,7850.\n"), "s", 4);
  EXPECT_GT(std::abs(plain[0] / meshes[0][0] - 1), 0.02);
}

TEST(LaminatedPlate, MaterialAxisByThetaMcidOrPlyAnglesSwapsXAndY) {
  // the square plate is symmetric under x <-> y: turning the material axis
  // by 90 degrees gives the same frequencies (the modes swap)
  const int n = 12;
  const std::vector<double> base = DeckFrequencies(PlateDeck(n, "", kPcomp), "base", 4);
  const std::vector<double> theta = DeckFrequencies(PlateDeck(n, "90.", kPcomp), "theta", 4);
  const std::vector<double> mcid = DeckFrequencies(PlateDeck(n, "2", kPcomp), "mcid", 4);
  const std::string pcompg = "PCOMPG,1\n,1,10,0.0025,90.\n,2,10,0.0025,0.\n,3,10,0.0025,0.\n,4,10,0.0025,90.\n";
  const std::vector<double> plies = DeckFrequencies(PlateDeck(n, "", pcompg), "pcompg", 4);
  for (size_t m = 0; m < 4; ++m) {
    EXPECT_NEAR(theta[m], base[m], 1e-9 * base[m]) << "mode " << m;
    EXPECT_NEAR(mcid[m], base[m], 1e-9 * base[m]) << "mode " << m;
    EXPECT_NEAR(plies[m], base[m], 1e-9 * base[m]) << "mode " << m;
  }
  // while a 45 degree axis changes them: the comparison sees the angle
  const std::vector<double> skew = DeckFrequencies(PlateDeck(n, "45.", kPcomp), "skew", 4);
  EXPECT_GT(std::abs(skew[0] / base[0] - 1), 1e-2);
}

}  // namespace fe_laminate_test
}  // namespace flexmb::fe::validation
