#include "flexmb/reduction/rigid_modes.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "flexmb/fe/assembly.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::reduction {
namespace {

using fe::testing::AddConstraint;
using fe::testing::AddNode;
using fe::testing::AddPointMass;
using fe::testing::AddRigidLink;
using fe::testing::Lattice;

// a free frame with a bracket on a rigid link
fe::Mesh Frame() {
  fe::Mesh mesh = Lattice(4, 3, 2, 0.4);
  const int bracket = AddNode(mesh, fe::Vec3(0.5, 0.5, 0.9));
  AddPointMass(mesh, bracket, 3.0, fe::Vec3::Zero(), fe::Mat3::Identity() * 0.01);
  AddRigidLink(mesh, 1, 7, {bracket});
  return mesh;
}

// the geometric vectors are rigid motions: zero strain energy (K R = 0 to
// round-off) and, through T, the rigid motion of every active DOF
TEST(RigidModes, GeometricVectorsHaveNoStrainEnergy) {
  const fe::Mesh mesh = Frame();
  const fe::AssembledModel model = fe::Assemble(mesh);
  const fe::Vec3 origin(0.3, -0.2, 0.5);
  const Eigen::MatrixXd r = RigidBodyVectors(mesh, model.dofs, origin);
  ASSERT_EQ(r.rows(), model.dofs.n_free);
  const Eigen::MatrixXd kr = Eigen::MatrixXd(model.K) * r;
  EXPECT_LT(kr.norm(), 1e-12 * Eigen::MatrixXd(model.K).norm() * r.norm());
  // T r is the rigid motion of the full system, the bracket included
  const Eigen::MatrixXd full = model.T * r;
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    const fe::Vec3 x = mesh.nodes[n].x - origin;
    for (int a = 3; a < 6; ++a) {
      fe::Vec3 th = fe::Vec3::Zero();
      th[a - 3] = 1.0;
      const fe::Vec3 u = th.cross(x);
      for (int c = 0; c < 6; ++c) {
        const int f = model.dofs.full[n][c];
        if (f >= 0) EXPECT_NEAR(full(f, a), c < 3 ? u[c] : th[c - 3], 1e-14) << "node " << n << " comp " << c;
      }
    }
  }
}

// the split on the full (unreduced) space: 6 rigid motions for a free
// frame, 3 for a frame pinned at one node, 0 when clamped
TEST(RigidModes, CountsFreePinnedAndClampedBodies) {
  struct Case {
    int pin_mask;
    int expected;
  };
  for (const Case& c : {Case{0, 6}, Case{0b000111, 3}, Case{0b111111, 0}}) {
    fe::Mesh mesh = Frame();
    if (c.pin_mask) AddConstraint(mesh, 0, c.pin_mask);
    const fe::AssembledModel model = fe::Assemble(mesh);
    const Eigen::MatrixXd k(model.K), m(model.M);
    const Eigen::MatrixXd r = RigidBodyVectors(mesh, model.dofs, fe::Vec3(0.6, 0.4, 0.2));
    const RigidSplit split = SplitRigidMotions(m, k, r, 1e10);
    EXPECT_EQ(split.count, c.expected) << "pin mask " << c.pin_mask;
    const Eigen::Index n = m.rows();
    ASSERT_EQ(split.complement.cols(), n - split.count);
    // M-orthonormal rigid coordinates, complement M-orthogonal to them and orthonormal
    if (split.count > 0) {
      const Eigen::MatrixXd g = split.rigid.transpose() * m * split.rigid;
      EXPECT_LT((g - Eigen::MatrixXd::Identity(split.count, split.count)).cwiseAbs().maxCoeff(), 1e-12);
      const Eigen::MatrixXd cross = split.complement.transpose() * m * split.rigid;
      EXPECT_LT(cross.cwiseAbs().maxCoeff(), 1e-12 * std::sqrt(m.cwiseAbs().maxCoeff()));
      // the rigid motions have no strain energy
      EXPECT_LT((k * split.rigid).norm(), 1e-6 * std::sqrt(k.norm()));
    }
    const Eigen::MatrixXd ztz = split.complement.transpose() * split.complement;
    EXPECT_LT((ztz - Eigen::MatrixXd::Identity(ztz.rows(), ztz.cols())).cwiseAbs().maxCoeff(), 1e-12);
  }
}

// dependent candidates (a repeated rigid vector, a zero column) are dropped
TEST(RigidModes, DependentCandidatesAreDropped) {
  const fe::Mesh mesh = Frame();
  const fe::AssembledModel model = fe::Assemble(mesh);
  const Eigen::MatrixXd k(model.K), m(model.M);
  const Eigen::MatrixXd r = RigidBodyVectors(mesh, model.dofs, fe::Vec3::Zero());
  Eigen::MatrixXd c(r.rows(), 8);
  c << r, r.col(2) * 3.0, Eigen::VectorXd::Zero(r.rows());
  const RigidSplit split = SplitRigidMotions(m, k, c, 1e10);
  EXPECT_EQ(split.count, 6);
  EXPECT_EQ(split.dependent, 2);
}

}  // namespace
}  // namespace flexmb::reduction
