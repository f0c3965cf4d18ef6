// Drilling modes of the 3- and 4-node shells (issue 17): the drilling
// penalty's modes must lie above the element's highest physical frequency,
// not in the range a user reduces (a 10 x 20 CQUAD4 plate, t = 3.2 mm, gave
// 31 identical modes at 17476 Hz at e9e4e90: the rz patterns that the
// one-point tie does not reach, held only by the stabilization
// beta G t with the rotary inertia rho t^3 / 12, sqrt(12 beta G / rho) /
// (2 pi t) whatever the mesh).
// - Flat free plate, all modes (dense solve): a flat Reissner-Mindlin shell
//   has 5 physical DOF per node (u, v, w and the two bending rotations); the
//   lowest 5 N modes must carry (almost) no rz kinetic energy and the
//   highest N must be the drilling modes, well above the physical ones.
//   Quads with consistent (the 10 x 20 deck) and lumped mass,
//   triangles (smaller meshes: the dense solve is the test's cost).
// - Cantilever plate against CalculiX S4 on the same mesh, the lowest 40
//   modes, a range that holds the old cluster.
// - Shell ladder frame (tests/unit/reduction): no cluster of equal
//   frequencies among its lowest 60 modes, the old cluster frequency of its
//   plates above them, and a Craig-Bampton reduction whose frequencies are
//   upper bounds of the full model's within 1 %.
// References: docs/validation.md, "Shell drilling modes".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/shell_common.h"
#include "flexmb/fe/modal.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/fe/fe_model.h"
#include "tests/unit/reduction/reduction_test_models.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace fe_shell_drilling_test {

constexpr double kDrillE = 2.1e11, kDrillNu = 0.3, kDrillRho = 7850.0;

// the 1 m x 2 m plate of n x 2n quads (each split in two triangles if asked)
ShellGrid DrillPlate(int n, double t, bool triangles) {
  return ShellGrid(
      n, 2 * n, [](double u, double v) { return Vec3(u, 2.0 * v, 0.0); }, t, kDrillE, kDrillNu,
      kDrillRho, triangles);
}

// frequency [Hz] of the drilling modes before the fix: stiffness beta G t,
// inertia rho t^3 / 12 on the same strain
double OldDrillingClusterHz(double t) {
  const double g = kDrillE / (2.0 * (1.0 + kDrillNu));
  return std::sqrt(12.0 * shell::kDrillingStabilization * g / kDrillRho) / (2.0 * kPi * t);
}

struct DrillSpectrum {
  std::vector<double> hz;        // ascending; a negative eigenvalue as a negative frequency
  std::vector<double> rz_share;  // share of the mode's kinetic energy in the rz DOF
};

// all modes of the mesh: dense generalized solve of the assembled K, M
DrillSpectrum DenseDrillSpectrum(const Mesh& mesh, MassForm form) {
  AssemblyOptions options;
  options.mass_form = form;
  const AssembledModel model = Assemble(mesh, options);
  const Eigen::MatrixXd k = Eigen::MatrixXd(model.K);
  const Eigen::MatrixXd m = Eigen::MatrixXd(model.M);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(k, m);
  EXPECT_EQ(es.info(), Eigen::Success);
  DrillSpectrum s;
  for (Eigen::Index j = 0; j < es.eigenvalues().size(); ++j) {
    const double l = es.eigenvalues()(j);
    s.hz.push_back(std::copysign(std::sqrt(std::abs(l)), l) / (2.0 * kPi));
    const Eigen::VectorXd phi = es.eigenvectors().col(j);
    const Eigen::VectorXd mphi = m * phi;
    double rz = 0.0;
    for (size_t n = 0; n < mesh.nodes.size(); ++n) {
      const int f = model.dofs.free[n][5];
      if (f >= 0) rz += phi(f) * mphi(f);
    }
    s.rz_share.push_back(rz / phi.dot(mphi));
  }
  return s;
}

// the largest number of frequencies within a relative 1e-6 of each other
int LargestDrillCluster(const std::vector<double>& hz) {
  int best = 1, run = 1;
  for (size_t k = 1; k < hz.size(); ++k) {
    run = std::abs(hz[k] - hz[k - 1]) <= 1e-6 * std::abs(hz[k]) ? run + 1 : 1;
    best = std::max(best, run);
  }
  return best;
}

struct DrillCase {
  const char* name;
  int n;  // n x 2n quads
  bool triangles;
  MassForm form;
};

TEST(FeShellDrilling, FreePlateSplitsIntoPhysicalAndDrillingModes) {
  const double t = 0.0032;
  for (const DrillCase& c : {DrillCase{"quad4 consistent 10 x 20", 10, false, MassForm::kConsistent},
                             DrillCase{"quad4 lumped 8 x 16", 8, false, MassForm::kLumped},
                             DrillCase{"tria3 consistent 6 x 12 x 2", 6, true, MassForm::kConsistent}}) {
    SCOPED_TRACE(c.name);
    const ShellGrid plate = DrillPlate(c.n, t, c.triangles);
    const int n_nodes = static_cast<int>(plate.mesh.nodes.size());
    const DrillSpectrum s = DenseDrillSpectrum(plate.mesh, c.form);
    ASSERT_EQ(static_cast<int>(s.hz.size()), 6 * n_nodes);
    const int n_phys = 5 * n_nodes;
    double max_phys_share = 0.0, min_drill_share = 1.0;
    for (int k = 0; k < n_phys; ++k) max_phys_share = std::max(max_phys_share, s.rz_share[k]);
    for (int k = n_phys; k < 6 * n_nodes; ++k) min_drill_share = std::min(min_drill_share, s.rz_share[k]);
    const double gap = s.hz[n_phys] / s.hz[n_phys - 1];
    std::vector<double> physical(s.hz.begin() + 6, s.hz.begin() + n_phys);
    std::printf(
        "%s: highest physical %.1f Hz, lowest drilling %.1f Hz (ratio %.2f; old cluster %.1f Hz), "
        "max rz share below %.2e, min above %.3f, largest cluster %d\n",
        c.name, s.hz[n_phys - 1], s.hz[n_phys], gap, OldDrillingClusterHz(t), max_phys_share,
        min_drill_share, LargestDrillCluster(physical));
    EXPECT_LT(max_phys_share, 1e-3);
    EXPECT_GT(min_drill_share, 0.5);
    EXPECT_GT(gap, 2.0);
    EXPECT_LE(LargestDrillCluster(physical), 2);
  }
}

TEST(FeShellDrilling, CantileverPlateMatchesS4PastTheOldCluster) {
  if (!::flexmb::testing::HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const double t = 0.05;
  ShellGrid plate = DrillPlate(20, t, false);
  plate.Fix([](int, int j) { return j == 0; }, {0, 1, 2, 3, 4, 5});
  const int count = 40;
  ::flexmb::testing::CcxScratchDir dir("drilling_plate");
  ASSERT_TRUE(::flexmb::testing::RunCcx(dir.path, "job", ::flexmb::testing::CcxDeck(plate.mesh, dir.path, count)));
  const std::vector<double> ccx = ::flexmb::testing::ParseCcxFrequencies(dir.path / "job.dat");
  const std::vector<double> ours = ::flexmb::testing::FlexmbFrequencies(Assemble(plate.mesh), count);
  ASSERT_EQ(ccx.size(), ours.size());
  double max_diff = 0.0;
  for (int k = 0; k < count; ++k) {
    const double d = std::abs(ours[k] - ccx[k]) / ccx[k];
    std::printf("mode %2d: flexmb %9.2f Hz, ccx S4 %9.2f Hz, rel diff %.4f\n", k + 1, ours[k], ccx[k], d);
    max_diff = std::max(max_diff, d);
  }
  std::printf("old drilling cluster at %.1f Hz, highest mode compared %.1f Hz, max rel diff %.4f\n",
              OldDrillingClusterHz(t), ccx.back(), max_diff);
  EXPECT_GT(ccx.back(), 1.5 * OldDrillingClusterHz(t));
  EXPECT_LT(max_diff, 0.03);
  EXPECT_LE(LargestDrillCluster(ours), 2);
}

TEST(FeShellDrilling, LadderFrameModesAndReduction) {
  const ::flexmb::reduction::testing::Ladder l = ::flexmb::reduction::testing::CoarseLadder();
  const AssembledModel full = Assemble(l.mesh);
  ModalOptions modal;
  modal.count = 60;
  const ModalResult r = SolveModes(full, modal);
  const std::vector<double> hz(r.frequencies_hz.data() + 6, r.frequencies_hz.data() + r.frequencies_hz.size());
  std::printf("ladder: modes 7..60 from %.2f to %.2f Hz, largest cluster %d, old cluster %.0f Hz\n", hz.front(),
              hz.back(), LargestDrillCluster(hz), OldDrillingClusterHz(0.006));
  EXPECT_LE(LargestDrillCluster(hz), 2);

  FeModel model;
  model.mesh = l.mesh;
  reduction::ReductionOptions options;
  options.interface_nodes = l.interface;
  options.normal_modes = 30;
  const reduction::ReducedBody body = reduction::ReduceCraigBampton(model, options);
  const std::vector<double> red(body.frequencies_hz.data(), body.frequencies_hz.data() + body.frequencies_hz.size());
  ASSERT_GE(red.size(), 10u);
  std::printf("ladder reduced (8 interface nodes, 30 normal modes): %zu flexible modes up to %.0f Hz, largest cluster %d\n",
              red.size(), red.back(), LargestDrillCluster(red));
  for (int k = 0; k < 10; ++k) {
    SCOPED_TRACE(k);
    EXPECT_GE(red[k], hz[k] * (1.0 - 1e-8));
    EXPECT_LT(red[k], hz[k] * 1.01);
  }
  EXPECT_LE(LargestDrillCluster(red), 2);
}

}  // namespace fe_shell_drilling_test
}  // namespace flexmb::fe::validation
