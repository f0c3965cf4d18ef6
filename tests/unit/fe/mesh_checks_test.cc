// fe::CheckMesh: which entries join nodes into one part (elements, scalar
// springs, rigid links, linear constraints; not point masses or SPCs), the
// supported flag, the order of the parts, unused nodes, and the warnings'
// count of rigid-body modes (6 per part without a support).
#include <gtest/gtest.h>

#include "flexmb/fe/elements/rod2.h"
#include "flexmb/fe/mesh_checks.h"

namespace flexmb::fe {
namespace {

// rods 0-1 and 2-3 (two parts), node 4 with a point mass, node 5 unused
Mesh TwoRods() {
  Mesh m;
  for (int k = 0; k < 6; ++k) {
    Node n;
    n.id = 10 + k;
    n.x = Vec3(k, 0, 0);
    m.nodes.push_back(n);
  }
  m.IndexNodes();
  for (int k = 0; k < 2; ++k) {
    Element e;
    e.id = 100 + k;
    e.type = kRod2;
    e.nodes = {2 * k, 2 * k + 1};
    m.elements.push_back(e);
  }
  PointMass pm;
  pm.node = 4;
  pm.mass = 1.0;
  m.point_masses.push_back(pm);
  return m;
}

TEST(MeshChecks, PartsJoinedByElementsSpringsLinksAndConstraintsOnly) {
  Mesh m = TwoRods();
  MeshCheck c = CheckMesh(m);
  ASSERT_EQ(c.parts.size(), 3u);
  EXPECT_EQ(c.parts[0].elements, 1);
  EXPECT_EQ(c.parts[0].first_element, 0);
  EXPECT_EQ(c.parts[1].first_element, 1);
  EXPECT_EQ(c.parts[2].elements, 0);  // the point mass's node
  EXPECT_EQ(c.parts[2].first_node, 4);
  ASSERT_EQ(c.unused_nodes.size(), 1u);
  EXPECT_EQ(c.unused_nodes[0], 5);

  // an SPC supports a part but joins nothing
  m.constraints.push_back(Constraint{1, 0b111111, {}});
  c = CheckMesh(m);
  ASSERT_EQ(c.parts.size(), 3u);
  EXPECT_TRUE(c.parts[0].supported);
  EXPECT_FALSE(c.parts[1].supported);
  const std::vector<std::string> w = MeshCheckWarnings(m, c, "m.bdf");
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("up to 12 rigid-body"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("(id 15)"), std::string::npos) << w[1];

  // a spring joins rod 1 to rod 2, a linear constraint the mass's node
  ScalarSpring s;
  s.node_a = 1;
  s.node_b = 2;
  s.k = 1.0;
  m.springs.push_back(s);
  LinearConstraint lc;
  lc.node = 4;
  lc.terms.push_back(MpcTerm{3, 0, 1.0});
  m.linear_constraints.push_back(lc);
  c = CheckMesh(m);
  ASSERT_EQ(c.parts.size(), 1u);
  EXPECT_EQ(c.parts[0].elements, 2);
  EXPECT_EQ(c.parts[0].nodes, 5);
  EXPECT_EQ(MeshCheckWarnings(m, c, "m.bdf").size(), 1u);  // the unused node only

  // a rigid link joins the unused node
  m.rigid_links.push_back(RigidLink{1, 0, {5}, 0b111111, {}});
  c = CheckMesh(m);
  EXPECT_EQ(c.parts.size(), 1u);
  EXPECT_TRUE(c.unused_nodes.empty());
  EXPECT_TRUE(MeshCheckWarnings(m, c, "m.bdf").empty());
}

TEST(MeshChecks, MeshWithoutElementsIsNotChecked) {
  Mesh m;
  m.nodes.resize(3);
  const MeshCheck c = CheckMesh(m);
  EXPECT_TRUE(c.parts.empty());
  EXPECT_TRUE(c.unused_nodes.empty());
}

}  // namespace
}  // namespace flexmb::fe
