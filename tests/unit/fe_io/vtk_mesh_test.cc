#include "flexmb/fe_io/vtk_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "flexmb/fe_io/gmsh_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using fe::ElementType;
using fe::Mesh;
using fe::Vec3;
using testing::FeData;
using testing::InputErrorOf;
using testing::WriteScratch;

// nodes (ids, coordinates bit for bit) and elements (ids, types, nodes) equal
void ExpectIdentical(const Mesh& a, const Mesh& b) {
  testing::ExpectSameNodes(a, b);
  testing::ExpectSameConnectivity(a, b);
}

// the mesh of all_cells_v3.vtk and all_cells_v51.vtk
void CheckAllCells(const Mesh& m) {
  ASSERT_EQ(m.nodes.size(), 14u);
  for (int k = 0; k < 14; ++k) EXPECT_EQ(m.nodes[k].id, 101 + k);
  EXPECT_EQ(m.nodes[12].x, Vec3(0.5, 0, 0));
  EXPECT_EQ(m.nodes[13].x, Vec3(3, 3, 3));
  EXPECT_EQ(m.NodeIndex(105), 4);
  // the two vertex cells (ids 900 and 901) are not elements
  const ElementType types[] = {ElementType::kBeam2, ElementType::kTria3, ElementType::kQuad4,
                               ElementType::kTet4,  ElementType::kHex8,  ElementType::kTet10};
  const std::vector<int> nodes[] = {{0, 12}, {0, 1, 2}, {4, 5, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7, 8, 9, 10, 11},
                                    {0, 1, 2, 3, 12, 4, 5, 6, 7, 8}};
  ASSERT_EQ(m.elements.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(m.elements[k].id, 11 + k);
    EXPECT_EQ(m.elements[k].type, types[k]);
    EXPECT_EQ(m.elements[k].nodes, nodes[k]);
    EXPECT_EQ(m.elements[k].property, -1);
  }
}

TEST(VtkMesh, ReadsEveryCellTypeClassicLayout) {
  const Mesh m = ReadVtk(FeData("vtk/all_cells_v3.vtk"));
  CheckAllCells(m);
  EXPECT_EQ(m.elements[0].origin.line, 16);  // "2 0 12"
  EXPECT_EQ(m.nodes[4].origin.line, 10);
}

TEST(VtkMesh, ReadsEveryCellTypeVersion51Layout) { CheckAllCells(ReadVtk(FeData("vtk/all_cells_v51.vtk"))); }

TEST(VtkMesh, GmshWrittenFileMatchesTheMshFile) {
  // gmsh wrote mixed.vtk and mixed_v41.msh from the same .geo: same points in
  // the same order (ids 1..n without a node_id array), same cells
  const Mesh v = ReadVtk(FeData("vtk/mixed.vtk"));
  const Mesh g = ReadGmsh(FeData("gmsh/mixed_v41.msh"));
  ASSERT_EQ(v.nodes.size(), g.nodes.size());
  for (size_t k = 0; k < v.nodes.size(); ++k) {
    EXPECT_EQ(v.nodes[k].id, static_cast<int>(k) + 1);
    EXPECT_LT((v.nodes[k].x - g.nodes[k].x).norm(), 1e-15);
  }
  testing::ExpectSameConnectivity(v, g, false);
}

TEST(VtkMesh, QuadraticTetraNodeOrder) {
  // gmsh's VTK export of 10-node tetrahedra: VTK order = flexmb order
  const Mesh m = ReadVtk(FeData("vtk/tet10.vtk"));
  ASSERT_EQ(m.elements.size(), 110u);
  const auto& edge = flexmb::fe::kTet10EdgeCorners;
  double volume = 0.0;
  for (const fe::Element& e : m.elements) {
    ASSERT_EQ(e.type, ElementType::kTet10);
    auto x = [&](int k) { return m.nodes[e.nodes[k]].x; };
    for (int k = 0; k < 6; ++k)
      EXPECT_LT((x(4 + k) - 0.5 * (x(edge[k][0]) + x(edge[k][1]))).norm(), 1e-12) << "element " << e.id;
    const double v = (x(1) - x(0)).cross(x(2) - x(0)).dot(x(3) - x(0)) / 6.0;
    EXPECT_GT(v, 0.0);
    volume += v;
  }
  EXPECT_NEAR(volume, 0.4 * 0.2 * 0.1, 1e-14);
}

TEST(VtkMesh, RoundTripIsBitForBit) {
  for (const char* f : {"gmsh/mixed_v41.msh", "gmsh/tet10_v41.msh", "gmsh/hex8_v22.msh", "gmsh/strip_v41.msh"}) {
    SCOPED_TRACE(f);
    const Mesh m = ReadGmsh(FeData(f));
    const std::string path = testing::ScratchPath("round_trip.vtk");
    WriteVtk(m, path);
    const Mesh r = ReadVtk(path);
    ExpectIdentical(m, r);
    // and the file written again is the same text
    const std::string first = testing::ReadText(path);
    WriteVtk(r, path);
    EXPECT_EQ(testing::ReadText(path), first);
  }
}

TEST(VtkMesh, RoundTripKeepsHardDoubles) {
  Mesh m;
  const double hard[] = {1.0 / 3.0,
                         -0.0,
                         std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::max(),
                         -std::numeric_limits<double>::min(),
                         0.1 + 0.2,
                         -1e-300,
                         M_PI,
                         9007199254740993.0,
                         123456789.12345678};
  int id = 7;
  for (size_t k = 0; k + 2 < std::size(hard); ++k) {
    fe::Node n;
    n.id = id;
    id += 13;
    n.x = Vec3(hard[k], hard[k + 1], hard[k + 2]);
    m.nodes.push_back(n);
  }
  fe::Element e;
  e.id = 42;
  e.type = ElementType::kTet4;
  e.nodes = {0, 3, 5, 7};
  m.elements.push_back(e);
  e.id = 5;
  e.type = ElementType::kBeam2;
  e.nodes = {6, 1};
  m.elements.push_back(e);
  m.IndexNodes();
  const std::string path = testing::ScratchPath("hard.vtk");
  WriteVtk(m, path);
  ExpectIdentical(m, ReadVtk(path));
}

// a small valid file whose lines are easy to count
const char* kSmall =
    "# vtk DataFile Version 3.0\n"  // 1
    "small\n"                       // 2
    "ASCII\n"                       // 3
    "DATASET UNSTRUCTURED_GRID\n"   // 4
    "POINTS 4 float\n"              // 5
    "0 0 0\n"                       // 6
    "1 0 0\n"                       // 7
    "0 1 0\n"                       // 8
    "0 0 1\n"                       // 9
    "CELLS 2 8\n"                   // 10
    "4 0 1 2 3\n"                   // 11
    "2 0 1\n"                       // 12
    "CELL_TYPES 2\n"                // 13
    "10\n"                          // 14
    "3\n"                           // 15
    "POINT_DATA 4\n"                // 16
    "SCALARS node_id int\n"         // 17
    "LOOKUP_TABLE default\n"        // 18
    "5 6 7 8\n";                    // 19

// kSmall with the first occurrence of `from` replaced by `to`
std::string VtkMeshSmall(const std::string& from, const std::string& to) { return testing::Replace(kSmall, from, to); }

TEST(VtkMesh, SmallFileReads) {
  const Mesh m = ReadVtk(WriteScratch("small.vtk", kSmall));
  ASSERT_EQ(m.nodes.size(), 4u);
  EXPECT_EQ(m.nodes[3].id, 8);
  ASSERT_EQ(m.elements.size(), 2u);
  EXPECT_EQ(m.elements[1].id, 2);  // without element_id: the cell number + 1
  EXPECT_EQ(m.elements[1].origin.line, 12);
}

// each case: file, ":line: entity: " after its path, part of the message
TEST(VtkMesh, BadInputNamesFileLineAndEntity) {
  testing::ExpectBadFiles(
      {
          {"binary.vtk", VtkMeshSmall("ASCII", "BINARY"), ":3: ", {"binary VTK not supported, save as ASCII"}},
          {"magic.vtk", VtkMeshSmall("# vtk DataFile", "# VTK File"), ":1: ", {"not a legacy VTK file"}},
          {"dataset.vtk", VtkMeshSmall("UNSTRUCTURED_GRID", "POLYDATA"), ":4: ", {"only DATASET UNSTRUCTURED_GRID"}},
          {"celltype.vtk", VtkMeshSmall("10\n3\n", "7\n3\n"), ":11: cell 0 (element 1): ",
           {"VTK cell type 7 is not supported"}},
          {"range.vtk", VtkMeshSmall("2 0 1\n", "2 0 4\n"), ":12: cell 1 (element 2): ", {"point index 4 does not exist"}},
          {"count.vtk", VtkMeshSmall("CELLS 2 8\n4 0 1 2 3\n2 0 1\n", "CELLS 2 8\n3 0 1 2\n3 0 1 2\n"),
           ":11: cell 0 (element 1): ", {"has 4 points, got 3"}},
          {"size.vtk", VtkMeshSmall("CELLS 2 8", "CELLS 2 9"), ":12: ", {"the CELLS size says 9"}},
          {"dupid.vtk", VtkMeshSmall("5 6 7 8", "5 6 5 8"), ":8: node 5: ", {"duplicate node id"}},
          {"inf.vtk", VtkMeshSmall("0 1 0\n", "0 inf 0\n"), ":8: point 2: ", {"y must be finite"}},
          {"short.vtk", VtkMeshSmall("0 0 1\n", "0 0\n"), ":10: point 3: ", {"expected a number for z, got 'CELLS'"}},
          {"idvalue.vtk", VtkMeshSmall("5 6 7 8", "5 6 7.5 8"), ":19: ", {"must be a whole number"}},
          {"types.vtk", VtkMeshSmall("CELL_TYPES 2", "CELL_TYPES 3"), ":13: ", {"CELL_TYPES 3 does not match the 2 cells"}},
          {"keyword.vtk", VtkMeshSmall("POINT_DATA 4", "POINT_DATUM 4"), ":16: ", {"unexpected 'POINT_DATUM'"}},
          {"pointdata.vtk", VtkMeshSmall("POINT_DATA 4", "POINT_DATA 5"), ":16: ", {"POINT_DATA 5 does not match"}},
          {"empty.vtk", "", ":1: ", {"empty file"}},
      },
      [](const std::string& path) { ReadVtk(path); });
}

TEST(VtkMesh, WriteRefusesBrokenMeshes) {
  Mesh m;
  m.nodes.resize(2);
  m.nodes[0].id = 1;
  m.nodes[1].id = 2;
  fe::Element e;
  e.id = 3;
  e.type = ElementType::kBeam2;
  e.nodes = {0, 2};
  e.origin = {"part.bdf", 12};
  m.elements.push_back(e);
  const std::string path = testing::ScratchPath("broken.vtk");
  testing::ExpectContains(InputErrorOf([&] { WriteVtk(m, path); }), {"part.bdf:12: element 3: refers to node index 2"},
                          "broken.vtk");
  m.elements[0].nodes = {0, 1};
  testing::ExpectContains(InputErrorOf([&] { WriteVtk(m, "/nonexistent/dir/x.vtk"); }),
                          {"/nonexistent/dir/x.vtk: cannot open for writing"}, "x.vtk");
}

}  // namespace
}  // namespace flexmb::io
