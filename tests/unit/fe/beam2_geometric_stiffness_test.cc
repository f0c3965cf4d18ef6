// Geometric stiffness of the 2-node beam (Beam2GeometricStiffness): the
// buckling loads of a cantilever column against Euler's P = (2k - 1)^2
// pi^2 E I / (4 L^2) (k = 1, 2, 3), in both bending planes separately (a section with
// Iy = 3 Iz, so a sign error in one plane shows), symmetry, and no force for
// a rigid translation of a turned element.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/beam2.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace {

constexpr double kE = 2.1e11, kL = 2.0;

// a cantilever column along x of `ne` elements, clamped at node 0; section
// Iz (bending in x-y), Iy = 3 Iz (bending in x-z)
Mesh Column(int ne, double Iz) {
  Mesh mesh;
  mesh.source = "column.bdf";
  const int mat = testing::AddMaterial(mesh, kE, 0.3, 7850.0);
  BeamSection s;
  s.id = 1;
  s.material = mat;
  s.A = 1e-3;
  s.Iz = Iz;
  s.Iy = 3.0 * Iz;
  s.J = 1e-7;
  mesh.beam_sections.push_back(s);
  for (int k = 0; k <= ne; ++k) testing::AddNode(mesh, Vec3(kL * k / ne, 0.0, 0.0));
  for (int k = 0; k < ne; ++k) testing::AddBeam(mesh, 0, k, k + 1, Vec3(0.3, 1.0, 0.0));
  return mesh;
}

// buckling loads P (ascending): K x = P KG(1) x, the column in compression
std::vector<double> BucklingLoads(const Mesh& mesh) {
  AssemblyOptions o;
  o.extra_fixed_nodes = {0};
  const AssembledModel a = Assemble(mesh, o);
  const Eigen::MatrixXd K(a.K);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(K.rows(), K.cols());
  MatX kg;
  for (const Element& e : mesh.elements) {
    const Vec3 x[2] = {mesh.nodes[e.nodes[0]].x, mesh.nodes[e.nodes[1]].x};
    ElementInput in;
    in.element = &e;
    in.x = x;
    in.beam = &mesh.beam_sections[0];
    in.material = &mesh.materials[0];
    Beam2GeometricStiffness(in, -1.0, kg);
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) {
        const int fi = a.dofs.free[e.nodes[i / 6]][i % 6], fj = a.dofs.free[e.nodes[j / 6]][j % 6];
        if (fi >= 0 && fj >= 0) G(fi, fj) -= kg(i, j);
      }
    }
  }
  // K = L L^T: P = 1 / mu for the eigenvalues mu of L^-1 G L^-T
  const Eigen::LLT<Eigen::MatrixXd> llt(K);
  const Eigen::MatrixXd Li = llt.matrixL().solve(Eigen::MatrixXd::Identity(K.rows(), K.cols()));
  const Eigen::VectorXd mu = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Li * G * Li.transpose()).eigenvalues();
  std::vector<double> p;
  for (int k = 0; k < mu.size(); ++k) {
    if (mu(k) > 0.0) p.push_back(1.0 / mu(k));
  }
  std::sort(p.begin(), p.end());
  return p;
}

TEST(Beam2GeometricStiffness, CantileverBucklingLoadsInBothPlanes) {
  const double Iz = 2e-7;
  const std::vector<double> p = BucklingLoads(Column(24, Iz));
  ASSERT_GE(p.size(), 4u);
  const double euler = M_PI * M_PI * kE * Iz / (4.0 * kL * kL);
  // x-y plane (Iz): P1, 9 P1, 25 P1; x-z plane (Iy = 3 Iz): 3 P1, 27 P1
  const double ref[4] = {euler, 3.0 * euler, 9.0 * euler, 25.0 * euler};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(p[k] / ref[k], 1.0, k < 2 ? 1e-6 : 1e-4) << "load " << k;
}

TEST(Beam2GeometricStiffness, SymmetricAndNoForceForATranslation) {
  Mesh mesh = Column(1, 2e-7);
  mesh.nodes[1].x = Vec3(0.4, -0.7, 1.1);
  mesh.elements[0].orientation = Vec3(0.2, 0.5, -0.3);
  mesh.elements[0].offset_a = Vec3(0.01, 0.02, -0.03);
  const Vec3 x[2] = {mesh.nodes[0].x, mesh.nodes[1].x};
  ElementInput in;
  in.element = &mesh.elements[0];
  in.x = x;
  in.beam = &mesh.beam_sections[0];
  in.material = &mesh.materials[0];
  MatX kg;
  Beam2GeometricStiffness(in, 1234.0, kg);
  ASSERT_EQ(kg.rows(), 12);
  EXPECT_LT((kg - kg.transpose()).norm(), 1e-12 * kg.norm());
  const MatX r = testing::RigidModes({x[0], x[1]}, 6);
  EXPECT_LT((kg * r.leftCols(3)).norm(), 1e-10 * kg.norm());
}

}  // namespace
}  // namespace flexmb::fe
