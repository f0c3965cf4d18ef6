#include "flexmb/fe_io/calculix_matrices.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using testing::ExpectBadFiles;
using testing::FeData;
using testing::Replace;

TEST(CalculixMatrices, ReadsMatrixStorageFiles) {
  // hand-written in ccx's format (matrixstorage.c): "%d %d %20.13e", one
  // triangle with ROW <= COLUMN, diagonal first; job.dof "node.direction"
  const CalculixMatrices m = ReadCalculixMatrixStorage(FeData("calculix/tiny"));
  Eigen::Matrix3d K, M;
  K << 2000, -1000, 0, -1000, 2000, -500, 0, -500, 1000;
  M << 0.25, 0, 0, 0, 0.25, 0, 0, 0, 0.5;
  EXPECT_EQ(Eigen::Matrix3d(Eigen::MatrixXd(m.K)), K);
  EXPECT_EQ(Eigen::Matrix3d(Eigen::MatrixXd(m.M)), M);
  ASSERT_EQ(m.dofs.rows.size(), 3u);
  EXPECT_EQ(m.dofs.rows[0].node_id, 10);
  EXPECT_EQ(m.dofs.rows[0].component, 1);
  EXPECT_EQ(m.dofs.rows[1].node_id, 10);
  EXPECT_EQ(m.dofs.rows[1].component, 2);
  EXPECT_EQ(m.dofs.rows[2].node_id, 20);
  EXPECT_EQ(m.dofs.rows[2].component, 1);
  EXPECT_EQ(m.dofs.rows[2].line, 3);
  EXPECT_EQ(m.K.nonZeros(), 9);  // 3 diagonal + 3 mirrored pairs, the explicit zero (1,3) kept
}

// each bad file: the message names the file, the line and the entry or row
TEST(CalculixMatrices, BadInputNamesFileLineAndEntry) {
  const std::string sti = testing::ReadText(FeData("calculix/tiny.sti"));
  ExpectBadFiles(
      {
          {"range.sti", Replace(sti, "2 3 -5", "2 4 -5"), ":6: entry 6 (row 2, column 4)", {"index out of range 1..3"}},
          {"nan.sti", Replace(sti, "-1.0000000000000e+03", "nan"), ":4: entry 4 (row 1, column 2)", {"not finite"}},
          {"twice.sti", Replace(sti, "2 3 -5", "2 1 -5"), ":6:", {"position (1,2) given twice (also line 4)"}},
          {"fields.sti", Replace(sti, "3 3 ", "3 "), ":3: entry 3", {"expected 'ROW COLUMN VALUE'"}},
          {"number.sti", Replace(sti, "-5.0000000000000e+02", "-5.0D+02"), ":6: entry 6 (row 2, column 3)",
           {"is not a number"}},
      },
      [](const std::string& path) { ReadCalculixMatrix(path, 3); });
  ExpectBadFiles(
      {
          {"temperature.dof", "10.1\n10.0\n", ":2: row 2", {"direction 0 (temperature)"}},
          {"direction.dof", "10.1\n10.7\n", ":2: row 2", {"direction 7 is not 1..6"}},
          {"node.dof", "10.1\n-3.1\n", ":2: row 2", {"node id -3 is not positive"}},
          {"syntax.dof", "10.1\n10 1\n", ":2: row 2", {"expected one 'NODE.DIRECTION' field"}},
          {"dot.dof", "10.1\n101\n", ":2: row 2", {"'101' is not 'NODE.DIRECTION'"}},
      },
      [](const std::string& path) { ReadCalculixDofs(path); });
}

}  // namespace
}  // namespace flexmb::io
