// The 6- and 15-node wedges side by side with CalculiX (ccx, Debian package
// calculix-ccx), as the other solids in fe_calculix_test.cc: single
// elements through ccx's matrix storage (*FREQUENCY, SOLVER=MATRIXSTORAGE)
// and a cantilever block of wedges written with io::WriteAbaqus plus a
// *FREQUENCY step, natural frequencies compared with fe::Assemble +
// fe::SolveModes. ccx integrates C3D6 with 1 x 2 points and C3D15 with
// 3 x 3 points, stiffness and mass alike; flexmb's wedge6 uses 3 x 2
// points, its wedge15 the same 3 x 3 stiffness and an exact 6 x 3 mass.
// Numbers and sources: docs/validation.md, "FE: wedges side by side with
// CalculiX".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/solid_wedge15.h"
#include "flexmb/fe/elements/solid_wedge6.h"

namespace flexmb::fe {
namespace fe_wedge_calculix_test {

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

// steel with one solid section
Mesh WedgeSteelMesh() {
  Mesh m = CcxSteelMesh();
  m.solid_sections.push_back({1, 0, {}});
  return m;
}

void AddWedge(Mesh& m, MeshNodeIndexer& node, const std::array<Vec3, 6>& c, bool quadratic) {
  Element e;
  e.id = static_cast<int>(m.elements.size()) + 1;
  e.type = quadratic ? kWedge15 : kWedge6;
  e.property = 0;
  for (const Vec3& x : c) e.nodes.push_back(node(x));
  if (quadratic)
    for (const auto& edge : kWedge15EdgeCorners) e.nodes.push_back(node(0.5 * (c[edge[0]] + c[edge[1]])));
  m.elements.push_back(std::move(e));
}

// cantilever block 1 x 0.2 x 0.2 m (steel) of nx x ny x nz cells, each cell
// two wedges along z (split along the diagonal of its x-y face), clamped
// (translations) at x = 0
Mesh WedgeCantilever(int nx, int ny, int nz, bool quadratic) {
  Mesh m = WedgeSteelMesh();
  MeshNodeIndexer node{m, {}};
  const Vec3 h(1.0 / nx, 0.2 / ny, 0.2 / nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        auto p = [&](int a, int b, int c) { return Vec3((i + a) * h.x(), (j + b) * h.y(), (k + c) * h.z()); };
        AddWedge(m, node, {p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 0, 1), p(1, 0, 1), p(1, 1, 1)}, quadratic);
        AddWedge(m, node, {p(0, 0, 0), p(1, 1, 0), p(0, 1, 0), p(0, 0, 1), p(1, 1, 1), p(0, 1, 1)}, quadratic);
      }
  for (size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes[n].x.x() == 0.0) m.constraints.push_back({static_cast<int>(n), 0b000111, {}});
  m.IndexNodes();
  return m;
}

// one distorted wedge with straight edges
Mesh OneWedge(bool quadratic) {
  Mesh m = WedgeSteelMesh();
  MeshNodeIndexer node{m, {}};
  AddWedge(m, node,
           {Vec3(0.0, 0.0, 0.0), Vec3(0.4, 0.05, 0.02), Vec3(0.1, 0.3, -0.03), Vec3(0.02, -0.01, 0.25),
            Vec3(0.45, 0.03, 0.3), Vec3(0.12, 0.33, 0.22)},
           quadratic);
  m.IndexNodes();
  return m;
}

ElementInput Input(const Mesh& m, const Element& e, std::vector<Vec3>& x) {
  x.clear();
  for (int n : e.nodes) x.push_back(m.nodes[n].x);
  ElementInput in;
  in.element = &e;
  in.x = x.data();
  in.material = &m.materials[0];
  return in;
}

// replaces K and M of `model` by the sums of `element(e, in, K, M)` over the mesh
void ReplaceMatrices(const Mesh& mesh, AssembledModel& model,
                     const std::function<void(const ElementInput&, MatX&, MatX&)>& element) {
  std::vector<Eigen::Triplet<double>> tk, tm;
  std::vector<Vec3> x;
  MatX k, m;
  for (const Element& e : mesh.elements) {
    element(Input(mesh, e, x), k, m);
    for (int p = 0; p < k.rows(); ++p)
      for (int q = 0; q < k.cols(); ++q) {
        const int r = model.dofs.free[e.nodes[p / 3]][p % 3], c = model.dofs.free[e.nodes[q / 3]][q % 3];
        if (r < 0 || c < 0) continue;
        tk.emplace_back(r, c, k(p, q));
        tm.emplace_back(r, c, m(p, q));
      }
  }
  model.K.setZero();
  model.K.setFromTriplets(tk.begin(), tk.end());
  model.M.setZero();
  model.M.setFromTriplets(tm.begin(), tm.end());
}

// ---------------------------------------------------------------------------

// C3D6 is flexmb's wedge6 with the two-point rule (stiffness and mass); on
// a cantilever the two agree to ccx's printed digits. flexmb's six-point
// wedge differs by the integration error, O(h^2): the difference must
// shrink about fourfold when h halves.
TEST(FeWedgeCalculix, Wedge6VsC3D6) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  {
    const Mesh one = OneWedge(false);
    CcxScratchDir dir("wedge6_matrix");
    ASSERT_TRUE(RunCcx(dir.path, "job", CcxDeck(one, dir.path, 0)));
    std::vector<Vec3> x;
    MatX k, m, k6, m6;
    SolidWedge6Matrices(Input(one, one.elements[0], x), k, m, Wedge6Integration::kTwoPoint);
    SolidWedge6Matrices(Input(one, one.elements[0], x), k6, m6);
    const Eigen::MatrixXd kc = ParseCcxMatrix(dir.path / "job.sti", 18);
    const Eigen::MatrixXd mc = ParseCcxMatrix(dir.path / "job.mas", 18);
    std::printf("  C3D6 vs flexmb wedge6 two-point: stiffness %.2e, mass %.2e; six-point: %.2e, %.2e\n",
                MatrixRelDiff(k, kc), MatrixRelDiff(m, mc), MatrixRelDiff(k6, kc), MatrixRelDiff(m6, mc));
    EXPECT_LT(MatrixRelDiff(k, kc), 1e-10);
    EXPECT_LT(MatrixRelDiff(m, mc), 1e-10);
  }
  double diff[2] = {0.0, 0.0};
  for (int level = 0; level < 2; ++level) {
    const int r = 1 << level;
    const Mesh mesh = WedgeCantilever(8 * r, 2 * r, 2 * r, false);
    CcxScratchDir dir("wedge6_" + std::to_string(level));
    ASSERT_TRUE(RunCcx(dir.path, "job", CcxDeck(mesh, dir.path, 6)));
    const std::vector<double> ccx = ParseCcxFrequencies(dir.path / "job.dat");
    AssembledModel model = Assemble(mesh);
    const std::vector<double> ours = FlexmbFrequencies(model, 6);
    PrintFrequencies(level == 0 ? "ccx C3D6 8x2x2x2 [Hz]" : "ccx C3D6 16x4x4x2 [Hz]", ccx);
    PrintFrequencies("flexmb wedge6 (six-point)", ours);
    ASSERT_EQ(ccx.size(), 6u);
    diff[level] = MaxRelDiff(ours, ccx);
    if (level == 0) {
      ReplaceMatrices(mesh, model, [](const ElementInput& in, MatX& k, MatX& m) {
        SolidWedge6Matrices(in, k, m, Wedge6Integration::kTwoPoint);
      });
      const std::vector<double> two = FlexmbFrequencies(model, 6);
      PrintFrequencies("flexmb wedge6 (two-point)", two);
      std::printf("  two-point vs ccx: max rel diff %.2e\n", MaxRelDiff(two, ccx));
      EXPECT_LT(MaxRelDiff(two, ccx), 1e-6);
    }
  }
  std::printf("  six-point vs ccx: max rel diff %.3e (8x2x2), %.3e (16x4x4)\n", diff[0], diff[1]);
  EXPECT_LT(diff[1], diff[0] / 2.5);
}

// C3D15: the same stiffness as flexmb's wedge15; ccx's mass is the
// nine-point one. With it the cantilever's frequencies agree to ccx's
// digits; with flexmb's exact mass they differ by the under-integration of
// the mass, an O(h^2) effect of the order of the discretization error.
TEST(FeWedgeCalculix, Wedge15VsC3D15) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  {
    const Mesh one = OneWedge(true);
    CcxScratchDir dir("wedge15_matrix");
    ASSERT_TRUE(RunCcx(dir.path, "job", CcxDeck(one, dir.path, 0)));
    std::vector<Vec3> x;
    MatX k, m, k9, m9;
    SolidWedge15Matrices(Input(one, one.elements[0], x), k, m);
    SolidWedge15Matrices(Input(one, one.elements[0], x), k9, m9, Wedge15Mass::kNinePoint);
    const Eigen::MatrixXd kc = ParseCcxMatrix(dir.path / "job.sti", 45);
    const Eigen::MatrixXd mc = ParseCcxMatrix(dir.path / "job.mas", 45);
    std::printf("  C3D15 vs flexmb wedge15: stiffness %.2e, mass %.2e (nine-point mass %.2e)\n", MatrixRelDiff(k, kc),
                MatrixRelDiff(m, mc), MatrixRelDiff(m9, mc));
    EXPECT_LT(MatrixRelDiff(k, kc), 1e-10);
    EXPECT_LT(MatrixRelDiff(m9, mc), 1e-10);
    EXPECT_GT(MatrixRelDiff(m, mc), 1e-3);
  }
  const Mesh mesh = WedgeCantilever(8, 2, 2, true);
  CcxScratchDir dir("wedge15");
  ASSERT_TRUE(RunCcx(dir.path, "job", CcxDeck(mesh, dir.path, 6)));
  const std::vector<double> ccx = ParseCcxFrequencies(dir.path / "job.dat");
  AssembledModel model = Assemble(mesh);
  const std::vector<double> exact = FlexmbFrequencies(model, 6);
  ReplaceMatrices(mesh, model, [](const ElementInput& in, MatX& k, MatX& m) {
    SolidWedge15Matrices(in, k, m, Wedge15Mass::kNinePoint);
  });
  const std::vector<double> nine = FlexmbFrequencies(model, 6);
  PrintFrequencies("ccx C3D15 8x2x2x2 [Hz]", ccx);
  PrintFrequencies("flexmb wedge15, nine-point mass", nine);
  PrintFrequencies("flexmb wedge15, exact mass", exact);
  ASSERT_EQ(ccx.size(), 6u);
  std::printf("  max rel diff: nine-point mass %.2e, exact mass %.2e\n", MaxRelDiff(nine, ccx), MaxRelDiff(exact, ccx));
  EXPECT_LT(MaxRelDiff(nine, ccx), 1e-6);
  EXPECT_LT(MaxRelDiff(exact, ccx), 1e-3);
}

}  // namespace fe_wedge_calculix_test
}  // namespace flexmb::fe
