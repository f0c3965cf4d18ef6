// The second-order shells in every mesh format that has them, each file
// written here in the format's documented order (corners, then the
// mid-edge nodes of edges 1-2, 2-3, ...: Nastran QRG CQUAD8 / CTRIA6,
// Abaqus S8R / STRI65, gmsh types 16 and 9, VTK 23 and 22): each read
// element comes out in flexmb's order (mass rho t A through the assembly); the Nastran cards'
// own field places (CQUAD8: T1-T4, THETA, ZOFFS, TFLAG after G8; CTRIA6:
// THETA, ZOFFS, T1-T3, TFLAG after G6) are read; a blank mid-side grid
// point is an error; gmsh's 6-node triangles on a 10-node tetrahedral mesh
// stay a boundary (node sets), not shells.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "flexmb/body_file/body_file_mesh.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/shell_quad8.h"
#include "flexmb/fe/elements/shell_tria6.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/gmsh_reader.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/fe_io/vtk_mesh.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::io {
namespace shell8_formats_test {

using fe::Vec3;

// a skew quadrilateral and a triangle in the plane z = 0.2, corners then mid-edge points
const std::vector<Vec3> kQ8 = {Vec3(0, 0, 0.2),    Vec3(1.2, 0.1, 0.2), Vec3(1.0, 0.9, 0.2),  Vec3(-0.1, 0.8, 0.2),
                               Vec3(0.6, 0.05, 0.2), Vec3(1.1, 0.5, 0.2), Vec3(0.45, 0.85, 0.2), Vec3(-0.05, 0.4, 0.2)};
const std::vector<Vec3> kT6 = {Vec3(0, 0, 0.2), Vec3(1.2, 0.1, 0.2), Vec3(0.3, 0.9, 0.2),
                               Vec3(0.6, 0.05, 0.2), Vec3(0.75, 0.5, 0.2), Vec3(0.15, 0.45, 0.2)};

std::string S8Num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

double QuadArea() { return 0.5 * (kQ8[2] - kQ8[0]).cross(kQ8[3] - kQ8[1]).norm(); }
double TriaArea() { return 0.5 * (kT6[1] - kT6[0]).cross(kT6[2] - kT6[0]).norm(); }

void ExpectOrder(const fe::Mesh& m, const fe::Element& e, const std::vector<Vec3>& x, fe::ElementType type) {
  EXPECT_EQ(e.type, type);
  ASSERT_EQ(e.nodes.size(), x.size());
  for (size_t k = 0; k < x.size(); ++k) EXPECT_LT((m.nodes[e.nodes[k]].x - x[k]).norm(), 1e-12) << k;
}

TEST(Shell8Formats, NastranCquad8AndCtria6FieldPlaces) {
  std::string deck = "BEGIN BULK\nMAT1,1,2.1e11,,0.3,7850.\nPSHELL,1,1,0.01,1\n";
  for (size_t k = 0; k < kQ8.size(); ++k)
    deck += "GRID," + std::to_string(k + 1) + ",," + S8Num(kQ8[k].x()) + "," + S8Num(kQ8[k].y()) + "," + S8Num(kQ8[k].z()) + "\n";
  for (size_t k = 0; k < kT6.size(); ++k)
    deck += "GRID," + std::to_string(k + 11) + ",," + S8Num(kT6[k].x()) + "," + S8Num(kT6[k].y()) + "," + S8Num(kT6[k].z()) + "\n";
  deck += "CQUAD8,1,1,1,2,3,4,5,6\n,7,8,0.01,0.01,,0.01,30.,0.002\n";
  deck += "CTRIA6,2,1,11,12,13,14,15,16\n,45.,-0.001,0.01\n";
  const fe::Mesh m = ReadNastran(testing::WriteScratch("shell8.bdf", deck + "ENDDATA\n"));
  ASSERT_EQ(m.elements.size(), 2u);
  ExpectOrder(m, m.elements[0], kQ8, fe::kQuad8);
  ExpectOrder(m, m.elements[1], kT6, fe::kTria6);
  EXPECT_NEAR(m.elements[0].shell_theta, M_PI / 6, 1e-15);
  EXPECT_NEAR(m.elements[0].shell_offset, 0.002, 1e-15);
  EXPECT_NEAR(m.elements[1].shell_theta, M_PI / 4, 1e-15);
  EXPECT_NEAR(m.elements[1].shell_offset, -0.001, 1e-15);
  // the translational mass along x: rho t (A_quad + A_tria)
  const fe::AssembledModel a = fe::Assemble(m);
  Eigen::VectorXd ex = Eigen::VectorXd::Zero(a.dofs.n_full);
  for (size_t n = 0; n < m.nodes.size(); ++n) ex[a.dofs.full[n][0]] = 1.0;
  const Eigen::VectorXd r = a.T.transpose() * ex;
  const double mass = 7850.0 * 0.01 * (QuadArea() + TriaArea());
  EXPECT_NEAR(r.dot(a.M * r), mass, 1e-12 * mass);
  // a corner thickness that differs, a blank mid-side grid point
  const std::vector<std::pair<std::string, std::vector<std::string>>> bad = {
      {"CQUAD8,1,1,1,2,3,4,5,6\n,7,8,0.02\n", {"CQUAD8 1", "corner thicknesses T1-T4"}},
      {"CQUAD8,1,1,1,2,3,4,5,6\n,,8\n", {"CQUAD8 1", "mid-side grid point G7 is blank"}},
      {"CTRIA6,2,1,11,12,13,14,,16\n", {"CTRIA6 2", "mid-side grid point G5 is blank"}},
  };
  const std::string head = deck.substr(0, deck.find("CQUAD8"));
  int k = 0;
  for (const auto& [cards, parts] : bad) {
    const std::string path = testing::WriteScratch("shell8_bad" + std::to_string(k++) + ".bdf", head + cards);
    testing::ExpectContains(testing::InputErrorOf([&] { ReadNastran(path); }), parts, cards);
  }
}

TEST(Shell8Formats, AbaqusS8RAndStri65) {
  std::string deck = "*NODE\n";
  for (size_t k = 0; k < kQ8.size(); ++k)
    deck += std::to_string(k + 1) + ", " + S8Num(kQ8[k].x()) + ", " + S8Num(kQ8[k].y()) + ", " + S8Num(kQ8[k].z()) + "\n";
  for (size_t k = 0; k < kT6.size(); ++k)
    deck += std::to_string(k + 11) + ", " + S8Num(kT6[k].x()) + ", " + S8Num(kT6[k].y()) + ", " + S8Num(kT6[k].z()) + "\n";
  deck += "*ELEMENT, TYPE=S8R, ELSET=SKIN\n1, 1, 2, 3, 4, 5, 6, 7, 8\n*ELEMENT, TYPE=STRI65, ELSET=SKIN\n2, 11, 12, 13, 14, 15, 16\n";
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n*SHELL SECTION, ELSET=SKIN, MATERIAL=STEEL\n0.01\n";
  const fe::Mesh m = ReadAbaqus(testing::WriteScratch("shell8.inp", deck));
  ASSERT_EQ(m.elements.size(), 2u);
  ExpectOrder(m, m.elements[0], kQ8, fe::kQuad8);
  ExpectOrder(m, m.elements[1], kT6, fe::kTria6);
}

TEST(Shell8Formats, GmshAndVtk) {
  std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n14\n";
  for (size_t k = 0; k < kQ8.size(); ++k)
    msh += std::to_string(k + 1) + " " + S8Num(kQ8[k].x()) + " " + S8Num(kQ8[k].y()) + " " + S8Num(kQ8[k].z()) + "\n";
  for (size_t k = 0; k < kT6.size(); ++k)
    msh += std::to_string(k + 11) + " " + S8Num(kT6[k].x()) + " " + S8Num(kT6[k].y()) + " " + S8Num(kT6[k].z()) + "\n";
  msh += "$EndNodes\n$Elements\n2\n1 16 2 1 1 1 2 3 4 5 6 7 8\n2 9 2 1 1 11 12 13 14 15 16\n$EndElements\n";
  const fe::Mesh m = ReadGmsh(testing::WriteScratch("shell8.msh", msh));
  ASSERT_EQ(m.elements.size(), 2u);
  ExpectOrder(m, m.elements[0], kQ8, fe::kQuad8);
  ExpectOrder(m, m.elements[1], kT6, fe::kTria6);

  std::string vtk = "# vtk DataFile Version 3.0\nshell8\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 14 double\n";
  for (const Vec3& q : kQ8) vtk += S8Num(q.x()) + " " + S8Num(q.y()) + " " + S8Num(q.z()) + "\n";
  for (const Vec3& q : kT6) vtk += S8Num(q.x()) + " " + S8Num(q.y()) + " " + S8Num(q.z()) + "\n";
  vtk += "CELLS 2 16\n8 0 1 2 3 4 5 6 7\n6 8 9 10 11 12 13\nCELL_TYPES 2\n23\n22\n";
  const fe::Mesh v = ReadVtk(testing::WriteScratch("shell8.vtk", vtk));
  ASSERT_EQ(v.elements.size(), 2u);
  ExpectOrder(v, v.elements[0], kQ8, fe::kQuad8);
  ExpectOrder(v, v.elements[1], kT6, fe::kTria6);
  EXPECT_TRUE(HasBodyFileTypeCode(fe::kQuad8));
  EXPECT_TRUE(HasBodyFileTypeCode(fe::kTria6));
}

// a 10-node tetrahedron with a 6-node triangle on its face 1-2-3 in a
// physical surface: the triangle is a boundary, its nodes join the set
TEST(Shell8Formats, GmshTria6OnATet10MeshStaysABoundary) {
  std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n2 1 \"face\"\n3 2 \"solid\"\n$EndPhysicalNames\n";
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.5, 0, 0),
                               Vec3(0.5, 0.5, 0), Vec3(0, 0.5, 0), Vec3(0, 0, 0.5), Vec3(0, 0.5, 0.5), Vec3(0.5, 0, 0.5)};
  msh += "$Nodes\n10\n";
  for (size_t k = 0; k < p.size(); ++k)
    msh += std::to_string(k + 1) + " " + S8Num(p[k].x()) + " " + S8Num(p[k].y()) + " " + S8Num(p[k].z()) + "\n";
  msh += "$EndNodes\n$Elements\n2\n1 11 2 2 1 1 2 3 4 5 6 7 8 10 9\n2 9 2 1 1 1 2 3 5 6 7\n$EndElements\n";
  const fe::Mesh m = ReadGmsh(testing::WriteScratch("tet10_face.msh", msh));
  ASSERT_EQ(m.elements.size(), 1u);
  EXPECT_EQ(m.node_sets.at("face").size(), 6u);
}

}  // namespace shell8_formats_test
}  // namespace flexmb::io
