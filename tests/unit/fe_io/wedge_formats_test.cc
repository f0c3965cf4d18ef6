// The 6- and 15-node wedges in every mesh format, each file written here in
// that format's own documented node order: Nastran CPENTA (QRG: G7-G9 on
// the edges 1-2, 2-3, 3-1, G10-G12 on 1-4, 2-5, 3-6, G13-G15 on 4-5, 5-6,
// 6-4), Abaqus C3D6/C3D15 (7-9 on 1-2, 2-3, 3-1, 10-12 on 4-5, 5-6, 6-4,
// 13-15 on 1-4, 2-5, 3-6), gmsh types 6 and 18 (reference manual: 6 on
// 0-1, 7 on 0-2, 8 on 0-3, 9 on 1-2, 10 on 1-4, 11 on 2-5, 12 on 3-4, 13 on
// 3-5, 14 on 4-5), VTK 13 and 26 (base 0 1 2 with its normal pointing away
// from 3 4 5, mid-edge nodes on (0,1), (1,2), (2,0), (3,4), (4,5), (5,3),
// (0,3), (1,4), (2,5)). Each read element must come out in flexmb's order
// (fe/elements/solid_wedge15.h) with a positive volume; the writers
// (Abaqus, VTK) read back to the same mesh.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/elements/solid_wedge15.h"
#include "flexmb/fe/elements/solid_wedge6.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"
#include "flexmb/body_file/body_file_mesh.h"
#include "flexmb/fe_io/gmsh_reader.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/fe_io/vtk_mesh.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::io {
namespace wedge_formats_test {

using fe::Vec3;

// corners of an oblique prism in flexmb's order (1 2 3 counter-clockwise seen from 4 5 6)
const std::vector<Vec3> kWedgeCorners = {{0.0, 0.0, 0.0}, {1.1, 0.1, 0.05}, {0.2, 0.9, -0.05},
                                         {0.2, 0.1, 0.8}, {1.3, 0.2, 0.85}, {0.4, 1.0, 0.75}};

// a format's node list: its corners (positions in kWedgeCorners) and its
// mid-edge nodes as pairs of positions in that corner list
struct FormatOrder {
  std::vector<int> corners;
  std::vector<std::array<int, 2>> edges;
};

std::vector<Vec3> FormatPoints(const FormatOrder& f) {
  std::vector<Vec3> p;
  for (int c : f.corners) p.push_back(kWedgeCorners[c]);
  for (const auto& e : f.edges) p.push_back(0.5 * (p[e[0]] + p[e[1]]));
  return p;
}

// the element's nodes in flexmb's order: corners as kWedgeCorners, mid-edge
// nodes per kWedge15EdgeCorners; and a positive volume (mass rho V > 0)
void ExpectFlexmbOrder(const fe::Mesh& mesh, const fe::Element& e) {
  ASSERT_TRUE(e.nodes.size() == 6 || e.nodes.size() == 15);
  EXPECT_EQ(e.type, e.nodes.size() == 6 ? fe::kWedge6 : fe::kWedge15);
  std::vector<Vec3> x;
  for (int n : e.nodes) x.push_back(mesh.nodes[n].x);
  for (int k = 0; k < 6; ++k) EXPECT_LT((x[k] - kWedgeCorners[k]).norm(), 1e-12) << "element " << e.id << " node " << k;
  for (size_t k = 6; k < x.size(); ++k) {
    const Vec3 mid = 0.5 * (kWedgeCorners[fe::kWedge15EdgeCorners[k - 6][0]] + kWedgeCorners[fe::kWedge15EdgeCorners[k - 6][1]]);
    EXPECT_LT((x[k] - mid).norm(), 1e-12) << "element " << e.id << " node " << k;
  }
  const double volume = (kWedgeCorners[1] - kWedgeCorners[0]).cross(kWedgeCorners[2] - kWedgeCorners[0]).dot(kWedgeCorners[3] - kWedgeCorners[0]) / 2.0;
  EXPECT_NEAR(testing::ElementTotalMass(e, x, 1000.0), 1000.0 * volume, 1e-10 * volume) << "element " << e.id;
}

std::string Num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

TEST(WedgeFormats, NastranCpenta) {
  const FormatOrder f{{0, 1, 2, 3, 4, 5}, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}}};
  const std::vector<Vec3> p = FormatPoints(f);
  std::string grids = "BEGIN BULK\nMAT1,1,2.1e11,,0.3,7850.0\nPSOLID,1,1\n";
  for (size_t k = 0; k < p.size(); ++k)
    grids += "GRID," + std::to_string(k + 1) + ",," + Num(p[k].x()) + "," + Num(p[k].y()) + "," + Num(p[k].z()) + "\n";
  const std::string deck = grids + "CPENTA,10,1,1,2,3,4,5,6\n" +
                           "CPENTA,11,1,1,2,3,4,5,6\n,7,8,9,10,11,12,13,14\n,15\nENDDATA\n";
  const fe::Mesh mesh = ReadNastran(testing::WriteScratch("wedges.bdf", deck));
  ASSERT_EQ(mesh.elements.size(), 2u);
  for (const fe::Element& e : mesh.elements) ExpectFlexmbOrder(mesh, e);
  const std::string bad = grids + "CPENTA,12,1,1,2,3,4,5,6\n,7,8\nENDDATA\n";
  EXPECT_NE(testing::InputErrorOf([&] { ReadNastran(testing::WriteScratch("wedge_bad.bdf", bad)); })
                .find("CPENTA with 8 grid points: only 6 or 15 are supported"),
            std::string::npos);
}

TEST(WedgeFormats, AbaqusC3D6AndC3D15) {
  const FormatOrder f{{0, 1, 2, 3, 4, 5}, {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}}};
  const std::vector<Vec3> p = FormatPoints(f);
  std::string deck = "*NODE\n";
  for (size_t k = 0; k < p.size(); ++k)
    deck += std::to_string(k + 1) + ", " + Num(p[k].x()) + ", " + Num(p[k].y()) + ", " + Num(p[k].z()) + "\n";
  deck += "*ELEMENT, TYPE=C3D6, ELSET=W\n10, 1, 2, 3, 4, 5, 6\n";
  deck += "*ELEMENT, TYPE=C3D15, ELSET=W\n11, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,\n11, 12, 13, 14, 15\n";
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n*SOLID SECTION, ELSET=W, MATERIAL=STEEL\n";
  deck += "*SURFACE, NAME=TOP, TYPE=ELEMENT\n10, S2\n11, S3\n";
  const fe::Mesh mesh = ReadAbaqus(testing::WriteScratch("wedges.inp", deck));
  ASSERT_EQ(mesh.elements.size(), 2u);
  for (const fe::Element& e : mesh.elements) ExpectFlexmbOrder(mesh, e);
  // written and read back
  const std::string path = testing::ScratchPath("wedges_written.inp");
  WriteAbaqus(mesh, path);
  EXPECT_NE(testing::ReadText(path).find("TYPE=C3D15"), std::string::npos);
  testing::ExpectSameConnectivity(mesh, ReadAbaqus(path));
}

TEST(WedgeFormats, GmshPrisms) {
  const FormatOrder f{{0, 1, 2, 3, 4, 5}, {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4}, {2, 5}, {3, 4}, {3, 5}, {4, 5}}};
  const std::vector<Vec3> p = FormatPoints(f);
  std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 \"solid\"\n$EndPhysicalNames\n";
  msh += "$Nodes\n" + std::to_string(p.size()) + "\n";
  for (size_t k = 0; k < p.size(); ++k)
    msh += std::to_string(k + 1) + " " + Num(p[k].x()) + " " + Num(p[k].y()) + " " + Num(p[k].z()) + "\n";
  msh += "$EndNodes\n$Elements\n2\n10 6 2 1 1 1 2 3 4 5 6\n11 18 2 1 1 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15\n$EndElements\n";
  const fe::Mesh mesh = ReadGmsh(testing::WriteScratch("wedges.msh", msh));
  ASSERT_EQ(mesh.elements.size(), 2u);
  for (const fe::Element& e : mesh.elements) ExpectFlexmbOrder(mesh, e);
}

TEST(WedgeFormats, VtkWedgesAndBodyFileCodes) {
  // VTK's base turns the other way: flexmb corners 0 2 1 below 3 5 4
  const FormatOrder f{{0, 2, 1, 3, 5, 4}, {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}}};
  const std::vector<Vec3> p = FormatPoints(f);
  std::string vtk = "# vtk DataFile Version 3.0\nwedges\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 15 double\n";
  for (const Vec3& q : p) vtk += Num(q.x()) + " " + Num(q.y()) + " " + Num(q.z()) + "\n";
  vtk += "CELLS 2 23\n6 0 1 2 3 4 5\n15 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14\nCELL_TYPES 2\n13\n26\n";
  const fe::Mesh mesh = ReadVtk(testing::WriteScratch("wedges.vtk", vtk));
  ASSERT_EQ(mesh.elements.size(), 2u);
  for (const fe::Element& e : mesh.elements) ExpectFlexmbOrder(mesh, e);
  // written in VTK's order: the same cells as the hand-written file
  const std::string path = testing::ScratchPath("wedges_written.vtk");
  WriteVtk(mesh, path);
  EXPECT_NE(testing::ReadText(path).find("6 0 1 2 3 4 5\n15 0 1 2 3 4 5 6 7 8 9 10 11 12 13 14\n"), std::string::npos);
  testing::ExpectSameConnectivity(mesh, ReadVtk(path));
  EXPECT_TRUE(HasBodyFileTypeCode(fe::kWedge6));
  EXPECT_TRUE(HasBodyFileTypeCode(fe::kWedge15));
}

}  // namespace wedge_formats_test
}  // namespace flexmb::io
