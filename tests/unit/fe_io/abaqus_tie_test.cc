// Abaqus / CalculiX *TIE read into fe::LinearConstraint rows: a slave node
// above a bilinear master face gets the face's shape functions at its
// projection (computed here by hand), is moved onto the face unless
// ADJUST=NO, is tied only within the position tolerance (CalculiX's default
// 2.5 % of the master faces' edge length, or POSITION TOLERANCE=), a node
// beyond it is named in a warning, and a tie that ties nothing is an error;
// shells tie their rotations too unless NO ROTATION; malformed cards name
// what is wrong. The comparison with CalculiX is
// tests/validation/abaqus_tie_calculix_test.cc.

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "flexmb/common/log.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io::abaqus_tie_test {

using testing::ExpectContains;
using testing::InputErrorOf;
using testing::WriteScratch;

// one C3D8I unit cube (nodes 1-8; its face S4, nodes 2 6 7 3, is x = 1),
// node 9 near that face and node 10 beyond it
std::string Cube(const std::string& node9, const std::string& node10) {
  return "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n9," + node9 + "\n10," +
         node10 + "\n*ELEMENT, TYPE=C3D8I, ELSET=E\n1,1,2,3,4,5,6,7,8\n"
         "*MATERIAL, NAME=S\n*ELASTIC\n2.1e11,0.3\n*DENSITY\n7850.\n*SOLID SECTION, ELSET=E, MATERIAL=S\n"
         "*SURFACE, NAME=MASTER, TYPE=ELEMENT\n1, S4\n";
}

// coefficients of the rows of node `id`, component `c`: node id -> weight
std::map<int, double> Row(const fe::Mesh& m, int id, int c) {
  std::map<int, double> w;
  for (const fe::LinearConstraint& r : m.linear_constraints)
    if (r.node == m.NodeIndex(id) && r.component == c)
      for (const fe::MpcTerm& t : r.terms) {
        EXPECT_EQ(t.component, c);
        w[m.nodes[t.node].id] += t.coef;
      }
  return w;
}

TEST(AbaqusTie, SlaveNodeFollowsTheBilinearFaceAndIsMovedOntoIt) {
  const std::string tie = "*SURFACE, NAME=SLAVE, TYPE=NODE\n9\n*TIE, NAME=GLUE\nSLAVE, MASTER\n";
  const fe::Mesh m = ReadAbaqus(WriteScratch("tie.inp", Cube("1.0004, 0.25, 0.75", "3, 3, 3") + tie));
  ASSERT_EQ(m.linear_constraints.size(), 3u);  // translations only: solids carry none
  // (y, z) = (0.25, 0.75) on the face: (1 - y)(1 - z), (1 - y) z, y z, y (1 - z)
  const std::map<int, double> expected = {{2, 0.1875}, {6, 0.5625}, {7, 0.1875}, {3, 0.0625}};
  for (int c = 0; c < 3; ++c) {
    const std::map<int, double> w = Row(m, 9, c);
    ASSERT_EQ(w.size(), 4u) << "component " << c;
    for (const auto& [id, v] : expected) EXPECT_NEAR(w.at(id), v, 1e-14) << "node " << id << " component " << c;
  }
  EXPECT_EQ(m.linear_constraints[0].card, "*TIE GLUE");
  EXPECT_NEAR(m.nodes[m.NodeIndex(9)].x.x(), 1.0, 1e-15);  // adjusted
  EXPECT_EQ(m.nodes[m.NodeIndex(9)].x.y(), 0.25);

  const fe::Mesh kept = ReadAbaqus(WriteScratch(
      "tie_noadjust.inp", Cube("1.0004, 0.25, 0.75", "3, 3, 3") +
                              "*SURFACE, NAME=SLAVE, TYPE=NODE\n9\n*TIE, NAME=GLUE, ADJUST=NO\nSLAVE, MASTER\n"));
  EXPECT_EQ(kept.nodes[kept.NodeIndex(9)].x.x(), 1.0004);
  EXPECT_EQ(kept.linear_constraints.size(), 3u);
}

TEST(AbaqusTie, PositionToleranceDecidesWhichNodesAreTied) {
  // node 9 is 0.02 m off the face (within 2.5 % of the 1 m edges), node 10 0.03 m
  const std::string slaves = "*SURFACE, NAME=SLAVE, TYPE=NODE\n9\n10\n";
  std::vector<std::string> warnings;
  const LogSink old = SetWarningSink([&](const std::string& w) { warnings.push_back(w); });
  const fe::Mesh m =
      ReadAbaqus(WriteScratch("tie_tol.inp", Cube("1.02, 0.5, 0.5", "1.03, 0.5, 0.5") + slaves +
                                                 "*TIE, NAME=GLUE\nSLAVE, MASTER\n"));
  SetWarningSink(old);
  EXPECT_EQ(Row(m, 9, 0).size(), 4u);
  EXPECT_TRUE(Row(m, 10, 0).empty());
  ASSERT_EQ(warnings.size(), 1u);
  ExpectContains(warnings[0], {"tie_tol.inp:", "*TIE GLUE", "1 of 2 slave nodes are not tied", "0.025", ": 10"},
                 "warning");
  // a larger tolerance takes both
  const fe::Mesh wide = ReadAbaqus(WriteScratch(
      "tie_wide.inp", Cube("1.02, 0.5, 0.5", "1.03, 0.5, 0.5") + slaves +
                          "*TIE, NAME=GLUE, POSITION TOLERANCE=0.05\nSLAVE, MASTER\n"));
  EXPECT_EQ(Row(wide, 10, 0).size(), 4u);
  // beyond an edge by more than the tolerance: not tied; nothing tied is an error
  const std::string none = WriteScratch("tie_none.inp", Cube("1.0, 1.2, 0.5", "3, 3, 3") +
                                                           "*SURFACE, NAME=SLAVE, TYPE=NODE\n9\n"
                                                           "*TIE, NAME=GLUE\nSLAVE, MASTER\n");
  ExpectContains(InputErrorOf([&] { ReadAbaqus(none); }),
                 {none + ":", "*TIE GLUE", "no node of the slave surface 'SLAVE'", "0.025", "POSITION TOLERANCE="},
                 "nothing tied");
}

TEST(AbaqusTie, ShellsTieTheirRotationsUnlessNoRotation) {
  // master shell 1 (z = 0, unit square); shell 2's node 5 lies on it
  const std::string shells =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0.5,0.5,0\n6,0.5,0.5,1\n7,0.5,1.5,1\n8,0.5,1.5,0\n"
      "*ELEMENT, TYPE=S4, ELSET=E\n1,1,2,3,4\n2,5,6,7,8\n"
      "*MATERIAL, NAME=S\n*ELASTIC\n2.1e11,0.3\n*DENSITY\n7850.\n*SHELL SECTION, ELSET=E, MATERIAL=S\n0.01\n"
      "*SURFACE, NAME=MASTER, TYPE=ELEMENT\n1, SPOS\n*SURFACE, NAME=SLAVE, TYPE=NODE\n5\n";
  const fe::Mesh m = ReadAbaqus(WriteScratch("tie_shell.inp", shells + "*TIE, NAME=T\nSLAVE, MASTER\n"));
  ASSERT_EQ(m.linear_constraints.size(), 6u);
  EXPECT_NEAR(Row(m, 5, 4).at(3), 0.25, 1e-14);
  const fe::Mesh t = ReadAbaqus(WriteScratch("tie_shell_t.inp", shells + "*TIE, NAME=T, NO ROTATION\nSLAVE, MASTER\n"));
  EXPECT_EQ(t.linear_constraints.size(), 3u);
}

TEST(AbaqusTie, MalformedCardsNameTheProblem) {
  const std::string cube = Cube("1.0, 0.5, 0.5", "3, 3, 3") + "*SURFACE, NAME=SLAVE, TYPE=NODE\n9\n";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"*TIE\nSLAVE, MASTER\n", {"*TIE", "needs NAME="}},
      {"*TIE, NAME=A\nSLAVE, MASTER\n*TIE, NAME=a\nSLAVE, MASTER\n", {"*TIE a", "already defined at", ".inp:"}},
      {"*TIE, NAME=A, CYCLIC SYMMETRY\nSLAVE, MASTER\n", {"CYCLIC SYMMETRY is not supported"}},
      {"*TIE, NAME=A\nSLAVE, NOPE\n", {"unknown master surface 'NOPE'"}},
      {"*TIE, NAME=A\nNOPE, MASTER\n", {"unknown slave surface 'NOPE'"}},
      {"*TIE, NAME=A\nMASTER, SLAVE\n", {"'SLAVE' has no element faces"}},
      {"*TIE, NAME=A\nSLAVE, MASTER\nSLAVE, MASTER\n", {"exactly one data line"}},
      {"*TIE, NAME=A, ADJUST=MAYBE\nSLAVE, MASTER\n", {"ADJUST=MAYBE", "YES or NO"}},
      {"*TIE, NAME=A, POSITION TOLERANCE=-1\nSLAVE, MASTER\n", {"must not be negative"}},
  };
  int k = 0;
  for (const auto& [card, parts] : cases) {
    const std::string path = WriteScratch("tie_bad" + std::to_string(k++) + ".inp", cube + card);
    std::vector<std::string> with_file = parts;
    with_file.push_back(path + ":");
    ExpectContains(InputErrorOf([&] { ReadAbaqus(path); }), with_file, card);
  }
}

}  // namespace flexmb::io::abaqus_tie_test
