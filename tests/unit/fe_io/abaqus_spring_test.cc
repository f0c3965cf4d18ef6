// Abaqus/CalculiX springs (SPRING1, SPRING2, SPRINGA with *SPRING) read
// into fe::ScalarSpring: the components and stiffness by hand, SPRINGA's
// direction from node 1 to node 2, the DOF line told from the stiffness
// line by its integers (CalculiX's rule), and the errors that name file,
// line and entity (NONLINEAR, ORIENTATION, a temperature table, the wrong
// number of DOF, a spring without *SPRING, coincident SPRINGA nodes).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::io {
namespace abaqus_spring_test {

const std::string kSpringNodes = "*NODE\n1, 0., 0., 0.\n2, 1., 2., 2.\n3, 2., 2., 2.\n";

TEST(AbaqusSprings, ThreeKindsReadAsScalarSprings) {
  const std::string deck = kSpringNodes +
                           "*ELEMENT, TYPE=SPRINGA, ELSET=SA\n1, 1, 2\n"
                           "*ELEMENT, TYPE=SPRING2, ELSET=S2\n2, 2, 3\n"
                           "*ELEMENT, TYPE=SPRING1, ELSET=S1\n3, 3\n"
                           "*SPRING, ELSET=SA\n\n1000.\n"
                           "*SPRING, ELSET=S2\n2, 3\n500.\n"
                           "*SPRING, ELSET=S1\n1\n3.e2\n";
  const fe::Mesh m = ReadAbaqus(testing::WriteScratch("springs.inp", deck));
  EXPECT_TRUE(m.elements.empty());
  ASSERT_EQ(m.springs.size(), 3u);
  const fe::ScalarSpring& a = m.springs[0];
  EXPECT_TRUE(a.directional);
  EXPECT_EQ(a.node_a, m.NodeIndex(1));
  EXPECT_EQ(a.node_b, m.NodeIndex(2));
  EXPECT_EQ(a.k, 1000.0);
  const double e[3] = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(a.coef_a[c], e[c], 1e-15);
    EXPECT_EQ(a.coef_b[c], a.coef_a[c]);
  }
  const fe::ScalarSpring& b = m.springs[1];
  EXPECT_FALSE(b.directional);
  EXPECT_EQ(b.component_a, 1);
  EXPECT_EQ(b.component_b, 2);
  EXPECT_EQ(b.node_b, m.NodeIndex(3));
  EXPECT_EQ(b.k, 500.0);
  const fe::ScalarSpring& c = m.springs[2];
  EXPECT_EQ(c.node_a, m.NodeIndex(3));
  EXPECT_EQ(c.node_b, -1);
  EXPECT_EQ(c.component_a, 0);
  EXPECT_EQ(c.k, 300.0);
  EXPECT_EQ(c.id, 3);
}

TEST(AbaqusSprings, BadSpringsNameFileLineAndEntity) {
  const std::string el = "*ELEMENT, TYPE=SPRING2, ELSET=S2\n2, 2, 3\n";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {el + "*SPRING, ELSET=S2, NONLINEAR\n2, 2\n0., 0.\n10., 1.\n", {"*SPRING (ELSET=S2)", "NONLINEAR"}},
      {el + "*SPRING, ELSET=S2, ORIENTATION=OR1\n2, 2\n10.\n", {"*SPRING (ELSET=S2)", "ORIENTATION"}},
      {el + "*SPRING, ELSET=S2\n2, 2\n10., , 20.\n12., , 100.\n", {"*SPRING (ELSET=S2)", "temperature"}},
      {el + "*SPRING, ELSET=S2\n2\n10.\n", {"SPRING2 element 2", "needs 2 degree(s) of freedom"}},
      {el + "*SPRING, ELSET=S2\n2, 7\n10.\n", {"*SPRING (ELSET=S2)", "degree of freedom"}},
      {el + "*SPRING, ELSET=S2\n2, 2\n-10.\n", {"must not be negative"}},
      {el, {"SPRING2 element 2", "no *SPRING is assigned"}},
      {"*ELEMENT, TYPE=SPRINGA, ELSET=SA\n1, 1, 1\n", {"SPRINGA element 1", "both nodes are the same"}},
  };
  int k = 0;
  for (const auto& [cards, parts] : cases) {
    const std::string path = testing::WriteScratch("spring_bad" + std::to_string(k++) + ".inp", kSpringNodes + cards);
    std::vector<std::string> with_file = parts;
    with_file.push_back(path + ":");
    testing::ExpectContains(testing::InputErrorOf([&] { ReadAbaqus(path); }), with_file, cards);
  }
}

}  // namespace abaqus_spring_test
}  // namespace flexmb::io
