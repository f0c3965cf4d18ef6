#include "flexmb/fe_io/dof_map.h"

#include <gtest/gtest.h>

#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using testing::WriteScratch;

TEST(DofMap, ReadsRowsInAnyOrderWithComments) {
  const std::string path = WriteScratch("map.txt",
                                        "# a DOF map\n"
                                        "  # indented comment\n"
                                        "2 7 3\n"
                                        "\n"
                                        "1 7 1\t\n"
                                        "3 12 6\r\n");
  const MatrixRowMap m = ReadDofMap(path);
  EXPECT_EQ(m.file, path);
  ASSERT_EQ(m.rows.size(), 3u);
  EXPECT_EQ(m.rows[0].node_id, 7);
  EXPECT_EQ(m.rows[0].component, 1);
  EXPECT_EQ(m.rows[0].line, 5);
  EXPECT_EQ(m.rows[1].node_id, 7);
  EXPECT_EQ(m.rows[1].component, 3);
  EXPECT_EQ(m.rows[2].node_id, 12);
  EXPECT_EQ(m.rows[2].component, 6);
}

TEST(DofMap, WriteReadRoundTrip) {
  std::vector<DofMapRow> rows;
  for (int i = 0; i < 20; ++i) rows.push_back(DofMapRow{100 + i / 6, 1 + i % 6, 0});
  const std::string path = testing::ScratchPath("round.txt");
  WriteDofMap(rows, path);
  const MatrixRowMap m = ReadDofMap(path);
  ASSERT_EQ(m.rows.size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(m.rows[i].node_id, rows[i].node_id);
    EXPECT_EQ(m.rows[i].component, rows[i].component);
    EXPECT_EQ(m.rows[i].line, static_cast<int>(i) + 3);  // two comment lines first
  }
}

TEST(DofMap, FreeDofRowsFollowTheFreeNumbering) {
  fe::Mesh mesh;
  for (int id : {5, 9}) {
    fe::Node n;
    n.id = id;
    mesh.nodes.push_back(n);
  }
  fe::DofMap d;
  d.free = {{-1, 2, -1, -1, -1, -1}, {0, -1, -1, -1, -1, 1}};
  d.n_free = 3;
  const std::vector<DofMapRow> rows = FreeDofRows(mesh, d);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].node_id, 9);
  EXPECT_EQ(rows[0].component, 1);
  EXPECT_EQ(rows[1].node_id, 9);
  EXPECT_EQ(rows[1].component, 6);
  EXPECT_EQ(rows[2].node_id, 5);
  EXPECT_EQ(rows[2].component, 2);
}

// each bad file: the message names the file, the line and the row
TEST(DofMap, BadInputNamesFileLineAndRow) {
  testing::ExpectBadFiles(
      {
          {"missing_row.txt", "1 5 1\n3 5 2\n", ":2: row 3", {"row out of range: the map has 2 lines"}},
          {"twice.txt", "1 5 1\n1 5 2\n", ":2: row 1", {"listed twice (also at line 1)"}},
          {"component.txt", "1 5 1\n2 5 7\n", ":2: row 2", {"component '7' is not 1..6"}},
          {"node.txt", "1 5 1\n2 0 1\n", ":2: row 2", {"node id '0' is not a positive integer"}},
          {"fields.txt", "1 5 1\n2 5\n", ":2:", {"expected 'ROW NODE COMPONENT', found 2 fields"}},
          {"row.txt", "1 5 1\nx 5 1\n", ":2:", {"row 'x' is not an integer"}},
          {"empty.txt", "# nothing\n", ": ", {"no rows in the DOF map"}},
      },
      [](const std::string& path) { ReadDofMap(path); });
}

}  // namespace
}  // namespace flexmb::io
