// Rod cards of the readers and the writer: Nastran PROD + CROD, CONROD and
// PTUBE + CTUBE (A and J of the tube computed by hand: OD 0.04, T 0.005 ->
// A = pi (0.04^2 - 0.03^2) / 4, J = pi (0.04^4 - 0.03^4) / 32), Nastran's
// C kept as the stress point (C, 0), non-structural mass; errors naming
// file, line and card for a missing property or material, A <= 0, a
// zero-length rod and a tapered PTUBE; Abaqus/CalculiX T3D2 with *SOLID
// SECTION (the area on its data line), and the Abaqus writer's T3D2 with
// the warning for a dropped J.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "flexmb/fe/elements/rod2.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using fe::Mesh;
using testing::ExpectBadFiles;
using testing::WarningCapture;
using testing::WriteScratch;

const std::string kRodGrids =  // lines 1-4
    "MAT1,1,7.+10,,.3,2700.\n"
    "GRID,1,,0.,0.,0.\n"
    "GRID,2,,1.,0.,0.\n"
    "GRID,3,,1.,1.,0.\n";

TEST(RodCards, NastranProdCrodConrodPtubeCtube) {
  const std::string path = WriteScratch("rods.bdf", kRodGrids +
                                                        "PROD,4,1,2.-4,3.-8,.01,.05\n"
                                                        "CROD,11,4,1,2\n"
                                                        "CONROD,12,2,3,1,5.-4,,,.2\n"
                                                        "PTUBE,6,1,.04,.005\n"
                                                        "CTUBE,13,6,1,3\n"
                                                        "CROD,14,,2,3\n"
                                                        "PROD,14,1,1.-4\n");
  const Mesh mesh = ReadNastran(path);
  ASSERT_EQ(mesh.elements.size(), 4u);
  for (const fe::Element& e : mesh.elements) EXPECT_EQ(e.type, fe::kRod2) << e.id;
  const fe::BeamSection& prod = mesh.beam_sections.at(mesh.elements[0].property);
  EXPECT_EQ(prod.A, 2.0e-4);
  EXPECT_EQ(prod.J, 3.0e-8);
  EXPECT_EQ(prod.nsm, 0.05);
  ASSERT_EQ(prod.stress_points.size(), 1u);
  EXPECT_EQ(prod.stress_points[0][0], 0.01);
  EXPECT_TRUE(fe::IsRodSection(prod));
  const fe::BeamSection& conrod = mesh.beam_sections.at(mesh.elements[1].property);
  EXPECT_EQ(conrod.A, 5.0e-4);
  EXPECT_EQ(conrod.J, 0.0);
  EXPECT_EQ(conrod.nsm, 0.2);
  EXPECT_EQ(mesh.nodes[mesh.elements[1].nodes[0]].id, 2);
  EXPECT_EQ(mesh.nodes[mesh.elements[1].nodes[1]].id, 3);
  const fe::BeamSection& tube = mesh.beam_sections.at(mesh.elements[2].property);
  const double pi = std::numbers::pi;
  EXPECT_NEAR(tube.A, pi * (0.04 * 0.04 - 0.03 * 0.03) / 4.0, 1e-17);
  EXPECT_NEAR(tube.J, pi * (std::pow(0.04, 4) - std::pow(0.03, 4)) / 32.0, 1e-20);
  EXPECT_EQ(tube.stress_points[0][0], 0.02);  // C = OD / 2
  // CROD with a blank PID: PID = EID
  EXPECT_EQ(mesh.beam_sections.at(mesh.elements[3].property).A, 1.0e-4);
}

TEST(RodCards, NastranBadRodsNameFileLineAndCard) {
  WarningCapture quiet;
  ExpectBadFiles(
      {
          {"rod_missing_property.bdf", kRodGrids + "CROD,11,4,1,2\n", ":5: CROD 11: property 4 does not exist", {}},
          {"rod_wrong_property.bdf", kRodGrids + "PTUBE,4,1,.04\nCROD,11,4,1,2\n",
           ":6: CROD 11: property 4 is a PTUBE; CROD needs a PROD", {}},
          {"rod_missing_material.bdf", kRodGrids + "PROD,4,9,2.-4\n", ":5: PROD 4: material 9 does not exist", {}},
          {"conrod_missing_material.bdf", kRodGrids + "CONROD,12,2,3,9,5.-4\n",
           ":5: CONROD 12: material 9 does not exist", {}},
          {"rod_area_zero.bdf", kRodGrids + "PROD,4,1,0.\n", ":5: PROD 4: area A must be positive", {}},
          {"conrod_area_negative.bdf", kRodGrids + "CONROD,12,2,3,1,-1.\n",
           ":5: CONROD 12: area A must be positive", {}},
          {"rod_zero_length.bdf", kRodGrids + "GRID,5,,1.,0.,0.\nPROD,4,1,2.-4\nCROD,11,4,2,5\n",
           ":7: CROD 11: zero length", {}},
          {"tube_tapered.bdf", kRodGrids + "PTUBE,6,1,.04,.005,,.03\n",
           ":5: PTUBE 6: OD2 = .03 differs from OD: tapered tubes are not supported", {}},
          {"tube_wall_too_thick.bdf", kRodGrids + "PTUBE,6,1,.04,.03\n", ":5: PTUBE 6: wall thickness T", {}},
      },
      [](const std::string& path) { ReadNastran(path); });
}

const std::string kTrussInp =
    "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n"
    "*ELEMENT, TYPE=T3D2, ELSET=BARS\n1, 1, 2\n2, 2, 3\n"
    "*MATERIAL, NAME=AL\n*ELASTIC\n7.E10, .3\n*DENSITY\n2700.\n"
    "*SOLID SECTION, ELSET=BARS, MATERIAL=AL\n3.E-4\n";

TEST(RodCards, AbaqusT3D2WithSolidSectionAndTheWriter) {
  const Mesh mesh = ReadAbaqus(WriteScratch("truss.inp", kTrussInp));
  ASSERT_EQ(mesh.elements.size(), 2u);
  for (const fe::Element& e : mesh.elements) {
    EXPECT_EQ(e.type, fe::kRod2);
    const fe::BeamSection& s = mesh.beam_sections.at(e.property);
    EXPECT_EQ(s.A, 3.0e-4);
    EXPECT_EQ(s.J, 0.0);
    EXPECT_TRUE(fe::IsRodSection(s));
  }
  // written as T3D2 and read back the same
  Mesh with_j = mesh;
  with_j.beam_sections[0].J = 1.0e-8;
  const std::string out = testing::ScratchPath("truss_out.inp");
  WarningCapture warnings;
  WriteAbaqus(with_j, out);
  EXPECT_EQ(warnings.Count("T3D2 elements carry no torsion"), 1);
  const std::string text = testing::ReadText(out);
  EXPECT_NE(text.find("TYPE=T3D2"), std::string::npos) << text;
  const Mesh back = ReadAbaqus(out);
  ASSERT_EQ(back.elements.size(), 2u);
  EXPECT_EQ(back.elements[1].type, fe::kRod2);
  EXPECT_EQ(back.beam_sections.at(back.elements[1].property).A, 3.0e-4);
  EXPECT_EQ(back.beam_sections.at(back.elements[1].property).J, 0.0);
}

TEST(RodCards, AbaqusTrussSectionErrors) {
  WarningCapture quiet;
  ExpectBadFiles(
      {
          {"truss_no_area.inp", kTrussInp.substr(0, kTrussInp.size() - 7), ":", {"cross-section area"}},
          {"truss_beam_section.inp",
           testing::Replace(kTrussInp, "*SOLID SECTION, ELSET=BARS, MATERIAL=AL\n3.E-4\n",
                            "*BEAM SECTION, ELSET=BARS, MATERIAL=AL, SECTION=RECT\n.01, .02\n"),
           ":", {"is not a beam element"}},
      },
      [](const std::string& path) { ReadAbaqus(path); });
}

}  // namespace
}  // namespace flexmb::io
