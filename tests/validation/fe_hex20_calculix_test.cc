// The 20-node hexahedron side by side with CalculiX (ccx, Debian package
// calculix-ccx): one distorted element through ccx's matrix storage
// (*FREQUENCY, SOLVER=MATRIXSTORAGE) for C3D20 (27 points) and C3D20R (8
// points for the stiffness), and a cantilever block of hex20 elements
// written with io::WriteAbaqus plus a *FREQUENCY step, the natural
// frequencies compared with fe::Assemble + fe::SolveModes. The same deck
// read back by flexmb's Abaqus reader gives the same frequencies.
// Numbers and sources: docs/validation.md, "FE: 20-node hexahedron side by
// side with CalculiX".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/solid_hex20.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"

namespace flexmb::fe {
namespace fe_hex20_calculix_test {

using flexmb::testing::CcxDeck;
using flexmb::testing::CcxScratchDir;
using flexmb::testing::CcxSteelMesh;
using flexmb::testing::FlexmbFrequencies;
using flexmb::testing::HaveCcx;
using flexmb::testing::MatrixRelDiff;
using flexmb::testing::MaxRelDiff;
using flexmb::testing::MeshNodeIndexer;
using flexmb::testing::ParseCcxFrequencies;
using flexmb::testing::ParseCcxMatrix;
using flexmb::testing::PrintFrequencies;
using flexmb::testing::RunCcx;

// a hexahedron from its 8 corners (flexmb's order); mid-edge nodes at the
// middle of the straight edges
void AddHex20(Mesh& m, MeshNodeIndexer& node, const std::array<Vec3, 8>& c, ElementType type) {
  Element e;
  e.id = static_cast<int>(m.elements.size()) + 1;
  e.type = type;
  e.property = 0;
  for (const Vec3& x : c) e.nodes.push_back(node(x));
  for (const auto& edge : kHex20EdgeCorners) e.nodes.push_back(node(0.5 * (c[edge[0]] + c[edge[1]])));
  m.elements.push_back(std::move(e));
}

Mesh Hex20SteelMesh() {
  Mesh m = CcxSteelMesh();
  m.solid_sections.push_back({1, 0, {}});
  return m;
}

// one distorted hexahedron with straight edges
Mesh OneHex20(ElementType type) {
  Mesh m = Hex20SteelMesh();
  MeshNodeIndexer node{m, {}};
  AddHex20(m, node,
           {Vec3(0.0, 0.0, 0.0), Vec3(0.5, 0.05, 0.02), Vec3(0.55, 0.42, -0.03), Vec3(0.03, 0.38, 0.01),
            Vec3(0.02, -0.03, 0.3), Vec3(0.47, 0.02, 0.33), Vec3(0.58, 0.45, 0.36), Vec3(-0.02, 0.4, 0.29)},
           type);
  m.IndexNodes();
  return m;
}

// cantilever block 1 x 0.2 x 0.2 m (steel) of nx x ny x nz hexahedra,
// clamped (translations) at x = 0
Mesh Hex20Cantilever(int nx, int ny, int nz, ElementType type) {
  Mesh m = Hex20SteelMesh();
  MeshNodeIndexer node{m, {}};
  const Vec3 h(1.0 / nx, 0.2 / ny, 0.2 / nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        auto p = [&](int a, int b, int c) { return Vec3((i + a) * h.x(), (j + b) * h.y(), (k + c) * h.z()); };
        AddHex20(m, node, {p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0), p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)},
                 type);
      }
  for (size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes[n].x.x() == 0.0) m.constraints.push_back({static_cast<int>(n), 0b000111, {}});
  m.IndexNodes();
  return m;
}

void ElementMatrices(const Mesh& m, MatX& k, MatX& mass) {
  std::vector<Vec3> x;
  for (int n : m.elements[0].nodes) x.push_back(m.nodes[n].x);
  ElementInput in;
  in.element = &m.elements[0];
  in.x = x.data();
  in.material = &m.materials[0];
  Traits(m.elements[0].type).matrices(in, k, mass);
}

// C3D20 and C3D20R: flexmb's stiffness is ccx's (27 and 8 Gauss points),
// and so is the 27-point consistent mass of C3D20; ccx integrates C3D20R's
// mass with its 8 stiffness points, which under-integrates the quartic
// N_i N_j (as its C3D10 and C3D15 masses do): flexmb keeps the exact one
TEST(FeHex20Calculix, OneElementMatchesC3D20AndC3D20R) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  for (ElementType type : {kHex20, kHex20R}) {
    const bool full = type == kHex20;
    const Mesh one = OneHex20(type);
    CcxScratchDir dir(full ? "hex20_matrix" : "hex20r_matrix");
    ASSERT_TRUE(RunCcx(dir.path, "job", CcxDeck(one, dir.path, 0)));
    MatX k, m;
    ElementMatrices(one, k, m);
    const Eigen::MatrixXd kc = ParseCcxMatrix(dir.path / "job.sti", 60);
    const Eigen::MatrixXd mc = ParseCcxMatrix(dir.path / "job.mas", 60);
    std::printf("  %s vs flexmb %s: stiffness %.2e, mass %.2e\n", full ? "C3D20" : "C3D20R", full ? "hex20" : "hex20r",
                MatrixRelDiff(k, kc), MatrixRelDiff(m, mc));
    EXPECT_LT(MatrixRelDiff(k, kc), 1e-10);
    if (full)
      EXPECT_LT(MatrixRelDiff(m, mc), 1e-10);
    else
      EXPECT_GT(MatrixRelDiff(m, mc), 1e-2);
  }
}

// a cantilever of C3D20 and of C3D20R elements: ccx's frequencies, flexmb's
// from the same mesh, and flexmb's from the deck ccx ran, read by the
// Abaqus reader. C3D20 agrees to ccx's digits; C3D20R differs by ccx's
// 8-point mass, an effect of the order of the discretization error
// (measured 7.3e-5)
TEST(FeHex20Calculix, CantileverFrequenciesMatchC3D20AndC3D20R) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  for (ElementType type : {kHex20R, kHex20}) {
    const Mesh mesh = Hex20Cantilever(8, 2, 2, type);
    CcxScratchDir dir(type == kHex20 ? "hex20_cantilever" : "hex20r_cantilever");
    const std::string deck = CcxDeck(mesh, dir.path, 6);
    ASSERT_TRUE(RunCcx(dir.path, "job", deck));
    const std::vector<double> ccx = ParseCcxFrequencies(dir.path / "job.dat");
    const std::vector<double> ours = FlexmbFrequencies(Assemble(mesh), 6);
    const Mesh read = io::ReadAbaqus((dir.path / "job.inp").string());
    const std::vector<double> from_deck = FlexmbFrequencies(Assemble(read), 6);
    PrintFrequencies(type == kHex20 ? "ccx C3D20 8x2x2 [Hz]" : "ccx C3D20R 8x2x2 [Hz]", ccx);
    PrintFrequencies("flexmb", ours);
    ASSERT_EQ(ccx.size(), 6u);
    std::printf("  max rel diff %.2e (deck read back: %.2e)\n", MaxRelDiff(ours, ccx), MaxRelDiff(from_deck, ours));
    EXPECT_LT(MaxRelDiff(from_deck, ours), 1e-12);
    EXPECT_LT(MaxRelDiff(ours, ccx), type == kHex20 ? 1e-6 : 1e-3);
  }
}

}  // namespace fe_hex20_calculix_test
}  // namespace flexmb::fe
