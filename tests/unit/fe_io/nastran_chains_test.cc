// Design optimisation cards (DEQATN's free-text equations, DESVAR, DVPREL1,
// DRESP1, ...) are skipped with one warning, and chains of rigid elements
// (fe/constraint_chains.h) read to the model of the equivalent one-level
// links; a loop is an error naming its cards.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io::nastran_chains_test {

using testing::WriteScratch;

// a clamped bar 1-2-3 and nodes 4, 5, 6 off its tip with masses
std::string ChainDeck(const std::string& cards) {
  return "BEGIN BULK\n"
         "MAT1,1,2.1E11,,0.3,7850.\n"
         "PBAR,1,1,3.E-4,2.E-8,3.E-8,4.E-8\n"
         "GRID,1,,0.,0.,0.,,123456\nGRID,2,,0.5,0.,0.\nGRID,3,,1.,0.,0.\n"
         "GRID,4,,1.2,0.3,0.1\nGRID,5,,1.6,0.3,-0.2\nGRID,6,,1.3,-0.4,0.2\n"
         "CBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,3,0.,1.,0.\n"
         "CONM2,10,4,,2.5\n,0.1,0.,0.1,0.,0.,0.1\nCONM2,11,5,,1.5\n,0.1,0.,0.1,0.,0.,0.1\n"
         "CONM2,12,6,,1.\n,0.1,0.,0.1,0.,0.,0.1\n" +
         cards + "ENDDATA\n";
}

void ExpectSameModel(const fe::AssembledModel& a, const fe::AssembledModel& b) {
  ASSERT_EQ(a.dofs.n_free, b.dofs.n_free);
  EXPECT_EQ(a.dofs.free, b.dofs.free);
  const double ks = Eigen::MatrixXd(b.K).cwiseAbs().maxCoeff();
  EXPECT_LT((Eigen::MatrixXd(a.K) - Eigen::MatrixXd(b.K)).cwiseAbs().maxCoeff(), 1e-12 * ks);
  EXPECT_LT((Eigen::MatrixXd(a.M) - Eigen::MatrixXd(b.M)).cwiseAbs().maxCoeff(), 1e-12);
}

fe::AssembledModel ChainAssemble(const std::string& name, const std::string& cards) {
  return fe::Assemble(ReadNastran(WriteScratch(name, ChainDeck(cards))));
}

// RBE2 3 -> 4, then RBAR 4 -> 5 (CMB blank: all six), then RBE2 5 -> 6 (CM 126): the
// rigid motion of 3 carried to 4, 5 and 6 directly is the same model
TEST(NastranChains, ChainIsTheDirectLinks) {
  const fe::AssembledModel chain =
      ChainAssemble("chain.bdf", "RBE2,7,3,123456,4\nRBAR,8,4,5,123456\nRBE2,9,5,126,6\n");
  const fe::AssembledModel direct =
      ChainAssemble("direct.bdf", "RBE2,7,3,123456,4\nRBE2,8,3,123456,5\nRBE2,9,3,126,6\n");
  ExpectSameModel(chain, direct);
  // the order of the cards does not matter
  const fe::AssembledModel reversed =
      ChainAssemble("reversed.bdf", "RBE2,9,5,126,6\nRBAR,8,4,5,123456\nRBE2,7,3,123456,4\n");
  ExpectSameModel(reversed, direct);
}

TEST(NastranChains, LoopIsAnErrorNamingItsCards) {
  const std::string m = testing::InputErrorOf(
      [] { ChainAssemble("loop.bdf", "RBE2,7,4,123456,5\nRBE2,8,5,123,6\nRBE2,9,6,1,4\n"); });
  testing::ExpectContains(m, {"constraints form a loop", "rigid link 7", "rigid link 8", "rigid link 9"}, "loop");
}

// DEQATN's equation holds commas and runs over lines without a name in
// columns 1 to 8; with DESVAR, DVPREL1, DRESP1, DCONSTR and DTABLE the
// deck reads to the same model as without them, with one warning
TEST(NastranChains, DesignCardsAreSkipped) {
  const std::string design =
      "DEQATN  1       F(A,B,C) = A + B*C;\n"
      "                G = F(A, B,\n"
      "+                C) + MAX(A,B)\n"
      "DEQATN,2,H(X)=X**2\n"
      "DESVAR,1,T1,0.01,0.001,0.1\n"
      "DVPREL1,10,PBAR,1,A,,,,\n,1,1.0\n"
      "DRESP1,2,W,WEIGHT\nDCONSTR,3,2,,100.\nDTABLE,L1,1.5,L2,2.5\n"
      "DRESP2,5,R2,1\n,DESVAR,1\n,DTABLE,L1\n";
  testing::WarningCapture capture;
  const fe::AssembledModel with = ChainAssemble("design.bdf", "RBE2,7,3,123456,4\n" + design);
  const fe::AssembledModel without = ChainAssemble("no_design.bdf", "RBE2,7,3,123456,4\n");
  ExpectSameModel(with, without);
  ASSERT_EQ(capture.Count("design optimisation cards (DEQATN and others: SOL 200) are skipped"), 1);
  ASSERT_EQ(capture.Count("skipped cards (they do not change the stiffness or mass): DEQATN (x2"), 1);
  EXPECT_EQ(capture.Count("DVPREL1 (x1"), 1);
  EXPECT_EQ(capture.Count("DRESP2 (x1"), 1);
}

}  // namespace flexmb::io::nastran_chains_test
