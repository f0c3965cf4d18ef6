// RBE3 against CalculiX's distributing coupling (ccx 2.20, *COUPLING with
// *DISTRIBUTING on a facial surface): a steel block of C3D8 elements
// clamped at x = 0, the tip face x = 1 m coupled to a reference node at its
// centre, a force at the reference node. The static tip displacements of
// flexmb (its hex8 with full 2x2x2 integration, which is ccx's C3D8, and an
// RBE3 over the tip face nodes with Ci = 123) must equal ccx's to its
// printed digits. ccx weights a facial surface's nodes by their share of
// the face area (here corner : edge : centre = 1 : 2 : 4), so the RBE3 gets
// those weights; with equal weights the result differs clearly (checked).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe/linear_constraint.h"

namespace flexmb::fe {
namespace rbe3_calculix_test {

using flexmb::testing::CcxReadText;
using flexmb::testing::CcxScratchDir;
using flexmb::testing::CcxSteelMesh;
using flexmb::testing::HaveCcx;
using flexmb::testing::MaxRelDiffByNode;
using flexmb::testing::ParseCcxDisplacements;
using flexmb::testing::RunCcx;

constexpr int kNx = 8, kNy = 2, kNz = 2;

int NodeAt(int i, int j, int k) { return (k * (kNy + 1) + j) * (kNx + 1) + i; }

// the block, clamped at x = 0, with a reference node at the tip face centre
Mesh Block() {
  Mesh m = CcxSteelMesh();
  m.solid_sections.push_back({1, 0, {}});
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j)
      for (int i = 0; i <= kNx; ++i) {
        Node n;
        n.id = static_cast<int>(m.nodes.size()) + 1;
        n.x = Vec3(1.0 * i / kNx, 0.2 * j / kNy, 0.2 * k / kNz);
        m.nodes.push_back(n);
      }
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i) {
        Element e;
        e.id = static_cast<int>(m.elements.size()) + 1;
        e.type = ElementType::kHex8;
        e.property = 0;
        e.nodes = {NodeAt(i, j, k),         NodeAt(i + 1, j, k),     NodeAt(i + 1, j + 1, k),
                   NodeAt(i, j + 1, k),     NodeAt(i, j, k + 1),     NodeAt(i + 1, j, k + 1),
                   NodeAt(i + 1, j + 1, k + 1), NodeAt(i, j + 1, k + 1)};
        m.elements.push_back(e);
      }
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j) m.constraints.push_back(Constraint{NodeAt(0, j, k), 0b111, {}});
  Node ref;
  ref.id = static_cast<int>(m.nodes.size()) + 1;
  ref.x = Vec3(1.0, 0.1, 0.1);
  m.nodes.push_back(ref);
  m.IndexNodes();
  return m;
}

// flexmb's tip displacements under the force f at the reference node, with
// tip face weights corner : edge : centre = 1 : 2 : 4 (area) or all 1
std::map<int, Vec3> FlexmbTip(const Mesh& block, const Vec3& f, bool area_weights) {
  Mesh m = block;
  const int ref = static_cast<int>(m.nodes.size()) - 1;
  Rbe3Spec spec;
  spec.id = 1;
  spec.ref_node = ref;
  spec.ref_components = 0b111111;
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j) {
      const int edges = (j == 0 || j == kNy) + (k == 0 || k == kNz);
      const double w = area_weights ? (edges == 2 ? 1.0 : edges == 1 ? 2.0 : 4.0) : 1.0;
      spec.groups.push_back({w, 0b111, {NodeAt(kNx, j, k)}});
    }
  m.linear_constraints = Rbe3Constraints(m, spec);
  const AssembledModel a = Assemble(m);
  // K from the hex8 with full integration (ccx's C3D8); element DOF are all free
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(a.dofs.n_free, a.dofs.n_free);
  for (const Element& e : m.elements) {
    std::vector<Vec3> x;
    for (int n : e.nodes) x.push_back(m.nodes[n].x);
    ElementInput in;
    in.element = &e;
    in.x = x.data();
    in.material = &m.materials[0];
    MatX ke, me;
    SolidHex8Matrices(in, ke, me, Hex8Formulation::kFullIntegration);
    for (int p = 0; p < 24; ++p)
      for (int q = 0; q < 24; ++q) {
        const int r = a.dofs.free[e.nodes[p / 3]][p % 3], c = a.dofs.free[e.nodes[q / 3]][q % 3];
        if (r >= 0 && c >= 0) k(r, c) += ke(p, q);
      }
  }
  Eigen::VectorXd f_full = Eigen::VectorXd::Zero(a.dofs.n_full);
  for (int c = 0; c < 3; ++c) f_full[a.dofs.full[ref][c]] = f[c];
  const Eigen::VectorXd u = k.ldlt().solve(a.T.transpose() * f_full);
  std::map<int, Vec3> tip;
  for (int kk = 0; kk <= kNz; ++kk)
    for (int j = 0; j <= kNy; ++j) {
      const int n = NodeAt(kNx, j, kk);
      tip[m.nodes[n].id] = Vec3(u[a.dofs.free[n][0]], u[a.dofs.free[n][1]], u[a.dofs.free[n][2]]);
    }
  return tip;
}

TEST(Rbe3Calculix, TipDeflectionMatchesDistributingCoupling) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const Mesh block = Block();
  const int ref_id = block.nodes.back().id;
  const Vec3 force(300.0, -500.0, -1000.0);
  CcxScratchDir dir("rbe3");
  // the deck: nodes, C3D8 elements, the clamp; the coupling and the step by hand
  std::ostringstream deck;
  deck << "*NODE\n";
  for (const Node& n : block.nodes) deck << n.id << ", " << n.x.x() << ", " << n.x.y() << ", " << n.x.z() << "\n";
  deck << "*ELEMENT, TYPE=C3D8, ELSET=EALL\n";
  for (const Element& e : block.elements) {
    deck << e.id;
    for (int n : e.nodes) deck << ", " << block.nodes[n].id;
    deck << "\n";
  }
  deck << "*NSET, NSET=ROOT\n";
  for (const Constraint& c : block.constraints) deck << block.nodes[c.node].id << "\n";
  deck << "*NSET, NSET=TIP\n";
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j) deck << block.nodes[NodeAt(kNx, j, k)].id << "\n";
  // the tip face is face S4 (nodes 2 6 7 3) of the last element of each row
  deck << "*SURFACE, NAME=TIPFACE, TYPE=ELEMENT\n";
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j) deck << (k * kNy + j) * kNx + kNx << ", S4\n";
  deck << "*COUPLING, REF NODE=" << ref_id << ", SURFACE=TIPFACE, CONSTRAINT NAME=C1\n*DISTRIBUTING\n1, 3\n"
       << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << flexmb::testing::kCcxE << ", " << flexmb::testing::kCcxNu
       << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*BOUNDARY\nROOT, 1, 3\n"
       << "*STEP\n*STATIC\n*CLOAD\n"
       << ref_id << ", 1, " << force.x() << "\n" << ref_id << ", 2, " << force.y() << "\n" << ref_id << ", 3, "
       << force.z() << "\n*NODE PRINT, NSET=TIP\nU\n*END STEP\n";
  ASSERT_TRUE(RunCcx(dir.path, "job", deck.str()));
  const std::map<int, Vec3> ccx = ParseCcxDisplacements(dir.path / "job.dat", "TIP");
  ASSERT_EQ(ccx.size(), 9u);
  const std::map<int, Vec3> area = FlexmbTip(block, force, true);
  const std::map<int, Vec3> equal = FlexmbTip(block, force, false);
  std::printf("  tip node %d uz: ccx %.7e, RBE3 area weights %.7e, equal weights %.7e\n", ccx.begin()->first,
              ccx.begin()->second.z(), area.at(ccx.begin()->first).z(), equal.at(ccx.begin()->first).z());
  std::printf("  max rel diff: area weights %.2e, equal weights %.2e\n", MaxRelDiffByNode(area, ccx), MaxRelDiffByNode(equal, ccx));
  // ccx prints 7 significant digits
  EXPECT_LT(MaxRelDiffByNode(area, ccx), 2e-6);
  EXPECT_GT(MaxRelDiffByNode(equal, ccx), 1e-4);
}

}  // namespace rbe3_calculix_test
}  // namespace flexmb::fe
