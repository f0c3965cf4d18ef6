#include "flexmb/fe_io/nastran/nastran_reader.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe_io/nastran/nastran_fields.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using fe::Mat3;
using fe::Mesh;
using fe::Vec3;

using testing::ExpectBadFiles;
using testing::InputErrorOf;
using testing::WarningCapture;
using testing::WriteScratch;

std::string DataPath(const std::string& name) { return testing::FeData("nastran/" + name); }

const fe::Node& NodeById(const Mesh& mesh, int id) {
  const int index = mesh.NodeIndex(id);
  EXPECT_GE(index, 0) << "node " << id;
  return mesh.nodes.at(index);
}

// ---- numbers ----------------------------------------------------------------

TEST(NastranFields, RealForms) {
  const std::vector<std::pair<std::string, double>> ok = {
      {"1.-3", 1e-3},  {"-.5+2", -50.0}, {"1.0D3", 1000.0}, {"7.", 7.0},     {"+7.", 7.0},
      {".5", 0.5},     {"5", 5.0},       {"1.5e+02", 150.0}, {"2.1+11", 2.1e11}, {" 3.E-2 ", 0.03},
      {"-1.25d-1", -0.125}, {"0.", 0.0}, {"1E3", 1000.0}};
  for (const auto& [text, value] : ok) {
    double v = -99.0;
    EXPECT_TRUE(nastran::ParseReal(text, &v)) << text;
    EXPECT_EQ(v, value) << text;
  }
  for (const char* bad : {"1.2.3", "E3", "1.E", "--1", "1 .0", "inf", "nan", "0x10", "1.-", "", ".", "+", "1.5X"}) {
    double v = 0.0;
    EXPECT_FALSE(nastran::ParseReal(bad, &v)) << bad;
  }
  double v = 0.0;
  EXPECT_FALSE(nastran::ParseReal("1.E999", &v));
  EXPECT_TRUE(nastran::LooksReal("1.-3"));
  EXPECT_TRUE(nastran::LooksReal("2+5"));
  EXPECT_FALSE(nastran::LooksReal("-25"));
}

TEST(NastranFields, IntegerForms) {
  int v = 0;
  EXPECT_TRUE(nastran::ParseInteger("12", &v));
  EXPECT_EQ(v, 12);
  EXPECT_TRUE(nastran::ParseInteger("-3", &v));
  EXPECT_EQ(v, -3);
  EXPECT_TRUE(nastran::ParseInteger("+99999999", &v));
  EXPECT_EQ(v, 99999999);
  for (const char* bad : {"1.", "1E2", "abc", "", "-", "3000000000", "1 2"})
    EXPECT_FALSE(nastran::ParseInteger(bad, &v)) << bad;
}

// ---- formats ---------------------------------------------------------------------

// the generated variants (tests/data/fe/make_nastran_data.py) hold one model
// in small, large, free and tab-separated field, and split over INCLUDEs
TEST(NastranReader, FormatVariantsReadToTheSameMesh) {
  WarningCapture quiet;
  const Mesh small = ReadNastran(DataPath("variants/small.bdf"));
  testing::MeshMatch tol;
  tol.position = 1e-15;
  for (const char* name : {"large.bdf", "free.bdf", "tabs.bdf", "include.bdf"}) {
    SCOPED_TRACE(name);
    testing::ExpectSameMesh(small, ReadNastran(DataPath(std::string("variants/") + name)), tol);
  }
  EXPECT_TRUE(quiet.messages.empty()) << quiet.messages.front();

  // spot checks against the card values
  EXPECT_EQ(small.nodes.size(), 19u);
  EXPECT_EQ(small.elements.size(), 9u);
  // GRID 10 in CORD2R 1 (origin (1,2,3), x = basic Y, y = -basic X): (0.1, -0.2, 0.5)
  EXPECT_LT((NodeById(small, 10).x - Vec3(1.2, 2.1, 3.5)).norm(), 1e-15);
  const fe::Element& quad = small.elements[1];
  EXPECT_EQ(quad.id, 102);
  EXPECT_EQ(quad.type, fe::ElementType::kQuad4);
  EXPECT_EQ(quad.shell_offset, 1e-3);
  const fe::Element& tria = small.elements[4];
  EXPECT_EQ(tria.id, 104);
  EXPECT_EQ(tria.shell_offset, -5e-4);
  const fe::Element& bar = small.elements[5];
  EXPECT_EQ(bar.type, fe::ElementType::kBeam2);
  EXPECT_EQ(bar.orientation, Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(bar.offset_a, Vec3(0.0, 0.0, 0.01));
  // CBEAM 202 with G0 = 1: v from GA (7) to G0
  const fe::Element& beam = small.elements[6];
  EXPECT_EQ(beam.orientation, NodeById(small, 1).x - NodeById(small, 7).x);
  EXPECT_EQ(small.elements[7].type, fe::ElementType::kHex8);
  EXPECT_EQ(small.elements[8].type, fe::ElementType::kTet4);
  // MAT1 2: NU from E and G
  EXPECT_NEAR(small.materials[1].nu, 7.0e10 / (2.0 * 2.6e10) - 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(small.materials[0].G, 2.1e11 / 2.6);
  // PBEAM K1 K2 and PSHELL NSM
  EXPECT_EQ(small.beam_sections[1].ky, 0.85);
  EXPECT_EQ(small.shell_sections[0].nsm, 0.5);
  // CONM2 402, CID -1: offset = X - node position
  EXPECT_LT((small.point_masses[1].offset - (Vec3(1.0, 2.0, 3.5) - Vec3(1.2, 2.1, 3.5))).norm(), 1e-15);
  // RBE2 7 THRU 9 and the sets
  EXPECT_EQ(small.rigid_links[0].dependent.size(), 3u);
  EXPECT_EQ(small.constraints.size(), 4u);
  EXPECT_EQ(small.constraints[3].dofs, 0b100);
  EXPECT_EQ(small.node_sets.at("ASET").size(), 3u);
  EXPECT_EQ(small.node_sets.at("SET1_5").size(), 6u);
  EXPECT_EQ(small.elements[0].origin.line, 41);
  EXPECT_NE(small.elements[0].origin.file.find("small.bdf"), std::string::npos);
}

std::string Pad(const std::string& s, size_t width) { return s + std::string(width - s.size(), ' '); }

TEST(NastranReader, ContinuationsAndCommentsInOneCard) {
  // one GRID written in four formats, and a free-field card continued with a
  // named marker in field 10
  const std::string text = "$ comment line\n" + Pad("GRID", 8) + Pad("1", 16) + Pad("1.", 8) + Pad("2.", 8) + "3.\n" +
                           Pad("GRID*", 8) + Pad("2", 32) + Pad("1.0", 16) + Pad("2.0", 16) + "*C2\n" +
                           Pad("*C2", 8) + "3.0\n" +
                           "GRID,3,,1.,2.,3.  $ trailing comment\n"
                           "\n"
                           "GRID\t4\t\t1.\t2.\t3.\n"
                           "CORD2R,9,,0.,0.,0.,0.,0.,1.,+C\n"
                           "+C,1.,0.,0.\n"
                           "GRID,5,9,1.,2.,3.\n";
  const Mesh mesh = ReadNastran(WriteScratch("cont.bdf", text));
  ASSERT_EQ(mesh.nodes.size(), 5u);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(mesh.nodes[k].x, Vec3(1.0, 2.0, 3.0)) << "node " << k + 1;
  EXPECT_EQ(mesh.nodes[1].origin.line, 3);
  EXPECT_EQ(mesh.nodes[2].origin.line, 5);
  EXPECT_EQ(mesh.nodes[3].origin.line, 7);
}

// BAROR defaults, OFFT (basic vs displacement system, offset system),
// GRDSET defaults and GRID PS
TEST(NastranReader, ReplicationEntriesMakeTheSameMeshAsTheCardsWrittenOut) {
  // MSC Nastran Quick Reference, "Bulk Data Entry": = copies the field above,
  // == it and the rest, *x adds x, =n repeats n times; blank stays blank
  const std::string written =
      "GRID    1               0.      0.      0.\n"
      "GRID    2               0.5     0.      0.\n"
      "GRID    3               1.      0.      0.\n"
      "GRID    4               1.5     0.      0.\n"
      "GRID    5               2.      0.      0.\n"
      "GRID    6               2.      0.5     0.\n"
      "CBAR    11      1       1       2       0.      0.      1.\n"
      "CBAR    12      1       2       3       0.      0.      1.\n"
      "CBAR    13      1       3       4       0.      0.      1.\n"
      "CBAR    14      1       4       5       0.      0.      1.\n"
      "PBAR    1       1       1.e-3   1.e-7   1.e-7   2.e-7\n"
      "MAT1    1       2.1e11          0.3     7850.\n";
  const std::string replicated =
      "GRID    1               0.      0.      0.\n"
      "=       *1      =       *.5     =       ==\n"
      "=2\n"
      "GRID,5,,2.,0.,0.\n"
      "=,*(1),,=,*0.5,=\n"
      "CBAR    11      1       1       2       0.      0.      1.\n"
      "=(3)    *1      =       *1      *(1)    ==\n"
      "PBAR    1       1       1.e-3   1.e-7   1.e-7   2.e-7\n"
      "MAT1    1       2.1e11          0.3     7850.\n";
  const Mesh a = ReadNastran(WriteScratch("written.bdf", written));
  const Mesh b = ReadNastran(WriteScratch("replicated.bdf", replicated));
  testing::MeshMatch tol;
  tol.position = 1e-15;
  testing::ExpectSameMesh(a, b, tol);
  ASSERT_EQ(b.nodes.size(), 6u);
  EXPECT_EQ(NodeById(b, 4).x, Vec3(1.5, 0.0, 0.0));
  EXPECT_EQ(NodeById(b, 6).x, Vec3(2.0, 0.5, 0.0));
  ASSERT_EQ(b.elements.size(), 4u);
  EXPECT_EQ(b.elements[3].id, 14);
  // a blank field above counts as 0 (pyNastran's models/other/dbxdra7.bdf
  // increments the blank CD of a GRID this way)
  const Mesh c = ReadNastran(WriteScratch("blank_increment.bdf", "GRID,1,,0.,,0.\n=,*1,=,*1.,*2.,=\n"));
  EXPECT_EQ(NodeById(c, 2).x, Vec3(1.0, 2.0, 0.0));
  // errors name the file and line
  for (const auto& [text, part] :
       {std::pair<const char*, const char*>{"=       *1\n", "without a preceding card"},
        {"GRID    1               0.      0.      0.\n=(x)\n", "malformed replication count"},
        {"GRID    1               0.      0.      0.\n=       *1      =       *A\n", "cannot add"},
        {"GRID    1               0.      0.      0.\n=       *1\n        1\n", "continuation line after a replication"},
        {"CBEAM   1       1       1       2       0.      0.      1.\n        1.\n=       *1\n",
         "a card with continuations"}}) {
    const std::string path = WriteScratch("bad_replication.bdf", text);
    const std::string message = InputErrorOf([&] { ReadNastran(path); });
    testing::ExpectContains(message, {part, "bad_replication.bdf:"}, text);
  }
}

TEST(NastranReader, TrailingCommasAddOnlyBlankFields) {
  // pyNastran's models/other/conedg01e.bdf: a full free-field line closed by
  // a comma ("..., 1.0, +C1,") has 11 parts, the last one empty
  const Mesh m = ReadNastran(WriteScratch("trailing_comma.bdf",
                                          "CORD2R, 5, , 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, +C1,\n"
                                          "+C1, 1.0, 0.0, 0.0,,\n"
                                          "GRID, 1, 5, 1.0, 2.0, 3.0,\n"));
  EXPECT_LT((NodeById(m, 1).x - Vec3(1.0, 2.0, 3.0)).norm(), 1e-15);
}

TEST(NastranReader, BeamOrientationOffsetsAndDefaults) {
  const std::string path = WriteScratch("beams.bdf",
                                        "MAT1,1,2.1+11,,.3,7850.\n"
                                        "PBAR,5,1,1.-4,1.-8,2.-8,3.-8\n"
                                        "PBAR,6,1,1.-4,1.-8,2.-8,3.-8\n"
                                        "BAROR,,5,,,0.,0.,1.,GOO\n"
                                        "$ 10: x = basic Y, z = basic Z\n"
                                        "CORD2R,10,,0.,0.,0.,0.,0.,1.\n"
                                        ",0.,1.,0.\n"
                                        "GRID,1,,0.,0.,0.\n"
                                        "GRID,2,,1.,0.,0.\n"
                                        "GRID,5,,0.,0.,0.,10\n"
                                        "GRID,6,,0.,0.,1.,,123456\n"
                                        "CBAR,1,,1,2\n"
                                        "CBAR,2,6,1,2,,,,\n"
                                        ",,,.1,.2,.3\n"
                                        "CBAR,3,6,5,6,1.,0.,0.,GGG\n"
                                        "CBAR,4,6,5,6,1.,0.,0.,BGG\n"
                                        "CBAR,7,6,5,6,1.,0.,0.,GGG\n"
                                        ",,,.1,0.,0.\n");
  const Mesh mesh = ReadNastran(path);
  ASSERT_EQ(mesh.elements.size(), 5u);
  // BAROR gives PID 5, v = Z and OFFT GOO
  EXPECT_EQ(mesh.beam_sections[mesh.elements[0].property].id, 5);
  EXPECT_EQ(mesh.elements[0].orientation, Vec3(0.0, 0.0, 1.0));
  // offset system of bar 2: x = GA->GB = X, y in the plane of x and v = Z, z = x cross y = -Y
  EXPECT_LT((mesh.elements[1].offset_a - Vec3(0.1, -0.3, 0.2)).norm(), 1e-15);
  EXPECT_EQ(mesh.beam_sections[mesh.elements[1].property].id, 6);
  // GA's CD = 10 rotates X1-X3 for OFFT G..; B.. keeps them in basic
  EXPECT_LT((mesh.elements[2].orientation - Vec3(0.0, 1.0, 0.0)).norm(), 1e-15);
  EXPECT_EQ(mesh.elements[3].orientation, Vec3(1.0, 0.0, 0.0));
  // end-A offset in GA's displacement system (G)
  EXPECT_LT((mesh.elements[4].offset_a - Vec3(0.0, 0.1, 0.0)).norm(), 1e-15);
  // GRID PS
  ASSERT_EQ(mesh.constraints.size(), 1u);
  EXPECT_EQ(mesh.constraints[0].node, mesh.NodeIndex(6));
  EXPECT_EQ(mesh.constraints[0].dofs, 0b111111);
}

// ---- sections ------------------------------------------------------------------

struct Moments {
  double A = 0, I1 = 0, I2 = 0, I12 = 0;
};

// second moments of a shape given by its indicator function, by cells of
// size h on [z0, z1] x [y0, y1] (exact when the edges lie on cell faces:
// each cell adds its own h^2 / 12 moments)
Moments Integrate(const std::function<bool(double z, double y)>& inside, double z0, double z1, double y0,
                  double y1, double h) {
  const int nz = static_cast<int>(std::lround((z1 - z0) / h)), ny = static_cast<int>(std::lround((y1 - y0) / h));
  double a = 0, sz = 0, sy = 0, szz = 0, syy = 0, syz = 0;
  for (int i = 0; i < nz; ++i) {
    for (int j = 0; j < ny; ++j) {
      const double z = z0 + (i + 0.5) * h, y = y0 + (j + 0.5) * h;
      if (!inside(z, y)) continue;
      const double da = h * h;
      a += da;
      sz += z * da;
      sy += y * da;
      szz += (z * z + h * h / 12.0) * da;
      syy += (y * y + h * h / 12.0) * da;
      syz += y * z * da;
    }
  }
  Moments m;
  m.A = a;
  const double zc = sz / a, yc = sy / a;
  m.I1 = syy - a * yc * yc;
  m.I2 = szz - a * zc * zc;
  m.I12 = syz - a * yc * zc;
  return m;
}

void ExpectMoments(const fe::BeamSection& s, const Moments& m, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_NEAR(s.A, m.A, 1e-9 * m.A);
  EXPECT_NEAR(s.Iz, m.I1, 1e-9 * m.I1);  // Nastran I1 = int y^2 dA -> Iz
  EXPECT_NEAR(s.Iy, m.I2, 1e-9 * m.I2);  // Nastran I2 = int z^2 dA -> Iy
  EXPECT_NEAR(s.Iyz, m.I12, 1e-9 * std::max(m.I1, m.I2));
}

// PBARL shapes against textbook formulas and, for the unsymmetric shapes,
// against a direct integration of the shape drawn as in the Nastran QRG
// (element y up, z across). References: Roark's Formulas for Stress and
// Strain (Young & Budynas, 7th ed.), Table A.1 (areas, second moments) and
// Table 10.7 (torsion); Timoshenko & Goodier, Theory of Elasticity, sec. 109,
// exact torsion constant of a 2:1 rectangle 0.229 a b^3; Bredt's formula
// for thin-walled tubes; Cowper (1966), shear coefficients.
TEST(NastranReader, PbarlSections) {
  const Mesh mesh = ReadNastran(DataPath("sections.bdf"));
  ASSERT_EQ(mesh.beam_sections.size(), 10u);
  auto section = [&](int pid) -> const fe::BeamSection& {
    for (const fe::BeamSection& s : mesh.beam_sections)
      if (s.id == pid) return s;
    throw std::runtime_error("no section " + std::to_string(pid));
  };
  const double pi = M_PI;
  {  // ROD r = 0.02: exact; Cowper k = 6 (1 + nu) / (7 + 6 nu)
    const fe::BeamSection& s = section(21);
    const double r = 0.02;
    EXPECT_NEAR(s.A, pi * r * r, 1e-15);
    EXPECT_NEAR(s.Iy, pi * std::pow(r, 4) / 4.0, 1e-20);
    EXPECT_NEAR(s.Iz, pi * std::pow(r, 4) / 4.0, 1e-20);
    EXPECT_NEAR(s.J, pi * std::pow(r, 4) / 2.0, 1e-20);
    EXPECT_NEAR(s.ky, 7.8 / 8.8, 1e-12);
  }
  {  // TUBE 0.03 / 0.025: exact
    const fe::BeamSection& s = section(22);
    EXPECT_NEAR(s.A, pi * (0.03 * 0.03 - 0.025 * 0.025), 1e-15);
    EXPECT_NEAR(s.Iz, pi * (std::pow(0.03, 4) - std::pow(0.025, 4)) / 4.0, 1e-20);
    EXPECT_NEAR(s.J, pi * (std::pow(0.03, 4) - std::pow(0.025, 4)) / 2.0, 1e-20);
  }
  {  // BAR 0.02 (z) x 0.04 (y), NU = 0: I1 = b h^3 / 12 about z; k = 5/6
    const fe::BeamSection& s = section(23);
    EXPECT_NEAR(s.A, 8e-4, 1e-18);
    EXPECT_NEAR(s.Iz, 0.02 * std::pow(0.04, 3) / 12.0, 1e-22);
    EXPECT_NEAR(s.Iy, 0.04 * std::pow(0.02, 3) / 12.0, 1e-22);
    EXPECT_NEAR(s.J, 0.229 * 0.04 * std::pow(0.02, 3), 0.002 * s.J);
    EXPECT_NEAR(s.ky, 5.0 / 6.0, 1e-12);
    EXPECT_EQ(s.nsm, 1.5);
  }
  {  // BOX 0.1 x 0.1, t = 0.005: I = (b^4 - b_i^4) / 12; Bredt J = t s^3 (s mid-line side)
    const fe::BeamSection& s = section(24);
    EXPECT_NEAR(s.A, 0.1 * 0.1 - 0.09 * 0.09, 1e-15);
    EXPECT_NEAR(s.Iz, (std::pow(0.1, 4) - std::pow(0.09, 4)) / 12.0, 1e-18);
    EXPECT_NEAR(s.Iy, s.Iz, 1e-18);
    EXPECT_NEAR(s.J, 0.005 * std::pow(0.095, 3), 1e-15);
  }
  {  // symmetric I: h 0.2, b 0.1, t_w 0.006, t_f 0.01
    const fe::BeamSection& s = section(25);
    const double h = 0.2, b = 0.1, tw = 0.006, tf = 0.01, hw = h - 2 * tf;
    EXPECT_NEAR(s.A, 2 * b * tf + hw * tw, 1e-15);
    EXPECT_NEAR(s.Iz, (b * h * h * h - (b - tw) * hw * hw * hw) / 12.0, 1e-15);
    EXPECT_NEAR(s.Iy, (2 * tf * b * b * b + hw * tw * tw * tw) / 12.0, 1e-15);
    EXPECT_NEAR(s.Iyz, 0.0, 1e-18);
    // thin-walled open section: sum of l t^3 / 3 on the mid-lines
    EXPECT_NEAR(s.J, (2 * b * tf * tf * tf + (h - tf) * tw * tw * tw) / 3.0, 1e-15);
  }
  const double cell = 0.0005;
  {  // CHAN 0.06 x 0.12, web 0.005 on the left, flanges 0.008
    const double b = 0.06, h = 0.12, tw = 0.005, tf = 0.008;
    const fe::BeamSection& s = section(26);
    EXPECT_NEAR(s.Iz, (b * h * h * h - (b - tw) * std::pow(h - 2 * tf, 3)) / 12.0, 1e-15);
    ExpectMoments(s, Integrate([&](double z, double y) { return z <= tw || y <= tf || y >= h - tf; }, 0, b, 0, h, cell),
                  "CHAN");
  }
  {  // L 0.08 x 0.06, legs along +z (t 0.006) and +y (t 0.005): I12 < 0
    const double b = 0.08, h = 0.06, t1 = 0.006, t2 = 0.005;
    const fe::BeamSection& s = section(27);
    ExpectMoments(s, Integrate([&](double z, double y) { return y <= t1 || z <= t2; }, 0, b, 0, h, cell), "L");
    EXPECT_LT(s.Iyz, 0.0);
  }
  {  // T: flange 0.1 x 0.01 on top, web 0.008 thick, height 0.08
    const double b = 0.1, h = 0.08, tf = 0.01, tw = 0.008;
    const fe::BeamSection& s = section(28);
    ExpectMoments(s,
                  Integrate([&](double z, double y) { return y >= h - tf || std::abs(z) <= tw / 2; }, -b / 2, b / 2,
                            0, h, cell),
                  "T");
  }
  {  // H: web 0.1 long, 0.008 thick; flanges 0.01 x 0.12 at its ends
    const double w = 0.1, tf = 0.01, hf = 0.12, tw = 0.008;
    const fe::BeamSection& s = section(29);
    ExpectMoments(s,
                  Integrate([&](double z, double y) { return std::abs(z) >= w / 2 || std::abs(y) <= tw / 2; },
                            -(w / 2 + tf), w / 2 + tf, -hf / 2, hf / 2, cell),
                  "H");
  }
  {  // PBEAML at a constant section equals the PBARL BAR (here with NU = 0.3)
    const fe::BeamSection& s = section(30);
    EXPECT_NEAR(s.Iz, 0.02 * std::pow(0.04, 3) / 12.0, 1e-22);
    EXPECT_NEAR(s.ky, 13.0 / 15.3, 1e-12);
  }
}

// ---- coordinate systems ------------------------------------------------------------

TEST(NastranReader, CoordinateSystems) {
  const Mesh mesh = ReadNastran(DataPath("coords.bdf"));
  const double r2 = std::sqrt(2.0);
  // 1: origin (1,2,3), axes x = Y, y = -X, z = Z: (a,b,c) -> (1 - b, 2 + a, 3 + c)
  EXPECT_LT((NodeById(mesh, 1).x - Vec3(1.2, 2.1, 3.5)).norm(), 1e-14);
  // 2 (in 1): origin (1, 2.5, 3), x = (-1,1,0)/r2, y = (-1,-1,0)/r2, z = Z
  EXPECT_LT((NodeById(mesh, 2).x - Vec3(1.0 + 0.249 / r2, 2.5 - 0.251 / r2, 3.75)).norm(), 1e-14);
  // 3 cylindrical: r 2, theta 30 deg, z 1
  EXPECT_LT((NodeById(mesh, 3).x - Vec3(std::sqrt(3.0), 1.0, 1.0)).norm(), 1e-14);
  // 4 spherical at (1,1,1): r 2, theta 90, phi 90 -> (0, 2, 0) + origin
  EXPECT_LT((NodeById(mesh, 4).x - Vec3(1.0, 3.0, 1.0)).norm(), 1e-14);
  // 5 cylindrical with the axes of 1: r 1, theta 90 -> (0,1,0) in 1 -> (0, 2, 3)
  EXPECT_LT((NodeById(mesh, 5).x - Vec3(0.0, 2.0, 3.0)).norm(), 1e-14);
  // 6 defined by points in the cylindrical system 3: x = Y
  EXPECT_LT((NodeById(mesh, 6).x - Vec3(0.0, 1.0, 0.0)).norm(), 1e-14);
  // CD does not move the grid
  EXPECT_EQ(NodeById(mesh, 7).x, Vec3(4.0, 5.0, 6.0));
}

// ---- mass properties -----------------------------------------------------------------

TEST(NastranReader, Rbe2Conm2MassProperties) {
  const Mesh mesh = ReadNastran(DataPath("mass.bdf"));
  ASSERT_EQ(mesh.point_masses.size(), 4u);
  ASSERT_EQ(mesh.rigid_links.size(), 1u);
  EXPECT_EQ(mesh.rigid_links[0].dependent.size(), 3u);

  // hand computation from the card values
  Mat3 r1;  // CORD2R 1: columns x = Y, y = -X, z = Z
  r1 << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  Mat3 i21, i23;  // inertia with Nastran's minus signs on I21 I31 I32
  i21 << 0.5, -0.1, 0.0, -0.1, 0.6, -0.05, 0.0, -0.05, 0.7;
  i23 << 1.0, -0.2, 0.0, -0.2, 2.0, 0.0, 0.0, 0.0, 3.0;
  struct Mass {
    double m;
    Vec3 x;
    Mat3 ic;
  };
  const std::vector<Mass> masses = {
      {2.0, Vec3(0.1, 0.0, 0.0), i21},
      {1.0, Vec3(1.0, 1.0, 0.0), Mat3::Zero()},
      {3.0, Vec3(0.0, 2.0, 0.0) + r1 * Vec3(0.2, 0.0, 0.0), r1 * i23 * r1.transpose()},
      {0.5, Vec3(0.0, 0.0, 3.0), Mat3::Zero()}};
  double total = 0.0;
  Vec3 moment = Vec3::Zero();
  for (const Mass& m : masses) {
    total += m.m;
    moment += m.m * m.x;
  }
  const Vec3 center = moment / total;
  Mat3 inertia = Mat3::Zero();
  for (const Mass& m : masses) {
    const Vec3 r = m.x - center;
    inertia += m.ic + m.m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }

  fe::AssemblyOptions options;
  options.apply_constraints = false;
  const fe::AssembledModel model = fe::Assemble(mesh, options);
  const fe::MassProperties p = fe::ComputeMassProperties(mesh, model);
  EXPECT_NEAR(p.mass, 6.5, 1e-12);
  EXPECT_LT((p.center - center).norm(), 1e-12);
  EXPECT_LT((p.inertia - inertia).cwiseAbs().maxCoeff(), 1e-12) << p.inertia << "\n\n" << inertia;
}

// ---- frequencies -------------------------------------------------------------------------

// Euler-Bernoulli cantilever: f1 = (1.875104^2 / (2 pi L^2)) sqrt(E I / (rho A))
TEST(NastranReader, CantileverStripFirstFrequency) {
  const Mesh mesh = ReadNastran(DataPath("strip.bdf"));
  ASSERT_EQ(mesh.elements.size(), 40u);
  ASSERT_EQ(mesh.constraints.size(), 3u);
  const double E = 2.1e11, rho = 7850.0, L = 1.0, t = 0.005;
  const double beta = 1.8751040687;
  const double f_ref = beta * beta / (2.0 * M_PI * L * L) * std::sqrt(E * t * t / (12.0 * rho));
  fe::ModalOptions options;
  options.count = 1;
  const fe::ModalResult r = fe::SolveModes(fe::Assemble(mesh), options);
  EXPECT_NEAR(r.frequencies_hz[0], f_ref, 0.01 * f_ref);
}

// ---- warnings ---------------------------------------------------------------------------------

// one warning at the end of reading lists the skipped card types with their
// count and first line; PARAM and EIGRL are skipped silently
TEST(NastranReader, UnknownCardsAreListedOnceAtTheEnd) {
  const std::string path = WriteScratch("warn.bdf",
                                        "PARAM,POST,-1\n"
                                        "EIGRL,1,,,10\n"
                                        "GRID,1,,0.,0.,0.\n"
                                        "FORCE,1,1,,1.,1.,0.,0.\n"
                                        "FORCE,1,1,,2.,1.,0.,0.\n"
                                        "MOMENT,1,1,,1.,1.,0.,0.\n");
  WarningCapture capture;
  ReadNastran(path);
  ASSERT_EQ(capture.messages.size(), 1u);
  EXPECT_NE(capture.messages[0].find("skipped cards (they do not change the stiffness or mass): FORCE (x2, first at "),
            std::string::npos)
      << capture.messages[0];
  EXPECT_NE(capture.messages[0].find("warn.bdf:4), MOMENT (x1, at "), std::string::npos) << capture.messages[0];
  EXPECT_EQ(capture.messages[0].find("PARAM"), std::string::npos) << capture.messages[0];
}

// every card that would change K or M is listed in one error, which names
// the first one's file, line and entity
TEST(NastranReader, UnsupportedCardsAreListedInOneError) {
  const std::string path = WriteScratch("unsupported.bdf",
                                        "GRID,1,,0.,0.,0.\n"
                                        "GRID,2,,1.,0.,0.\n"
                                        "CBUSH1D,7,1,1,2\n"
                                        "FORCE,1,1,,1.,1.,0.,0.\n"
                                        "RBE1,9,1,123456,,,,,\n"
                                        "CBUSH1D,8,1,1,2\n");
  try {
    ReadNastran(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("unsupported.bdf:3: CBUSH1D 7: 2 card types are not supported and would change the stiffness or mass"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("CBUSH1D (x2, first at "), std::string::npos) << m;
    EXPECT_NE(m.find("unsupported.bdf:5)"), std::string::npos) << m;  // RBE1
    EXPECT_EQ(m.find("FORCE"), std::string::npos) << m;
  }
}

// ---- bad input ---------------------------------------------------------------------------------

const std::string kBase =  // lines 1-6
    "MAT1,1,2.1+11,,.3,7850.\n"
    "PSHELL,1,1,.01,1\n"
    "GRID,1,,0.,0.,0.\n"
    "GRID,2,,1.,0.,0.\n"
    "GRID,3,,1.,1.,0.\n"
    "GRID,4,,0.,1.,0.\n";

// each case: file, ":line: card id: message" after its path, further parts
TEST(NastranReader, BadInputNamesFileLineAndEntity) {
  WarningCapture quiet;
  ExpectBadFiles(
      {
          {"malformed_number.bdf", "GRID,1,,0.,0.,0.\nGRID,2,,1.2.3,0.,0.\n",
           ":2: GRID 2: X1: malformed number '1.2.3'", {}},
          {"non_finite_number.bdf", "GRID,1,,1.E999,0.,0.\n", ":1: GRID 1: X1: number '1.E999' is not finite", {}},
          {"missing_required_field.bdf", kBase + "CQUAD4,7,1,1,2,3\n", ":7: CQUAD4 7: G4 is required", {}},
          {"duplicate_grid.bdf", "GRID,1,,0.,0.,0.\n$ c\nGRID,1,,1.,0.,0.\n",
           ":3: GRID 1: duplicate GRID id 1 (first defined at ", {"duplicate_grid.bdf:1)"}},
          {"duplicate_element.bdf", kBase + "CQUAD4,7,1,1,2,3,4\nCTRIA3,7,1,1,2,3\n",
           ":8: CTRIA3 7: duplicate element id 7", {}},
          {"duplicate_property.bdf", kBase + "PSHELL,1,1,.02,1\n", ":7: PSHELL 1: duplicate property id 1", {}},
          {"duplicate_material.bdf", kBase + "MAT1,1,7.+10,,.3\n", ":7: MAT1 1: duplicate material id 1", {}},
          {"dangling_node.bdf", kBase + "CQUAD4,17,1,1,2,3,99\n", ":7: CQUAD4 17: node 99 does not exist", {}},
          {"missing_property.bdf", kBase + "CQUAD4,7,5,1,2,3,4\n", ":7: CQUAD4 7: property 5 does not exist", {}},
          {"missing_material.bdf", "PSHELL,1,9,.01,9\n", ":1: PSHELL 1: material 9 does not exist", {}},
          {"e_not_positive.bdf", "MAT1,1,-2.1+11,,.3\n", ":1: MAT1 1: E must be positive", {}},
          {"thickness_not_positive.bdf", "MAT1,1,2.1+11,,.3\nPSHELL,1,1,0.,1\n",
           ":2: PSHELL 1: thickness T must be positive", {}},
          {"area_not_positive.bdf", "MAT1,1,2.1+11,,.3\nPBAR,3,1,0.,1.-8,1.-8,2.-8\n",
           ":2: PBAR 3: area A must be positive", {}},
          {"unsupported_element.bdf", kBase + "CBUSH1D,5,1,1,2\n", ":7: CBUSH1D 5: CBUSH1D is not supported", {}},
          {"pshell_mid4.bdf", "MAT1,1,2.1+11,,.3\nPSHELL,1,1,.01,1\n,,,1\n",
           ":3: PSHELL 1: the membrane-bending coupling of MID4 = 1 makes the section's stiffness [A B; B D] indefinite",
           {}},
          {"chexa15.bdf",
           "PSOLID,1,1\nMAT1,1,2.1+11,,.3\nCHEXA,4,1,1,2,3,4,5,6\n,7,8,9,10,11,12,13,14\n,15\n",
           ":3: CHEXA 4: CHEXA with 15 grid points: only 8 or 20 are supported", {"unsupported"}},
          {"orphan_continuation.bdf", "+,1,2\nGRID,1,,0.,0.,0.\n",
           ":1: continuation line without a preceding card", {}},
          {"error_on_a_continuation_line.bdf", kBase + "CQUAD4,7,1,1,2,3,4\n,,,ABC\n",
           ":8: CQUAD4 7: T1: malformed number 'ABC'", {}},
          {"pin_flags.bdf",
           "MAT1,1,2.1+11,,.3\nPBAR,3,1,1.-4,1.-8,1.-8,2.-8\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n"
           "CBAR,9,3,1,2,0.,1.,0.\n,456\n",
           ":6: CBAR 9: pin flags PA/PB are not supported", {}},
          {"cd_and_components.bdf",
           "CORD2R,1,,0.,0.,0.,0.,0.,1.\n,1.,1.,0.\nGRID,2,,1.,0.,0.,1\nGRID,3,,2.,0.,0.\nGRID,4,,2.,1.,0.\n"
           "RBE3,9,,2,3,1.,123,3,4\n",
           ":6: RBE3 9: components 3 of node 2 refer to its displacement system CD = 1", {"unsupported"}},
          {"wrong_property_kind.bdf", kBase + "PBAR,3,1,1.-4,1.-8,1.-8,2.-8\nCQUAD4,7,3,1,2,3,4\n",
           ":8: CQUAD4 7: property 3 is a PBAR; CQUAD4 needs a PSHELL", {}},
          {"unsupported_material.bdf", "MAT9,2,1.+11\nPSHELL,1,2,.01,2\n",
           ":2: PSHELL 1: material 2 is a MAT9", {"not supported"}},
          {"space_separated_fixed_format.bdf", "GRID 1 0 1. 2. 3.\n", ":1: malformed card name 'GRID 1 0'", {}},
          {"too_many_free_fields.bdf", "GRID,1,,0.,0.,0.,,,,,7\n", ":1: free-field line has 11 fields", {}},
          {"missing_coordinate_system.bdf", "GRID,1,5,0.,0.,0.\n",
           ":1: GRID 1: coordinate system 5 does not exist", {}},
          {"coordinate_system_cycle.bdf",
           "CORD2R,1,2,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\nCORD2R,2,1,0.,0.,0.,0.,0.,1.\n,1.,0.,0.\n",
           ":", {": CORD2R ", "cycle"}},
          {"degenerate_cord2r.bdf", "CORD2R,1,,0.,0.,0.,0.,0.,0.\n,1.,0.,0.\n",
           ":1: CORD2R 1: points A and B coincide", {}},
          {"mat1_with_e_only.bdf", "MAT1,1,2.1+11\n", ":1: MAT1 1: only E is given", {}},
          {"tapered_pbeam.bdf", "MAT1,1,2.1+11,,.3\nPBEAM,4,1,1.-4,1.-8,1.-8,,2.-8\n,,,,,,,,\n,YES,1.,2.-4\n",
           ":4: PBEAM 4: tapered PBEAM", {}},
          {"pbeam_n2b.bdf", "MAT1,1,2.1+11,,.3\nPBEAM,4,1,1.-4,1.-8,1.-8,,2.-8\n,,,,,,,,\n,,,,,,,,\n,,,,,0.,0.01,0.,0.02\n",
           ":5: PBEAM 4: N2(B) differs from N2(A): a tapered PBEAM is not supported", {}},
          {"pbeam_nsi.bdf", "MAT1,1,2.1+11,,.3\nPBEAM,4,1,1.-4,1.-8,1.-8,,2.-8\n,,,,,,,,\n,,,,,-1.\n",
           ":4: PBEAM 4: NSI(A)", {"must not be negative"}},
          {"unknown_pbarl_type.bdf", "MAT1,1,2.1+11,,.3\nPBARL,5,1,,ZED\n,.1,.1,.1,.1\n",
           ":2: PBARL 5: section TYPE ZED is not supported", {}},
          {"box_walls_too_thick.bdf", "MAT1,1,2.1+11,,.3\nPBARL,5,1,,BOX\n,.1,.1,.06,.01\n",
           ":3: PBARL 5: BOX: DIM2 must exceed 2 DIM3", {}},
          {"malformed_integer.bdf", kBase + "CQUAD4,7.,1,1,2,3,4\n", ":7: CQUAD4 7.: EID: malformed integer '7.'", {}},
      },
      [](const std::string& path) { ReadNastran(path); });
}

TEST(NastranReader, IncludeErrors) {
  WarningCapture quiet;
  // included by a.bdf and e.bdf below
  WriteScratch("b.bdf", "GRID,2,,0.,0.,0.\nINCLUDE 'a.bdf'\n");
  WriteScratch("sub/e2.bdf", "$ included\nGRID,5,,0.,x,0.\n");
  ExpectBadFiles(
      {
          // a cycle through two files
          {"a.bdf", "GRID,1,,0.,0.,0.\nINCLUDE 'b.bdf'\n", "", {"b.bdf:2: INCLUDE cycle"}},
          // a missing file
          {"c.bdf", "BEGIN BULK\nINCLUDE 'nowhere.bdf'\n", ":2: INCLUDE: cannot open", {}},
          // an unterminated quoted name
          {"d.bdf", "INCLUDE 'sub/\n", ":1: INCLUDE: unterminated", {}},
          // an error in an included file names that file and line
          {"e.bdf", "GRID,1,,0.,0.,0.\nINCLUDE \"sub/e2.bdf\"\n", "",
           {"sub/e2.bdf:2: GRID 5: X2: malformed number 'X'"}},
          // a file that includes itself
          {"f.bdf", "INCLUDE 'f.bdf'\n", ":1: INCLUDE cycle", {}},
      },
      [](const std::string& path) { ReadNastran(path); });
  // the main file itself missing
  testing::ExpectContains(InputErrorOf([] { ReadNastran(testing::ScratchPath("none.bdf")); }), {"cannot open"},
                          "none.bdf");
}

// a scalar point (SPOINT, one by one or THRU a range) is not a node: a card
// that uses one says so, naming the SPOINT card; a bad THRU is an error
TEST(NastranReader, ScalarPointsAreNamedWhereTheyAreUsed) {
  const std::string base = "MAT1,1,2.1e11,,0.3,7850.\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nPROD,1,1,1.e-4\n"
                           "CROD,1,1,1,2\nSPOINT,100,THRU,120,130\n";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"MPC,7,1,1,1.,110,0,-1.\n", {":7: MPC 7", "110 is a scalar point (SPOINT at ", "spoint0.bdf:6)"}},
      {"CELAS2,9,1.e3,130,0,2,1\n", {":7: CELAS2 9", "130 is a scalar point"}},
      {"MPC,7,1,1,1.,121,0,-1.\n", {":7: MPC 7", "node 121 does not exist"}},
      {"SPOINT,THRU,5\n", {":7: SPOINT", "THRU needs an id right before it"}},
      {"SPOINT,9,THRU,5\n", {":7: SPOINT", "THRU range ends below its start"}},
  };
  int k = 0;
  for (const auto& [cards, parts] : cases) {
    const std::string path = WriteScratch("spoint" + std::to_string(k++) + ".bdf", base + cards);
    testing::ExpectContains(InputErrorOf([&] { ReadNastran(path); }), parts, cards);
  }
}

// CQUADR and CTRIAR (Nastran's shells with their own drilling DOF) are read
// as the 4- and 3-node shells, with one warning per card name: the same
// element matrices as CQUAD4 / CTRIA3 on the same grid points
TEST(NastranReader, CquadrAndCtriarReadAsFirstOrderShellsWithAWarning) {
  const std::string base = "MAT1,1,2.1e11,,0.3,7850.\nPSHELL,1,1,0.01,1\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\n"
                           "GRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\n";
  testing::WarningCapture w;
  const fe::Mesh r = ReadNastran(WriteScratch("cquadr.bdf", base + "CQUADR,1,1,1,2,3,4\nCQUADR,2,1,1,2,3,4\nCTRIAR,3,1,1,2,3\n"));
  const fe::Mesh q = ReadNastran(WriteScratch("cquad4.bdf", base + "CQUAD4,1,1,1,2,3,4\nCQUAD4,2,1,1,2,3,4\nCTRIA3,3,1,1,2,3\n"));
  ASSERT_EQ(r.elements.size(), 3u);
  EXPECT_EQ(r.elements[0].type, fe::ElementType::kQuad4);
  EXPECT_EQ(r.elements[2].type, fe::ElementType::kTria3);
  EXPECT_EQ(w.Count("CQUADR elements are read as flexmb's 4-node shell"), 1);
  EXPECT_EQ(w.Count("CTRIAR elements are read as flexmb's 3-node shell"), 1);
  const fe::AssembledModel a = fe::Assemble(r), b = fe::Assemble(q);
  EXPECT_EQ((Eigen::MatrixXd(a.K) - Eigen::MatrixXd(b.K)).norm(), 0.0);
}

}  // namespace
}  // namespace flexmb::io
