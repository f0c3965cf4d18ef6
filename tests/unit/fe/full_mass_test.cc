// AssembledModel::M_full: the mass of every active DOF before rigid-link
// elimination and constraints.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "fe_test_models.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/fe_model.h"

namespace flexmb::fe {
namespace {

using testing::AddConstraint;
using testing::AddNode;
using testing::AddPointMass;
using testing::AddRigidLink;
using testing::Lattice;

// a free frame with a bracket node on a rigid link carrying a point mass
// with inertia, a second link of translations only, and a constraint
Mesh LinkedFrame(bool constrained) {
  Mesh mesh = Lattice(3, 2, 2, 0.5);
  const int bracket = AddNode(mesh, Vec3(0.7, 0.3, 1.2));
  Mat3 j = Mat3::Zero();
  j.diagonal() << 0.02, 0.03, 0.04;
  AddPointMass(mesh, bracket, 2.5, Vec3(0.05, 0.0, 0.0), j);
  AddRigidLink(mesh, 1, 4, {bracket});
  const int slider = AddNode(mesh, Vec3(-0.3, 0.1, 0.2));
  AddPointMass(mesh, slider, 1.5);
  AddRigidLink(mesh, 2, 0, {slider}, 0b000111);
  if (constrained) AddConstraint(mesh, 11, 0b111111);
  return mesh;
}

Eigen::MatrixXd Dense(const SparseMat& a) { return Eigen::MatrixXd(a); }

// T^T M_full T = M on the free DOF, with links and constraints
TEST(FullMass, ReducesToTheFreeMassMatrix) {
  for (bool constrained : {false, true}) {
    const Mesh mesh = LinkedFrame(constrained);
    const AssembledModel model = Assemble(mesh);
    ASSERT_EQ(model.M_full.rows(), model.dofs.n_full);
    ASSERT_EQ(model.M_full.cols(), model.dofs.n_full);
    ASSERT_LT(model.dofs.n_free, model.dofs.n_full);
    const Eigen::MatrixXd reduced = Dense(model.T).transpose() * Dense(model.M_full) * Dense(model.T);
    const Eigen::MatrixXd m = Dense(model.M);
    EXPECT_LT((reduced - m).cwiseAbs().maxCoeff(), 1e-12 * m.cwiseAbs().maxCoeff()) << "constrained " << constrained;
    const Eigen::MatrixXd full = Dense(model.M_full);
    EXPECT_LT((full - full.transpose()).cwiseAbs().maxCoeff(), 1e-14 * full.cwiseAbs().maxCoeff());
  }
}

// the rigid translation of every active DOF carries the whole mass: the
// lattice's bars (rho A L each) and both point masses, the constrained node
// and the dependent nodes included
TEST(FullMass, KeepsTheMassOfDependentAndConstrainedNodes) {
  const Mesh mesh = LinkedFrame(true);
  const AssembledModel model = Assemble(mesh);
  double bars = 0.0;
  for (const Element& e : mesh.elements) {
    const BeamSection& s = mesh.beam_sections[e.property];
    bars += mesh.materials[s.material].rho * s.A * (mesh.nodes[e.nodes[1]].x - mesh.nodes[e.nodes[0]].x).norm();
  }
  const double expected = bars + 2.5 + 1.5;
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(model.dofs.n_full);
    for (const auto& node : model.dofs.full) {
      if (node[c] >= 0) u[node[c]] = 1.0;
    }
    EXPECT_NEAR(u.dot(model.M_full * u), expected, 1e-12 * expected) << "direction " << c;
  }
}

// no links or constraints: M_full is M; imported matrices: M_full is the
// imported M, kept when nodes are fixed later
TEST(FullMass, PlainAndImportedModels) {
  const Mesh mesh = Lattice(3, 2, 2, 0.5);
  const AssembledModel plain = Assemble(mesh);
  EXPECT_EQ(plain.dofs.n_full, plain.dofs.n_free);
  EXPECT_EQ((Dense(plain.M_full) - Dense(plain.M)).cwiseAbs().maxCoeff(), 0.0);

  FeModel imported;
  imported.mesh = mesh;
  imported.imported = plain;
  imported.imported->M_full = SparseMat();
  AssemblyOptions fix;
  fix.extra_fixed_nodes = {0, 5};
  const AssembledModel built = BuildMatrices(imported, fix);
  EXPECT_LT(built.dofs.n_free, plain.dofs.n_free);
  EXPECT_EQ((Dense(built.M_full) - Dense(plain.M)).cwiseAbs().maxCoeff(), 0.0);
  const AssembledModel fixed_later = FixNodes(Assemble(LinkedFrame(false)), {2});
  const AssembledModel whole = Assemble(LinkedFrame(false));
  EXPECT_EQ((Dense(fixed_later.M_full) - Dense(whole.M_full)).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace flexmb::fe
