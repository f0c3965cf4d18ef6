#include "flexmb/fe/assembly.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "flexmb/common/error.h"
#include "flexmb/fe/point_mass.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace {

using testing::AddBeam;
using testing::AddConstraint;
using testing::AddElement;
using testing::AddMaterial;
using testing::AddNode;
using testing::AddPointMass;
using testing::AddRigidLink;
using testing::AddRoundBar;
using testing::Skew;

// beams 0-1-2, a shell 1-2-3-4, a tetrahedron 5-6-7-8 whose nodes 5 and 6
// hang on node 2 by a rigid link, a point mass with inertia at node 7,
// node 0 clamped and ux of node 8 fixed
Mesh MixedModel() {
  Mesh mesh;
  const int steel = AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  const int alu = AddMaterial(mesh, 7.0e10, 0.33, 2700.0);
  const int bar = AddRoundBar(mesh, steel, 0.02);
  ShellSection shell;
  shell.id = 1;
  shell.material = alu;
  shell.thickness = 0.004;
  mesh.shell_sections.push_back(shell);
  SolidSection solid;
  solid.id = 2;
  solid.material = alu;
  mesh.solid_sections.push_back(solid);
  for (const Vec3& x : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(3, 0, 0),
                        Vec3(4, 0.1, 0), Vec3(3, 1, 0.2), Vec3(3.1, 0, 1)}) {
    AddNode(mesh, x);
  }
  AddBeam(mesh, bar, 0, 1, Vec3(0, 1, 0));
  AddBeam(mesh, bar, 1, 2, Vec3(0, 0.3, 1));
  AddElement(mesh, ElementType::kQuad4, 0, {1, 2, 3, 4});
  AddElement(mesh, ElementType::kTet4, 0, {5, 6, 7, 8});
  Mat3 inertia;
  inertia << 0.2, 0.01, 0.0, 0.01, 0.3, -0.02, 0.0, -0.02, 0.25;
  AddPointMass(mesh, 7, 4.0, Vec3(0.1, -0.2, 0.3), inertia);
  AddRigidLink(mesh, 7, 2, {5, 6});
  AddConstraint(mesh, 0, 0b111111);
  AddConstraint(mesh, 8, 0b000001);
  return mesh;
}

// mass and centre from the assembled mass matrix, consistent and lumped,
// against the analytic values
void ExpectMassAndCenter(const Mesh& mesh, double m, const Vec3& center) {
  for (MassForm form : {MassForm::kConsistent, MassForm::kLumped}) {
    AssemblyOptions options;
    options.mass_form = form;
    const MassProperties p = ComputeMassProperties(mesh, Assemble(mesh, options));
    EXPECT_NEAR(p.mass, m, 1e-13 * m);
    EXPECT_LT((p.center - center).norm(), 1e-13);
  }
}

TEST(Assembly, MixedModelNumbering) {
  const Mesh mesh = MixedModel();
  const AssembledModel model = Assemble(mesh);
  const DofMap& dm = model.dofs;
  // nodes 0-4: 6 slots; 5, 6, 8: translations (solid only); 7: 6 (point mass with inertia)
  EXPECT_EQ(dm.n_full, 5 * 6 + 3 + 3 + 6 + 3);
  // minus node 0 (6), translations of 5 and 6 (dependent), ux of 8
  EXPECT_EQ(dm.n_free, dm.n_full - 6 - 6 - 1);
  for (int n : {5, 6, 8}) {
    for (int c = 3; c < 6; ++c) EXPECT_EQ(dm.full[n][c], -1) << "node " << n;
  }
  for (int c = 0; c < 6; ++c) EXPECT_EQ(dm.free[0][c], -1);
  EXPECT_EQ(dm.free[8][0], -1);
  EXPECT_GE(dm.free[8][1], 0);
  // the numbering is a bijection onto 0..n-1
  std::vector<int> seen_full(dm.n_full, 0), seen_free(dm.n_free, 0);
  for (size_t n = 0; n < dm.full.size(); ++n) {
    for (int c = 0; c < 6; ++c) {
      if (dm.full[n][c] >= 0) seen_full[dm.full[n][c]]++;
      if (dm.free[n][c] >= 0) {
        seen_free[dm.free[n][c]]++;
        EXPECT_GE(dm.full[n][c], 0);
      }
    }
  }
  for (int s : seen_full) EXPECT_EQ(s, 1);
  for (int s : seen_free) EXPECT_EQ(s, 1);
}

// K and M against a dense assembly of the same element matrices with a
// rigid-link matrix built here from u_dep = u_ind + theta_ind x (x_dep - x_ind)
TEST(Assembly, MixedModelMatchesDenseReference) {
  const Mesh mesh = MixedModel();
  for (MassForm form : {MassForm::kConsistent, MassForm::kLumped}) {
    AssemblyOptions options;
    options.mass_form = form;
    const AssembledModel model = Assemble(mesh, options);
    const DofMap& dm = model.dofs;
    Eigen::MatrixXd kf = Eigen::MatrixXd::Zero(dm.n_full, dm.n_full), mf = kf;
    for (const Element& e : mesh.elements) {
      std::vector<Vec3> x;
      for (int n : e.nodes) x.push_back(mesh.nodes[n].x);
      ElementInput in;
      in.element = &e;
      in.x = x.data();
      in.mass_form = form;
      if (e.type == ElementType::kBeam2) {
        in.beam = &mesh.beam_sections[e.property];
        in.material = &mesh.materials[in.beam->material];
      } else if (e.type == ElementType::kQuad4) {
        in.shell = &mesh.shell_sections[e.property];
        in.material = &mesh.materials[in.shell->material];
      } else {
        in.material = &mesh.materials[mesh.solid_sections[e.property].material];
      }
      MatX ke, me;
      ElementMatrices(in, ke, me);
      const int dpn = DofsPerNode(e.type);
      for (int a = 0; a < static_cast<int>(e.nodes.size()); ++a)
        for (int b = 0; b < static_cast<int>(e.nodes.size()); ++b)
          for (int i = 0; i < dpn; ++i)
            for (int j = 0; j < dpn; ++j) {
              const int fi = dm.full[e.nodes[a]][i], fj = dm.full[e.nodes[b]][j];
              ASSERT_GE(fi, 0);
              ASSERT_GE(fj, 0);
              kf(fi, fj) += ke(a * dpn + i, b * dpn + j);
              mf(fi, fj) += me(a * dpn + i, b * dpn + j);
            }
    }
    const Mat6 pm = PointMassMatrix(mesh.point_masses[0]);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) mf(dm.full[7][i], dm.full[7][j]) += pm(i, j);

    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(dm.n_full, dm.n_free);
    for (int n = 0; n < static_cast<int>(mesh.nodes.size()); ++n)
      for (int c = 0; c < 6; ++c)
        if (dm.free[n][c] >= 0) t(dm.full[n][c], dm.free[n][c]) = 1.0;
    for (int d : {5, 6}) {
      const Vec3 r = mesh.nodes[d].x - mesh.nodes[2].x;
      for (int c = 0; c < 6; ++c) {
        Vec3 u = Vec3::Zero(), theta = Vec3::Zero();
        (c < 3 ? u : theta)[c % 3] = 1.0;
        const Vec3 ud = u + theta.cross(r);
        for (int i = 0; i < 3; ++i) t(dm.full[d][i], dm.free[2][c]) = ud[i];
      }
    }
    EXPECT_LT((Eigen::MatrixXd(model.T) - t).cwiseAbs().maxCoeff(), 1e-15);
    const Eigen::MatrixXd kref = t.transpose() * kf * t, mref = t.transpose() * mf * t;
    EXPECT_LT((Eigen::MatrixXd(model.K) - kref).cwiseAbs().maxCoeff(), 1e-12 * kref.cwiseAbs().maxCoeff());
    EXPECT_LT((Eigen::MatrixXd(model.M) - mref).cwiseAbs().maxCoeff(), 1e-12 * mref.cwiseAbs().maxCoeff());
    const Eigen::MatrixXd kd = Eigen::MatrixXd(model.K), md = Eigen::MatrixXd(model.M);
    EXPECT_EQ((kd - kd.transpose()).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((md - md.transpose()).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(Assembly, OptionsForConstraintsAndFixedNodes) {
  const Mesh mesh = MixedModel();
  AssemblyOptions free_model;
  free_model.apply_constraints = false;
  const AssembledModel a = Assemble(mesh, free_model);
  EXPECT_EQ(a.dofs.n_free, a.dofs.n_full - 6);
  AssemblyOptions fixed = free_model;
  fixed.extra_fixed_nodes = {3, 8};
  const AssembledModel b = Assemble(mesh, fixed);
  EXPECT_EQ(b.dofs.n_free, a.dofs.n_free - 6 - 3);
  for (int c = 0; c < 6; ++c) EXPECT_EQ(b.dofs.free[3][c], -1);
}

// a rigid link between point masses is one rigid body: the 6 x 6 mass at the
// independent node and the mass properties match the analytic sums
// A distributed assembly gives each process a share of the blocks: the
// matrices of the shares (elements, the point mass, in two subsets) sum to
// the whole model's K, M and M_full, with the same DOF map and T; a subset
// of the wrong size is refused.
TEST(Assembly, BlockSubsetsSumToTheWholeModel) {
  const Mesh mesh = MixedModel();
  const AssembledModel whole = Assemble(mesh);
  const size_t blocks = mesh.elements.size() + mesh.point_masses.size() + mesh.springs.size();
  AssemblyOptions a, b;
  a.block_subset.assign(blocks, 0);
  b.block_subset.assign(blocks, 1);
  for (size_t k = 0; k < blocks; k += 2) {
    a.block_subset[k] = 1;
    b.block_subset[k] = 0;
  }
  const AssembledModel pa = Assemble(mesh, a), pb = Assemble(mesh, b);
  EXPECT_EQ(pa.dofs.n_free, whole.dofs.n_free);
  EXPECT_EQ((Eigen::MatrixXd(pa.T) - Eigen::MatrixXd(whole.T)).norm(), 0.0);
  const Eigen::MatrixXd k = Eigen::MatrixXd(whole.K), m = Eigen::MatrixXd(whole.M), mf = Eigen::MatrixXd(whole.M_full);
  // both shares hold something of K and M, and the point mass went to one
  for (const AssembledModel* p : {&pa, &pb}) {
    EXPECT_GT(Eigen::MatrixXd(p->K).norm(), 1e-6 * k.norm());
    EXPECT_GT(Eigen::MatrixXd(p->M).norm(), 1e-6 * m.norm());
  }
  EXPECT_LT((Eigen::MatrixXd(pa.K) + Eigen::MatrixXd(pb.K) - k).norm(), 1e-14 * k.norm());
  EXPECT_LT((Eigen::MatrixXd(pa.M) + Eigen::MatrixXd(pb.M) - m).norm(), 1e-14 * m.norm());
  EXPECT_LT((Eigen::MatrixXd(pa.M_full) + Eigen::MatrixXd(pb.M_full) - mf).norm(), 1e-14 * mf.norm());
  AssemblyOptions bad;
  bad.block_subset.assign(blocks + 1, 1);
  EXPECT_THROW(Assemble(mesh, bad), InputError);
}

TEST(Assembly, RigidLinkReproducesRigidBodyMass) {
  Mesh mesh;
  const Vec3 xa(0.2, -0.1, 0.3), xb(1.0, 2.0, -0.5), xc(-0.7, 0.4, 1.1);
  AddNode(mesh, xa);
  AddNode(mesh, xb);
  AddNode(mesh, xc);
  Mat3 ib;
  ib << 0.5, 0.05, -0.02, 0.05, 0.7, 0.01, -0.02, 0.01, 0.4;
  const Vec3 db(0.1, 0.2, -0.3);
  AddPointMass(mesh, 0, 0.5);
  AddPointMass(mesh, 1, 2.0, db, ib);
  AddPointMass(mesh, 2, 3.0);
  AddRigidLink(mesh, 1, 0, {1, 2});
  const AssembledModel model = Assemble(mesh);
  ASSERT_EQ(model.dofs.n_free, 6);

  // analytic: three particles (one with inertia) about their common centre
  const double m = 5.5;
  const Vec3 pb = xb + db;
  const Vec3 center = (0.5 * xa + 2.0 * pb + 3.0 * xc) / m;
  auto steiner = [&](double mi, const Vec3& p) {
    const Vec3 r = p - center;
    return Mat3(mi * (r.squaredNorm() * Mat3::Identity() - r * r.transpose()));
  };
  const Mat3 inertia = steiner(0.5, xa) + steiner(2.0, pb) + ib + steiner(3.0, xc);

  const MassProperties p = ComputeMassProperties(mesh, model);
  EXPECT_NEAR(p.mass, m, 1e-14 * m);
  EXPECT_LT((p.center - center).norm(), 1e-14);
  EXPECT_LT((p.inertia - inertia).cwiseAbs().maxCoeff(), 1e-13 * inertia.norm());

  // the reduced mass is the rigid body's mass matrix at node 0
  const Vec3 c = center - xa;
  Mat6 ref;
  ref << m * Mat3::Identity(), -m * Skew(c), m * Skew(c), inertia - m * Skew(c) * Skew(c);
  const Eigen::MatrixXd md(model.M);
  ASSERT_EQ(model.dofs.free[0][0], 0);
  EXPECT_LT((md - ref).cwiseAbs().maxCoeff(), 1e-13 * ref.norm());
}

// Two beams joined by a rigid link whose dependent node has all six DOF
// (rotations follow theta_dep = theta_ind, translations u_ind + theta x r),
// and a tetrahedron hanging on the second beam's end by a translations-only
// link: the free model has exactly six zero-energy modes, the rigid-body
// motions, which the link matrix T carries to every DOF of the full system,
// and the assembled mass has the parts' exact mass and centre.
TEST(Assembly, RigidLinksWithRotationsKeepExactlySixRigidModes) {
  Mesh mesh;
  const int steel = AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  const int bar = AddRoundBar(mesh, steel, 0.03);
  SolidSection solid;
  solid.material = steel;
  mesh.solid_sections.push_back(solid);
  const std::vector<Vec3> x = {{0.0, 0.0, 0.0}, {1.0, 0.1, 0.0},  {1.4, 0.3, 0.2},
                               {2.3, 0.2, 0.5}, {2.5, 0.2, 0.4},  {2.6, 0.6, 0.5},
                               {2.4, 0.4, 0.9}, {2.9, 0.7, 0.95}};
  for (const Vec3& p : x) AddNode(mesh, p);
  AddBeam(mesh, bar, 0, 1, Vec3(0, 0, 1));
  AddBeam(mesh, bar, 2, 3, Vec3(0, 1, 0));
  AddElement(mesh, ElementType::kTet4, 0, {4, 5, 6, 7});
  AddRigidLink(mesh, 1, 1, {2});
  AddRigidLink(mesh, 2, 3, {4, 5, 6}, 0b000111);
  Mat3 inertia;
  inertia << 0.02, 0.001, 0.0, 0.001, 0.03, 0.0, 0.0, 0.0, 0.025;
  AddPointMass(mesh, 0, 3.0, Vec3(0.05, -0.1, 0.02), inertia);
  const AssembledModel model = Assemble(mesh);
  const DofMap& dm = model.dofs;
  // node 2's six DOF and the translations of 4, 5, 6 are dependent
  EXPECT_EQ(dm.n_free, dm.n_full - 6 - 9);

  // rigid motion in free coordinates, and in full coordinates for T
  auto rigid = [&](bool full) {
    const auto& index = full ? dm.full : dm.free;
    Eigen::MatrixXd r = Eigen::MatrixXd::Zero(full ? dm.n_full : dm.n_free, 6);
    for (size_t n = 0; n < x.size(); ++n)
      for (int c = 0; c < 6; ++c) {
        if (index[n][c] < 0) continue;
        for (int a = 0; a < 6; ++a) {
          Vec3 u = Vec3::Zero(), th = Vec3::Zero();
          (a < 3 ? u : th)[a % 3] = 1.0;
          r(index[n][c], a) = c < 3 ? (u + th.cross(x[n]))[c] : th[c - 3];
        }
      }
    return r;
  };
  const Eigen::MatrixXd r_free = rigid(false), r_full = rigid(true);
  EXPECT_LT((model.T * r_free - r_full).cwiseAbs().maxCoeff(), 1e-14);
  const Eigen::MatrixXd k(model.K);
  EXPECT_LT((k * r_free).norm(), 1e-12 * k.norm() * r_free.norm());
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues();
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(ev(i)), 1e-11 * ev.maxCoeff()) << "eigenvalue " << i;
  EXPECT_GT(ev(6), 1e-9 * ev.maxCoeff());

  // mass and centre: bars (mass at their middle), tetrahedron (centroid), point mass
  const double rho_a = 7850.0 * mesh.beam_sections[bar].A;
  const double l1 = (x[1] - x[0]).norm(), l2 = (x[3] - x[2]).norm();
  const double v_tet = (x[5] - x[4]).cross(x[6] - x[4]).dot(x[7] - x[4]) / 6.0;
  ASSERT_GT(v_tet, 0.0);
  const double m = rho_a * (l1 + l2) + 7850.0 * v_tet + 3.0;
  const Vec3 center = (rho_a * l1 * 0.5 * (x[0] + x[1]) + rho_a * l2 * 0.5 * (x[2] + x[3]) +
                       7850.0 * v_tet * 0.25 * (x[4] + x[5] + x[6] + x[7]) +
                       3.0 * (x[0] + Vec3(0.05, -0.1, 0.02))) /
                      m;
  ExpectMassAndCenter(mesh, m, center);
}

// mass and centre of beams with point masses, consistent and lumped
TEST(Assembly, MassPropertiesOfBeamsExact) {
  Mesh mesh;
  const int steel = AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  const int bar = AddRoundBar(mesh, steel, 0.03);
  const double rho_a = 7850.0 * mesh.beam_sections[bar].A;
  const Vec3 x0(0, 0, 0), x1(2, 0, 0), x2(2, 1.5, 0), x3(2, 1.5, 1);
  for (const Vec3& x : {x0, x1, x2, x3}) AddNode(mesh, x);
  AddBeam(mesh, bar, 0, 1, Vec3(0, 1, 0));
  AddBeam(mesh, bar, 1, 2, Vec3(0, 0, 1));
  AddBeam(mesh, bar, 2, 3, Vec3(1, 0, 0));
  AddPointMass(mesh, 3, 10.0, Vec3(0, 0, 0.5));
  const double m = rho_a * (2.0 + 1.5 + 1.0) + 10.0;
  const Vec3 center =
      (rho_a * (2.0 * (x0 + x1) / 2 + 1.5 * (x1 + x2) / 2 + 1.0 * (x2 + x3) / 2) + 10.0 * (x3 + Vec3(0, 0, 0.5))) / m;
  ExpectMassAndCenter(mesh, m, center);
  AddConstraint(mesh, 0, 0b111111);
  EXPECT_THROW(ComputeMassProperties(mesh, Assemble(mesh)), InputError);
}

// the error message carries file:line and the entity
void ExpectInputError(const Mesh& mesh, const std::string& a, const std::string& b) {
  try {
    Assemble(mesh);
    FAIL() << "no error; expected one mentioning " << a;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(a), std::string::npos) << what;
    EXPECT_NE(what.find(b), std::string::npos) << what;
  }
}

TEST(Assembly, BadRigidLinks) {
  {
    Mesh mesh = MixedModel();
    mesh.rigid_links[0].dependent.push_back(99);
    ExpectInputError(mesh, "test.bdf:3007", "rigid link 7");
  }
  {
    Mesh mesh = MixedModel();
    mesh.rigid_links[0].independent = -1;
    ExpectInputError(mesh, "test.bdf:3007", "independent node does not exist");
  }
  {
    Mesh mesh = MixedModel();
    AddRigidLink(mesh, 8, 1, {6}, 0b000100);
    ExpectInputError(mesh, "test.bdf:3008", "already dependent in rigid link 7 (test.bdf:3007)");
  }
  {
    Mesh mesh = MixedModel();
    AddRigidLink(mesh, 9, 5, {4});
    ExpectInputError(mesh, "rigid link 9", "independent node 6 is itself dependent in rigid link 7");
  }
  {
    Mesh mesh = MixedModel();
    AddConstraint(mesh, 6, 0b000010);
    ExpectInputError(mesh, "rigid link 7", "dependent node 7 component uy is also fixed");
  }
  {
    // a fixed rotation of a solid node is not a DOF: no conflict
    Mesh mesh = MixedModel();
    AddConstraint(mesh, 6, 0b111000);
    EXPECT_NO_THROW(Assemble(mesh));
  }
}

TEST(Assembly, BadElementsAndMasses) {
  {
    Mesh mesh = MixedModel();
    mesh.elements[1].nodes[1] = 42;
    ExpectInputError(mesh, "test.bdf:1002", "2-node beam element 2");
  }
  {
    Mesh mesh = MixedModel();
    mesh.elements[0].property = 5;
    ExpectInputError(mesh, "test.bdf:1001", "no beam section");
  }
  {
    Mesh mesh = MixedModel();
    mesh.beam_sections[0].material = 3;
    ExpectInputError(mesh, "test.bdf:1001", "no material");
  }
  {
    Mesh mesh = MixedModel();
    mesh.point_masses[0].node = 20;
    ExpectInputError(mesh, "test.bdf:2001", "point mass 1");
  }
  {
    Mesh mesh = MixedModel();
    AssemblyOptions options;
    options.extra_fixed_nodes = {12};
    EXPECT_THROW(Assemble(mesh, options), InputError);
  }
}

}  // namespace
}  // namespace flexmb::fe
