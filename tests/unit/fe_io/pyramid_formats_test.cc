// The 5-node pyramid in every mesh format, each file written in that
// format's own documented node order, which is the same in all four: the
// base 1 2 3 4, then the apex (Nastran CPYRAM G1-G5; Abaqus C3D5; gmsh
// type 7; VTK_PYRAMID 14, whose base "forms a quadrilateral whose normal
// points in the direction of the apex" by the right-hand rule). Each read
// element must come out in flexmb's order (fe/elements/solid_pyramid5.h)
// with a positive volume; the Abaqus and VTK writers read back to the same
// mesh (the Nastran writer writes shells only).

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>
#include <string>
#include <vector>

#include "flexmb/body_file/body_file_mesh.h"
#include "flexmb/fe/elements/solid_pyramid5.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"
#include "flexmb/fe_io/gmsh_reader.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/fe_io/vtk_mesh.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::io {
namespace pyramid_formats_test {

using fe::Vec3;

// a parallelogram base, counter-clockwise seen from the apex
const std::vector<Vec3> kPyramid = {{0.0, 0.0, 0.0}, {1.2, 0.1, 0.05}, {1.5, 1.0, 0.01}, {0.3, 0.9, -0.04},
                                    {0.9, 0.2, 0.8}};

std::string Num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

void ExpectFlexmbOrder(const fe::Mesh& mesh, const fe::Element& e) {
  ASSERT_EQ(e.nodes.size(), 5u);
  EXPECT_EQ(e.type, fe::kPyramid5);
  std::vector<Vec3> x;
  for (int n : e.nodes) x.push_back(mesh.nodes[n].x);
  for (int k = 0; k < 5; ++k) EXPECT_LT((x[k] - kPyramid[k]).norm(), 1e-12) << "element " << e.id << " node " << k;
  const double volume = (kPyramid[1] - kPyramid[0]).cross(kPyramid[3] - kPyramid[0]).dot(kPyramid[4] - kPyramid[0]) / 3.0;
  EXPECT_NEAR(testing::ElementTotalMass(e, x, 1000.0), 1000.0 * volume, 1e-10 * volume) << "element " << e.id;
}

TEST(PyramidFormats, NastranCpyram) {
  std::string grids = "BEGIN BULK\nMAT1,1,2.1e11,,0.3,7850.0\nPSOLID,1,1\n";
  for (size_t k = 0; k < kPyramid.size(); ++k)
    grids += "GRID," + std::to_string(k + 1) + ",," + Num(kPyramid[k].x()) + "," + Num(kPyramid[k].y()) + "," +
             Num(kPyramid[k].z()) + "\n";
  const fe::Mesh mesh = ReadNastran(testing::WriteScratch("pyramid.bdf", grids + "CPYRAM,10,1,1,2,3,4,5\nENDDATA\n"));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectFlexmbOrder(mesh, mesh.elements[0]);
  // the 13-node pyramid is not supported: an error, not a 5-node one
  const std::string bad = grids + "CPYRAM,12,1,1,2,3,4,5,1\n,2,3,4,5,1,2,3\nENDDATA\n";
  EXPECT_NE(testing::InputErrorOf([&] { ReadNastran(testing::WriteScratch("pyramid13.bdf", bad)); })
                .find("CPYRAM with 13 grid points: only 5 are supported"),
            std::string::npos);
}

TEST(PyramidFormats, AbaqusC3D5) {
  std::string deck = "*NODE\n";
  for (size_t k = 0; k < kPyramid.size(); ++k)
    deck += std::to_string(k + 1) + ", " + Num(kPyramid[k].x()) + ", " + Num(kPyramid[k].y()) + ", " +
            Num(kPyramid[k].z()) + "\n";
  deck += "*ELEMENT, TYPE=C3D5, ELSET=P\n10, 1, 2, 3, 4, 5\n";
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n*SOLID SECTION, ELSET=P, MATERIAL=STEEL\n";
  const fe::Mesh mesh = ReadAbaqus(testing::WriteScratch("pyramid.inp", deck));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectFlexmbOrder(mesh, mesh.elements[0]);
  const std::string path = testing::ScratchPath("pyramid_written.inp");
  WriteAbaqus(mesh, path);
  EXPECT_NE(testing::ReadText(path).find("TYPE=C3D5"), std::string::npos);
  testing::ExpectSameConnectivity(mesh, ReadAbaqus(path));
}

TEST(PyramidFormats, GmshPyramid) {
  std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 \"solid\"\n$EndPhysicalNames\n";
  msh += "$Nodes\n5\n";
  for (size_t k = 0; k < kPyramid.size(); ++k)
    msh += std::to_string(k + 1) + " " + Num(kPyramid[k].x()) + " " + Num(kPyramid[k].y()) + " " +
           Num(kPyramid[k].z()) + "\n";
  msh += "$EndNodes\n$Elements\n1\n10 7 2 1 1 1 2 3 4 5\n$EndElements\n";
  const fe::Mesh mesh = ReadGmsh(testing::WriteScratch("pyramid.msh", msh));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectFlexmbOrder(mesh, mesh.elements[0]);
}

TEST(PyramidFormats, VtkPyramidAndBodyFileCode) {
  std::string vtk = "# vtk DataFile Version 3.0\npyramid\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n";
  for (const Vec3& q : kPyramid) vtk += Num(q.x()) + " " + Num(q.y()) + " " + Num(q.z()) + "\n";
  vtk += "CELLS 1 6\n5 0 1 2 3 4\nCELL_TYPES 1\n14\n";
  const fe::Mesh mesh = ReadVtk(testing::WriteScratch("pyramid.vtk", vtk));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectFlexmbOrder(mesh, mesh.elements[0]);
  const std::string path = testing::ScratchPath("pyramid_written.vtk");
  WriteVtk(mesh, path);
  EXPECT_NE(testing::ReadText(path).find("5 0 1 2 3 4\n"), std::string::npos);
  testing::ExpectSameConnectivity(mesh, ReadVtk(path));
  EXPECT_TRUE(HasBodyFileTypeCode(fe::kPyramid5));
}

}  // namespace pyramid_formats_test
}  // namespace flexmb::io
