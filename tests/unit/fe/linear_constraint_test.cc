// RBE3 as linear constraints (fe/linear_constraint.h) and their master-slave
// elimination in fe::Assemble, checked against the defining properties:
// a rigid motion of the independent nodes is the reference node's motion,
// the weighted bolt-group distribution of a force, no added stiffness, and
// the Guyan stiffness seen through the RBE3 (reference: the flexibility
// C K^-1 C^T of the model without it).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/linear_constraint.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/craig_bampton_basis.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe::linear_constraint_test {

using testing::AddBeam;
using testing::AddConstraint;
using testing::AddMaterial;
using testing::AddNode;
using testing::AddPointMass;
using testing::AddRigidLink;
using testing::AddRoundBar;
using testing::ExpectInputErrorWith;

Rbe3Spec Spec(int id, int ref, int refc, std::vector<Rbe3Group> groups) {
  Rbe3Spec s;
  s.id = id;
  s.ref_node = ref;
  s.ref_components = refc;
  s.groups = std::move(groups);
  s.origin = {"rbe3.bdf", 40 + id};
  return s;
}

void AddRbe3(Mesh& mesh, const Rbe3Spec& s) {
  for (LinearConstraint& row : Rbe3Constraints(mesh, s)) mesh.linear_constraints.push_back(row);
}

// rigid motion about the basic origin: translation t, small rotation theta
Eigen::Matrix<double, 6, 1> RigidAt(const Vec3& x, const Vec3& t, const Vec3& theta) {
  Eigen::Matrix<double, 6, 1> u;
  u << t + theta.cross(x), theta;
  return u;
}

// an unsymmetric node set, unequal weights, mixed components, eccentric reference
Mesh UnsymmetricRbe3(int ref_components) {
  Mesh mesh;
  for (const Vec3& x : {Vec3(0, 0, 0), Vec3(1.3, 0.1, 0), Vec3(0.2, 0.9, 0.3), Vec3(1.1, 1.2, -0.4),
                        Vec3(0.5, -0.7, 0.8), Vec3(2.0, 0.5, 1.0)})
    AddNode(mesh, x);
  AddRbe3(mesh, Spec(7, 5, ref_components,
                     {{1.0, 0b111, {0, 1, 2}}, {2.5, 0b111111, {3}}, {0.7, 0b011, {4}}, {0.3, 0b100, {4}}}));
  return mesh;
}

TEST(Rbe3, RigidMotionOfIndependentNodesIsTheReferenceMotion) {
  const Mesh mesh = UnsymmetricRbe3(0b111111);
  ASSERT_EQ(mesh.linear_constraints.size(), 6u);
  const AssembledModel a = Assemble(mesh);
  const Vec3 t(1e-3, -2e-3, 0.5e-3), theta(2e-4, -1e-4, 3e-4);
  Eigen::VectorXd u_free = Eigen::VectorXd::Zero(a.dofs.n_free);
  for (int n = 0; n < 5; ++n) {
    const Eigen::Matrix<double, 6, 1> u = RigidAt(mesh.nodes[n].x, t, theta);
    for (int c = 0; c < 6; ++c)
      if (a.dofs.free[n][c] >= 0) u_free[a.dofs.free[n][c]] = u[c];
  }
  const Eigen::VectorXd u_full = a.T * u_free;
  const Eigen::Matrix<double, 6, 1> expected = RigidAt(mesh.nodes[5].x, t, theta);
  for (int c = 0; c < 6; ++c) {
    ASSERT_GE(a.dofs.full[5][c], 0);
    EXPECT_EQ(a.dofs.free[5][c], -1);
    EXPECT_NEAR(u_full[a.dofs.full[5][c]], expected[c], 1e-14) << c;
  }
}

// f_i = w_i (F / W + (J^-1 M_c) x r_i), r_i from the weighted centroid c,
// J = sum w_i (|r_i|^2 I - r_i r_i^T), M_c the moment about c: the weighted
// bolt-group formula of a translation-only RBE3
std::vector<Vec3> BoltGroupForces(const std::vector<Vec3>& x, const std::vector<double>& w, const Vec3& x_ref,
                                  const Vec3& force, const Vec3& moment) {
  double wsum = 0.0;
  Vec3 c = Vec3::Zero();
  for (size_t i = 0; i < x.size(); ++i) wsum += w[i], c += w[i] * x[i];
  c /= wsum;
  Mat3 j = Mat3::Zero();
  for (size_t i = 0; i < x.size(); ++i) {
    const Vec3 r = x[i] - c;
    j += w[i] * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  const Vec3 alpha = j.inverse() * (moment + (x_ref - c).cross(force));
  std::vector<Vec3> f;
  for (size_t i = 0; i < x.size(); ++i) f.push_back(w[i] * (force / wsum + alpha.cross(x[i] - c)));
  return f;
}

// the free-DOF force f = T^T f_full of a load (force, moment) at the reference node
void ExpectDistribution(const std::vector<Vec3>& x, const std::vector<double>& w, const Vec3& x_ref,
                        const Vec3& force, const Vec3& moment) {
  Mesh mesh;
  std::vector<Rbe3Group> groups;
  for (size_t i = 0; i < x.size(); ++i) groups.push_back({w[i], 0b111, {AddNode(mesh, x[i])}});
  const int ref = AddNode(mesh, x_ref);
  AddRbe3(mesh, Spec(3, ref, 0b111111, groups));
  const AssembledModel a = Assemble(mesh);
  Eigen::VectorXd f_full = Eigen::VectorXd::Zero(a.dofs.n_full);
  for (int c = 0; c < 3; ++c) {
    f_full[a.dofs.full[ref][c]] = force[c];
    f_full[a.dofs.full[ref][3 + c]] = moment[c];
  }
  const Eigen::VectorXd f = a.T.transpose() * f_full;
  const std::vector<Vec3> expected = BoltGroupForces(x, w, x_ref, force, moment);
  for (size_t i = 0; i < x.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[a.dofs.free[i][c]], expected[i][c], 1e-12) << i << " " << c;
}

TEST(Rbe3, SymmetricForceIsSharedByWeight) {
  // square, reference at the weighted centroid: f_i = F w_i / sum w exactly
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)};
  ExpectDistribution(x, {1, 1, 1, 1}, Vec3(1, 1, 0), Vec3(0, 0, -100), Vec3::Zero());
  const std::vector<double> w = {1.0, 3.0, 3.0, 1.0};
  const std::vector<Vec3> f = BoltGroupForces(x, w, Vec3(1.5, 1, 0), Vec3(0, 0, -80), Vec3::Zero());
  EXPECT_NEAR(f[1].z(), -30.0, 1e-12);  // the reference formula itself: 80 * 3 / 8
  ExpectDistribution(x, w, Vec3(1.5, 1, 0), Vec3(0, 0, -80), Vec3::Zero());
}

TEST(Rbe3, EccentricForceAndMomentFollowTheBoltGroupFormula) {
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1.3, 0.1, 0.05), Vec3(0.2, 0.9, -0.1), Vec3(1.1, 1.2, 0.2),
                               Vec3(0.6, 0.4, 0.6)};
  ExpectDistribution(x, {1.0, 2.0, 0.5, 1.5, 0.8}, Vec3(2.0, -0.5, 0.7), Vec3(10, -20, 30), Vec3(3, -4, 5));
}

TEST(Rbe3, BadDefinitionsAreNamed) {
  Mesh mesh;
  for (int k = 0; k < 4; ++k) AddNode(mesh, Vec3(k, 0, 0));
  const int ref = AddNode(mesh, Vec3(1, 1, 0));
  // collinear nodes, translations only: the rotation about the line is free
  ExpectInputErrorWith([&] { Rbe3Constraints(mesh, Spec(9, ref, 0b111111, {{1.0, 0b111, {0, 1, 2}}})); },
                       {"rbe3.bdf:49", "RBE3 9", "cannot carry every rigid motion"});
  ExpectInputErrorWith([&] { Rbe3Constraints(mesh, Spec(9, ref, 0b111, {{0.0, 0b111, {0, 1, 2}}})); },
                       {"RBE3 9", "must be > 0"});
  ExpectInputErrorWith([&] { Rbe3Constraints(mesh, Spec(9, ref, 0b111, {{1.0, 0b111111, {0, ref}}})); },
                       {"RBE3 9", "also an independent node"});
}

TEST(Rbe3, ConflictsWithLinksConstraintsAndChainsAreNamed) {
  {
    Mesh mesh = UnsymmetricRbe3(0b111);
    AddRigidLink(mesh, 11, 0, {5}, 0b1);
    ExpectInputErrorWith([&] { Assemble(mesh); }, {"RBE3 7", "node 6 component ux is already dependent in rigid link 11"});
  }
  {
    Mesh mesh = UnsymmetricRbe3(0b111);
    AddConstraint(mesh, 5, 0b10);
    ExpectInputErrorWith([&] { Assemble(mesh); }, {"RBE3 7", "node 6 component uy is also fixed"});
  }
  {
    // the reference of a second RBE3 among the first's independent nodes
    Mesh mesh = UnsymmetricRbe3(0b111);
    const int far = AddNode(mesh, Vec3(3, 3, 3));
    AddRbe3(mesh, Spec(8, 0, 0b111, {{1.0, 0b111, {1, 2, far}}}));
    ExpectInputErrorWith([&] { Assemble(mesh); }, {"RBE3 7", "independent node 1 component ux is itself dependent in RBE3 8",
                                                   "chained constraints are not supported"});
  }
  {
    Mesh mesh = UnsymmetricRbe3(0b111);
    AddRbe3(mesh, Spec(8, 5, 0b100, {{1.0, 0b111, {0, 1, 2}}}));
    ExpectInputErrorWith([&] { Assemble(mesh); }, {"RBE3 8", "node 6 component uz is already dependent in RBE3 7"});
  }
}

// free-free beam of 10 elements, a small cross at its end
Mesh BeamWithCross() {
  Mesh mesh;
  const int mat = AddMaterial(mesh, 210e9, 0.3, 7850);
  const int sec = AddRoundBar(mesh, mat, 0.02);
  for (int k = 0; k <= 10; ++k) AddNode(mesh, Vec3(0.1 * k, 0, 0));
  for (int k = 0; k < 10; ++k) AddBeam(mesh, sec, k, k + 1, Vec3(0, 1, 0));
  const int y = AddNode(mesh, Vec3(1.0, 0.1, 0)), z = AddNode(mesh, Vec3(1.0, 0, 0.1));
  AddBeam(mesh, sec, 10, y, Vec3(0, 0, 1));
  AddBeam(mesh, sec, 10, z, Vec3(0, 1, 0));
  return mesh;
}

Eigen::VectorXd Eigenvalues(const AssembledModel& a) {
  const Eigen::MatrixXd k(a.K), m(a.M);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(k, m);
  return es.eigenvalues();
}

TEST(Rbe3, AddsNoStiffnessUnlikeRbe2) {
  const Mesh plain = BeamWithCross();
  Mesh with_rbe3 = plain;
  const int ref = AddNode(with_rbe3, Vec3(0.5, 0.3, 0.2));  // massless, no element
  AddRbe3(with_rbe3, Spec(5, ref, 0b111111, {{1.0, 0b111, {3, 4, 5}}, {2.0, 0b111111, {6}}}));
  Mesh with_rbe2 = plain;
  AddRigidLink(with_rbe2, 6, 3, {4, 5, 6});

  const Eigen::VectorXd l0 = Eigenvalues(Assemble(plain));
  const Eigen::VectorXd l3 = Eigenvalues(Assemble(with_rbe3));
  const Eigen::VectorXd l2 = Eigenvalues(Assemble(with_rbe2));
  ASSERT_EQ(l0.size(), l3.size());
  const double scale = l0.cwiseAbs().maxCoeff();
  auto rigid = [&](const Eigen::VectorXd& l) { return (l.array().abs() < 1e-9 * scale).count(); };
  EXPECT_EQ(rigid(l0), 6);
  EXPECT_EQ(rigid(l3), 6);
  for (int k = 6; k < l0.size(); ++k) EXPECT_NEAR(l3[k] / l0[k], 1.0, 1e-9) << k;
  // the RBE2 makes two beam elements rigid: the first bending mode stiffens
  EXPECT_EQ(rigid(l2), 6);
  EXPECT_GT(l2[6] / l0[6], 1.05);
}

TEST(Rbe3, ReferenceNodeAsInterfaceNodeGivesTheGuyanStiffnessThroughTheRbe3) {
  Mesh mesh = BeamWithCross();
  AddConstraint(mesh, 0, 0b111111);
  const int ref = AddNode(mesh, Vec3(1.05, 0.05, 0.05));
  AddRbe3(mesh, Spec(5, ref, 0b111111, {{1.0, 0b111, {10}}, {2.0, 0b111, {11}}, {0.5, 0b111, {12}}}));

  // reference: K0 without the RBE3, G = C K0^-1 C^T, K_ref = G^-1
  Mesh plain = mesh;
  plain.linear_constraints.clear();
  const AssembledModel a0 = Assemble(plain);
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(6, a0.dofs.n_free);
  for (const LinearConstraint& row : mesh.linear_constraints)
    for (const MpcTerm& t : row.terms) c(row.component, a0.dofs.free[t.node][t.component]) += t.coef;
  const Eigen::MatrixXd g = c * Eigen::MatrixXd(a0.K).ldlt().solve(c.transpose());
  const Eigen::MatrixXd k_ref = g.inverse();

  AssemblyOptions ao;
  ao.independent_nodes = {ref};
  const AssembledModel a = Assemble(mesh, ao);
  reduction::ReductionOptions ro;
  ro.interface_nodes = {ref};
  ro.normal_modes = 0;
  const reduction::CraigBamptonBasis basis = reduction::BuildCraigBamptonBasis(mesh, a, ro);
  ASSERT_EQ(basis.static_modes(), 6);
  for (int c6 = 0; c6 < 6; ++c6) EXPECT_EQ(basis.boundary[c6], a.dofs.free[ref][c6]);
  EXPECT_LT((basis.stiffness - k_ref).norm(), 1e-9 * k_ref.norm()) << basis.stiffness << "\n\n" << k_ref;

  // the swap is the same constraint: a rigid motion still moves the reference rigidly
  const Vec3 t(1e-3, 2e-3, -1e-3), theta(1e-3, -2e-3, 5e-4);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(a.dofs.n_free);
  for (int n = 0; n < static_cast<int>(mesh.nodes.size()); ++n)
    for (int c6 = 0; c6 < 6; ++c6)
      if (a.dofs.free[n][c6] >= 0) u[a.dofs.free[n][c6]] = RigidAt(mesh.nodes[n].x, t, theta)[c6];
  const Eigen::VectorXd full = a.T * u;
  for (int n : {10, 11, 12})
    for (int c6 = 0; c6 < 3; ++c6)
      EXPECT_NEAR(full[a.dofs.full[n][c6]], RigidAt(mesh.nodes[n].x, t, theta)[c6], 1e-14);

  // and the whole reduction accepts it
  fe::FeModel model;
  model.mesh = mesh;
  ro.normal_modes = 4;
  const reduction::ReducedBody body = reduction::ReduceCraigBampton(model, ro);
  EXPECT_EQ(body.interface_nodes.size(), 1u);
}

// two RBE3 sharing an independent node, both references interface nodes:
// the swap picks pivots outside the shared node, the Guyan reduction runs
TEST(Rbe3, TwoReferenceNodesSharingAnIndependentNode) {
  Mesh mesh = BeamWithCross();
  AddConstraint(mesh, 0, 0b111111);
  const int r1 = AddNode(mesh, Vec3(1.0, 0.05, 0.05)), r2 = AddNode(mesh, Vec3(0.8, 0.0, 0.1));
  AddRbe3(mesh, Spec(5, r1, 0b111111, {{1.0, 0b111, {8, 10, 11, 12}}}));
  AddRbe3(mesh, Spec(6, r2, 0b111111, {{1.0, 0b111, {6, 7, 10}}, {1.0, 0b111111, {9}}}));
  AssemblyOptions ao;
  ao.independent_nodes = {r1, r2};
  const AssembledModel a = Assemble(mesh, ao);
  for (int c = 0; c < 6; ++c) {
    EXPECT_GE(a.dofs.free[r1][c], 0);
    EXPECT_GE(a.dofs.free[r2][c], 0);
  }
  for (int c = 0; c < 3; ++c) EXPECT_GE(a.dofs.free[10][c], 0);  // the shared node stays independent
  reduction::ReductionOptions ro;
  ro.interface_nodes = {r1, r2};
  ro.normal_modes = 0;
  EXPECT_EQ(reduction::BuildCraigBamptonBasis(mesh, a, ro).static_modes(), 12);
}

}  // namespace flexmb::fe::linear_constraint_test
