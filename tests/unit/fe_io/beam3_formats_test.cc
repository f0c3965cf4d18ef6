// The 3-node beam in every mesh format that has it, each file written here
// in that format's documented node order: Abaqus/CalculiX B32 and B32R (end,
// mid node, end: CalculiX manual, "Three-node 3D beam element"), gmsh type
// 8 (3-node line: the ends, then the mid node) and VTK 21
// (vtkQuadraticEdge: the same). Each read element must come out in
// flexmb's order (A, mid, B; fe/elements/beam3.h); the Abaqus deck's
// section (RECT with its 1-axis) gives the element its orientation and
// mass rho A L; the Abaqus and VTK writers read back to the same mesh (the
// Abaqus writer refuses a 3-node beam without shear flexibility); a
// curved B32 is an error naming the element when its matrices are built.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "flexmb/body_file/body_file_mesh.h"
#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/beam3.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"
#include "flexmb/fe_io/gmsh_reader.h"
#include "flexmb/fe_io/vtk_mesh.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::io {
namespace beam3_formats_test {

using fe::Vec3;

// ends A, B and the mid node of a skew beam, in flexmb's order
const std::vector<Vec3> kBeam3Points = {Vec3(0.1, 0.2, -0.3), Vec3(0.6, 0.5, 0.0), Vec3(1.1, 0.8, 0.3)};

std::string Beam3Num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

void ExpectBeam3Order(const fe::Mesh& mesh, const fe::Element& e, const std::string& what) {
  ASSERT_EQ(e.nodes.size(), 3u) << what;
  EXPECT_EQ(e.type, fe::kBeam3) << what;
  for (int k = 0; k < 3; ++k) EXPECT_LT((mesh.nodes[e.nodes[k]].x - kBeam3Points[k]).norm(), 1e-12) << what << " " << k;
}

std::string AbaqusDeck(const std::string& type) {
  std::string deck = "*NODE, NSET=ALL\n";
  for (int k = 0; k < 3; ++k)
    deck += std::to_string(k + 1) + ", " + Beam3Num(kBeam3Points[k].x()) + ", " + Beam3Num(kBeam3Points[k].y()) +
            ", " + Beam3Num(kBeam3Points[k].z()) + "\n";
  deck += "*ELEMENT, TYPE=" + type + ", ELSET=BOOM\n7, 1, 2, 3\n";
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n";
  deck += "*BEAM SECTION, ELSET=BOOM, MATERIAL=STEEL, SECTION=RECT\n0.04, 0.1\n0., 0., 1.\n";
  return deck;
}

TEST(Beam3Formats, AbaqusB32AndB32R) {
  for (const std::string type : {"B32", "B32R"}) {
    const fe::Mesh mesh = ReadAbaqus(testing::WriteScratch("beam3.inp", AbaqusDeck(type)));
    ASSERT_EQ(mesh.elements.size(), 1u);
    ExpectBeam3Order(mesh, mesh.elements[0], type);
    EXPECT_LT((mesh.elements[0].orientation - Vec3(0.0, 0.0, 1.0)).norm(), 1e-15);
    ASSERT_EQ(mesh.beam_sections.size(), 1u);
    EXPECT_NEAR(mesh.beam_sections[0].A, 0.004, 1e-15);
    const double L = (kBeam3Points[2] - kBeam3Points[0]).norm();
    const fe::AssembledModel a = fe::Assemble(mesh);
    // the translational mass along x: rho A L
    Eigen::VectorXd ex = Eigen::VectorXd::Zero(a.dofs.n_full);
    for (int n = 0; n < 3; ++n) ex[a.dofs.full[n][0]] = 1.0;
    const Eigen::VectorXd r = a.T.transpose() * ex;
    EXPECT_NEAR(r.dot(a.M * r), 7850.0 * 0.004 * L, 1e-9 * 7850.0 * 0.004 * L) << type;
  }
  // the writer names it B32 and reads back the same
  const fe::Mesh mesh = ReadAbaqus(testing::WriteScratch("beam3.inp", AbaqusDeck("B32R")));
  const std::string path = testing::ScratchPath("beam3_written.inp");
  WriteAbaqus(mesh, path);
  EXPECT_NE(testing::ReadText(path).find("TYPE=B32"), std::string::npos);
  const fe::Mesh back = ReadAbaqus(path);
  testing::ExpectSameConnectivity(mesh, back);
  EXPECT_LT((back.elements[0].orientation - mesh.elements[0].orientation).norm(), 1e-12);
  // without shear flexibility it has no Abaqus name (B33 is a 2-node beam)
  fe::Mesh euler = mesh;
  euler.beam_sections[0].ky = euler.beam_sections[0].kz = 0.0;
  try {
    WriteAbaqus(euler, testing::ScratchPath("beam3_euler.inp"));
    ADD_FAILURE() << "a 3-node Euler-Bernoulli beam was written";
  } catch (const InputError& e) {
    testing::ExpectContains(e.what(), {"3-node beam element 7", "no Abaqus name"}, "Euler-Bernoulli beam3");
  }
}

TEST(Beam3Formats, CurvedB32IsAnErrorNamingTheElement) {
  std::string deck = testing::Replace(AbaqusDeck("B32"), "2, " + Beam3Num(kBeam3Points[1].x()),
                                      "2, " + Beam3Num(kBeam3Points[1].x() + 0.05));
  const fe::Mesh mesh = ReadAbaqus(testing::WriteScratch("beam3_curved.inp", deck));
  try {
    fe::Assemble(mesh);
    ADD_FAILURE() << "a curved B32 was accepted";
  } catch (const InputError& e) {
    testing::ExpectContains(e.what(), {"curved", "3-node beam 7", "beam3_curved.inp:"}, "curved B32");
  }
}

TEST(Beam3Formats, GmshLine3) {
  std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n1 1 \"boom\"\n$EndPhysicalNames\n";
  msh += "$Nodes\n3\n";
  // gmsh lists the ends first: flexmb nodes A, B, mid as gmsh 1, 2, 3
  const int order[3] = {0, 2, 1};
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = kBeam3Points[order[k]];
    msh += std::to_string(k + 1) + " " + Beam3Num(p.x()) + " " + Beam3Num(p.y()) + " " + Beam3Num(p.z()) + "\n";
  }
  msh += "$EndNodes\n$Elements\n1\n5 8 2 1 1 1 2 3\n$EndElements\n";
  const fe::Mesh mesh = ReadGmsh(testing::WriteScratch("beam3.msh", msh));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectBeam3Order(mesh, mesh.elements[0], "gmsh");
}

TEST(Beam3Formats, VtkQuadraticEdgeAndBodyFileCode) {
  std::string vtk = "# vtk DataFile Version 3.0\nbeam3\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n";
  for (int k : {0, 2, 1})
    vtk += Beam3Num(kBeam3Points[k].x()) + " " + Beam3Num(kBeam3Points[k].y()) + " " + Beam3Num(kBeam3Points[k].z()) + "\n";
  vtk += "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n21\n";
  const fe::Mesh mesh = ReadVtk(testing::WriteScratch("beam3.vtk", vtk));
  ASSERT_EQ(mesh.elements.size(), 1u);
  ExpectBeam3Order(mesh, mesh.elements[0], "vtk");
  const std::string path = testing::ScratchPath("beam3_written.vtk");
  WriteVtk(mesh, path);
  testing::ExpectSameConnectivity(mesh, ReadVtk(path));
  EXPECT_TRUE(HasBodyFileTypeCode(fe::kBeam3));
}

}  // namespace beam3_formats_test
}  // namespace flexmb::io
