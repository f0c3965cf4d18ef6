// Stress sensors of the floating-frame flexible body (issue 5) against a
// full-FE stress recovery of the same static deflection. A steel plate
// cantilever (4-node shells) is reduced by Craig-Bampton with its root and
// tip edges as interface. Its static deflection under a tip load, solved on
// the full clamped FE model, lies in the span of the constraint modes (loads
// and supports at interface nodes only), so it is the rigid motion of the
// root plus H w for one w (found by least squares on [rigid modes, H], the
// residual checked). With that w as the body's modal state the element
// stress sensor must reproduce the element recovery S u_e of the full
// solution (fe/elements/shell_quad4.h), von Mises by hand, the node sensor
// the average of the adjacent elements, and beam theory must hold for the
// bending stress 6 F (L - x) / (b t^2) away from the root.
// docs/validation.md, "Flexible bodies (FFR): sensors, animation".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/shell_quad4.h"
#include "flexmb/model/workspace.h"
#include "flexmb/sensors/flexible_sensors.h"
#include "tests/validation/flexible_body_fixture.h"

namespace flexmb {
namespace flexible_body_stress_test {

constexpr int kNx = 10, kNy = 2;
constexpr double kL = 1.0, kB = 0.2, kT = 0.01, kF = 10.0;

int NodeAt(int i, int j) { return i * (kNy + 1) + j; }

fe::FeModel Plate() {
  fe::FeModel model;
  fe::Mesh& mesh = model.mesh;
  mesh.source = "plate.bdf";
  const int mat = fe::testing::AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  fe::ShellSection sec;
  sec.id = 1;
  sec.material = mat;
  sec.thickness = kT;
  mesh.shell_sections.push_back(sec);
  for (int i = 0; i <= kNx; ++i) {
    for (int j = 0; j <= kNy; ++j) fe::testing::AddNode(mesh, fe::Vec3(kL * i / kNx, kB * j / kNy, 0.0));
  }
  for (int i = 0; i < kNx; ++i) {
    for (int j = 0; j < kNy; ++j)
      fe::testing::AddElement(mesh, fe::ElementType::kQuad4, 0,
                              {NodeAt(i, j), NodeAt(i + 1, j), NodeAt(i + 1, j + 1), NodeAt(i, j + 1)});
  }
  return model;
}

int ElementAt(int i, int j) { return i * kNy + j; }

double VonMisesByHand(double sxx, double syy, double sxy) {
  return std::sqrt(sxx * sxx - sxx * syy + syy * syy + 3.0 * sxy * sxy);
}

TEST(FlexibleBodyStress, SensorsMatchFullFeRecoveryOfAStaticDeflection) {
  const fe::FeModel model = Plate();
  const fe::Mesh& mesh = model.mesh;
  std::vector<int> root, tip;
  for (int j = 0; j <= kNy; ++j) root.push_back(NodeAt(0, j)), tip.push_back(NodeAt(kNx, j));
  std::vector<int> interface = root;
  interface.insert(interface.end(), tip.begin(), tip.end());
  const auto reduced = testing::Reduced(model, interface, 4);
  const int n = reduced->invariants.n;
  ASSERT_EQ(static_cast<int>(reduced->stress.shell.elements.size()), kNx * kNy);

  // full FE: root clamped, tip edge load F along z (consistent: 1/4 1/2 1/4)
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = root;
  const fe::AssembledModel a = fe::Assemble(mesh, o);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(a.dofs.n_free);
  for (int j = 0; j <= kNy; ++j) f(a.dofs.free[tip[j]][2]) = kF * (j == 0 || j == kNy ? 0.25 : 0.5);
  const Eigen::VectorXd u_free = Eigen::MatrixXd(a.K).ldlt().solve(f);
  const int nodes = static_cast<int>(mesh.nodes.size());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * nodes);
  for (int k = 0; k < nodes; ++k) {
    for (int c = 0; c < 6; ++c) {
      if (a.dofs.free[k][c] >= 0) u(6 * k + c) = u_free(a.dofs.free[k][c]);
    }
  }

  // u = rigid motion + H w
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(6 * nodes, 6 + n);
  for (int k = 0; k < nodes; ++k) {
    A.block<3, 3>(6 * k, 0).setIdentity();
    A.block<3, 3>(6 * k, 3) = -fe::testing::Skew(mesh.nodes[k].x);
    A.block<3, 3>(6 * k + 3, 3).setIdentity();
  }
  A.rightCols(n) = reduced->modes;
  const Eigen::VectorXd coef = A.colPivHouseholderQr().solve(u);
  const double residual = (A * coef - u).norm() / u.norm();
  std::printf("plate cantilever %dx%d shells, %d modes: tip deflection %.4e m, fit residual %.2e\n", kNx, kNy, n,
              u(6 * tip[1] + 2), residual);
  ASSERT_LT(residual, 1e-9);

  Model m;
  const int b = testing::AddFinalizedPosedFlexibleBody(m, "plate", reduced, coef.tail(n));
  const auto& body = static_cast<const FlexibleBody&>(*m.bodies[b]);
  const State s = m.InitialState();
  const Workspace ws;

  // every element: sensor = S u_e of the full solution
  double max_stress = 0.0, max_diff = 0.0, max_vm_diff = 0.0;
  std::vector<Eigen::Matrix<double, 6, 1>> ref(mesh.elements.size());
  for (size_t e = 0; e < mesh.elements.size(); ++e) {
    const fe::Element& el = mesh.elements[e];
    fe::Vec3 x[4];
    Eigen::Matrix<double, 24, 1> ue;
    for (int c = 0; c < 4; ++c) x[c] = mesh.nodes[el.nodes[c]].x, ue.segment<6>(6 * c) = u.segment<6>(6 * el.nodes[c]);
    fe::ElementInput in;
    in.element = &el;
    in.x = x;
    in.material = &mesh.materials[0];
    in.shell = &mesh.shell_sections[0];
    fe::MatX S;
    fe::Mat3 axes;
    fe::ShellQuad4Stress(in, S, axes);
    ref[e] = S * ue;
    double out[8];
    ElementStressSensor("s", b, body, static_cast<int>(e)).Evaluate(m, s, ws, out);
    for (int l = 0; l < 2; ++l) {
      for (int c = 0; c < 3; ++c) max_diff = std::max(max_diff, std::abs(out[4 * l + c] - ref[e](3 * l + c)));
      const double vm = VonMisesByHand(ref[e](3 * l), ref[e](3 * l + 1), ref[e](3 * l + 2));
      max_vm_diff = std::max(max_vm_diff, std::abs(out[4 * l + 3] - vm));
      max_stress = std::max(max_stress, vm);
    }
  }
  std::printf("  max von Mises %.4e Pa; max |sensor - full FE| %.2e Pa (components), %.2e Pa (von Mises)\n",
              max_stress, max_diff, max_vm_diff);
  EXPECT_LT(max_diff, 1e-7 * max_stress);
  EXPECT_LT(max_vm_diff, 1e-7 * max_stress);

  // beam theory at mid span: top surface in compression, 6 F (L - x) / (b t^2)
  const int i = kNx / 2;
  const double x = kL * (i + 0.5) / kNx, beam = 6.0 * kF * (kL - x) / (kB * kT * kT);
  double top = 0.0;
  for (int j = 0; j < kNy; ++j) {
    double out[8];
    ElementStressSensor("s", b, body, ElementAt(i, j)).Evaluate(m, s, ws, out);
    top += out[4] / kNy;
  }
  std::printf("  mid-span top sxx %.5e Pa, beam theory %.5e Pa\n", top, -beam);
  EXPECT_NEAR(top, -beam, 0.02 * beam);

  // node between four elements: the average of their (body-axes) tensors
  const NodeStressSensor ns("n", b, body, NodeAt(i, 1));
  ASSERT_EQ(ns.Components().size(), 14u);
  EXPECT_EQ(ns.Components()[7], "top_sxx");
  double out[14];
  ns.Evaluate(m, s, ws, out);
  for (int l = 0; l < 2; ++l) {
    Eigen::Vector3d avg = Eigen::Vector3d::Zero();
    for (int e : {ElementAt(i - 1, 0), ElementAt(i - 1, 1), ElementAt(i, 0), ElementAt(i, 1)})
      avg += 0.25 * ref[e].segment<3>(3 * l);
    const double* o = out + 7 * l;
    EXPECT_NEAR(o[0], avg(0), 1e-7 * max_stress);
    EXPECT_NEAR(o[1], avg(1), 1e-7 * max_stress);
    EXPECT_NEAR(o[3], avg(2), 1e-7 * max_stress);
    EXPECT_NEAR(o[2], 0.0, 1e-7 * max_stress);
    EXPECT_NEAR(o[4], 0.0, 1e-7 * max_stress);
    EXPECT_NEAR(o[5], 0.0, 1e-7 * max_stress);
    EXPECT_NEAR(o[6], VonMisesByHand(avg(0), avg(1), avg(2)), 1e-7 * max_stress);
  }
}

}  // namespace flexible_body_stress_test
}  // namespace flexmb
