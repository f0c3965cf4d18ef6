// Rod elements (CROD / CONROD / CTUBE, T3D2) against independent references:
// - a symmetric tripod of a PROD/CROD, a CONROD and a PTUBE/CTUBE leg read
//   from a Nastran deck: apex deflection under a vertical load P,
//   P L / (3 E A cos^2 phi), and under a horizontal load H, H / (3/2 E A /
//   L sin^2 phi) (statics of a determinate space truss, any textbook, e.g.
//   Hibbeler, Structural Analysis, ch. 3 and 9), and the legs' axial stress
//   -P / (3 A cos phi) from the stress modes (beam_fibre table);
// - the axial natural frequencies of a fixed-free bar of N CROD elements
//   (with non-structural mass): the closed form of the discrete chain,
//   omega^2 = 6 c^2 / h^2 (1 - cos t) / (2 + cos t) (consistent mass) and
//   2 c^2 / h^2 (1 - cos t) (lumped), t = (2n - 1) pi / (2N), to round-off,
//   and the continuum f_n = (2n - 1) / (4 L) c, c = sqrt(E / (rho + nsm /
//   A)), converging as N^-2;
// - CalculiX (ccx) as a peer: a space truss tower read from a Nastran deck,
//   written as T3D2 and loaded at its top nodes: static displacements equal
//   to ccx's printed 7 digits (ccx expands T3D2 into 20-node bricks, so its
//   natural frequencies differ from a 2-node rod's; static nodal
//   displacements of a truss under nodal loads are exact in both);
// - Craig-Bampton of the free tower (nodes without rotations; interface its
//   base, 8 of 9 fixed-interface modes): the six rigid-body modes are
//   removed and the 11 flexible Ritz frequencies interlace the full model's
//   (Cauchy interlacing of a Ritz basis of 17 of 18 DOF).
// Numbers and sources: docs/validation.md, "FE: rod elements".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include "flexmb/fe/elements/rod2.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/stress_modes.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe {
namespace fe_rod_test {

constexpr double kPi = std::numbers::pi;
constexpr double kRodE = 7.0e10, kRodNu = 0.3, kRodRho = 2700.0;

using flexmb::testing::CcxScratchDir;
using validation::SolveMeshModes;
using validation::SolveStatic;

std::string Num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// writes `text` to dir/name and reads it with io::ReadNastran
Mesh RodReadDeck(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return io::ReadNastran((dir / name).string());
}

std::string Grid(int id, const Vec3& x) {
  return "GRID," + std::to_string(id) + ",," + Num(x.x()) + "," + Num(x.y()) + "," + Num(x.z()) + "\n";
}

// nodal load vector (6 per node) with force f at the node of id `id`
void RodAddForce(const Mesh& mesh, int id, const Vec3& f, Eigen::VectorXd& load) {
  load.segment<3>(6 * mesh.NodeIndex(id)) += f;
}

TEST(FeRod, TripodFromNastranDeckDeflectionAndStress) {
  CcxScratchDir dir("rod_tripod");
  // legs from the base circle (radius R, z = 0) to the apex (0, 0, H); equal
  // areas: the tube's, given to PROD and CONROD too
  const double R = 1.0, H = 1.5, od = 0.03, t = 0.004;
  const double A = kPi / 4.0 * (od * od - (od - 2 * t) * (od - 2 * t));
  std::string deck = "MAT1,1," + Num(kRodE) + ",," + Num(kRodNu) + "," + Num(kRodRho) + "\n";
  for (int k = 0; k < 3; ++k)
    deck += Grid(k + 1, Vec3(R * std::cos(2 * kPi * k / 3), R * std::sin(2 * kPi * k / 3), 0.0));
  deck += Grid(4, Vec3(0.0, 0.0, H));
  deck += "PROD,10,1," + Num(A) + ",1.-8,.015\nCROD,1,10,1,4\n";
  deck += "CONROD,2,2,4,1," + Num(A) + "\n";
  deck += "PTUBE,30,1," + Num(od) + "," + Num(t) + "\nCTUBE,3,30,3,4\n";
  deck += "SPC1,1,123,1,2,3\n";
  const Mesh mesh = RodReadDeck(dir.path, "tripod.bdf", deck);

  const double L = std::hypot(R, H), cphi = H / L, sphi = R / L;
  const double P = 2.0e4, Hx = 3.0e3;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * mesh.nodes.size());
  RodAddForce(mesh, 4, Vec3(0.0, 0.0, -P), f);
  const Eigen::VectorXd u = SolveStatic(mesh, f);
  const int apex = mesh.NodeIndex(4);
  const double dz = P * L / (3.0 * kRodE * A * cphi * cphi);
  EXPECT_NEAR(u(6 * apex + 2), -dz, 1e-10 * dz);
  EXPECT_NEAR(u(6 * apex), 0.0, 1e-10 * dz);
  std::printf("  tripod apex deflection %.10e m (analytic %.10e)\n", -u(6 * apex + 2), dz);

  // leg stresses from the stress modes of the displacement: -P / (3 A cos phi)
  Eigen::MatrixXd mode = u;
  const reduction::StressModes sm = reduction::ComputeStressModes(mesh, mode);
  ASSERT_EQ(sm.beam_fibre.elements.size(), 3u);
  const double sigma = -P / (3.0 * A * cphi);
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < sm.beam_fibre.Locations(); ++l)
      EXPECT_NEAR(sm.beam_fibre.modes(sm.beam_fibre.Row(k, l, 0), 0), sigma, 1e-9 * std::abs(sigma)) << k << l;

  // horizontal stiffness of the symmetric tripod: 3/2 E A / L sin^2 phi
  f.setZero();
  RodAddForce(mesh, 4, Vec3(Hx, 0.0, 0.0), f);
  const Eigen::VectorXd uh = SolveStatic(mesh, f);
  const double dx = Hx / (1.5 * kRodE * A / L * sphi * sphi);
  EXPECT_NEAR(uh(6 * apex), dx, 1e-10 * dx);
  EXPECT_NEAR(uh(6 * apex + 1), 0.0, 1e-10 * dx);
}

// fixed-free bar along x of n CROD elements (transverse motion held): the
// lowest `count` frequencies
std::vector<double> BarFrequencies(int n, double L, double A, double nsm, MassForm form, int count) {
  CcxScratchDir dir("rod_bar_" + std::to_string(n));
  std::string deck = "MAT1,1," + Num(kRodE) + ",," + Num(kRodNu) + "," + Num(kRodRho) + "\n";
  deck += "PROD,1,1," + Num(A) + ",,," + Num(nsm) + "\n";
  for (int k = 0; k <= n; ++k) deck += Grid(k + 1, Vec3(L * k / n, 0.0, 0.0));
  for (int k = 0; k < n; ++k) deck += "CROD," + std::to_string(k + 1) + ",1," + std::to_string(k + 1) + "," +
                                      std::to_string(k + 2) + "\n";
  deck += "SPC1,1,123,1\nSPC1,1,23,2,THRU," + std::to_string(n + 1) + "\n";
  const Mesh mesh = RodReadDeck(dir.path, "bar.bdf", deck);
  const ModalResult r = SolveMeshModes(mesh, count, form);
  return std::vector<double>(r.frequencies_hz.data(), r.frequencies_hz.data() + count);
}

TEST(FeRod, FixedFreeBarAxialFrequencies) {
  const double L = 2.0, A = 3.0e-4, nsm = 0.12;
  const double c = std::sqrt(kRodE / (kRodRho + nsm / A));
  const int count = 3;
  double previous_error[count] = {0.0, 0.0, 0.0};
  for (int n : {8, 16, 32}) {
    const std::vector<double> fc = BarFrequencies(n, L, A, nsm, MassForm::kConsistent, count);
    const std::vector<double> fl = BarFrequencies(n, L, A, nsm, MassForm::kLumped, count);
    const double h = L / n;
    for (int m = 1; m <= count; ++m) {
      const double t = (2 * m - 1) * kPi / (2.0 * n);
      const double wc = std::sqrt(6.0 * c * c / (h * h) * (1.0 - std::cos(t)) / (2.0 + std::cos(t)));
      const double wl = std::sqrt(2.0 * c * c / (h * h) * (1.0 - std::cos(t)));
      EXPECT_NEAR(fc[m - 1], wc / (2 * kPi), 1e-9 * fc[m - 1]) << n << " " << m;
      EXPECT_NEAR(fl[m - 1], wl / (2 * kPi), 1e-9 * fl[m - 1]) << n << " " << m;
      // continuum: consistent mass above, lumped below, error ~ N^-2
      const double exact = (2 * m - 1) / (4.0 * L) * c;
      EXPECT_GT(fc[m - 1], exact);
      EXPECT_LT(fl[m - 1], exact);
      const double err = fc[m - 1] / exact - 1.0;
      if (previous_error[m - 1] > 0.0) {
        EXPECT_GT(previous_error[m - 1] / err, 3.8) << n << " " << m;
        EXPECT_LT(previous_error[m - 1] / err, 4.2) << n << " " << m;
      }
      previous_error[m - 1] = err;
    }
    std::printf("  bar N = %2d: f1 %.8g Hz (consistent), %.8g Hz (lumped), continuum %.8g Hz\n", n, fc[0], fl[0],
                c / (4.0 * L));
  }
  EXPECT_LT(previous_error[0], 1.5e-4);
}

// a space truss tower: base triangle (ids 1-3, z = 0, radius 0.8), top
// triangle (4-6, z = 1.2, radius 0.5, turned by 40 degrees), base, top,
// vertical and diagonal bars
std::string TowerDeck(bool fixed_base) {
  std::string deck = "MAT1,1," + Num(kRodE) + ",," + Num(kRodNu) + "," + Num(kRodRho) + "\n";
  const double rb = 0.8, rt = 0.5, ht = 1.2, turn = 40.0 * kPi / 180.0;
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * kPi * k / 3 + 0.3;  // no bar along an axis up to round-off (ccx rejects those)
    deck += Grid(k + 1, Vec3(rb * std::cos(a), rb * std::sin(a), 0.0));
    deck += Grid(k + 4, Vec3(rt * std::cos(a + turn), rt * std::sin(a + turn), ht));
  }
  deck += "PROD,1,1,4.-4\nPROD,2,1,2.5-4\n";
  int eid = 1;
  auto bar = [&](int pid, int a, int b) {
    deck += "CROD," + std::to_string(eid++) + "," + std::to_string(pid) + "," + std::to_string(a) + "," +
            std::to_string(b) + "\n";
  };
  for (int k = 0; k < 3; ++k) {
    bar(1, k + 1, (k + 1) % 3 + 1);      // base
    bar(2, k + 4, (k + 1) % 3 + 4);      // top
    bar(1, k + 1, k + 4);                // vertical
    bar(2, (k + 1) % 3 + 1, k + 4);      // diagonal
  }
  if (fixed_base) deck += "SPC1,1,123,1,2,3\n";
  return deck;
}

// ccx's "displacements (vx,vy,vz)" table of job.dat: node id -> u
std::map<int, Vec3> ParseCcxDisplacements(const std::filesystem::path& dat) {
  std::ifstream in(dat);
  std::string line;
  std::map<int, Vec3> u;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.find("displacements (vx,vy,vz)") != std::string::npos) {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    std::istringstream s(line);
    int id = 0;
    Vec3 v;
    if (s >> id >> v.x() >> v.y() >> v.z()) u[id] = v;
    else if (!u.empty()) break;
  }
  return u;
}

TEST(FeRod, TowerStaticsEqualCalculixT3D2) {
  if (!flexmb::testing::HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  CcxScratchDir dir("rod_tower");
  const Mesh mesh = RodReadDeck(dir.path, "tower.bdf", TowerDeck(true));
  const Vec3 loads[3] = {Vec3(4.0e3, -1.0e3, -2.0e4), Vec3(-2.5e3, 3.0e3, -1.0e4), Vec3(1.0e3, 2.0e3, 5.0e3)};
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * mesh.nodes.size());
  for (int k = 0; k < 3; ++k) RodAddForce(mesh, k + 4, loads[k], f);
  const Eigen::VectorXd u = SolveStatic(mesh, f);

  io::WriteAbaqus(mesh, (dir.path / "model.inp").string());
  std::string deck = flexmb::testing::CcxReadText(dir.path / "model.inp");
  ASSERT_NE(deck.find("TYPE=T3D2"), std::string::npos);
  deck += "*NSET, NSET=TOWER_TOP\n4, 5, 6\n*STEP\n*STATIC\n*CLOAD\n";
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) deck += std::to_string(k + 4) + ", " + std::to_string(c + 1) + ", " + Num(loads[k](c)) + "\n";
  deck += "*NODE PRINT, NSET=TOWER_TOP\nU\n*END STEP\n";
  ASSERT_TRUE(flexmb::testing::RunCcx(dir.path, "tower", deck)) << deck;
  const std::map<int, Vec3> ccx = ParseCcxDisplacements(dir.path / "tower.dat");
  ASSERT_EQ(ccx.size(), 3u);
  double umax = 0.0;
  for (int k = 4; k <= 6; ++k) umax = std::max(umax, u.segment<3>(6 * mesh.NodeIndex(k)).cwiseAbs().maxCoeff());
  double diff = 0.0;
  for (const auto& [id, v] : ccx) diff = std::max(diff, (u.segment<3>(6 * mesh.NodeIndex(id)) - v).cwiseAbs().maxCoeff());
  std::printf("  tower top: largest displacement %.7e m, largest difference to ccx %.2e m (%.2e relative)\n", umax,
              diff, diff / umax);
  EXPECT_LT(diff, 1e-6 * umax);
}

TEST(FeRod, TowerCraigBamptonFreeFreeRitzBounds) {
  CcxScratchDir dir("rod_tower_cb");
  FeModel model;
  model.mesh = RodReadDeck(dir.path, "tower_free.bdf", TowerDeck(false));
  // full model: 18 translational DOF (no rotations), dense eigenproblem:
  // six rigid-body modes, 12 flexible
  const AssembledModel full = Assemble(model.mesh);
  ASSERT_EQ(full.dofs.n_free, 18);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(Eigen::MatrixXd(full.K), Eigen::MatrixXd(full.M));
  const Eigen::VectorXd lambda = eig.eigenvalues();
  for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(lambda(k)), 1e-9 * lambda(6)) << k;
  Eigen::VectorXd f(12);
  for (int k = 0; k < 12; ++k) f(k) = std::sqrt(lambda(k + 6)) / (2 * kPi);
  // Craig-Bampton, interface the base (9 static modes), 8 of the 9
  // fixed-interface modes: a Ritz basis of 17 of the 18 DOF, so the 11
  // flexible Ritz frequencies interlace the exact ones, f_k <= g_k <= f_k+1
  reduction::ReductionOptions options;
  options.interface_nodes = {model.mesh.NodeIndex(1), model.mesh.NodeIndex(2), model.mesh.NodeIndex(3)};
  options.normal_modes = 8;
  const reduction::ReducedBody body = reduction::ReduceCraigBampton(model, options);
  EXPECT_EQ(body.rigid_modes_removed, 6);
  ASSERT_EQ(body.frequencies_hz.size(), 11);
  for (int k = 0; k < 11; ++k) {
    EXPECT_GE(body.frequencies_hz(k), f(k) * (1.0 - 1e-9)) << k;
    EXPECT_LE(body.frequencies_hz(k), f(k + 1) * (1.0 + 1e-9)) << k;
  }
  const double first = body.frequencies_hz(0) / f(0) - 1.0;
  EXPECT_LT(first, 1e-3);
  std::printf("  tower free-free f1 %.8g Hz, reduced %.8g Hz (%.2e)\n", f(0), body.frequencies_hz(0), first);
  // every rod has a beam_fibre stress row (sigma = N / A)
  EXPECT_EQ(body.stress.beam_fibre.elements.size(), 12u);
}

}  // namespace fe_rod_test
}  // namespace flexmb::fe
