// Abaqus springs (SPRINGA along a skew line, SPRING2 between two DOF,
// SPRING1 to ground) against CalculiX (ccx 2.20): the same deck, *STATIC
// with nodal loads, the displacements of both loaded nodes must agree to
// ccx's printed digits. A contrast run with the SPRINGA acting along x
// instead of its line (the spring read as a SPRING2 on DOF 1) differs
// clearly, so the comparison sees the direction. Sources: docs/validation.md,
// "Abaqus springs".

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

#include <Eigen/Dense>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"

namespace flexmb::fe {
namespace abaqus_spring_calculix_test {

using flexmb::testing::CcxScratchDir;
using flexmb::testing::HaveCcx;
using flexmb::testing::MaxRelDiffByNode;
using flexmb::testing::ParseCcxDisplacements;
using flexmb::testing::RunCcx;

// node 1 fixed; SPRINGA 1-2 (k 1000) along (1, 2, 2) / 3; SPRING2 2-3 on
// DOF 2, 2 (500); SPRING1 on node 2 DOF 2, 3 and node 3 DOF 1, 2, 3
std::string SpringDeck() {
  return "*NODE, NSET=NALL\n1, 0., 0., 0.\n2, 1., 2., 2.\n3, 2., 2., 2.\n"
         "*ELEMENT, TYPE=SPRINGA, ELSET=SA\n1, 1, 2\n"
         "*ELEMENT, TYPE=SPRING2, ELSET=S2\n2, 2, 3\n"
         "*ELEMENT, TYPE=SPRING1, ELSET=G22\n3, 2\n"
         "*ELEMENT, TYPE=SPRING1, ELSET=G23\n4, 2\n"
         "*ELEMENT, TYPE=SPRING1, ELSET=G31\n5, 3\n"
         "*ELEMENT, TYPE=SPRING1, ELSET=G32\n6, 3\n"
         "*ELEMENT, TYPE=SPRING1, ELSET=G33\n7, 3\n"
         "*SPRING, ELSET=SA\n\n1000.\n*SPRING, ELSET=S2\n2, 2\n500.\n"
         "*SPRING, ELSET=G22\n2\n100.\n*SPRING, ELSET=G23\n3\n200.\n"
         "*SPRING, ELSET=G31\n1\n300.\n*SPRING, ELSET=G32\n2\n50.\n*SPRING, ELSET=G33\n3\n60.\n"
         "*BOUNDARY\n1, 1, 3\n*NSET, NSET=LOADED\n2, 3\n"
         "*STEP\n*STATIC\n*CLOAD\n2, 1, 10.\n2, 2, -5.\n2, 3, 3.\n3, 1, 2.\n3, 2, 4.\n3, 3, -1.\n"
         "*NODE PRINT, NSET=LOADED\nU\n*END STEP\n";
}

std::map<int, Vec3> FlexmbDisplacements(const Mesh& m) {
  const AssembledModel a = Assemble(m);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(a.dofs.n_full);
  const int n2 = m.NodeIndex(2), n3 = m.NodeIndex(3);
  f[a.dofs.full[n2][0]] = 10.0;
  f[a.dofs.full[n2][1]] = -5.0;
  f[a.dofs.full[n2][2]] = 3.0;
  f[a.dofs.full[n3][0]] = 2.0;
  f[a.dofs.full[n3][1]] = 4.0;
  f[a.dofs.full[n3][2]] = -1.0;
  const Eigen::MatrixXd k(a.K);
  const Eigen::VectorXd u = a.T * k.ldlt().solve(a.T.transpose() * f);
  std::map<int, Vec3> out;
  for (int id : {2, 3}) {
    const int n = m.NodeIndex(id);
    out[id] = Vec3(u[a.dofs.full[n][0]], u[a.dofs.full[n][1]], u[a.dofs.full[n][2]]);
  }
  return out;
}

TEST(AbaqusSpringCalculix, StaticDisplacementsEqualCcx) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  CcxScratchDir dir("springs");
  ASSERT_TRUE(RunCcx(dir.path, "job", SpringDeck()));
  const std::map<int, Vec3> ccx = ParseCcxDisplacements(dir.path / "job.dat", "LOADED");
  Mesh mesh = io::ReadAbaqus((dir.path / "job.inp").string());
  const std::map<int, Vec3> ours = FlexmbDisplacements(mesh);
  // contrast: the SPRINGA along x (as a SPRING2 on DOF 1)
  for (ScalarSpring& s : mesh.springs)
    if (s.directional) s.directional = false, s.component_a = s.component_b = 0;
  const std::map<int, Vec3> along_x = FlexmbDisplacements(mesh);
  std::printf("  node 2: ccx (%.6e, %.6e, %.6e), flexmb (%.6e, %.6e, %.6e)\n", ccx.at(2).x(), ccx.at(2).y(), ccx.at(2).z(),
              ours.at(2).x(), ours.at(2).y(), ours.at(2).z());
  std::printf("  max rel diff: springs %.2e, SPRINGA along x %.2e\n", MaxRelDiffByNode(ours, ccx), MaxRelDiffByNode(along_x, ccx));
  EXPECT_LT(MaxRelDiffByNode(ours, ccx), 2e-6);  // ccx prints 7 significant digits
  EXPECT_GT(MaxRelDiffByNode(along_x, ccx), 1e-2);
}

}  // namespace abaqus_spring_calculix_test
}  // namespace flexmb::fe
