// RBAR, RBAR1 and RBE3 in the Nastran reader (nastran_rigid_elements.cc):
// an RBAR deck assembles to exactly the model of the equivalent RBE2 deck;
// RBE3 cards read to the rows of fe::Rbe3Constraints for the same groups;
// unsupported forms are errors naming file, line and fields.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/linear_constraint.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io::nastran_rigid_elements_test {

using testing::ExpectContains;
using testing::InputErrorOf;
using testing::WriteScratch;

// a clamped bar 1-2-3, an arm 4-5, and the card under test joining 3 and 4
std::string RigidDeck(const std::string& card) {
  return "BEGIN BULK\n"
         "MAT1,1,2.1E11,,0.3,7850.\n"
         "PBAR,1,1,3.E-4,2.E-8,3.E-8,4.E-8\n"
         "GRID,1,,0.,0.,0.\n"
         "GRID,2,,0.5,0.,0.\n"
         "GRID,3,,1.,0.,0.\n"
         "GRID,4,,1.2,0.3,0.1\n"
         "GRID,5,,1.6,0.3,0.1\n"
         "GRID,6,,1.2,0.5,-0.1\n"
         "CBAR,1,1,1,2,0.,1.,0.\n"
         "CBAR,2,1,2,3,0.,1.,0.\n"
         "CBAR,3,1,4,5,0.,1.,0.\n"
         "CONM2,10,5,,2.5\n"
         "CONM2,11,6,,1.5\n"
         "SPC1,1,123456,1\n" +
         card + "\nENDDATA\n";
}

fe::AssembledModel AssembleDeck(const std::string& name, const std::string& card) {
  return fe::Assemble(ReadNastran(WriteScratch(name, RigidDeck(card))));
}

void ExpectSameModel(const fe::AssembledModel& a, const fe::AssembledModel& b) {
  ASSERT_EQ(a.dofs.n_free, b.dofs.n_free);
  ASSERT_EQ(a.dofs.n_full, b.dofs.n_full);
  EXPECT_EQ(a.dofs.free, b.dofs.free);
  EXPECT_EQ(Eigen::MatrixXd(a.K), Eigen::MatrixXd(b.K));
  EXPECT_EQ(Eigen::MatrixXd(a.M), Eigen::MatrixXd(b.M));
  EXPECT_EQ(Eigen::MatrixXd(a.T), Eigen::MatrixXd(b.T));
}

TEST(NastranRigidElements, RbarIsTheEquivalentRbe2) {
  struct Case {
    const char* rbar;
    const char* rbe2;
  };
  const Case cases[] = {
      {"RBAR,7,3,4,123456", "RBE2,7,3,123456,4"},                 // CMA, CMB blank: all of GB dependent
      {"RBAR,7,3,4,123456,,,123456", "RBE2,7,3,123456,4"},
      {"RBAR,7,3,4,123456,0,0,135", "RBE2,7,3,135,4"},          // zero fields are blank
      {"RBAR,7,4,3,,123456,23", "RBE2,7,3,23,4"},                // the mirror: GB independent
      {"RBAR1,7,3,4,123", "RBE2,7,3,123,4"},
      {"RBAR1,7,3,4,,1.2E-5", "RBE2,7,3,123456,4"},             // CB blank: all six; ALPHA ignored
  };
  int k = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.rbar);
    const std::string n = std::to_string(k++);
    const fe::AssembledModel rbar = AssembleDeck("rbar" + n + ".bdf", c.rbar);
    const fe::AssembledModel rbe2 = AssembleDeck("rbe2" + n + ".bdf", c.rbe2);
    ExpectSameModel(rbar, rbe2);
    // the link is there: fewer free DOF than without it
    EXPECT_LT(rbar.dofs.n_free, rbar.dofs.n_full);
  }
}

TEST(NastranRigidElements, UnsupportedRbarFormsNameTheFields) {
  const std::string split = WriteScratch("rbar_split.bdf", RigidDeck("RBAR,7,3,4,123,456"));
  ExpectContains(InputErrorOf([&] { ReadNastran(split); }),
                 {split + ":16", "RBAR 7", "CNA = 123, CNB = 456, CMA = blank, CMB = blank", "not supported"}, "split");
  const std::string both = WriteScratch("rbar_both.bdf", RigidDeck("RBAR,7,3,4,123456,,1"));
  ExpectContains(InputErrorOf([&] { ReadNastran(both); }), {both + ":16", "RBAR 7", "CMA = 1"}, "CMA");
  const std::string same = WriteScratch("rbar_same.bdf", RigidDeck("RBAR1,7,3,3,123"));
  ExpectContains(InputErrorOf([&] { ReadNastran(same); }), {"RBAR1 7", "same grid point"}, "same");
}

TEST(NastranRigidElements, Rbe3ReadsToItsWeightedRows) {
  // two weight groups over a continuation, ALPHA at the end
  const fe::Mesh mesh = ReadNastran(WriteScratch(
      "rbe3.bdf", RigidDeck("GRID,30,,1.3,0.2,0.0\n"
                            "RBE3,20,,30,123456,1.0,123,3,4\n"
                            ",5,2.5,123456,6,ALPHA,1.1E-5")));
  ASSERT_EQ(mesh.linear_constraints.size(), 6u);
  fe::Rbe3Spec spec;
  spec.id = 20;
  spec.ref_node = mesh.NodeIndex(30);
  spec.ref_components = 0b111111;
  spec.groups = {{1.0, 0b111, {mesh.NodeIndex(3), mesh.NodeIndex(4), mesh.NodeIndex(5)}},
                 {2.5, 0b111111, {mesh.NodeIndex(6)}}};
  const std::vector<fe::LinearConstraint> expected = fe::Rbe3Constraints(mesh, spec);
  for (size_t r = 0; r < expected.size(); ++r) {
    const fe::LinearConstraint& row = mesh.linear_constraints[r];
    EXPECT_EQ(row.card, "RBE3");
    EXPECT_EQ(row.id, 20);
    EXPECT_EQ(row.node, spec.ref_node);
    EXPECT_EQ(row.component, expected[r].component);
    EXPECT_EQ(row.origin.line, 17);
    ASSERT_EQ(row.terms.size(), expected[r].terms.size());
    for (size_t t = 0; t < row.terms.size(); ++t) {
      EXPECT_EQ(row.terms[t].node, expected[r].terms[t].node);
      EXPECT_EQ(row.terms[t].component, expected[r].terms[t].component);
      EXPECT_EQ(row.terms[t].coef, expected[r].terms[t].coef);
    }
  }
  // it assembles: the reference DOF are dependent
  const fe::AssembledModel a = fe::Assemble(mesh);
  for (int c = 0; c < 6; ++c) EXPECT_EQ(a.dofs.free[mesh.NodeIndex(30)][c], -1);
}

TEST(NastranRigidElements, Rbe3BadCardsNameTheField) {
  struct Case {
    const char* card;
    std::vector<std::string> parts;
  };
  const Case cases[] = {
      {"RBE3,20,,6,123,1.0,123,3,4,5\n,UM,3,1", {":17", "RBE3 20", "UM", "not supported"}},
      {"RBE3,20,,6,123,1,123,3,4,5", {":16", "RBE3 20", "weight WTi expected"}},
      {"RBE3,20,,6,123,-1.0,123,3,4,5", {":16", "RBE3 20", "must be > 0"}},
      {"RBE3,20,,6,123,1.0,123,2.0,123,3", {":16", "RBE3 20", "has no grid points"}},
      {"RBE3,20,,6,123,1.0,123,1,2,3", {"RBE3 20", "cannot carry every rigid motion"}},
      {"RBE3,20,,6,123,1.0,123,99,4", {":16", "RBE3 20", "node 99 does not exist"}},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string path = WriteScratch("rbe3_bad" + std::to_string(k++) + ".bdf", RigidDeck(c.card));
    std::vector<std::string> parts = c.parts;
    if (parts[0][0] == ':') parts[0] = path + parts[0];
    ExpectContains(InputErrorOf([&] { ReadNastran(path); }), parts, c.card);
  }
}

}  // namespace flexmb::io::nastran_rigid_elements_test
