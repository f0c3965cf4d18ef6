// The modes file of the exchange set (body_file/modes_file.h): a Craig-Bampton
// basis written next to the exchange set reads back bit for bit; the read
// static modes are in static equilibrium (K H_s = 0 on the interior DOF)
// and the normal modes solve K phi = (2 pi f)^2 M phi there with the
// frequencies of the header; the reduced eigenproblem of the imported
// matrices on the imported modes gives the frequencies of
// ReduceCraigBampton on the mesh; and malformed files and modes that do not
// fit the DOF map are errors naming the file, line, column and DOF.

#include "flexmb/body_file/modes_file.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "flexmb/fe/fe_model.h"
#include "flexmb/fe_io/exchange_set.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/craig_bampton_basis.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"
#include "tests/unit/reduction/reduction_test_models.h"

namespace flexmb::io {
namespace {

namespace fs = std::filesystem;
using testing::BadFile;
using testing::ExpectBadFiles;
using testing::ExpectContains;
using testing::InputErrorOf;
using testing::ScratchPath;

constexpr double kPi = 3.14159265358979323846;

// a free 0.6 x 0.4 m steel plate, 6 x 4 shells 4 mm thick, interface at two
// corners, its exchange set and Craig-Bampton modes written to `dir`
struct PlateSet {
  fe::FeModel model;
  reduction::ReductionOptions options;
  fe::AssembledModel assembled;
  ExchangeModes modes;
  std::string dir;
};

PlateSet WritePlateSet(const std::string& name) {
  PlateSet p;
  const std::vector<int> grid = reduction::testing::AddPlate(p.model.mesh, 6, 4, 0.6, 0.4, 0.004);
  p.options.interface_nodes = {grid[0], grid[6]};
  p.options.normal_modes = 5;
  p.assembled = fe::BuildMatrices(p.model, fe::AssemblyOptions{});
  const reduction::CraigBamptonBasis basis =
      reduction::BuildCraigBamptonBasis(p.model.mesh, p.assembled, p.options);
  p.modes = ModesOfBasis(basis, p.model.mesh, p.assembled.dofs);
  p.dir = ScratchPath(name);
  WriteExchangeSet(p.model.mesh, p.assembled, p.dir);
  WriteModesFile(p.modes, (fs::path(p.dir) / kModesFileName).string());
  return p;
}

TEST(ModesFile, RoundTripIsBitForBit) {
  const PlateSet p = WritePlateSet("modes_round_trip");
  ASSERT_EQ(p.modes.StaticModes(), 12);
  ASSERT_EQ(p.modes.NormalModes(), 5);
  const ExchangeModes back = ReadExchangeSetModes(p.dir);
  ASSERT_EQ(back.modes.rows(), p.assembled.dofs.n_free);
  ASSERT_EQ(back.modes.cols(), 17);
  EXPECT_EQ(std::memcmp(back.modes.data(), p.modes.modes.data(), sizeof(double) * back.modes.size()), 0);
  ASSERT_EQ(back.normal_frequencies_hz.size(), 5);
  EXPECT_EQ(std::memcmp(back.normal_frequencies_hz.data(), p.modes.normal_frequencies_hz.data(), 5 * sizeof(double)),
            0);
  // the interface DOF: nodes 1 and 7 (ids = index + 1), all six components
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(back.static_dofs[k].node_id, k < 6 ? 1 : 7) << k;
    EXPECT_EQ(back.static_dofs[k].component, k % 6 + 1) << k;
  }
  for (Eigen::Index j = 1; j < 5; ++j) EXPECT_GT(back.normal_frequencies_hz[j], back.normal_frequencies_hz[j - 1]);
}

TEST(ModesFile, ImportedModesAreCraigBamptonModesOfTheImportedMatrices) {
  const PlateSet p = WritePlateSet("modes_physics");
  const ExchangeModes m = ReadExchangeSetModes(p.dir);
  const fe::FeModel imported = ReadExchangeSet(p.dir);
  const fe::AssembledModel a = fe::BuildMatrices(imported, fe::AssemblyOptions{});
  const Eigen::MatrixXd K = Eigen::MatrixXd(a.K), M = Eigen::MatrixXd(a.M);
  ASSERT_EQ(K.rows(), m.modes.rows());

  // interior rows: every row of the DOF map that is not an interface DOF
  const MatrixRowMap map = ReadDofMap((fs::path(p.dir) / "dof_map.txt").string());
  std::vector<bool> interface(K.rows(), false);
  for (Eigen::Index r = 0; r < K.rows(); ++r) {
    for (const DofMapRow& d : m.static_dofs) {
      if (d.node_id == map.rows[r].node_id && d.component == map.rows[r].component) interface[r] = true;
    }
  }
  EXPECT_EQ(std::count(interface.begin(), interface.end(), true), 12);
  const double k_scale = K.cwiseAbs().maxCoeff();
  const Eigen::MatrixXd kh = K * m.modes;
  const Eigen::MatrixXd mh = M * m.modes;
  for (Eigen::Index j = 0; j < m.modes.cols(); ++j) {
    const bool normal = j >= m.StaticModes();
    const double lambda = normal ? std::pow(2 * kPi * m.normal_frequencies_hz[j - m.StaticModes()], 2) : 0.0;
    double worst = 0.0;
    for (Eigen::Index r = 0; r < K.rows(); ++r) {
      if (!interface[r]) worst = std::max(worst, std::abs(kh(r, j) - lambda * mh(r, j)));
    }
    EXPECT_LT(worst, 1e-9 * k_scale * m.modes.col(j).cwiseAbs().maxCoeff()) << "column " << j + 1;
  }
  const Eigen::MatrixXd phi = m.modes.rightCols(m.NormalModes());
  EXPECT_LT((phi.transpose() * M * phi - Eigen::MatrixXd::Identity(5, 5)).norm(), 1e-10);

  // the reduced eigenproblem: six rigid-body modes near 0, then the flexible
  // frequencies of the reduction of the mesh
  const Eigen::MatrixXd kr = m.modes.transpose() * K * m.modes, mr = m.modes.transpose() * M * m.modes;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (kr + kr.transpose()),
                                                                      0.5 * (mr + mr.transpose()));
  ASSERT_EQ(eig.info(), Eigen::Success);
  const Eigen::VectorXd lambda = eig.eigenvalues();
  const reduction::ReducedBody body = reduction::ReduceCraigBampton(p.model, p.options);
  ASSERT_EQ(body.frequencies_hz.size(), 11);
  // the rigid-body eigenvalues are round-off: a backward-stable solve of
  // (kr, mr) perturbs each eigenvalue by about eps times the largest one
  // (the shells' drilling modes make that large); 100 times that
  const double roundoff = std::numeric_limits<double>::epsilon() * lambda.cwiseAbs().maxCoeff();
  std::printf("rigid-body eigenvalues up to %.3g; round-off scale %.3g; first flexible %.6g\n",
              lambda.head(6).cwiseAbs().maxCoeff(), roundoff, lambda[6]);
  for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(lambda[k]), 100.0 * roundoff) << k;
  EXPECT_LT(100.0 * roundoff, 1e-5 * lambda[6]);  // still far below the flexible modes
  for (int k = 0; k < 11; ++k) {
    const double f = std::sqrt(lambda[6 + k]) / (2 * kPi);
    EXPECT_NEAR(f, body.frequencies_hz[k], 1e-9 * body.frequencies_hz[k]) << "flexible mode " << k + 1;
  }
}

TEST(ModesFile, BasisOfImportedModesIsTheBasisOfTheReduction) {
  const PlateSet p = WritePlateSet("modes_basis");
  const ExchangeModes m = ReadExchangeSetModes(p.dir);
  const fe::FeModel imported = ReadExchangeSet(p.dir);
  const fe::AssembledModel a = fe::BuildMatrices(imported, fe::AssemblyOptions{});
  const reduction::CraigBamptonBasis b = BasisOfModes(m, imported.mesh, a, p.dir);
  const reduction::CraigBamptonBasis ref = reduction::BuildCraigBamptonBasis(p.model.mesh, p.assembled, p.options);
  EXPECT_EQ(b.boundary, ref.boundary);
  EXPECT_EQ(b.interior, ref.interior);
  // psi and phi came through the file bit for bit
  EXPECT_EQ(b.psi, ref.psi);
  EXPECT_EQ(b.phi, ref.phi);
  EXPECT_EQ(b.fixed_interface_hz, ref.fixed_interface_hz);
  EXPECT_EQ(b.stiffness_scale, ref.stiffness_scale);
  // the reduced matrices: the same products in another order
  EXPECT_LT((b.mass - ref.mass).cwiseAbs().maxCoeff(), 1e-12 * ref.mass.cwiseAbs().maxCoeff());
  EXPECT_LT((b.stiffness - ref.stiffness).cwiseAbs().maxCoeff(), 1e-12 * ref.stiffness.cwiseAbs().maxCoeff());

  ExchangeModes shifted = m;
  shifted.static_dofs[3].node_id = 999;
  ExpectContains(InputErrorOf([&] { BasisOfModes(shifted, imported.mesh, a, p.dir); }),
                 {p.dir, "column 4: static mode of node 999 rx: not a free DOF of the model"}, "dof");
  ExchangeModes fewer = m;
  fewer.modes.conservativeResize(m.modes.rows() - 1, Eigen::NoChange);
  ExpectContains(InputErrorOf([&] { BasisOfModes(fewer, imported.mesh, a, p.dir); }),
                 {p.dir, "modes file: the modes are"}, "rows");
}

// a valid file: 3 DOF, static modes of rows 1 and 2, one normal mode
const std::string kHeader =
    "%%MatrixMarket matrix array real general\n"
    "% flexmb modes version 1\n"
    "% static 2\n"
    "% normal 1\n"
    "% column 1 static node 1 component 1\n"
    "% column 2 static node 2 component 3\n"
    "% column 3 normal 1 frequency_hz 12.5\n";
const std::string kValues = "3 3\n1\n0\n0.5\n0\n1\n-0.25\n0\n0\n1\n";

TEST(ModesFile, ReadsAValidFileAndChecksItAgainstTheDofMap) {
  const std::string path = testing::WriteScratch("valid_modes.mtx", kHeader + "% another comment\n\n" + kValues);
  const ExchangeModes m = ReadModesFile(path);
  Eigen::MatrixXd want(3, 3);
  want << 1, 0, 0, 0, 1, 0, 0.5, -0.25, 1;
  EXPECT_EQ(m.modes, want);
  ASSERT_EQ(m.StaticModes(), 2);
  EXPECT_EQ(m.static_dofs[1].node_id, 2);
  EXPECT_EQ(m.static_dofs[1].component, 3);
  EXPECT_EQ(m.static_dofs[1].line, 6);
  EXPECT_EQ(m.normal_frequencies_hz, Eigen::VectorXd::Constant(1, 12.5));

  MatrixRowMap map;
  map.file = "dof_map.txt";
  map.rows = {{1, 1, 3}, {2, 3, 4}, {3, 1, 5}};
  CheckModesAgainstDofMap(m, map, path);

  MatrixRowMap two = map;
  two.rows.pop_back();
  ExpectContains(InputErrorOf([&] { CheckModesAgainstDofMap(m, two, path); }),
                 {path + ": modes file: the modes have 3 rows, the DOF map dof_map.txt has 2"}, "rows");
  MatrixRowMap other = map;
  other.rows[1].component = 2;
  ExpectContains(InputErrorOf([&] { CheckModesAgainstDofMap(m, other, path); }),
                 {path + ":6: column 2: static mode of node 2 uz: the DOF map dof_map.txt has no row for it"}, "dof");
  ExchangeModes off = m;
  off.modes(1, 1) = 0.5;
  ExpectContains(InputErrorOf([&] { CheckModesAgainstDofMap(off, map, path); }),
                 {path + ": column 2: static mode of node 2 uz: the value at row 2 (node 2 uz, an interface DOF) is "
                         "0.5, expected 1"},
                 "unit");
  off = m;
  off.modes(0, 2) = 1e-3;
  ExpectContains(InputErrorOf([&] { CheckModesAgainstDofMap(off, map, path); }),
                 {path + ": column 3: normal mode: the value at row 1 (node 1 ux", "expected 0"}, "normal");
  ExchangeModes twice = m;
  twice.static_dofs[1] = twice.static_dofs[0];
  ExpectContains(InputErrorOf([&] { CheckModesAgainstDofMap(twice, map, path); }),
                 {"column 2: static mode of node 1 ux: the same DOF as column 1"}, "twice");
}

TEST(ModesFile, MalformedFiles) {
  auto with = [](const std::string& from, const std::string& to) { return testing::Replace(kHeader, from, to); };
  const std::vector<BadFile> cases = {
      {"coordinate.mtx", with("array", "coordinate") + kValues, ":1: ", {"expected the banner"}},
      {"no_version.mtx", with("% flexmb modes version 1\n", "") + kValues, ": ", {"not a flexmb modes file"}},
      {"version2.mtx", with("version 1", "version 2") + kValues, ":2: ", {"modes file version 2"}},
      {"no_column.mtx", with("% column 2 static node 2 component 3\n", "") + kValues, ": ",
       {"column 2 has no '% column' header line"}},
      {"twice.mtx", kHeader + "% column 2 static node 3 component 3\n" + kValues, ":8: ",
       {"column 2 is described twice (also at line 6)"}},
      {"order.mtx", with("% static 2\n% normal 1", "% static 1\n% normal 2") + kValues, ":6: column 2: ",
       {"expected a normal mode (static modes come first)"}},
      {"counts.mtx", with("% normal 1", "% normal 2") + kValues, ":8: ",
       {"2 static + 2 normal modes, but the size line has 3 columns"}},
      {"component.mtx", with("component 3", "component 7") + kValues, ":6: ", {"expected '% column J static"}},
      {"frequency.mtx", with("12.5", "inf") + kValues, ":7: ", {"frequency_hz"}},
      {"fortran.mtx", kHeader + testing::Replace(kValues, "0.5", "0.5D0"), ":11: row 3, column 1: ",
       {"value '0.5D0' is not a number"}},
      {"nan.mtx", kHeader + testing::Replace(kValues, "-0.25", "nan"), ":14: row 3, column 2: ",
       {"value 'nan' is not finite"}},
      {"few.mtx", kHeader + kValues.substr(0, kValues.size() - 2), ":16: ", {"ends after 8 of 9 values"}},
      {"many.mtx", kHeader + kValues + "7\n", ":18: ", {"more values than the 9 of the size line"}},
      {"size.mtx", kHeader + "3\n", ":8: ", {"expected the size line 'ROWS COLUMNS'"}},
      {"empty.mtx", "", ": ", {"empty file"}},
  };
  ExpectBadFiles(cases, [](const std::string& path) { ReadModesFile(path); });
}

TEST(ModesFile, WriteRefusesInconsistentModes) {
  ExchangeModes m;
  m.static_dofs = {{1, 1, 0}};
  m.normal_frequencies_hz = Eigen::VectorXd::Constant(1, 3.0);
  m.modes = Eigen::MatrixXd::Identity(3, 3);
  const std::string path = ScratchPath("bad_write.mtx");
  ExpectContains(InputErrorOf([&] { WriteModesFile(m, path); }),
                 {path, "3 columns, but 1 static DOF and 1 normal-mode frequencies"}, "columns");
  m.modes = Eigen::MatrixXd::Identity(3, 2);
  m.modes(2, 1) = std::nan("");
  ExpectContains(InputErrorOf([&] { WriteModesFile(m, path); }), {path, "row 3, column 2 is not finite"}, "nan");
  m.modes(2, 1) = 0.0;
  m.static_dofs[0].component = 0;
  ExpectContains(InputErrorOf([&] { WriteModesFile(m, path); }),
                 {path, "static mode 1: invalid node id 1 or component 0"}, "component");
  EXPECT_FALSE(fs::exists(path));
  ExpectContains(InputErrorOf([&] { ReadExchangeSetModes(ScratchPath("no_modes_here")); }), {"modes.mtx", "missing"},
                 "missing");
}

}  // namespace
}  // namespace flexmb::io
