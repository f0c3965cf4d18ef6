// Abaqus / CalculiX input decks: syntax features, sets, the mapping of
// sections and materials (checked through mass properties and closed-form
// section constants), the writer's round trip, and bad input naming file,
// line and entity. Data: tests/data/fe/abaqus/.

#include "flexmb/fe_io/abaqus/abaqus_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "flexmb/common/log.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using fe::ElementType;
using fe::Mesh;
using fe::Vec3;
using testing::FeData;
using testing::InputErrorOf;
using testing::WriteScratch;
using testing::WarningCapture;

constexpr double kPi = 3.14159265358979323846;

// a and b agree to round-off (closed forms evaluated in another order)
void ExpectRel(double a, double b, double tol = 1e-14) { EXPECT_NEAR(a, b, tol * std::abs(b)); }

std::vector<int> Ids(const Mesh& m, const std::vector<int>& node_indices) {
  std::vector<int> ids;
  for (int n : node_indices) ids.push_back(m.nodes[n].id);
  return ids;
}

TEST(AbaqusReader, SyntaxFeatures) {
  WarningCapture w;
  const Mesh m = ReadAbaqus(FeData("abaqus/features.inp"));
  // nodes: 6 from the include, 10 through INPUT=, 1 in a local system
  ASSERT_EQ(m.nodes.size(), 17u);
  EXPECT_EQ(m.nodes[6].id, 11);
  EXPECT_EQ(m.nodes[6].x, Vec3(0.0, 0.0, 1.0));
  EXPECT_NE(m.nodes[6].origin.file.find("features_tet_nodes.txt"), std::string::npos);
  EXPECT_EQ(m.nodes[6].origin.line, 1);
  // local system: origin (10, 0, 0), x' = y, y' = -x: (1, 2, 3) -> (8, 1, 3)
  EXPECT_LT((m.nodes[16].x - Vec3(8.0, 1.0, 3.0)).norm(), 1e-14);
  EXPECT_EQ(m.NodeIndex(30), 16);

  ASSERT_EQ(m.elements.size(), 3u);
  EXPECT_EQ(m.elements[0].type, ElementType::kQuad4);
  EXPECT_EQ(m.elements[2].type, ElementType::kTet10);
  EXPECT_EQ(m.elements[2].id, 10);
  EXPECT_EQ(Ids(m, m.elements[2].nodes), (std::vector<int>{11, 12, 13, 14, 15, 16, 17, 18, 19, 20}));
  EXPECT_EQ(m.elements[2].origin.line, 12);  // the first line of the continued element

  // sets: GENERATE, quoted names, sets of sets, nodes of an element set,
  // case-insensitive names keeping their first spelling
  EXPECT_EQ(Ids(m, m.node_sets.at("Edge")), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(Ids(m, m.node_sets.at("Corner Nodes")), (std::vector<int>{1, 3, 6}));
  EXPECT_EQ(Ids(m, m.node_sets.at("Both")), (std::vector<int>{1, 2, 3, 6}));
  EXPECT_EQ(Ids(m, m.node_sets.at("TipNodes")), (std::vector<int>{11, 12, 13, 14, 15, 16, 17, 18, 19, 20}));
  EXPECT_EQ(m.node_sets.at("NALL").size(), 6u);
  EXPECT_EQ(m.element_sets.at("All"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(m.element_sets.count("ALL"), 0u);
  EXPECT_EQ(m.element_sets.at("everything"), (std::vector<int>{0, 1, 2}));  // the MASS element is not a mesh element
  EXPECT_TRUE(m.element_sets.at("LUMP").empty());

  // material (Fortran exponent), shell section with OFFSET=SPOS, the lumped mass
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].name, "Steel");
  EXPECT_EQ(m.materials[0].rho, 7850.0);
  EXPECT_DOUBLE_EQ(m.materials[0].G, 2.1e11 / 2.6);
  ASSERT_EQ(m.shell_sections.size(), 1u);
  EXPECT_EQ(m.shell_sections[0].thickness, 0.01);
  EXPECT_DOUBLE_EQ(m.elements[0].shell_offset, -0.005);
  EXPECT_EQ(m.elements[2].property, 0);
  ASSERT_EQ(m.point_masses.size(), 1u);
  EXPECT_EQ(m.point_masses[0].id, 20);
  EXPECT_EQ(m.point_masses[0].mass, 2.5);
  EXPECT_EQ(m.point_masses[0].node, 16);

  // boundary conditions of the model, not those of the step
  ASSERT_EQ(m.constraints.size(), 5u);
  EXPECT_EQ(m.constraints[0].dofs, 0b111111);
  EXPECT_EQ(m.nodes[m.constraints[3].node].id, 4);
  EXPECT_EQ(m.constraints[3].dofs, 0b000111);
  EXPECT_EQ(m.constraints[4].dofs, 0b000100);
  EXPECT_EQ(w.Count("*BOUNDARY inside a *STEP"), 1);
  EXPECT_EQ(w.Count("skipped keywords (they do not change the stiffness or mass): *ORIENTATION (x1, at "), 1);
  EXPECT_EQ(w.messages.size(), 2u);
}

// keywords that would change K or M (constraints, springs, other sections)
// are listed in one error naming the first one's file and line; loads are
// listed in one warning
TEST(AbaqusReader, UnsupportedKeywordsAreListedInOneError) {
  const std::string base =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n"
      "*ELEMENT, TYPE=S4, ELSET=P\n1,1,2,3,4\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n*SHELL SECTION, ELSET=P, MATERIAL=M\n0.01\n";
  const std::string path = WriteScratch("unsupported.inp", base +
                                                              "*MPC\nBEAM,1,2\n"  // line 15
                                                              "*CLOAD\n3,3,100.\n"
                                                              "*DASHPOT, ELSET=P\n1.\n"
                                                              "*MPC\nBEAM,1,3\n");
  const std::string m = InputErrorOf([&] { ReadAbaqus(path); });
  testing::ExpectContains(m, {"unsupported.inp:15: *MPC: 2 keyword types are not supported and would change the "
                              "stiffness or mass of the model: *MPC (x2, first at ",
                              "*DASHPOT (x1, at "},
                          m);
  EXPECT_EQ(m.find("CLOAD"), std::string::npos) << m;
  WarningCapture w;
  const std::string loads = WriteScratch("loads.inp", base + "*CLOAD\n3,3,100.\n*DLOAD\nP,P,1.\n*CLOAD\n4,3,1.\n");
  ReadAbaqus(loads);
  EXPECT_EQ(w.Count("skipped keywords (they do not change the stiffness or mass): *CLOAD (x2, first at "), 1);
  EXPECT_EQ(w.Count("*DLOAD (x1, at "), 1);
  EXPECT_EQ(w.messages.size(), 1u);
}

// a parameter flexmb does not know on a keyword it reads is an error
// naming it (a misspelling, or an option that would change the model, such
// as a coupling in a local orientation); on other keywords (loads, output)
// parameters are not checked
TEST(AbaqusReader, UnknownParametersAreErrors) {
  const std::string base =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0.5,0.5,1\n"
      "*ELEMENT, TYPE=S4, ELSET=P\n1,1,2,3,4\n*MATERIAL, NAME=M\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850\n";
  const std::string good = WriteScratch(
      "params_good.inp", base + "*Shell Section, elset=P, material=M, section integration=SIMPSON\n0.01\n"
                                "*CLOAD, OP=NEW, WHATEVER=1\n3,3,100.\n");
  EXPECT_EQ(ReadAbaqus(good).elements.size(), 1u);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"*SHELL SECTION, ELSET=P, MATERIAL=M, OFSET=0.5\n0.01\n", "*SHELL SECTION: unknown parameter OFSET=0.5"},
      {"*SHELL SECTION, ELSET=P, MATERIAL=M\n0.01\n*SURFACE, NAME=S, TYPE=ELEMENT\n1, SPOS\n"
       "*COUPLING, REF NODE=5, SURFACE=S, CONSTRAINT NAME=C, ORIENTATION=OR1\n*KINEMATIC\n",
       "*COUPLING: unknown parameter ORIENTATION=OR1 (flexmb knows REFNODE, SURFACE, CONSTRAINTNAME)"},
      {"*SHELL SECTION, ELSET=P, MATERIAL=M\n0.01\n*NSET, NSET=A, FREQUENCY=100\n1\n",
       "*NSET: unknown parameter FREQUENCY=100"},
      {"*SHELL SECTION, ELSET=P, MATERIAL=M\n0.01\n*SYSTEM, R\n", "*SYSTEM: unknown parameter R (this keyword takes none)"},
  };
  int k = 0;
  for (const auto& [cards, message] : cases) {
    const std::string path = WriteScratch("params_bad" + std::to_string(k++) + ".inp", base + cards);
    testing::ExpectContains(InputErrorOf([&] { ReadAbaqus(path); }), {path + ":", message}, cards);
  }
}

TEST(AbaqusReader, SectionsByMassProperties) {
  const Mesh m = ReadAbaqus(FeData("abaqus/sections.inp"));
  ASSERT_EQ(m.elements.size(), 12u);
  const double steel = 7850.0, alu = 2700.0;
  // beam sections, closed forms (section 1-axis = element y = n1)
  ASSERT_EQ(m.beam_sections.size(), 6u);
  const fe::BeamSection& rect = m.beam_sections[0];
  ExpectRel(rect.A, 0.1 * 0.05);
  ExpectRel(rect.Iy, 0.1 * std::pow(0.05, 3) / 12.0);
  ExpectRel(rect.Iz, 0.05 * std::pow(0.1, 3) / 12.0);
  // Timoshenko & Goodier, Theory of Elasticity, torsion of a 2:1 rectangle:
  // J = 0.229 a b^3, to the table's three digits
  EXPECT_NEAR(rect.J / (0.1 * std::pow(0.05, 3)), 0.229, 0.0005);
  ExpectRel(rect.ky, 10.0 * 1.3 / (12.0 + 11.0 * 0.3));  // Cowper (1966)
  EXPECT_EQ(m.elements[2].orientation, Vec3(0.0, 1.0, 0.0));
  const fe::BeamSection& circ = m.beam_sections[1];
  ExpectRel(circ.A, kPi * 0.02 * 0.02);
  ExpectRel(circ.J, kPi * std::pow(0.02, 4) / 2.0);
  EXPECT_EQ(circ.material, 1);
  const fe::BeamSection& pipe = m.beam_sections[2];
  ExpectRel(pipe.A, kPi * (0.05 * 0.05 - 0.045 * 0.045));
  ExpectRel(pipe.Iy, kPi * (std::pow(0.05, 4) - std::pow(0.045, 4)) / 4.0);
  const fe::BeamSection& box = m.beam_sections[3];
  ExpectRel(box.A, 0.1 * 0.06 - 0.09 * 0.052);
  ExpectRel(box.Iy, (0.1 * std::pow(0.06, 3) - 0.09 * std::pow(0.052, 3)) / 12.0);
  ExpectRel(box.Iz, (0.06 * std::pow(0.1, 3) - 0.052 * std::pow(0.09, 3)) / 12.0);
  // Bredt: J = 4 Am^2 / (sum of wall length / thickness) on the mid-line
  ExpectRel(box.J, 4.0 * std::pow(0.095 * 0.056, 2) / (2.0 * 0.095 / 0.004 + 2.0 * 0.056 / 0.005));
  EXPECT_EQ(m.elements[6].orientation, Vec3(0.0, 0.0, -1.0));  // Abaqus default n1
  const fe::BeamSection& gen = m.beam_sections[4];
  EXPECT_EQ(gen.A, 0.002);
  EXPECT_EQ(gen.Iy, 1.0e-6);
  EXPECT_EQ(gen.Iyz, 1.0e-7);
  EXPECT_EQ(gen.Iz, 2.0e-6);
  EXPECT_EQ(gen.J, 1.5e-6);
  EXPECT_EQ(gen.ky, 0.0);  // B33: Euler-Bernoulli
  const fe::Material& gm = m.materials[gen.material];
  EXPECT_EQ(gm.E, 2.0e11);
  EXPECT_EQ(gm.G, 8.0e10);
  EXPECT_EQ(gm.rho, 1000.0);
  const fe::BeamSection& gen2 = m.beam_sections[5];
  EXPECT_EQ(gen2.material, 1);
  const double g_alu = 7.0e10 / (2.0 * 1.33);
  EXPECT_DOUBLE_EQ(gen2.kz, 1.0e8 / (g_alu * 0.003));  // K23
  EXPECT_DOUBLE_EQ(gen2.ky, 2.0e8 / (g_alu * 0.003));  // K13
  // lumped mass with the rotary inertia of the ROTARYI element on its node
  ASSERT_EQ(m.point_masses.size(), 1u);
  EXPECT_EQ(m.point_masses[0].mass, 5.0);
  fe::Mat3 inertia;
  inertia << 1.0, 0.1, 0.2, 0.1, 2.0, 0.3, 0.2, 0.3, 3.0;
  EXPECT_EQ(m.point_masses[0].inertia, inertia);

  // total mass and centre of mass, part by part
  struct Part {
    double mass;
    Vec3 c;
  };
  const std::vector<Part> parts = {
      {steel * 2.0 * 1.0 * 0.01, {1.0, 0.5, 0.0}},                                  // plate
      {steel * 0.005 * 2.0, {1.0, 0.0, 1.0}},                                      // RECT
      {alu * kPi * 0.0004, {0.0, 2.5, 0.0}},                                       // CIRC
      {steel * kPi * (0.0025 - 0.045 * 0.045), {3.0, 0.0, 0.5}},                   // PIPE
      {alu * (0.006 - 0.09 * 0.052), {0.5, 5.0, 0.0}},                             // BOX
      {1000.0 * 0.002, {0.5, 6.0, 0.0}},                                           // GENERAL, DENSITY=
      {alu * 0.003, {0.5, 7.0, 0.0}},                                              // GENERAL, MATERIAL=
      {steel * 1e-3, {5.05, 0.05, 0.05}},                                          // cube
      {alu * 0.027 / 6.0, {6.075, 0.075, 0.075}},                                  // tet10
      {alu * 0.216 / 6.0, {7.15, 0.15, 0.15}},                                     // tet4
      {5.0, {10.0, 0.0, 0.0}}};                                                    // MASS
  double mass = 0.0;
  Vec3 moment = Vec3::Zero();
  for (const Part& p : parts) {
    mass += p.mass;
    moment += p.mass * p.c;
  }
  const fe::MassProperties mp = fe::ComputeMassProperties(m, fe::Assemble(m));
  EXPECT_NEAR(mp.mass / mass, 1.0, 1e-12);
  EXPECT_LT((mp.center - moment / mass).norm(), 1e-11);
}

// A mesh built in memory with every feature the writer supports; ids are
// positions + 1 (as the reader numbers materials and sections).
Mesh FeatureMesh() {
  Mesh m;
  m.source = "memory";
  auto node = [&](double x, double y, double z) {
    fe::Node n;
    n.id = 10 * static_cast<int>(m.nodes.size()) + 7;
    n.x = Vec3(x, y, z) / 3.0;  // coordinates that are not short decimals
    m.nodes.push_back(n);
    return static_cast<int>(m.nodes.size()) - 1;
  };
  auto element = [&](ElementType t, int property, std::vector<int> nodes) {
    fe::Element e;
    e.id = 100 + 3 * static_cast<int>(m.elements.size());
    e.type = t;
    e.property = property;
    e.nodes = std::move(nodes);
    m.elements.push_back(std::move(e));
    return static_cast<int>(m.elements.size()) - 1;
  };
  fe::Material steel;
  steel.id = 1;
  steel.name = "Steel";
  steel.E = 2.1e11;
  steel.nu = 0.3;
  steel.G = steel.E / (2.0 * (1.0 + steel.nu));
  steel.rho = 7850.0;
  fe::Material alu = steel;
  alu.id = 2;
  alu.name = "ALU-6061";
  alu.E = 6.9e10;
  alu.nu = 0.33;
  alu.G = alu.E / (2.0 * (1.0 + alu.nu));
  alu.rho = 2700.0;
  m.materials = {steel, alu};
  m.shell_sections.push_back({1, 0, 0.01, 0.0, {}});
  m.shell_sections.push_back({2, 1, 0.004, 0.0, {}});
  fe::BeamSection b;
  b.id = 1;
  b.material = 0;
  b.A = 1.1e-3;
  b.Iy = 2.3e-7;
  b.Iz = 4.1e-7;
  b.Iyz = 1.3e-8;
  b.J = 3.7e-7;
  b.ky = 0.85;
  b.kz = 0.6;
  m.beam_sections.push_back(b);
  b.id = 2;
  b.material = 1;
  b.ky = b.kz = 0.0;
  m.beam_sections.push_back(b);
  m.solid_sections.push_back({1, 0, {}});
  m.solid_sections.push_back({2, 1, {}});

  // hex8 (steel), tet4 and tet10 (aluminium)
  std::vector<int> hex;
  for (const Vec3& c : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 1),
                        Vec3(1, 1, 1), Vec3(0, 1, 1)})
    hex.push_back(node(c.x(), c.y(), c.z()));
  element(ElementType::kHex8, 0, hex);
  const int t0 = node(2, 0, 0), t1 = node(3, 0, 0), t2 = node(2, 1, 0), t3 = node(2, 0, 1);
  element(ElementType::kTet4, 1, {t0, t1, t2, t3});
  std::vector<int> tet10;
  const Vec3 c[4] = {{4, 0, 0}, {5, 0, 0}, {4, 1, 0}, {4, 0, 1}};
  for (const Vec3& p : c) tet10.push_back(node(p.x(), p.y(), p.z()));
  const auto& edges = flexmb::fe::kTet10EdgeCorners;
  for (const auto& e : edges) {
    const Vec3 p = 0.5 * (c[e[0]] + c[e[1]]);
    tet10.push_back(node(p.x(), p.y(), p.z()));
  }
  element(ElementType::kTet10, 1, tet10);
  // shells: two quads (one offset), a triangle in another section
  const int q0 = node(0, 2, 0), q1 = node(1, 2, 0), q2 = node(2, 2, 0), q3 = node(0, 3, 0), q4 = node(1, 3, 0),
            q5 = node(2, 3, 0);
  element(ElementType::kQuad4, 0, {q0, q1, q4, q3});
  const int offset_quad = element(ElementType::kQuad4, 0, {q1, q2, q5, q4});
  m.elements[offset_quad].shell_offset = 0.003;
  element(ElementType::kTria3, 1, {q3, q4, node(0, 4, 0)});
  // beams: shear-flexible and Euler-Bernoulli, two orientations
  const int b0 = node(0, 6, 0), b1 = node(1, 6, 0), b2 = node(2, 6, 0), b3 = node(3, 6, 0);
  const int e0 = element(ElementType::kBeam2, 0, {b0, b1});
  const int e1 = element(ElementType::kBeam2, 0, {b1, b2});
  const int e2 = element(ElementType::kBeam2, 1, {b2, b3});
  m.elements[e0].orientation = m.elements[e1].orientation = Vec3(0.0, 0.0, 1.0);
  m.elements[e2].orientation = Vec3(0.0, 1.0, 1.0);
  // point masses, rigid links, constraints
  fe::PointMass pm;
  pm.id = 900;
  pm.node = b3;
  pm.mass = 12.5;
  pm.inertia << 0.4, 0.01, 0.02, 0.01, 0.5, 0.03, 0.02, 0.03, 0.6;
  m.point_masses.push_back(pm);
  pm.id = 901;
  pm.node = q2;
  pm.mass = 1.25;
  pm.inertia.setZero();
  m.point_masses.push_back(pm);
  const int ref1 = node(5, 5, 5), ref2 = node(6, 6, 6);
  m.rigid_links.push_back({1, ref1, {t1, t2, t3}, 0b111111, {}});
  m.rigid_links.push_back({2, ref2, {hex[6], hex[7]}, 0b000111, {}});
  m.constraints.push_back({hex[0], 0b000111, {}});
  m.constraints.push_back({b0, 0b111111, {}});
  m.constraints.push_back({q0, 0b101101, {}});
  m.node_sets["clamp"] = {hex[0], hex[1], hex[2], hex[3]};
  m.node_sets["beam nodes"] = {b0, b1, b2, b3};
  m.element_sets["SHELLS"] = {3, 4, 5};
  m.element_sets["empty"] = {};
  m.IndexNodes();
  return m;
}

// Everything of b that the writer carries equals a (coordinates bit for
// bit; shear factors via k G A and back); b may add the writer's own sets
// (named flexmb_...).
void ExpectSameMesh(const Mesh& a, const Mesh& b) {
  testing::MeshMatch tol;
  tol.shell_offset = 1e-16;
  tol.shear = 4e-16;
  tol.writer_sets = "flexmb_";
  testing::ExpectSameMesh(a, b, tol);
}

TEST(AbaqusReader, WriteReadRoundTrip) {
  const Mesh original = FeatureMesh();
  const std::string path1 = testing::ScratchPath("round_trip_1.inp");
  WriteAbaqus(original, path1);
  const Mesh once = ReadAbaqus(path1);
  ExpectSameMesh(original, once);
  // writing what was read reproduces it, the writer's sets of the first
  // pass included (the second pass adds its own under new names)
  const std::string path2 = testing::ScratchPath("round_trip_2.inp");
  WriteAbaqus(once, path2);
  const Mesh twice = ReadAbaqus(path2);
  ExpectSameMesh(once, twice);
  // the same model: assembled matrices agree
  const fe::AssembledModel a = fe::Assemble(original), b = fe::Assemble(once);
  ASSERT_EQ(a.K.rows(), b.K.rows());
  EXPECT_LT((a.K - b.K).norm(), 1e-12 * a.K.norm());
  EXPECT_LT((a.M - b.M).norm(), 1e-12 * a.M.norm());
}

TEST(AbaqusReader, WriterRefusesWhatADeckCannotCarry) {
  const std::string path = testing::ScratchPath("refused.inp");
  struct Case {
    void (*change)(Mesh&);  // applied to FeatureMesh()
    const char* message;    // part of the writer's message
  };
  const Case cases[] = {
      {[](Mesh& m) { m.beam_sections[0].nsm = 0.5; }, "beam section 1: non-structural mass"},
      {[](Mesh& m) { m.materials[0].G = 7.0e10; }, "material Steel: shear modulus"},
      {[](Mesh& m) { m.point_masses[0].offset = Vec3(0.1, 0.0, 0.0); }, "point mass 900: an offset"},
      {[](Mesh& m) { m.elements[6].offset_a = Vec3(0.0, 0.01, 0.0); }, "beam end offsets"},
  };
  for (const Case& c : cases) {
    Mesh m = FeatureMesh();
    c.change(m);
    testing::ExpectContains(InputErrorOf([&] { WriteAbaqus(m, path); }), {c.message}, c.message);
  }
}

TEST(AbaqusReader, OtherHexFormulationsWarnOncePerType) {
  WarningCapture w;
  const std::string path = WriteScratch("c3d8r.inp",
                                        "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
                                        "*ELEMENT, TYPE=C3D8R, ELSET=A\n1,1,2,3,4,5,6,7,8\n"
                                        "*ELEMENT, TYPE=C3D8R, ELSET=A\n2,1,2,3,4,5,6,7,8\n"
                                        "*ELEMENT, TYPE=C3D8, ELSET=A\n3,1,2,3,4,5,6,7,8\n"
                                        "*ELEMENT, TYPE=C3D8I, ELSET=A\n4,1,2,3,4,5,6,7,8\n"
                                        "*MATERIAL, NAME=M\n*ELASTIC\n1e9, 0.3\n*SOLID SECTION, ELSET=A, MATERIAL=M\n");
  const Mesh m = ReadAbaqus(path);
  EXPECT_EQ(m.elements.size(), 4u);
  // C3D8R: the incompatible-mode hexahedron, with one warning; C3D8:
  // CalculiX's plain full integration (no Abaqus/CAE line), with one
  // warning that says which; C3D8I: the incompatible modes, without a word
  EXPECT_EQ(w.Count("C3D8R elements are read as"), 1);
  EXPECT_EQ(w.Count("C3D8 elements are read as CalculiX's C3D8 (plain 2 x 2 x 2 integration)"), 1);
  EXPECT_EQ(w.messages.size(), 2u);
  EXPECT_NE(w.messages[0].find("c3d8r.inp:10"), std::string::npos);
  EXPECT_EQ(m.elements[0].type, ElementType::kHex8);
  EXPECT_EQ(m.elements[2].type, fe::kHex8Full);
  EXPECT_EQ(m.elements[3].type, ElementType::kHex8);
  // the same deck as Abaqus/CAE writes it: Abaqus's C3D8
  const std::string cae = WriteScratch("c3d8_cae.inp", "** Generated by: Abaqus/CAE 2021\n" + testing::ReadText(path));
  WarningCapture w2;
  const Mesh mc = ReadAbaqus(cae);
  EXPECT_EQ(mc.elements[2].type, fe::kHex8Selective);
  EXPECT_EQ(mc.elements[0].type, ElementType::kHex8);
  EXPECT_EQ(w2.Count("read as Abaqus's C3D8 (selectively reduced"), 1);
  // written back, it stays Abaqus's (the writer writes the Abaqus/CAE line)
  const std::string again = testing::ScratchPath("c3d8_cae_again.inp");
  WriteAbaqus(mc, again);
  EXPECT_EQ(ReadAbaqus(again).elements[2].type, fe::kHex8Selective);
  // CalculiX's and Abaqus's C3D8 in one mesh cannot be written
  Mesh mixed = mc;
  mixed.elements[1].type = fe::kHex8Full;
  testing::ExpectContains(InputErrorOf([&] { WriteAbaqus(mixed, testing::ScratchPath("mixed.inp")); }),
                          {"both CalculiX's C3D8", "Abaqus's"}, "mixed");
  // a path or another comment naming Abaqus/CAE is no Abaqus/CAE header
  const std::string other = WriteScratch("c3d8_other.inp", "** from abaqus/cae_models/x.inp\n" + testing::ReadText(path));
  EXPECT_EQ(ReadAbaqus(other).elements[2].type, fe::kHex8Full);
}

TEST(AbaqusReader, KinematicCouplingOnAnElementSurface) {
  const std::string path = WriteScratch(
      "coupling.inp",
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n9,0.5,0.5,2\n"
      "*ELEMENT, TYPE=C3D8I, ELSET=A\n1,1,2,3,4,5,6,7,8\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1e9, 0.3\n*SOLID SECTION, ELSET=A, MATERIAL=M\n"
      "*SURFACE, NAME=TOP, TYPE=ELEMENT\nA, S2\n"
      "*COUPLING, REF NODE=9, SURFACE=TOP, CONSTRAINT NAME=C1\n*KINEMATIC\n1, 3\n6\n"
      "*NSET, NSET=BOTTOM\n1, 2\n*RIGID BODY, REF NODE=9, PIN NSET=BOTTOM\n");
  const Mesh m = ReadAbaqus(path);
  ASSERT_EQ(m.rigid_links.size(), 2u);
  EXPECT_EQ(m.rigid_links[0].independent, 8);
  EXPECT_EQ(Ids(m, m.rigid_links[0].dependent), (std::vector<int>{5, 8, 7, 6}));  // face S2 of a C3D8
  EXPECT_EQ(m.rigid_links[0].dofs, 0b100111);
  EXPECT_EQ(Ids(m, m.rigid_links[1].dependent), (std::vector<int>{1, 2}));
  EXPECT_EQ(m.rigid_links[1].dofs, 0b000111);
  EXPECT_EQ(m.rigid_links[1].id, 2);
}

// A deck written by gmsh 4.8 (tests/data/fe/abaqus/make_gmsh_box.sh), with
// material and section added by an including deck: the mass of the tet10
// mesh is exactly rho times the box volume.
TEST(AbaqusReader, GmshDeckThroughInclude) {
  const Mesh m = ReadAbaqus(FeData("abaqus/gmsh_box_model.inp"));
  EXPECT_GT(m.elements.size(), 10u);
  for (const fe::Element& e : m.elements) EXPECT_EQ(e.type, ElementType::kTet10);
  const fe::MassProperties mp = fe::ComputeMassProperties(m, fe::Assemble(m));
  EXPECT_NEAR(mp.mass, 7850.0 * 0.3 * 0.1 * 0.05, 1e-10);
  EXPECT_LT((mp.center - Vec3(0.15, 0.05, 0.025)).norm(), 1e-12);
  EXPECT_EQ(m.element_sets.at("PART").size(), m.elements.size());
}

const char* const kNodes = "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n";

// each case: file, ":line:" after its path, the entity ("ENTITY: ") and
// part of the message
TEST(AbaqusReader, BadInputNamesFileLineAndEntity) {
  const std::string nodes = kNodes;
  const std::string mat = "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n";
  const std::string shell = "*ELEMENT, TYPE=S4, ELSET=P\n1, 1, 2, 3, 4\n";
  const std::string section = "*SHELL SECTION, ELSET=P, MATERIAL=STEEL\n0.01\n";
  const std::string ok = nodes + shell + mat + section;
  testing::ExpectBadFiles(
      {
          {"unknown_type.inp", nodes + "*ELEMENT, TYPE=C3D27, ELSET=P\n1, 1, 2, 3, 4\n", ":6:",
           {"*ELEMENT: ", "unknown or unsupported element type C3D27"}},
          {"missing_material.inp", nodes + shell + "*SHELL SECTION, ELSET=P, MATERIAL=ALU\n0.01\n", ":8:",
           {"*SHELL SECTION (ELSET=P): ", "material 'ALU' is not defined"}},
          {"dangling_node.inp", nodes + "*ELEMENT, TYPE=S4, ELSET=P\n1, 1, 2, 3, 99\n", ":7:",
           {"S4 element 1: ", "node 99 does not exist"}},
          {"duplicate_node.inp", nodes + "2, 5, 5, 5\n", ":6:", {"node 2: ", "duplicate node id (first defined at"}},
          {"bad_number.inp", "*NODE\n1,0,0,0\n2,1.0.0,0,0\n", ":3:",
           {"node 2: ", "expected a number for x, got '1.0.0'"}},
          {"missing_section.inp", nodes + shell + mat, ":7:", {"4-node shell element 1: ", "no section is assigned"}},
          {"unknown_set.inp", ok + "*BOUNDARY\nFIXX, 1, 6\n", ":14:", {"*BOUNDARY: ", "unknown node set 'FIXX'"}},
          {"nonzero_boundary.inp", ok + "*BOUNDARY\n1, 1, 3, 0.001\n", ":14:",
           {"*BOUNDARY: ", "prescribed value 0.001: only zero"}},
          {"duplicate_element.inp", nodes + shell + "1, 2, 3, 4, 1\n", ":8:",
           {"S4 element 1: ", "duplicate element id (first defined at"}},
          {"wrong_node_count.inp", nodes + "*ELEMENT, TYPE=S4, ELSET=P\n1, 1, 2, 3\n", ":7:",
           {"S4 element 1: ", "expected 4 node ids, found 3"}},
          {"generate_gap.inp", nodes + "*NSET, NSET=ALL, GENERATE\n1, 9, 2\n", ":7:",
           {"*NSET ALL: ", "node 5 does not exist"}},
          {"unterminated_step.inp", ok + "*STEP\n*FREQUENCY\n5\n", ":13:", {"*STEP: ", "no *END STEP"}},
          {"elastic_outside.inp", nodes + "*ELASTIC\n2e11, 0.3\n", ":6:", {"*ELASTIC: ", "outside a *MATERIAL"}},
          {"missing_include.inp", "*INCLUDE, INPUT=no_such_file.inp\n", ":1:", {"*INCLUDE: ", "does not exist"}},
          {"self_include.inp", "*INCLUDE, INPUT=self_include.inp\n", ":1:", {"*INCLUDE: ", "nested deeper than"}},
          {"negative_density.inp", "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*DENSITY\n-1.\n", ":5:",
           {"material STEEL: ", "density must not be negative"}},
          {"shell_on_solid.inp",
           "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n*ELEMENT, TYPE=C3D4, ELSET=P\n1, 1, 2, 3, 4\n" + mat + section,
           ":11:", {"*SHELL SECTION (ELSET=P): ", "is not a shell element"}},
          {"bad_dof.inp", ok + "*BOUNDARY\n1, 7\n", ":14:",
           {"*BOUNDARY: ", "first degree of freedom 7 is out of range"}},
      },
      [](const std::string& path) { ReadAbaqus(path); });
}

// SECTION=CIRC: one value is the radius (Abaqus), with one warning that
// CalculiX means the diameter; two values (CalculiX's ellipse) and OFFSETk
// on a CIRC (a CalculiX deck) are errors
TEST(AbaqusReader, CircSectionConventions) {
  const std::string base = "*NODE\n1,0,0,0\n2,1,0,0\n*ELEMENT, TYPE=B31, ELSET=B\n1,1,2\n*MATERIAL, NAME=M\n*ELASTIC\n"
                           "2.1e11, 0.3\n";
  WarningCapture w;
  const Mesh m = ReadAbaqus(WriteScratch("circ.inp", base + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n0.02\n"));
  EXPECT_NEAR(m.beam_sections[0].A, kPi * 0.0004, 1e-15);
  EXPECT_EQ(w.Count("SECTION=CIRC 0.02 is read as the radius (Abaqus); CalculiX reads it as the diameter"), 1);
  const std::string two = WriteScratch("circ2.inp", base + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n0.02, 0.03\n");
  testing::ExpectContains(InputErrorOf([&] { ReadAbaqus(two); }), {"circ2.inp:10", "elliptical section"}, "two values");
  const std::string off =
      WriteScratch("circ3.inp", base + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC, OFFSET1=0.5\n0.02\n0., 0., 1.\n");
  testing::ExpectContains(InputErrorOf([&] { ReadAbaqus(off); }), {"circ3.inp:9", "OFFSET1 / OFFSET2", "PIPE"}, "offset");
}

}  // namespace
}  // namespace flexmb::io
