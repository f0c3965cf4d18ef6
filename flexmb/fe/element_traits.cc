#include "flexmb/fe/element_traits.h"

#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/beam2.h"
#include "flexmb/fe/elements/beam3.h"
#include "flexmb/fe/elements/rod2.h"
#include "flexmb/fe/elements/shear4.h"
#include "flexmb/fe/elements/shell_quad4.h"
#include "flexmb/fe/elements/shell_quad8.h"
#include "flexmb/fe/elements/shell_tria3.h"
#include "flexmb/fe/elements/shell_tria6.h"
#include "flexmb/fe/elements/solid_hex20.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe/elements/solid_pyramid5.h"
#include "flexmb/fe/elements/solid_tet10.h"
#include "flexmb/fe/elements/solid_tet4.h"
#include "flexmb/fe/elements/solid_wedge15.h"
#include "flexmb/fe/elements/solid_wedge6.h"

namespace flexmb::fe {
namespace {

// kernels in the table's signatures

template <void (*Geometric)(const ElementInput&, const Eigen::VectorXd&, MatX&)>
void TraitsGeometric(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG, double*) {
  Geometric(in, u, KG);
}

template <void (*Stress)(const ElementInput&, MatX&)>
void TraitsSolidStress(const ElementInput& in, MatX& S, Eigen::Matrix3d&) {
  Stress(in, S);
}

// the rod's prestress is its axial force
void TraitsRod2Geometric(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG, double* axial_force) {
  MatX S;
  Eigen::Matrix3d axes;
  Rod2SectionForces(in, S, axes);
  const double N = S.row(0).dot(u);
  if (axial_force != nullptr) *axial_force = N;
  Rod2GeometricStiffness(in, N, KG);
}

void TraitsHex8Matrices(const ElementInput& in, MatX& K, MatX& M) { SolidHex8Matrices(in, K, M); }
void TraitsHex8FullMatrices(const ElementInput& in, MatX& K, MatX& M) {
  SolidHex8Matrices(in, K, M, Hex8Formulation::kFullIntegration);
}
void TraitsHex8SelectiveMatrices(const ElementInput& in, MatX& K, MatX& M) {
  SolidHex8Matrices(in, K, M, Hex8Formulation::kSelectiveReduced);
}
void TraitsWedge6Matrices(const ElementInput& in, MatX& K, MatX& M) { SolidWedge6Matrices(in, K, M); }
void TraitsPyramid5Matrices(const ElementInput& in, MatX& K, MatX& M) { SolidPyramid5Matrices(in, K, M); }
void TraitsWedge15Matrices(const ElementInput& in, MatX& K, MatX& M) { SolidWedge15Matrices(in, K, M); }
void TraitsHex20Matrices(const ElementInput& in, MatX& K, MatX& M) {
  SolidHex20Matrices(in, K, M, Hex20Integration::kFull);
}
void TraitsHex20RMatrices(const ElementInput& in, MatX& K, MatX& M) {
  SolidHex20Matrices(in, K, M, Hex20Integration::kReduced);
}

// Nastran cards
constexpr const char* kTraitsCquad4[] = {"CQUAD4", "CQUADR"};
constexpr const char* kTraitsCquad8[] = {"CQUAD8"};
constexpr const char* kTraitsCtria6[] = {"CTRIA6"};
constexpr const char* kTraitsCtria3[] = {"CTRIA3", "CTRIAR"};
constexpr const char* kTraitsCbar[] = {"CBAR", "CBEAM"};
constexpr const char* kTraitsCtetra[] = {"CTETRA"};
constexpr const char* kTraitsChexa[] = {"CHEXA"};
constexpr const char* kTraitsCpenta[] = {"CPENTA"};
constexpr const char* kTraitsCpyram[] = {"CPYRAM"};
constexpr const char* kTraitsCrod[] = {"CROD", "CONROD", "CTUBE"};
constexpr const char* kTraitsCshear[] = {"CSHEAR"};

// Abaqus names
constexpr AbaqusName kTraitsS4[] = {
    {"S4"}, {"S4R"}, {"S4R5"}, {"M3D4", AbaqusVariant::kMembrane}, {"M3D4R", AbaqusVariant::kMembrane}};
constexpr AbaqusName kTraitsS3[] = {{"S3"}, {"S3R"}, {"STRI3"}, {"M3D3", AbaqusVariant::kMembrane}};
constexpr AbaqusName kTraitsB31[] = {{"B31"},
                                     {"B31H"},
                                     {"B31R"},
                                     {"B33", AbaqusVariant::kEulerBernoulli},
                                     {"B33H", AbaqusVariant::kEulerBernoulli}};
constexpr AbaqusName kTraitsC3D4[] = {{"C3D4"}};
constexpr AbaqusName kTraitsC3D10[] = {{"C3D10"}};
constexpr const char* kTraitsOtherHexNote =
    "read as flexmb's 8-node hexahedron with incompatible modes (like C3D8I): reduced integration with "
    "hourglass control is not in flexmb, the formulation differs";
constexpr AbaqusName kTraitsC3D8[] = {{"C3D8I"}, {"C3D8R", AbaqusVariant::kOther, kTraitsOtherHexNote}};
// C3D8 means plain full integration in CalculiX and selectively reduced
// integration in Abaqus: the reader picks the row by the deck's author
// (abaqus_mesh.cc, docs/formats.md); this row is CalculiX's
constexpr AbaqusName kTraitsC3D8Full[] = {{"C3D8"}};
constexpr AbaqusName kTraitsC3D6[] = {{"C3D6"}};
constexpr AbaqusName kTraitsC3D5[] = {{"C3D5"}};
constexpr AbaqusName kTraitsC3D15[] = {{"C3D15"}};
constexpr AbaqusName kTraitsC3D20[] = {{"C3D20"}};
constexpr AbaqusName kTraitsC3D20R[] = {{"C3D20R"}};
constexpr AbaqusName kTraitsT3D2[] = {{"T3D2"}};
constexpr AbaqusName kTraitsB32[] = {{"B32"}, {"B32R"}, {"B32H"}};
constexpr AbaqusName kTraitsS8[] = {{"S8R"}, {"S8"}, {"S8R5"}};
constexpr AbaqusName kTraitsS6[] = {{"STRI65"}, {"S6"}};

// Abaqus faces (element-based surfaces); a shell's both sides are all its nodes
constexpr AbaqusFace kTraitsQuadFaces[] = {
    {"SPOS", 4, {1, 2, 3, 4}}, {"SNEG", 4, {1, 2, 3, 4}}, {"S1", 4, {1, 2, 3, 4}}, {"S2", 4, {1, 2, 3, 4}}};
constexpr AbaqusFace kTraitsTriaFaces[] = {
    {"SPOS", 3, {1, 2, 3}}, {"SNEG", 3, {1, 2, 3}}, {"S1", 3, {1, 2, 3}}, {"S2", 3, {1, 2, 3}}};
constexpr AbaqusFace kTraitsQuad8Faces[] = {{"SPOS", 8, {1, 2, 3, 4, 5, 6, 7, 8}},
                                            {"SNEG", 8, {1, 2, 3, 4, 5, 6, 7, 8}},
                                            {"S1", 8, {1, 2, 3, 4, 5, 6, 7, 8}},
                                            {"S2", 8, {1, 2, 3, 4, 5, 6, 7, 8}}};
constexpr AbaqusFace kTraitsTria6Faces[] = {{"SPOS", 6, {1, 2, 3, 4, 5, 6}},
                                            {"SNEG", 6, {1, 2, 3, 4, 5, 6}},
                                            {"S1", 6, {1, 2, 3, 4, 5, 6}},
                                            {"S2", 6, {1, 2, 3, 4, 5, 6}}};
constexpr AbaqusFace kTraitsTet4Faces[] = {
    {"S1", 3, {1, 2, 3}}, {"S2", 3, {1, 4, 2}}, {"S3", 3, {2, 4, 3}}, {"S4", 3, {3, 4, 1}}};
constexpr AbaqusFace kTraitsTet10Faces[] = {{"S1", 6, {1, 2, 3, 5, 6, 7}},
                                            {"S2", 6, {1, 4, 2, 8, 9, 5}},
                                            {"S3", 6, {2, 4, 3, 9, 10, 6}},
                                            {"S4", 6, {3, 4, 1, 10, 8, 7}}};
constexpr AbaqusFace kTraitsHexFaces[] = {{"S1", 4, {1, 2, 3, 4}}, {"S2", 4, {5, 8, 7, 6}},
                                          {"S3", 4, {1, 5, 6, 2}}, {"S4", 4, {2, 6, 7, 3}},
                                          {"S5", 4, {3, 7, 8, 4}}, {"S6", 4, {4, 8, 5, 1}}};
constexpr AbaqusFace kTraitsWedge6Faces[] = {{"S1", 3, {1, 2, 3}},
                                             {"S2", 3, {4, 6, 5}},
                                             {"S3", 4, {1, 4, 5, 2}},
                                             {"S4", 4, {2, 5, 6, 3}},
                                             {"S5", 4, {3, 6, 4, 1}}};
constexpr AbaqusFace kTraitsWedge15Faces[] = {{"S1", 6, {1, 2, 3, 7, 8, 9}},
                                              {"S2", 6, {4, 6, 5, 12, 11, 10}},
                                              {"S3", 8, {1, 4, 5, 2, 13, 10, 14, 7}},
                                              {"S4", 8, {2, 5, 6, 3, 14, 11, 15, 8}},
                                              {"S5", 8, {3, 6, 4, 1, 15, 12, 13, 9}}};

constexpr AbaqusFace kTraitsHex20Faces[] = {{"S1", 8, {1, 2, 3, 4, 9, 10, 11, 12}},
                                            {"S2", 8, {5, 8, 7, 6, 16, 15, 14, 13}},
                                            {"S3", 8, {1, 5, 6, 2, 17, 13, 18, 9}},
                                            {"S4", 8, {2, 6, 7, 3, 18, 14, 19, 10}},
                                            {"S5", 8, {3, 7, 8, 4, 19, 15, 20, 11}},
                                            {"S6", 8, {4, 8, 5, 1, 20, 16, 17, 12}}};
// Nastran CHEXA: vertical edges (G13-G16) before the top ones (G17-G20)
constexpr int kTraitsNastranHex20[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14, 15};
// gmsh hexahedron 20: edges 0-1, 0-3, 0-4, 1-2, 1-5, 2-3, 2-6, 3-7, 4-5, 4-7, 5-6, 6-7
constexpr int kTraitsGmshHex20[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15};
// Nastran CPENTA: vertical edges (G10-G12) before the top ones (G13-G15)
constexpr int kTraitsNastranWedge15[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 13, 14, 9, 10, 11};

// gmsh: mid-edge node 9 lies on edge 3-4, 10 on edge 2-4 (flexmb: 2-4, then 3-4)
constexpr int kTraitsGmshTet10[] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
// gmsh prism 15: edges 0-1, 0-2, 0-3, 1-2, 1-4, 2-5, 3-4, 3-5, 4-5
constexpr int kTraitsGmshWedge15[] = {0, 1, 2, 3, 4, 5, 6, 9, 7, 12, 14, 13, 8, 10, 11};

// gmsh line 3 and VTK quadratic edge: the mid node last (flexmb, as Abaqus: A, mid, B)
constexpr int kTraitsLine3Order[] = {0, 2, 1};

// VTK wedges: the base 0 1 2 turns the other way (its normal points away from 3 4 5)
constexpr int kTraitsVtkWedge6[] = {0, 2, 1, 3, 5, 4};
constexpr int kTraitsVtkWedge15[] = {0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13};

constexpr ElementTraits kTraitsRows[] = {
    {.type = ElementType::kQuad4,
     .name = "quad4",
     .description = "4-node shell",
     .nodes = 4,
     .corners = 4,
     .family = ElementFamily::kShell,
     .nastran_cards = kTraitsCquad4,
     .abaqus = kTraitsS4,
     .abaqus_faces = kTraitsQuadFaces,
     .gmsh_code = 3,
     .vtk_code = 9,
     .body_file_code = 0,
     .matrices = ShellQuad4Matrices,
     .stress = ShellQuad4Stress,
     .geometric_stiffness = TraitsGeometric<ShellQuad4GeometricStiffness>},
    {.type = ElementType::kTria3,
     .name = "tria3",
     .description = "3-node shell",
     .nodes = 3,
     .corners = 3,
     .family = ElementFamily::kShell,
     .nastran_cards = kTraitsCtria3,
     .abaqus = kTraitsS3,
     .abaqus_faces = kTraitsTriaFaces,
     .gmsh_code = 2,
     .vtk_code = 5,
     .body_file_code = 1,
     .matrices = ShellTria3Matrices,
     .stress = ShellTria3Stress,
     .geometric_stiffness = TraitsGeometric<ShellTria3GeometricStiffness>},
    {.type = ElementType::kBeam2,
     .name = "beam2",
     .description = "2-node beam",
     .nodes = 2,
     .corners = 2,
     .family = ElementFamily::kBeam,
     .nastran_cards = kTraitsCbar,
     .abaqus = kTraitsB31,
     .gmsh_code = 1,
     .vtk_code = 3,
     .body_file_code = 2,
     .matrices = Beam2Matrices,
     .stress = Beam2SectionForces,
     .geometric_stiffness = Beam2GeometricStiffnessUnder},
    {.type = ElementType::kTet4,
     .name = "tet4",
     .description = "4-node tetrahedron",
     .nodes = 4,
     .corners = 4,
     .family = ElementFamily::kSolid,
     .nastran_cards = kTraitsCtetra,
     .nastran_card_grids = 10,
     .abaqus = kTraitsC3D4,
     .abaqus_faces = kTraitsTet4Faces,
     .gmsh_code = 4,
     .vtk_code = 10,
     .body_file_code = 3,
     .matrices = SolidTet4Matrices,
     .stress = TraitsSolidStress<SolidTet4Stress>,
     .corner_stress = SolidTet4CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidTet4GeometricStiffness>},
    {.type = ElementType::kTet10,
     .name = "tet10",
     .description = "10-node tetrahedron",
     .nodes = 10,
     .corners = 4,
     .family = ElementFamily::kSolid,
     .nastran_cards = kTraitsCtetra,
     .nastran_card_grids = 10,
     .abaqus = kTraitsC3D10,
     .abaqus_faces = kTraitsTet10Faces,
     .gmsh_code = 11,
     .gmsh_order = kTraitsGmshTet10,
     .vtk_code = 24,
     .body_file_code = 4,
     .matrices = SolidTet10Matrices,
     .stress = TraitsSolidStress<SolidTet10Stress>,
     .corner_stress = SolidTet10CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidTet10GeometricStiffness>},
    {.type = ElementType::kHex8,
     .name = "hex8",
     .description = "8-node hexahedron",
     .nodes = 8,
     .corners = 8,
     .family = ElementFamily::kSolid,
     .nastran_cards = kTraitsChexa,
     .nastran_card_grids = 20,
     .abaqus = kTraitsC3D8,
     .abaqus_faces = kTraitsHexFaces,
     .gmsh_code = 5,
     .vtk_code = 12,
     .body_file_code = 5,
     .matrices = TraitsHex8Matrices,
     .stress = TraitsSolidStress<SolidHex8Stress>,
     .corner_stress = SolidHex8CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidHex8GeometricStiffness>},
    {.type = kWedge6,
     .name = "wedge6",
     .description = "6-node wedge",
     .nodes = 6,
     .corners = 6,
     .family = ElementFamily::kSolid,
     .nastran_cards = kTraitsCpenta,
     .nastran_card_grids = 15,
     .abaqus = kTraitsC3D6,
     .abaqus_faces = kTraitsWedge6Faces,
     .gmsh_code = 6,
     .vtk_code = 13,
     .vtk_order = kTraitsVtkWedge6,
     .body_file_code = 6,
     .matrices = TraitsWedge6Matrices,
     .stress = TraitsSolidStress<SolidWedge6Stress>,
     .corner_stress = SolidWedge6CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidWedge6GeometricStiffness>},
    {.type = kWedge15,
     .name = "wedge15",
     .description = "15-node wedge",
     .nodes = 15,
     .corners = 6,
     .family = ElementFamily::kSolid,
     .nastran_cards = kTraitsCpenta,
     .nastran_card_grids = 15,
     .nastran_order = kTraitsNastranWedge15,
     .abaqus = kTraitsC3D15,
     .abaqus_faces = kTraitsWedge15Faces,
     .gmsh_code = 18,
     .gmsh_order = kTraitsGmshWedge15,
     .vtk_code = 26,
     .vtk_order = kTraitsVtkWedge15,
     .body_file_code = 7,
     .matrices = TraitsWedge15Matrices,
     .stress = TraitsSolidStress<SolidWedge15Stress>,
     .corner_stress = SolidWedge15CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidWedge15GeometricStiffness>},
    {.type = kHex20,
     .name = "hex20",
     .description = "20-node hexahedron",
     .nodes = 20,
     .corners = 8,
     .family = ElementFamily::kSolid,
     .nastran_cards = kTraitsChexa,
     .nastran_card_grids = 20,
     .nastran_order = kTraitsNastranHex20,
     .abaqus = kTraitsC3D20,
     .abaqus_faces = kTraitsHex20Faces,
     .gmsh_code = 17,
     .gmsh_order = kTraitsGmshHex20,
     .vtk_code = 25,
     .body_file_code = 8,
     .matrices = TraitsHex20Matrices,
     .stress = TraitsSolidStress<SolidHex20Stress>,
     .corner_stress = SolidHex20CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidHex20GeometricStiffness>},
    {.type = kHex20R,
     .name = "hex20r",
     .description = "20-node hexahedron, reduced integration",
     .nodes = 20,
     .corners = 8,
     .family = ElementFamily::kSolid,
     .abaqus = kTraitsC3D20R,
     .abaqus_faces = kTraitsHex20Faces,
     .vtk_code = 25,
     .body_file_code = 9,
     .matrices = TraitsHex20RMatrices,
     .stress = TraitsSolidStress<SolidHex20Stress>,
     .corner_stress = SolidHex20CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidHex20GeometricStiffness>},
    {.type = kRod2,
     .name = "rod2",
     .description = "2-node rod",
     .nodes = 2,
     .corners = 2,
     .family = ElementFamily::kBeam,
     .nastran_cards = kTraitsCrod,
     .abaqus = kTraitsT3D2,
     .vtk_code = 3,
     .body_file_code = 10,
     .matrices = Rod2Matrices,
     .stress = Rod2SectionForces,
     .geometric_stiffness = TraitsRod2Geometric,
     .translations_only = true},
    {.type = kBeam3,
     .name = "beam3",
     .description = "3-node beam",
     .nodes = 3,
     .corners = 2,  // the ends, nodes 1 and 3 (Abaqus's order puts the mid node between them)
     .family = ElementFamily::kBeam,
     .abaqus = kTraitsB32,
     .gmsh_code = 8,
     .gmsh_order = kTraitsLine3Order,
     .vtk_code = 21,
     .vtk_order = kTraitsLine3Order,
     .body_file_code = 11,
     .matrices = Beam3Matrices,
     .stress = Beam3SectionForces,
     .geometric_stiffness = Beam3GeometricStiffness},
    {.type = kQuad8,
     .name = "quad8",
     .description = "8-node shell",
     .nodes = 8,
     .corners = 4,
     .family = ElementFamily::kShell,
     .nastran_cards = kTraitsCquad8,
     .abaqus = kTraitsS8,
     .abaqus_faces = kTraitsQuad8Faces,
     .gmsh_code = 16,
     .vtk_code = 23,
     .body_file_code = 12,
     .matrices = ShellQuad8Matrices,
     .stress = ShellQuad8Stress,
     .geometric_stiffness = TraitsGeometric<ShellQuad8GeometricStiffness>},
    {.type = kTria6,
     .name = "tria6",
     .description = "6-node shell",
     .nodes = 6,
     .corners = 3,
     .family = ElementFamily::kShell,
     .nastran_cards = kTraitsCtria6,
     .abaqus = kTraitsS6,
     .abaqus_faces = kTraitsTria6Faces,
     .gmsh_code = 9,
     .vtk_code = 22,
     .body_file_code = 13,
     .matrices = ShellTria6Matrices,
     .stress = ShellTria6Stress,
     .geometric_stiffness = TraitsGeometric<ShellTria6GeometricStiffness>},
    {.type = kShear4,
     .name = "shear4",
     .description = "4-node shear panel",
     .nodes = 4,
     .corners = 4,
     .family = ElementFamily::kShell,
     .nastran_cards = kTraitsCshear,
     .vtk_code = 9,
     .body_file_code = 14,
     .matrices = Shear4Matrices,
     .stress = Shear4Stress,
     .geometric_stiffness = TraitsGeometric<Shear4GeometricStiffness>,
     .translations_only = true},
    {.type = kHex8Full,
     .name = "hex8f",
     .description = "8-node hexahedron, full integration",
     .nodes = 8,
     .corners = 8,
     .family = ElementFamily::kSolid,
     .abaqus = kTraitsC3D8Full,
     .abaqus_faces = kTraitsHexFaces,
     .vtk_code = 12,
     .body_file_code = 15,
     .matrices = TraitsHex8FullMatrices,
     .stress = TraitsSolidStress<SolidHex8Stress>,
     .corner_stress = SolidHex8CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidHex8GeometricStiffness>},
    {.type = kHex8Selective,
     .name = "hex8s",
     .description = "8-node hexahedron, selectively reduced integration",
     .nodes = 8,
     .corners = 8,
     .family = ElementFamily::kSolid,
     .abaqus_faces = kTraitsHexFaces,
     .vtk_code = 12,
     .body_file_code = 16,
     .matrices = TraitsHex8SelectiveMatrices,
     .stress = TraitsSolidStress<SolidHex8Stress>,
     .corner_stress = SolidHex8CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidHex8GeometricStiffness>},
    {.type = kPyramid5,
     .name = "pyramid5",
     .description = "5-node pyramid",
     .nodes = 5,
     .corners = 5,
     .family = ElementFamily::kSolid,
     .nastran_cards = kTraitsCpyram,
     .nastran_card_grids = 13,
     .abaqus = kTraitsC3D5,
     .gmsh_code = 7,
     .vtk_code = 14,
     .body_file_code = 17,
     .matrices = TraitsPyramid5Matrices,
     .stress = TraitsSolidStress<SolidPyramid5Stress>,
     .corner_stress = SolidPyramid5CornerStress,
     .geometric_stiffness = TraitsGeometric<SolidPyramid5GeometricStiffness>},
};

constexpr bool TraitsRowsInIdOrder() {
  for (int k = 0; k < static_cast<int>(std::size(kTraitsRows)); ++k)
    if (static_cast<int>(kTraitsRows[k].type) != k) return false;
  return true;
}
static_assert(TraitsRowsInIdOrder(), "element traits rows must be stored in type id order");

}  // namespace

std::span<const ElementTraits> AllElementTraits() { return kTraitsRows; }

const ElementTraits& Traits(ElementType type) {
  const int k = static_cast<int>(type);
  if (k < 0 || k >= static_cast<int>(std::size(kTraitsRows)))
    throw InputError("unknown element type id " + std::to_string(k));
  return kTraitsRows[k];
}

const char* FamilyName(ElementFamily family) {
  switch (family) {
    case ElementFamily::kShell: return "shell";
    case ElementFamily::kBeam: return "beam";
    case ElementFamily::kSolid: return "solid";
  }
  return "";
}

}  // namespace flexmb::fe
