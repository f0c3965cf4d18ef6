// Abaqus / CalculiX linear constraints: *EQUATION read into
// fe::LinearConstraint rows (the first term dependent), *COUPLING with
// *DISTRIBUTING read as an RBE3 weighted by face area (CalculiX's rule,
// tests/validation/rbe3_calculix_test.cc), and the writer's *EQUATION
// read back to the same assembled model.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/linear_constraint.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"
#include "mesh_io_test_util.h"

namespace flexmb::io::abaqus_equation_test {

using testing::ExpectContains;
using testing::InputErrorOf;
using testing::ScratchPath;
using testing::WriteScratch;

// one C3D8 unit cube (nodes 1-8), a free node 9 beside its x = 1 face
const std::string kCube =
    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n9,1.5,0.5,0.5\n"
    "*ELEMENT, TYPE=C3D8, ELSET=E\n1,1,2,3,4,5,6,7,8\n"
    "*MATERIAL, NAME=S\n*ELASTIC\n2.1e11,0.3\n*DENSITY\n7850.\n*SOLID SECTION, ELSET=E, MATERIAL=S\n";

TEST(AbaqusEquation, FirstTermIsDependent) {
  const fe::Mesh m = ReadAbaqus(WriteScratch("equation.inp", kCube +
                                                                 "*EQUATION\n3\n9, 2, 2., 2, 2, -1., 3, 2, -1.\n"
                                                                 "4\n9, 1, -1., 2, 1, 0.25, 3, 1, 0.25, 6, 1, 0.5\n"));
  ASSERT_EQ(m.linear_constraints.size(), 2u);
  const fe::LinearConstraint& a = m.linear_constraints[0];
  EXPECT_EQ(a.node, m.NodeIndex(9));
  EXPECT_EQ(a.component, 1);
  ASSERT_EQ(a.terms.size(), 2u);
  EXPECT_EQ(a.terms[0].node, m.NodeIndex(2));
  EXPECT_EQ(a.terms[0].coef, 0.5);
  const fe::LinearConstraint& b = m.linear_constraints[1];
  EXPECT_EQ(b.component, 0);
  ASSERT_EQ(b.terms.size(), 3u);  // the fourth term on one line
  EXPECT_EQ(b.terms[2].node, m.NodeIndex(6));
  EXPECT_EQ(b.terms[2].coef, 0.5);
  // u_9y = (u_2y + u_3y) / 2 through T
  const fe::AssembledModel am = fe::Assemble(m);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(am.dofs.n_free);
  u[am.dofs.free[m.NodeIndex(2)][1]] = 1.0;
  u[am.dofs.free[m.NodeIndex(3)][1]] = 3.0;
  EXPECT_EQ((am.T * u)[am.dofs.full[m.NodeIndex(9)][1]], 2.0);

  const std::string bad = WriteScratch("equation_bad.inp", kCube + "*EQUATION\n3\n9, 2, 2., 2, 2, -1.\n");
  ExpectContains(InputErrorOf([&] { ReadAbaqus(bad); }), {bad + ":", "fewer terms than the 3 announced"}, "short");
}

TEST(AbaqusEquation, DistributingCouplingIsAnAreaWeightedRbe3) {
  const fe::Mesh m = ReadAbaqus(WriteScratch(
      "distributing.inp", kCube + "*SURFACE, NAME=TIP, TYPE=ELEMENT\n1, S4\n"
                                  "*COUPLING, REF NODE=9, SURFACE=TIP, CONSTRAINT NAME=C\n*DISTRIBUTING\n1, 6\n"));
  fe::Rbe3Spec spec;
  spec.ref_node = m.NodeIndex(9);
  spec.ref_components = 0b111111;
  // face S4 (nodes 2 6 7 3) of area 1: a quarter each
  for (int id : {2, 6, 7, 3}) spec.groups.push_back({0.25, 0b111, {m.NodeIndex(id)}});
  const std::vector<fe::LinearConstraint> expected = fe::Rbe3Constraints(m, spec);
  ASSERT_EQ(m.linear_constraints.size(), expected.size());
  for (size_t r = 0; r < expected.size(); ++r) {
    ASSERT_EQ(m.linear_constraints[r].terms.size(), expected[r].terms.size());
    for (size_t t = 0; t < expected[r].terms.size(); ++t) {
      EXPECT_EQ(m.linear_constraints[r].terms[t].node, expected[r].terms[t].node);
      EXPECT_EQ(m.linear_constraints[r].terms[t].coef, expected[r].terms[t].coef);
    }
  }
  const std::string cubic = WriteScratch(
      "distributing_cubic.inp", kCube + "*SURFACE, NAME=TIP, TYPE=ELEMENT\n1, S4\n"
                                        "*COUPLING, REF NODE=9, SURFACE=TIP\n*DISTRIBUTING, WEIGHTING METHOD=CUBIC\n");
  ExpectContains(InputErrorOf([&] { ReadAbaqus(cubic); }), {cubic + ":", "WEIGHTING METHOD=CUBIC is not supported"},
                 "cubic");
}

TEST(AbaqusEquation, WrittenRbe3ReadsBackToTheSameModel) {
  fe::Mesh m = ReadAbaqus(WriteScratch("rbe3_src.inp", kCube));
  fe::Rbe3Spec spec;
  spec.ref_node = m.NodeIndex(9);
  spec.ref_components = 0b111111;
  spec.groups = {{1.0, 0b111, {m.NodeIndex(2), m.NodeIndex(6)}}, {3.0, 0b111, {m.NodeIndex(7), m.NodeIndex(3)}}};
  m.linear_constraints = fe::Rbe3Constraints(m, spec);
  const std::string path = ScratchPath("rbe3_written.inp");
  WriteAbaqus(m, path);
  const fe::Mesh back = ReadAbaqus(path);
  ASSERT_EQ(back.linear_constraints.size(), 6u);
  const fe::AssembledModel a = fe::Assemble(m), b = fe::Assemble(back);
  ASSERT_EQ(a.dofs.free, b.dofs.free);
  EXPECT_LT((Eigen::MatrixXd(a.T) - Eigen::MatrixXd(b.T)).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((Eigen::MatrixXd(a.K) - Eigen::MatrixXd(b.K)).cwiseAbs().maxCoeff(), 1e-15 * Eigen::MatrixXd(a.K).cwiseAbs().maxCoeff());
}

}  // namespace flexmb::io::abaqus_equation_test
