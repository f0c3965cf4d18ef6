// The 20-node hexahedron in every mesh format, each file written here in
// that format's own documented node order: Nastran CHEXA with 20 grid
// points (QRG: G9-G12 on the bottom edges 1-2, 2-3, 3-4, 4-1, G13-G16 on
// the vertical edges 1-5, 2-6, 3-7, 4-8, G17-G20 on the top edges 5-6,
// 6-7, 7-8, 8-5), Abaqus C3D20 and C3D20R (9-12 bottom, 13-16 top, 17-20
// vertical), gmsh type 17 (reference manual: 8 on 0-1, 9 on 0-3, 10 on 0-4,
// 11 on 1-2, 12 on 1-5, 13 on 2-3, 14 on 2-6, 15 on 3-7, 16 on 4-5, 17 on
// 4-7, 18 on 5-6, 19 on 6-7), VTK 25 (vtkQuadraticHexahedron: as Abaqus).
// Each read element must come out in flexmb's order (fe/elements/
// solid_hex20.h) with mass rho V; the writers (Abaqus, VTK) read back to
// the same mesh; C3D20R stays C3D20R through the Abaqus writer, whose
// element lines hold at most 16 entries.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "flexmb/body_file/body_file_mesh.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/elements/solid_hex20.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"
#include "flexmb/fe_io/gmsh_reader.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/fe_io/vtk_mesh.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::io {
namespace hex20_formats_test {

using fe::Vec3;

// an oblique parallelepiped, corners in flexmb's order
const Vec3 kHex20O(0.1, 0.2, -0.1), kHex20A(1.1, 0.1, 0.05), kHex20B(0.2, 0.9, -0.05), kHex20C(0.2, 0.1, 0.8);
const std::vector<Vec3> kHex20Corners = {kHex20O,
                                         kHex20O + kHex20A,
                                         kHex20O + kHex20A + kHex20B,
                                         kHex20O + kHex20B,
                                         kHex20O + kHex20C,
                                         kHex20O + kHex20A + kHex20C,
                                         kHex20O + kHex20A + kHex20B + kHex20C,
                                         kHex20O + kHex20B + kHex20C};

// a format's node list: the corners, then mid-edge nodes on corner pairs
std::vector<Vec3> Hex20FormatPoints(const std::vector<std::array<int, 2>>& edges) {
  std::vector<Vec3> p = kHex20Corners;
  for (const auto& e : edges) p.push_back(0.5 * (p[e[0]] + p[e[1]]));
  return p;
}

void ExpectHex20Order(const fe::Mesh& mesh, const fe::Element& e, fe::ElementType type) {
  ASSERT_EQ(e.nodes.size(), 20u);
  EXPECT_EQ(e.type, type);
  std::vector<Vec3> x;
  for (int n : e.nodes) x.push_back(mesh.nodes[n].x);
  for (int k = 0; k < 8; ++k) EXPECT_LT((x[k] - kHex20Corners[k]).norm(), 1e-12) << "element " << e.id << " node " << k;
  for (int k = 8; k < 20; ++k) {
    const Vec3 mid = 0.5 * (kHex20Corners[fe::kHex20EdgeCorners[k - 8][0]] + kHex20Corners[fe::kHex20EdgeCorners[k - 8][1]]);
    EXPECT_LT((x[k] - mid).norm(), 1e-12) << "element " << e.id << " node " << k;
  }
  const double volume = kHex20A.dot(kHex20B.cross(kHex20C));
  EXPECT_NEAR(testing::ElementTotalMass(e, x, 1000.0), 1000.0 * volume, 1e-10 * volume) << "element " << e.id;
}

std::string Hex20Num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

const std::vector<std::array<int, 2>> kHex20AbaqusEdges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                            {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

TEST(Hex20Formats, NastranChexa20) {
  const std::vector<Vec3> p = Hex20FormatPoints(
      {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}});
  std::string deck = "BEGIN BULK\nMAT1,1,2.1e11,,0.3,7850.0\nPSOLID,1,1\n";
  for (size_t k = 0; k < p.size(); ++k)
    deck += "GRID," + std::to_string(k + 1) + ",," + Hex20Num(p[k].x()) + "," + Hex20Num(p[k].y()) + "," +
            Hex20Num(p[k].z()) + "\n";
  deck += "CHEXA,10,1,1,2,3,4,5,6\n,7,8,9,10,11,12,13,14\n,15,16,17,18,19,20\nENDDATA\n";
  const fe::Mesh mesh = ReadNastran(testing::WriteScratch("hex20.bdf", deck));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectHex20Order(mesh, mesh.elements[0], fe::kHex20);
}

TEST(Hex20Formats, AbaqusC3D20AndC3D20R) {
  const std::vector<Vec3> p = Hex20FormatPoints(kHex20AbaqusEdges);
  std::string deck = "*NODE\n";
  for (size_t k = 0; k < p.size(); ++k)
    deck += std::to_string(k + 1) + ", " + Hex20Num(p[k].x()) + ", " + Hex20Num(p[k].y()) + ", " + Hex20Num(p[k].z()) + "\n";
  const std::string nodes = "1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,\n16, 17, 18, 19, 20\n";
  deck += "*ELEMENT, TYPE=C3D20, ELSET=H\n10, " + nodes + "*ELEMENT, TYPE=C3D20R, ELSET=H\n11, " + nodes;
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n*SOLID SECTION, ELSET=H, MATERIAL=STEEL\n";
  deck += "*SURFACE, NAME=TOP, TYPE=ELEMENT\n10, S2\n11, S6\n";
  const fe::Mesh mesh = ReadAbaqus(testing::WriteScratch("hex20.inp", deck));
  ASSERT_EQ(mesh.elements.size(), 2u);
  ExpectHex20Order(mesh, mesh.elements[0], fe::kHex20);
  ExpectHex20Order(mesh, mesh.elements[1], fe::kHex20R);
  const std::string path = testing::ScratchPath("hex20_written.inp");
  WriteAbaqus(mesh, path);
  const std::string written = testing::ReadText(path);
  EXPECT_NE(written.find("TYPE=C3D20,"), std::string::npos);
  EXPECT_NE(written.find("TYPE=C3D20R,"), std::string::npos);
  // Abaqus and CalculiX read at most 16 entries per data line (ccx stops
  // with an error on a 21-entry C3D20 line)
  std::istringstream lines(written);
  for (std::string line; std::getline(lines, line);)
    EXPECT_LE(std::count(line.begin(), line.end(), ','), line.empty() || line.back() == ',' ? 16 : 15) << line;
  const fe::Mesh back = ReadAbaqus(path);
  testing::ExpectSameConnectivity(mesh, back);
  EXPECT_EQ(back.elements[1].type, fe::kHex20R);
}

TEST(Hex20Formats, GmshHexahedron20) {
  const std::vector<Vec3> p = Hex20FormatPoints(
      {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3}, {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}});
  std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 \"solid\"\n$EndPhysicalNames\n";
  msh += "$Nodes\n" + std::to_string(p.size()) + "\n";
  for (size_t k = 0; k < p.size(); ++k)
    msh += std::to_string(k + 1) + " " + Hex20Num(p[k].x()) + " " + Hex20Num(p[k].y()) + " " + Hex20Num(p[k].z()) + "\n";
  msh += "$EndNodes\n$Elements\n1\n10 17 2 1 1 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20\n$EndElements\n";
  const fe::Mesh mesh = ReadGmsh(testing::WriteScratch("hex20.msh", msh));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectHex20Order(mesh, mesh.elements[0], fe::kHex20);
}

TEST(Hex20Formats, VtkQuadraticHexahedronAndBodyFileCodes) {
  const std::vector<Vec3> p = Hex20FormatPoints(kHex20AbaqusEdges);
  std::string vtk = "# vtk DataFile Version 3.0\nhex20\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 20 double\n";
  for (const Vec3& q : p) vtk += Hex20Num(q.x()) + " " + Hex20Num(q.y()) + " " + Hex20Num(q.z()) + "\n";
  vtk += "CELLS 1 21\n20 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19\nCELL_TYPES 1\n25\n";
  const fe::Mesh mesh = ReadVtk(testing::WriteScratch("hex20.vtk", vtk));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectHex20Order(mesh, mesh.elements[0], fe::kHex20);
  const std::string path = testing::ScratchPath("hex20_written.vtk");
  WriteVtk(mesh, path);
  testing::ExpectSameConnectivity(mesh, ReadVtk(path));
  EXPECT_TRUE(HasBodyFileTypeCode(fe::kHex20));
  EXPECT_TRUE(HasBodyFileTypeCode(fe::kHex20R));
}

}  // namespace hex20_formats_test
}  // namespace flexmb::io
