// WriteNastranBulk: what it writes ReadNastran reads back as the same model
// (reals to the 10 digits a 16-character field holds, short decimals bit for
// bit; the same assembled K and M to that precision), and what it cannot
// carry is refused, naming it.
#include <gtest/gtest.h>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/fe_io/nastran/nastran_writer.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::io::nastran_writer_test {
namespace {

using fe::ElementType;
using fe::Mesh;
using fe::Vec3;

// a bent plate of quads and triangles, two thicknesses (one with a
// non-structural mass), an offset element, a rigid spider to a node above
// it and a node set; coordinates that are not short decimals
Mesh ShellMesh() {
  Mesh m;
  m.source = "memory";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      fe::Node n;
      n.id = 11 + 4 * j + i;
      n.x = Vec3(0.37 * i / 3.0, 0.29 * j / 7.0, 0.05 * i * i / 9.0);
      m.nodes.push_back(n);
    }
  fe::Node top;
  top.id = 40;
  top.x = Vec3(0.2, 0.05, 0.3);
  m.nodes.push_back(top);
  fe::Material steel;
  steel.id = 3;
  steel.E = 2.1e11;
  steel.nu = 0.3;
  steel.G = steel.E / 2.6;
  steel.rho = 7850.0;
  m.materials = {steel};
  m.shell_sections.push_back({7, 0, 0.007, 147.2437017, {}});
  m.shell_sections.push_back({8, 0, 0.006, 0.0, {}});
  int eid = 1;
  auto element = [&](ElementType t, int property, std::vector<int> nodes, double offset = 0.0) {
    fe::Element e;
    e.id = eid++;
    e.type = t;
    e.property = property;
    e.nodes = std::move(nodes);
    e.shell_offset = offset;
    m.elements.push_back(e);
  };
  element(ElementType::kQuad4, 0, {0, 1, 5, 4});
  element(ElementType::kQuad4, 0, {1, 2, 6, 5}, 0.0035);
  element(ElementType::kQuad4, 1, {2, 3, 7, 6});
  element(ElementType::kTria3, 1, {4, 5, 9});
  element(ElementType::kTria3, 1, {4, 9, 8}, -0.003);
  element(ElementType::kQuad4, 0, {5, 6, 10, 9});
  element(ElementType::kQuad4, 1, {6, 7, 11, 10});
  fe::RigidLink spider;
  spider.id = 1;  // the same id as an element: the writer renumbers it
  spider.independent = 12;
  spider.dependent = {5, 6, 9, 10, 1, 2, 4, 7, 8};  // more than one line of grids
  m.rigid_links.push_back(spider);
  m.node_sets["edge"] = {0, 4, 8};
  m.IndexNodes();
  return m;
}

TEST(NastranWriter, ReadsBackAsTheSameModel) {
  const Mesh original = ShellMesh();
  NastranDeckExtras extras;
  extras.comments = {"a comment line"};
  extras.interface_nodes = {12, 3};
  const std::string path = testing::ScratchPath("written.bdf");
  WriteNastranBulk(original, path, extras);
  const Mesh back = ReadNastran(path);
  testing::ExpectSameNodes(original, back, 1e-10);  // 10 significant digits of coordinates below 1 m
  testing::ExpectSameConnectivity(original, back);
  ASSERT_EQ(back.elements.size(), original.elements.size());
  for (size_t k = 0; k < original.elements.size(); ++k)
    EXPECT_EQ(back.elements[k].shell_offset, original.elements[k].shell_offset) << k;
  ASSERT_EQ(back.shell_sections.size(), 2u);
  EXPECT_EQ(back.shell_sections[0].id, 7);
  EXPECT_EQ(back.shell_sections[0].nsm, 147.2437017);
  EXPECT_EQ(back.shell_sections[1].thickness, 0.006);
  ASSERT_EQ(back.rigid_links.size(), 1u);
  EXPECT_EQ(back.rigid_links[0].id, 8);  // after the largest element id
  EXPECT_EQ(back.rigid_links[0].independent, 12);
  EXPECT_EQ(back.rigid_links[0].dependent, original.rigid_links[0].dependent);
  EXPECT_EQ(back.rigid_links[0].dofs, 0b111111);
  EXPECT_EQ(back.node_sets.at("SET1_1"), (std::vector<int>{0, 4, 8}));
  EXPECT_EQ(back.node_sets.at("ASET"), (std::vector<int>{12, 3}));
  const fe::AssembledModel a = fe::Assemble(original), b = fe::Assemble(back);
  ASSERT_EQ(a.K.rows(), b.K.rows());
  EXPECT_LT((a.K - b.K).norm(), 1e-9 * a.K.norm());
  EXPECT_LT((a.M - b.M).norm(), 1e-9 * a.M.norm());
  EXPECT_NE(testing::ReadText(path).find("$ a comment line"), std::string::npos);
}

TEST(NastranWriter, ShortDecimalsBitForBitElseTenDigits) {
  Mesh m = ShellMesh();
  m.nodes[1].x = Vec3(-6.76, 0.43, 1.07);  // as the ladder frame's
  m.nodes[0].x = Vec3(-1.0 / 3.0 * 1e-7, 2.0 / 7.0 * 1e5, 1e-300);
  const std::string path = testing::ScratchPath("digits.bdf");
  WriteNastranBulk(m, path);
  const Mesh back = ReadNastran(path);
  testing::ExpectSameVec3(back.nodes[0].x, m.nodes[0].x, 1e-10 * m.nodes[0].x.norm(), "node 11");
  testing::ExpectSameVec3(back.nodes[1].x, m.nodes[1].x, 0.0, "node 12");
}

TEST(NastranWriter, RefusesWhatTheDeckWouldNotCarry) {
  const std::string path = testing::ScratchPath("refused.bdf");
  struct Case {
    void (*change)(Mesh&);
    const char* expected;
  };
  const Case cases[] = {
      {[](Mesh& m) { m.point_masses.push_back({}); }, "1 point masses"},
      {[](Mesh& m) { m.springs.push_back({}); }, "1 springs"},
      {[](Mesh& m) { m.beam_sections.push_back({}); }, "beam or solid sections"},
      {[](Mesh& m) { m.linear_constraints.push_back({}); }, "linear constraints"},
      {[](Mesh& m) { m.constraints.push_back({}); }, "single-point constraints"},
      {[](Mesh& m) { m.nodes[3].id = 0; }, "node id 0 is not positive"},
      {[](Mesh& m) { m.elements[2].type = ElementType::kHex8; }, "element 3 (8-node hexahedron: only 3- and 4-node shells are written)"},
      {[](Mesh& m) { m.nodes[1].x.x() = std::nan(""); }, "is not finite"},
  };
  for (const Case& c : cases) {
    Mesh m = ShellMesh();
    c.change(m);
    testing::ExpectContains(testing::InputErrorOf([&] { WriteNastranBulk(m, path); }), {c.expected}, c.expected);
  }
  EXPECT_NE(testing::InputErrorOf([&] { WriteNastranBulk(ShellMesh(), "/nonexistent/dir/x.bdf"); }).find("cannot write"),
            std::string::npos);
}

}  // namespace
}  // namespace flexmb::io::nastran_writer_test
