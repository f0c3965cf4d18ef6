// Stress of a floating-frame flexible body meshed with solids (issue 5)
// against a full-FE stress recovery of the same static deflection, as
// flexible_body_stress_test.cc does for shells. A steel block cantilever of
// 8-node hexahedra is reduced by Craig-Bampton with its root and tip faces as
// interface; the static deflection under a tip load on the full clamped FE
// model lies in the span of the constraint modes, so it is a rigid motion
// plus H w for one w (least squares, residual checked). With that w as the
// body's modal state:
// - the node stress sensor at an interior node (shear) and at a top-surface
//   node (bending) equals the average of the centroid stresses S u_e
//   (fe/elements/solid_hex8.h) of its eight (four) elements from the full
//   solution, von Mises by hand;
// - the deformed-mesh animation frame (results/vtk_animation.h) carries as cell
//   data "von_mises" the full-FE centroid von Mises stress of every element,
//   non-zero for the loaded body (read back from the .vtu text);
// - bending stress at mid span against beam theory 12 F (L - x) z / (b h^3).
// docs/validation.md, "Geometric stiffening of shells and solids; units;
// solid stress sensors".

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/results/vtk_animation.h"
#include "flexmb/model/workspace.h"
#include "flexmb/sensors/flexible_sensors.h"
#include "tests/validation/flexible_body_fixture.h"

namespace flexmb {
namespace flexible_body_solid_stress_test {

constexpr int kSsNx = 8, kSsNy = 2, kSsNz = 2;
constexpr double kSsL = 1.0, kSsB = 0.1, kSsH = 0.1, kSsF = 1000.0;

int SsNode(int i, int j, int k) { return i + (kSsNx + 1) * (j + (kSsNy + 1) * k); }
int SsElement(int i, int j, int k) { return i + kSsNx * (j + kSsNy * k); }

fe::FeModel SsBlock() {
  fe::FeModel model;
  fe::Mesh& mesh = model.mesh;
  mesh.source = "block.bdf";
  const int mat = fe::testing::AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  fe::SolidSection sec;
  sec.id = 1;
  sec.material = mat;
  mesh.solid_sections.push_back(sec);
  for (int k = 0; k <= kSsNz; ++k)
    for (int j = 0; j <= kSsNy; ++j)
      for (int i = 0; i <= kSsNx; ++i)
        fe::testing::AddNode(mesh, fe::Vec3(kSsL * i / kSsNx, kSsB * j / kSsNy - 0.5 * kSsB, kSsH * k / kSsNz - 0.5 * kSsH));
  for (int k = 0; k < kSsNz; ++k)
    for (int j = 0; j < kSsNy; ++j)
      for (int i = 0; i < kSsNx; ++i)
        fe::testing::AddElement(mesh, fe::ElementType::kHex8, 0,
                                {SsNode(i, j, k), SsNode(i + 1, j, k), SsNode(i + 1, j + 1, k), SsNode(i, j + 1, k),
                                 SsNode(i, j, k + 1), SsNode(i + 1, j, k + 1), SsNode(i + 1, j + 1, k + 1),
                                 SsNode(i, j + 1, k + 1)});
  return model;
}

double SsVonMises(const Eigen::Matrix<double, 6, 1>& s) {
  const double a = s(0) - s(1), b = s(1) - s(2), c = s(2) - s(0);
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

// the numbers of the DataArray named `name` in a .vtu written as ASCII
std::vector<double> SsDataArray(const std::string& path, const std::string& name) {
  std::ifstream in(path);
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  std::vector<double> out;
  const size_t at = text.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return out;
  const size_t begin = text.find('>', at) + 1, end = text.find('<', begin);
  std::istringstream values(text.substr(begin, end - begin));
  double v;
  while (values >> v) out.push_back(v);
  return out;
}

TEST(FlexibleBodySolidStress, NodeSensorAndAnimationMatchFullFeRecovery) {
  const fe::FeModel model = SsBlock();
  const fe::Mesh& mesh = model.mesh;
  std::vector<int> root, tip;
  for (int k = 0; k <= kSsNz; ++k)
    for (int j = 0; j <= kSsNy; ++j) root.push_back(SsNode(0, j, k)), tip.push_back(SsNode(kSsNx, j, k));
  std::vector<int> interface = root;
  interface.insert(interface.end(), tip.begin(), tip.end());
  const auto reduced = testing::Reduced(model, interface, 4);
  const int n = reduced->invariants.n;
  ASSERT_EQ(static_cast<int>(reduced->stress.solid.elements.size()), kSsNx * kSsNy * kSsNz);

  // full FE: root clamped, tip face load F along z (bilinear consistent: 1/16, 1/8, 1/4 on the 3 x 3 face nodes)
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = root;
  const fe::AssembledModel a = fe::Assemble(mesh, o);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(a.dofs.n_free);
  for (int k = 0; k <= kSsNz; ++k)
    for (int j = 0; j <= kSsNy; ++j) {
      const double wj = (j == 0 || j == kSsNy) ? 0.25 : 0.5, wk = (k == 0 || k == kSsNz) ? 0.25 : 0.5;
      f(a.dofs.free[SsNode(kSsNx, j, k)][2]) = kSsF * wj * wk;
    }
  const Eigen::VectorXd u_free = Eigen::MatrixXd(a.K).ldlt().solve(f);
  const int nodes = static_cast<int>(mesh.nodes.size());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * nodes);
  for (int k = 0; k < nodes; ++k)
    for (int c = 0; c < 3; ++c) {
      if (a.dofs.free[k][c] >= 0) u(6 * k + c) = u_free(a.dofs.free[k][c]);
    }

  // u = rigid motion + H w (translations only: solids have no rotation DOF)
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * nodes, 6 + n);
  Eigen::VectorXd ut(3 * nodes);
  for (int k = 0; k < nodes; ++k) {
    A.block<3, 3>(3 * k, 0).setIdentity();
    A.block<3, 3>(3 * k, 3) = -fe::testing::Skew(mesh.nodes[k].x);
    A.block(3 * k, 6, 3, n) = reduced->modes.middleRows(6 * k, 3);
    ut.segment<3>(3 * k) = u.segment<3>(6 * k);
  }
  const Eigen::VectorXd coef = A.colPivHouseholderQr().solve(ut);
  const double residual = (A * coef - ut).norm() / ut.norm();
  std::printf("hex8 block cantilever %dx%dx%d, %d modes: tip deflection %.4e m, fit residual %.2e\n", kSsNx, kSsNy,
              kSsNz, n, u(6 * SsNode(kSsNx, 1, 1) + 2), residual);
  ASSERT_LT(residual, 1e-9);

  Model m;
  const int b = testing::AddFinalizedPosedFlexibleBody(m, "block", reduced, coef.tail(n));
  const auto& body = static_cast<const FlexibleBody&>(*m.bodies[b]);
  const State s = m.InitialState();
  const Workspace ws;

  // full-FE centroid stresses of every element
  std::vector<Eigen::Matrix<double, 6, 1>> ref(mesh.elements.size());
  double max_vm = 0.0;
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const fe::Element& el = mesh.elements[e];
    fe::Vec3 x[8];
    Eigen::Matrix<double, 24, 1> ue;
    for (int c = 0; c < 8; ++c) x[c] = mesh.nodes[el.nodes[c]].x, ue.segment<3>(3 * c) = u.segment<3>(6 * el.nodes[c]);
    fe::ElementInput in;
    in.element = &el;
    in.x = x;
    in.material = &mesh.materials[0];
    fe::MatX S;
    fe::SolidHex8Stress(in, S);
    ref[e] = S * ue;
    max_vm = std::max(max_vm, SsVonMises(ref[e]));
  }

  // node sensor at the interior node (4, 1, 1) on the neutral axis (shear
  // there): average of its eight elements; at the top-surface node (4, 1, 2)
  // (bending): average of its four
  struct SsNodeCase {
    int node;
    std::vector<int> elements;
  };
  const SsNodeCase cases[2] = {
      {SsNode(4, 1, 1),
       {SsElement(3, 0, 0), SsElement(3, 1, 0), SsElement(4, 0, 0), SsElement(4, 1, 0), SsElement(3, 0, 1),
        SsElement(3, 1, 1), SsElement(4, 0, 1), SsElement(4, 1, 1)}},
      {SsNode(4, 1, 2), {SsElement(3, 0, 1), SsElement(3, 1, 1), SsElement(4, 0, 1), SsElement(4, 1, 1)}}};
  for (const SsNodeCase& nc : cases) {
    const NodeStressSensor ns("n", b, body, nc.node);
    ASSERT_EQ(ns.Components().size(), 7u);
    EXPECT_EQ(ns.Components()[0], "centroid_sxx");
    EXPECT_EQ(ns.Components()[6], "centroid_von_mises");
    double out[7];
    ns.Evaluate(m, s, ws, out);
    Eigen::Matrix<double, 6, 1> avg = Eigen::Matrix<double, 6, 1>::Zero();
    for (int e : nc.elements) avg += ref[e] / static_cast<double>(nc.elements.size());
    double max_diff = 0.0;
    for (int c = 0; c < 6; ++c) max_diff = std::max(max_diff, std::abs(out[c] - avg(c)));
    std::printf("  node %d: sensor sxx %.6e szx %.6e von Mises %.6e Pa; full FE %.6e %.6e %.6e Pa; max |diff| %.2e Pa\n",
                mesh.nodes[nc.node].id, out[0], out[5], out[6], avg(0), avg(5), SsVonMises(avg), max_diff);
    EXPECT_GT(SsVonMises(avg), 0.05 * max_vm);  // a stressed point, not a trivial zero
    EXPECT_LT(max_diff, 1e-7 * max_vm);
    EXPECT_NEAR(out[6], SsVonMises(avg), 1e-7 * max_vm);
  }

  // beam theory at the centroids of the mid-span elements next to the top and
  // bottom: sxx = -12 F (L - x) z / (b h^3) (load along +z bends the top into compression)
  {
    const double x = kSsL * 4.5 / kSsNx, z = 0.25 * kSsH;
    const double beam = 12.0 * kSsF * (kSsL - x) * z / (kSsB * std::pow(kSsH, 3));
    const double top = 0.5 * (ref[SsElement(4, 0, 1)](0) + ref[SsElement(4, 1, 1)](0));
    const double bottom = 0.5 * (ref[SsElement(4, 0, 0)](0) + ref[SsElement(4, 1, 0)](0));
    std::printf("  mid-span sxx at z = +-h/4: %.5e / %.5e Pa, beam theory -+%.5e Pa\n", top, bottom, beam);
    EXPECT_NEAR(top, -beam, 0.02 * beam);
    EXPECT_NEAR(bottom, beam, 0.02 * beam);
  }

  // animation: von Mises cell data of the deformed mesh = full-FE centroid von Mises
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("flexmb_solid_vtk_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  {
    VtkAnimationWriter w(dir.string(), m, VtkEncoding::kAscii);  // read back as text below
    w.WriteFrame(s);
    const std::vector<double> vm = SsDataArray(w.FramePath(0), "von_mises");
    ASSERT_EQ(vm.size(), mesh.elements.size());
    double vm_diff = 0.0, smallest = max_vm;
    for (size_t e = 0; e < vm.size(); ++e) {
      vm_diff = std::max(vm_diff, std::abs(vm[e] - SsVonMises(ref[e])));
      smallest = std::min(smallest, vm[e]);
    }
    std::printf("  animation von_mises: max |cell - full FE| %.2e Pa, smallest cell %.4e Pa\n", vm_diff, smallest);
    EXPECT_LT(vm_diff, 1e-6 * max_vm);  // written with 8 significant digits
    EXPECT_GT(smallest, 1e-3 * max_vm);  // every element of the loaded block is stressed
  }
  std::filesystem::remove_all(dir);
}

}  // namespace flexible_body_solid_stress_test
}  // namespace flexmb
