#include "flexmb/fe_io/gmsh_reader.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <set>
#include <tuple>

#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using fe::ElementType;
using fe::Mesh;
using fe::Vec3;
using testing::FeData;
using testing::InputErrorOf;
using testing::WriteScratch;

std::string Gmsh(const std::string& name) { return FeData("gmsh/" + name); }

int Count(const Mesh& m, ElementType t) {
  return static_cast<int>(std::count_if(m.elements.begin(), m.elements.end(), [t](const fe::Element& e) { return e.type == t; }));
}

// area of a planar quad or triangle from its corner coordinates (shoelace in 3D)
double Area(const Mesh& m, const fe::Element& e) {
  Vec3 twice = Vec3::Zero();
  const int n = static_cast<int>(e.nodes.size());
  for (int k = 0; k < n; ++k) twice += m.nodes[e.nodes[k]].x.cross(m.nodes[e.nodes[(k + 1) % n]].x);
  return 0.5 * twice.norm();
}

double TetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

// the strip of strip.geo: 41 x 3 nodes, 40 x 2 quads, 2 line elements on the clamped edge
void CheckStrip(const Mesh& m) {
  ASSERT_EQ(m.nodes.size(), 123u);
  EXPECT_EQ(Count(m, ElementType::kQuad4), 80);
  EXPECT_EQ(Count(m, ElementType::kBeam2), 2);
  EXPECT_EQ(m.elements.size(), 82u);  // the point element of "tip" is not an element
  double area = 0.0;
  for (const fe::Element& e : m.elements)
    if (e.type == ElementType::kQuad4) area += Area(m, e);
  EXPECT_NEAR(area, 1.0 * 0.05, 1e-12);
  for (const fe::Node& n : m.nodes) {
    EXPECT_GE(n.x.x(), -1e-15);
    EXPECT_LE(n.x.x(), 1.0 + 1e-15);
    EXPECT_EQ(n.x.z(), 0.0);
    EXPECT_EQ(m.NodeIndex(n.id), &n - m.nodes.data());
  }
  ASSERT_TRUE(m.element_sets.count("strip"));
  ASSERT_TRUE(m.element_sets.count("clamp"));
  EXPECT_EQ(m.element_sets.at("strip").size(), 80u);
  EXPECT_EQ(m.element_sets.at("clamp").size(), 2u);
  for (int e : m.element_sets.at("clamp")) EXPECT_EQ(m.elements[e].type, ElementType::kBeam2);
  EXPECT_EQ(m.element_sets.count("tip"), 0u);  // a point group gives a node set only
  ASSERT_EQ(m.node_sets.at("clamp").size(), 3u);
  for (int n : m.node_sets.at("clamp")) EXPECT_NEAR(m.nodes[n].x.x(), 0.0, 1e-15);
  ASSERT_EQ(m.node_sets.at("tip").size(), 1u);
  EXPECT_EQ(m.nodes[m.node_sets.at("tip")[0]].x, Vec3(1, 0, 0));
  EXPECT_EQ(m.node_sets.at("strip").size(), 123u);
  EXPECT_EQ(m.elements[m.element_sets.at("strip")[0]].origin.file, m.source);
  for (const fe::Element& e : m.elements) EXPECT_EQ(e.property, -1);
}

TEST(GmshReader, StripVersion41) { CheckStrip(ReadGmsh(Gmsh("strip_v41.msh"))); }
TEST(GmshReader, StripVersion22) { CheckStrip(ReadGmsh(Gmsh("strip_v22.msh"))); }

TEST(GmshReader, VersionsAgree) {
  for (const char* g : {"strip", "beam", "hex8", "tet10", "mixed"}) {
    SCOPED_TRACE(g);
    // both formats, written by gmsh from the same .geo, read to the same mesh
    const Mesh a = ReadGmsh(Gmsh(std::string(g) + "_v41.msh")), b = ReadGmsh(Gmsh(std::string(g) + "_v22.msh"));
    testing::ExpectSameNodes(a, b);
    testing::ExpectSameConnectivity(a, b, false);
    EXPECT_EQ(a.node_sets, b.node_sets);
    EXPECT_EQ(a.element_sets, b.element_sets);
  }
}

TEST(GmshReader, Tet10MidEdgeNodesFollowFlexmbOrder) {
  for (const char* f : {"tet10_v41.msh", "tet10_v22.msh"}) {
    const Mesh m = ReadGmsh(Gmsh(f));
    ASSERT_EQ(Count(m, ElementType::kTet10), 110) << f;
    // flexmb (Nastran) order: 5 on 1-2, 6 on 2-3, 7 on 3-1, 8 on 1-4, 9 on 2-4, 10 on 3-4
    const auto& edge = flexmb::fe::kTet10EdgeCorners;
    double volume = 0.0;
    for (const fe::Element& e : m.elements) {
      if (e.type != ElementType::kTet10) continue;
      auto x = [&](int k) { return m.nodes[e.nodes[k]].x; };
      for (int k = 0; k < 6; ++k)
        EXPECT_LT((x(4 + k) - 0.5 * (x(edge[k][0]) + x(edge[k][1]))).norm(), 1e-12) << f << " element " << e.id;
      const double v = TetVolume(x(0), x(1), x(2), x(3));
      EXPECT_GT(v, 0.0) << "element " << e.id;
      volume += v;
    }
    EXPECT_NEAR(volume, 0.4 * 0.2 * 0.1, 1e-14);
    // the face z = 0 (second-order triangles) is not read: only its nodes form the set
    EXPECT_EQ(m.element_sets.count("base"), 0u);
  }
}

TEST(GmshReader, Hex8AndUnnamedGroup) {
  const Mesh m = ReadGmsh(Gmsh("hex8_v41.msh"));
  EXPECT_EQ(Count(m, ElementType::kHex8), 6);
  EXPECT_EQ(m.element_sets.at("block").size(), 6u);
  EXPECT_EQ(m.element_sets.at("bottom").size(), 6u);
  ASSERT_TRUE(m.element_sets.count("group7"));  // physical surface 7 has no name
  EXPECT_EQ(m.element_sets.at("group7").size(), 2u);
  for (int n : m.node_sets.at("group7")) EXPECT_EQ(m.nodes[n].x.x(), 0.0);
  for (int n : m.node_sets.at("bottom")) EXPECT_EQ(m.nodes[n].x.z(), 0.0);
  for (const fe::Element& e : m.elements) {
    if (e.type != ElementType::kHex8) continue;
    auto x = [&](int k) { return m.nodes[e.nodes[k]].x; };
    // flexmb order: 1 2 3 4 counter-clockwise seen from 5 6 7 8 (positive Jacobian at node 1)
    EXPECT_GT((x(1) - x(0)).cross(x(3) - x(0)).dot(x(4) - x(0)), 0.0) << "element " << e.id;
  }
}

TEST(GmshReader, MixedTypesAndElementsInTwoGroups) {
  for (const char* f : {"mixed_v41.msh", "mixed_v22.msh"}) {
    SCOPED_TRACE(f);
    const Mesh m = ReadGmsh(Gmsh(f));
    EXPECT_EQ(Count(m, ElementType::kTria3), 22);
    EXPECT_EQ(Count(m, ElementType::kTet4), 101);
    // 4 stiffener lines in two groups count once (2.2 writes them twice, under new ids)
    EXPECT_EQ(Count(m, ElementType::kBeam2), 6);
    EXPECT_EQ(m.element_sets.at("stiffener").size(), 4u);
    EXPECT_EQ(m.element_sets.at("edges").size(), 6u);
    std::vector<int> common;
    std::set_intersection(m.element_sets.at("stiffener").begin(), m.element_sets.at("stiffener").end(),
                          m.element_sets.at("edges").begin(), m.element_sets.at("edges").end(),
                          std::back_inserter(common));
    EXPECT_EQ(common.size(), 4u);
    double area = 0.0;
    for (const fe::Element& e : m.elements)
      if (e.type == ElementType::kTria3) area += Area(m, e);
    EXPECT_NEAR(area, 0.2 * 0.1, 1e-14);
  }
}

TEST(GmshReader, BinaryFileIsRefused) {
  testing::ExpectContains(InputErrorOf([] { ReadGmsh(Gmsh("beam_binary.msh")); }),
                          {"beam_binary.msh:2: ", "binary .msh not supported, save as ASCII"}, "beam_binary.msh");
}

// a small valid 4.1 file whose lines are easy to count
const char* kSmall41 =
    "$MeshFormat\n"            // 1
    "4.1 0 8\n"                // 2
    "$EndMeshFormat\n"         // 3
    "$Nodes\n"                 // 4
    "1 4 1 4\n"                // 5
    "2 1 0 4\n"                // 6
    "1\n2\n3\n4\n"             // 7-10
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"  // 11-14
    "$EndNodes\n"              // 15
    "$Elements\n"              // 16
    "1 1 1 1\n"                // 17
    "2 1 3 1\n"                // 18
    "7 1 2 3 4\n"              // 19
    "$EndElements\n";          // 20

TEST(GmshReader, SmallFileReads) {
  const Mesh m = ReadGmsh(WriteScratch("small.msh", kSmall41));
  ASSERT_EQ(m.elements.size(), 1u);
  EXPECT_EQ(m.elements[0].id, 7);
  EXPECT_EQ(m.elements[0].origin.line, 19);
  EXPECT_EQ(m.nodes[2].origin.line, 13);
  EXPECT_TRUE(m.element_sets.empty());
}

// kSmall41 with the first occurrence of `from` replaced by `to`
std::string Small(const std::string& from, const std::string& to) { return testing::Replace(kSmall41, from, to); }

// each case: file, ":line: entity: " after its path, part of the message
TEST(GmshReader, BadInputNamesFileLineAndEntity) {
  testing::ExpectBadFiles(
      {
          {"dangling.msh", Small("7 1 2 3 4", "7 1 2 3 99"), ":19: element 7: ", {"node 99 does not exist"}},
          {"dupnode.msh", Small("1\n2\n3\n4\n", "1\n2\n3\n2\n"), ":14: node 2: ", {"duplicate node id"}},
          {"dupelem.msh", Small("1 1 1 1\n2 1 3 1\n7 1 2 3 4\n", "1 2 1 7\n2 1 3 2\n7 1 2 3 4\n7 2 3 4 1\n"),
           ":20: element 7: ", {"duplicate element id"}},
          {"type.msh", Small("2 1 3 1", "2 1 99 1"), ":18: ", {"gmsh element type 99 is not supported"}},
          {"quad9.msh", Small("2 1 3 1\n7 1 2 3 4", "2 1 10 1\n7 1 2 3 4 1 2 3 4 1"), ":19: element 7: ",
           {"gmsh element type 10 (9-node quadrangle) is not supported"}},
          {"count.msh", Small("7 1 2 3 4", "7 1 2 3"), ":19: element 7: ", {"has 4 nodes, got 3"}},
          {"nan.msh", Small("1 1 0\n0 1 0", "1 nan 0\n0 1 0"), ":13: node 3: ", {"y must be finite"}},
          {"text.msh", Small("1 1 0\n0 1 0", "1 1 0\n0 one 0"), ":14: node 4: ", {"expected a number for y"}},
          {"version.msh", Small("4.1 0 8", "3.0 0 8"), ":2: ", {"version 3.0 is not supported"}},
          {"short.msh", Small("$EndElements\n", ""), ":", {"expected $EndElements"}},
          {"fewer.msh", Small("1 4 1 4", "1 5 1 5"), ":5: ", {"4 nodes, the header announced 5"}},
          {"unclosed.msh", std::string(kSmall41) + "$Comments\nhello\n", ":21: ", {"$Comments is not closed"}},
          {"nosection.msh", "hello\n", ":1: ", {"not a gmsh .msh file"}},
          {"names.msh", Small("$Nodes\n", "$PhysicalNames\n1\n2 1 my name\n$EndPhysicalNames\n$Nodes\n"), ":6: ",
           {"physical name must be in double quotes"}},
          {"badtag.msh", Small("1\n2\n3\n4\n", "1\n2\n-3\n4\n"), ":9: ", {"node tag must be in [1, 2147483647]"}},
          {"empty.msh", "", ": ", {"empty file"}},
      },
      [](const std::string& path) { ReadGmsh(path); });
  // a file that does not exist
  testing::ExpectContains(InputErrorOf([] { ReadGmsh("/nonexistent/part.msh"); }),
                          {"/nonexistent/part.msh: cannot open"}, "part.msh");
}

TEST(GmshReader, Version22PhysicalTagZeroMeansNoGroup) {
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
      "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
      "$Elements\n2\n1 2 2 0 1 1 2 3\n2 1 2 5 1 1 2\n$EndElements\n";
  const Mesh m = ReadGmsh(WriteScratch("tags22.msh", text));
  ASSERT_EQ(m.elements.size(), 2u);
  EXPECT_EQ(m.element_sets.size(), 1u);
  EXPECT_EQ(m.element_sets.at("group5"), std::vector<int>{1});
  EXPECT_EQ(m.node_sets.at("group5"), (std::vector<int>{0, 1}));
}

}  // namespace
}  // namespace flexmb::io
