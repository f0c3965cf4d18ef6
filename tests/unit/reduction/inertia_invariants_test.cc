// Inertia invariants of a reduced body (THEORY sections 3 and 4): M(w) from
// the invariants against the brute-force sum over node pairs of
// L_k(w)^T M_kl L_l(w), the mass properties at w = 0, the orthonormal
// basis, the kinetic energy of a rigid plus modal motion, the mean-axis
// conditions of a free body.

#include "flexmb/reduction/inertia_invariants.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/reduction/craig_bampton.h"
#include "tests/unit/reduction/reduction_test_models.h"

namespace flexmb::reduction {
namespace {

using fe::testing::AddBeam;
using fe::testing::AddNode;
using fe::testing::AddPointMass;
using fe::testing::AddRigidLink;
using fe::testing::AddRoundBar;
using fe::testing::Skew;
using testing::AddPlate;
using Mat6 = Eigen::Matrix<double, 6, 6>;

// shells (a plate turned by `rotation` and moved off the origin), a tube of
// three beams from a plate corner with a point mass (offset, full inertia
// tensor) at its tip, an RBE2 spider from a node above the plate to four
// plate nodes and a bracket carrying a point mass, and a translation-only
// link to a slider mass; interface: the spider's node and the tube's tip
struct MixedBody {
  fe::FeModel model;
  ReductionOptions options;
  std::vector<int> grid;
  int spider = -1, tip = -1;
};
MixedBody Mixed(const Mat3& rotation) {
  MixedBody b;
  fe::Mesh& mesh = b.model.mesh;
  b.grid = AddPlate(mesh, 4, 3, 0.4, 0.3, 0.004);
  const Vec3 shift(0.3, -0.2, 0.5);
  for (int g : b.grid) mesh.nodes[g].x = rotation * mesh.nodes[g].x + shift;
  const int bar = AddRoundBar(mesh, 0, 0.008);
  const Vec3 dir = rotation * Vec3(0.3, 0.2, 1.0).normalized();
  int prev = b.grid[4];
  for (int s = 1; s <= 3; ++s) {
    const int node = AddNode(mesh, mesh.nodes[b.grid[4]].x + 0.1 * s * dir);
    AddBeam(mesh, bar, prev, node, rotation * Vec3(1.0, 0.0, 0.0));
    prev = node;
  }
  b.tip = prev;
  Mat3 j;
  j << 2e-3, 3e-4, -2e-4, 3e-4, 1.5e-3, 1e-4, -2e-4, 1e-4, 1e-3;
  AddPointMass(mesh, b.tip, 0.8, Vec3(0.02, -0.03, 0.04), j);
  b.spider = AddNode(mesh, rotation * Vec3(0.2, 0.15, 0.05) + shift);
  const int bracket = AddNode(mesh, rotation * Vec3(0.25, 0.1, -0.06) + shift);
  AddPointMass(mesh, bracket, 0.5, Vec3(0.01, 0.0, 0.02), Vec3(1e-3, 2e-3, 1.5e-3).asDiagonal());
  AddRigidLink(mesh, 1, b.spider, {b.grid[6], b.grid[8], b.grid[11], b.grid[13], bracket});
  const int slider = AddNode(mesh, rotation * Vec3(-0.05, 0.0, 0.0) + shift);
  AddPointMass(mesh, slider, 0.3);
  AddRigidLink(mesh, 2, b.grid[0], {slider}, 0b000111);
  b.options.interface_nodes = {b.spider, b.tip};
  b.options.normal_modes = 6;
  return b;
}

// the brute-force M(w) of THEORY sections 3 and 4: L_k(w) for every node
// and the dense 6 x 6 blocks M_kl of M_full, summed over all node pairs
MatX BruteForceMass(const fe::Mesh& mesh, const fe::AssembledModel& a, const MatX& modes, const VecX& w) {
  const int nn = static_cast<int>(mesh.nodes.size());
  const int n = static_cast<int>(modes.cols());
  const MatX mf(a.M_full);
  std::vector<MatX> l(nn);
  for (int k = 0; k < nn; ++k) {
    const MatX ht = modes.block(6 * k, 0, 3, n), hr = modes.block(6 * k + 3, 0, 3, n);
    const Vec3 u = mesh.nodes[k].x + ht * w;
    l[k] = MatX::Zero(6, 6 + n);
    l[k].block(0, 0, 3, 3).setIdentity();
    l[k].block(0, 3, 3, 3) = -Skew(u);
    l[k].block(0, 6, 3, n) = ht;
    l[k].block(3, 3, 3, 3).setIdentity();
    l[k].block(3, 6, 3, n) = hr;
  }
  MatX m = MatX::Zero(6 + n, 6 + n);
  for (int k = 0; k < nn; ++k) {
    for (int q = 0; q < nn; ++q) {
      Mat6 mkq = Mat6::Zero();
      for (int c = 0; c < 6; ++c) {
        for (int d = 0; d < 6; ++d) {
          const int f = a.dofs.full[k][c], g = a.dofs.full[q][d];
          if (f >= 0 && g >= 0) mkq(c, d) = mf(f, g);
        }
      }
      if (mkq.isZero(0.0)) continue;
      m += l[k].transpose() * mkq * l[q];
    }
  }
  return m;
}

double MaxAbs(const MatX& m) { return m.cwiseAbs().maxCoeff(); }

// The model with every point mass that has an offset moved onto a node of
// its own at node + offset (the same mass and rotary inertia, no offset),
// assembled, and mode rows for those nodes: a point carried by the node
// moves with u + theta x e and turns with theta. On this model the
// node-by-node sums of THEORY section 4 are exact for the point masses,
// which is what the invariants of the original model must give
// (docs/design.md, "Inertia of the nodes' rotations").
struct Exploded {
  fe::FeModel model;
  fe::AssembledModel a;
  MatX modes;
};
Exploded Explode(const fe::FeModel& model, const MatX& modes, const std::vector<int>& fixed = {}) {
  Exploded x;
  x.model = model;
  fe::Mesh& mesh = x.model.mesh;
  const Eigen::Index rows = modes.rows();
  std::vector<std::pair<int, Vec3>> carried;  // carrying node, offset
  for (fe::PointMass& pm : mesh.point_masses) {
    if (pm.general || !(pm.mass > 0.0) || pm.offset.squaredNorm() == 0.0) continue;
    carried.emplace_back(pm.node, pm.offset);
    pm.node = AddNode(mesh, mesh.nodes[pm.node].x + pm.offset);
    pm.offset.setZero();
  }
  x.modes = MatX::Zero(rows + 6 * static_cast<Eigen::Index>(carried.size()), modes.cols());
  x.modes.topRows(rows) = modes;
  for (size_t p = 0; p < carried.size(); ++p) {
    const Eigen::Index k = 6 * carried[p].first, r = rows + 6 * static_cast<Eigen::Index>(p);
    x.modes.middleRows(r, 3) = modes.middleRows(k, 3) - Skew(carried[p].second) * modes.middleRows(k + 3, 3);
    x.modes.middleRows(r + 3, 3) = modes.middleRows(k + 3, 3);
  }
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = fixed;
  x.a = fe::BuildMatrices(x.model, o);
  return x;
}

fe::AssembledModel AssembleFor(const MixedBody& b) {
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = b.options.fixed_nodes;
  return fe::BuildMatrices(b.model, o);
}

// M(w) from the invariants equals the brute-force double sum, for the
// reduced body's modes (free and clamped) and for arbitrary mode shapes
TEST(InertiaInvariants, MassMatrixEqualsBruteForceSum) {
  for (unsigned seed : {0u, 11u}) {
    const Mat3 rotation = seed == 0 ? Mat3::Identity() : fe::testing::RandomRotation(seed);
    for (bool clamped : {false, true}) {
      MixedBody b = Mixed(rotation);
      if (clamped) b.options.fixed_nodes = {b.grid[19]};
      const ReducedBody body = ReduceCraigBampton(b.model, b.options);
      const fe::AssembledModel a = AssembleFor(b);
      const int n = static_cast<int>(body.modes.cols());
      ASSERT_EQ(body.invariants.n, n);
      std::srand(seed + 3);
      const MatX random_modes = 0.2 * MatX::Random(body.modes.rows(), 5);
      const InertiaInvariants random_inv = ComputeInertiaInvariants(b.model.mesh, a, random_modes);
      const Exploded xb = Explode(b.model, body.modes, b.options.fixed_nodes);
      const Exploded xr = Explode(b.model, random_modes, b.options.fixed_nodes);
      for (int trial = 0; trial < 4; ++trial) {
        const std::string what = "seed " + std::to_string(seed) + (clamped ? " clamped" : " free") + " trial " +
                                 std::to_string(trial);
        // mode amplitudes that move nodes by centimetres
        const VecX w = trial == 0 ? VecX::Zero(n) : VecX(0.05 * VecX::Random(n));
        const MatX reference = BruteForceMass(xb.model.mesh, xb.a, xb.modes, w);
        const MatX m = MassMatrix(body.invariants, w);
        EXPECT_LE(MaxAbs(m - reference), 1e-12 * MaxAbs(reference)) << what;
        if (trial > 0) {
          // the test sees the dependence on w
          EXPECT_GT(MaxAbs(reference - BruteForceMass(xb.model.mesh, xb.a, xb.modes, VecX::Zero(n))),
                    1e-4 * MaxAbs(reference))
              << what;
        }
        const VecX wr = VecX::Random(5);
        const MatX rr = BruteForceMass(xr.model.mesh, xr.a, xr.modes, wr);
        EXPECT_LE(MaxAbs(MassMatrix(random_inv, wr) - rr), 1e-12 * MaxAbs(rr)) << what << " random modes";
        EXPECT_GT(MaxAbs(rr - BruteForceMass(xr.model.mesh, xr.a, xr.modes, VecX::Zero(5))), 1e-2 * MaxAbs(rr));
      }
    }
  }
}

// every invariant against its definition in reduced_body.h, with the
// columns E, Omega0, Omega1_i and H of L formed densely on the full DOF
// (pins the conventions M(w) cannot see, e.g. moo2[i n + j] against its
// transpose)
TEST(InertiaInvariants, InvariantsMatchTheirDefinitions) {
  const MixedBody b = Mixed(fe::testing::RandomRotation(19));
  const int n = 4;
  std::srand(23);
  const MatX original_modes = 0.3 * MatX::Random(6 * static_cast<Eigen::Index>(b.model.mesh.nodes.size()), n);
  const InertiaInvariants inv = ComputeInertiaInvariants(b.model.mesh, AssembleFor(b), original_modes);
  // the definitions on the model with the offset point masses on nodes of their own
  const Exploded x = Explode(b.model, original_modes);
  const fe::AssembledModel& a = x.a;
  const fe::Mesh& mesh = x.model.mesh;
  const MatX& modes = x.modes;
  const int nn = static_cast<int>(mesh.nodes.size()), nf = a.dofs.n_full;
  MatX e = MatX::Zero(nf, 3), o0 = MatX::Zero(nf, 3), h = MatX::Zero(nf, n);
  std::vector<MatX> o1(n, MatX::Zero(nf, 3));
  for (int k = 0; k < nn; ++k) {
    const Mat3 s0 = -Skew(mesh.nodes[k].x);
    for (int c = 0; c < 6; ++c) {
      const int f = a.dofs.full[k][c];
      if (f < 0) continue;
      h.row(f) = modes.row(6 * k + c);
      if (c < 3) {
        e(f, c) = 1.0;
        o0.row(f) = s0.row(c);
        for (int i = 0; i < n; ++i) o1[i].row(f) = -Skew(modes.block(6 * k, i, 3, 1)).row(c);
      } else {
        o0(f, c - 3) = 1.0;
      }
    }
  }
  const MatX m(a.M_full);
  const double scale = MaxAbs(m) * (1.0 + MaxAbs(o0)) * (1.0 + MaxAbs(o0)) * nf;
  auto expect = [&](const MatX& got, const MatX& want, const std::string& what) {
    ASSERT_EQ(got.rows(), want.rows()) << what;
    ASSERT_EQ(got.cols(), want.cols()) << what;
    EXPECT_LE(MaxAbs(got - want), 1e-14 * scale) << what;
    EXPECT_GT(MaxAbs(want), 1e-6 * scale) << what << " is not exercised";
  };
  expect(inv.mvv, e.transpose() * m * e, "mvv");
  expect(inv.mvo0, e.transpose() * m * o0, "mvo0");
  expect(inv.mvw, e.transpose() * m * h, "mvw");
  expect(inv.moo0, o0.transpose() * m * o0, "moo0");
  expect(inv.mow0, o0.transpose() * m * h, "mow0");
  expect(inv.mww, h.transpose() * m * h, "mww");
  for (int i = 0; i < n; ++i) {
    const std::string id = "[" + std::to_string(i) + "]";
    expect(inv.mvo1[i], e.transpose() * m * o1[i], "mvo1" + id);
    expect(inv.moo1[i], o0.transpose() * m * o1[i] + o1[i].transpose() * m * o0, "moo1" + id);
    expect(inv.mow1[i], o1[i].transpose() * m * h, "mow1" + id);
    for (int j = 0; j < n; ++j) {
      expect(inv.moo2[i * n + j], o1[i].transpose() * m * o1[j], "moo2[" + std::to_string(i * n + j) + "]");
    }
  }
}

// w = 0: the total mass, the first moment (-m skew(c)) and the inertia
// about the origin, against fe::ComputeMassProperties
TEST(InertiaInvariants, RigidBlocksGiveTheMassProperties) {
  const MixedBody b = Mixed(fe::testing::RandomRotation(5));
  const ReducedBody body = ReduceCraigBampton(b.model, b.options);
  const fe::MassProperties p = fe::ComputeMassProperties(b.model.mesh, fe::Assemble(b.model.mesh));
  const InertiaInvariants& inv = body.invariants;
  const Mat3 sc = Skew(p.center);
  const Mat3 j_origin = p.inertia - p.mass * sc * sc;
  EXPECT_LE((inv.mvv - p.mass * Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-13 * p.mass);
  EXPECT_LE((inv.mvo0 + p.mass * sc).cwiseAbs().maxCoeff(), 1e-13 * p.mass * p.center.norm());
  EXPECT_LE((inv.moo0 - j_origin).cwiseAbs().maxCoeff(), 1e-13 * j_origin.norm());
}

// point masses with offsets and inertia on nodes, one on a dependent node
// of a rigid link: the rigid blocks by hand, sum m, sum m p, sum (J_c + m
// (p.p I - p p^T)) with p = node + offset
TEST(InertiaInvariants, RigidBlocksOfPointMassesByHand) {
  fe::Mesh mesh;
  mesh.source = "masses.bdf";
  const int n0 = AddNode(mesh, Vec3(0.3, -0.1, 0.2));
  const int n1 = AddNode(mesh, Vec3(-0.4, 0.5, 0.1));
  const int n2 = AddNode(mesh, Vec3(0.1, 0.2, -0.7));
  Mat3 j0;
  j0 << 0.3, 0.02, -0.01, 0.02, 0.2, 0.03, -0.01, 0.03, 0.25;
  AddPointMass(mesh, n0, 4.0, Vec3(0.05, 0.1, -0.02), j0);
  AddPointMass(mesh, n1, 2.5);
  AddPointMass(mesh, n2, 1.5, Vec3(-0.1, 0.0, 0.3), Vec3(0.1, 0.12, 0.05).asDiagonal());
  AddRigidLink(mesh, 1, n0, {n2});
  const fe::AssembledModel a = fe::Assemble(mesh);
  double m = 0.0;
  Vec3 s = Vec3::Zero();
  Mat3 j = Mat3::Zero();
  for (const fe::PointMass& pm : mesh.point_masses) {
    const Vec3 p = mesh.nodes[pm.node].x + pm.offset;
    m += pm.mass;
    s += pm.mass * p;
    j += pm.inertia + pm.mass * (p.dot(p) * Mat3::Identity() - p * p.transpose());
  }
  std::srand(4);
  const MatX modes = MatX::Random(6 * 3, 2);
  const InertiaInvariants inv = ComputeInertiaInvariants(mesh, a, modes);
  EXPECT_LE((inv.mvv - m * Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-14 * m);
  EXPECT_LE((inv.mvo0 + Skew(s)).cwiseAbs().maxCoeff(), 1e-14 * s.norm());
  EXPECT_LE((inv.moo0 - j).cwiseAbs().maxCoeff(), 1e-14 * j.norm());
  // no modes: the rigid blocks alone, a 6 x 6 rigid-body mass matrix
  const InertiaInvariants rigid = ComputeInertiaInvariants(mesh, a, MatX(18, 0));
  EXPECT_EQ(rigid.n, 0);
  const MatX m6 = MassMatrix(rigid, VecX(0));
  ASSERT_EQ(m6.rows(), 6);
  EXPECT_EQ(m6.block(0, 0, 3, 3), inv.mvv);
  EXPECT_EQ(m6.block(3, 3, 3, 3), inv.moo0);
}

// the reduced body's basis is mass-orthonormal: M_ww = I
TEST(InertiaInvariants, OrthonormalBasisGivesIdentityModalMass) {
  for (bool clamped : {false, true}) {
    MixedBody b = Mixed(fe::testing::RandomRotation(7));
    if (clamped) b.options.fixed_nodes = {b.grid[19]};
    const ReducedBody body = ReduceCraigBampton(b.model, b.options);
    const int n = body.invariants.n;
    ASSERT_GT(n, 0);
    EXPECT_LE(MaxAbs(body.invariants.mww - MatX::Identity(n, n)), 1e-12) << (clamped ? "clamped" : "free");
  }
}

// 1/2 nu^T M(w) nu equals 1/2 v_n^T M_full v_n with the nodal velocities
// of a rigid motion (r', omega) plus the modal velocity w' at the deformed
// configuration w, nu = (R^T r', omega, w') in body components
TEST(InertiaInvariants, KineticEnergyOfRigidPlusModalMotion) {
  const MixedBody b = Mixed(fe::testing::RandomRotation(9));
  const ReducedBody body = ReduceCraigBampton(b.model, b.options);
  // the kinetic energy of the point masses at their own places
  const Exploded x = Explode(b.model, body.modes);
  const fe::AssembledModel& a = x.a;
  const fe::Mesh& mesh = x.model.mesh;
  const int n = body.invariants.n;
  const MatX& h = x.modes;
  for (unsigned trial = 0; trial < 5; ++trial) {
    std::srand(100 + trial);
    const Mat3 r = fe::testing::RandomRotation(200 + trial);
    const Vec3 rdot = Vec3::Random(), omega = 3.0 * Vec3::Random();
    const VecX w = 0.05 * VecX::Random(n), wdot = VecX::Random(n);
    const Vec3 v = r.transpose() * rdot;
    VecX vn = VecX::Zero(a.dofs.n_full);
    for (size_t k = 0; k < mesh.nodes.size(); ++k) {
      const Eigen::Index row = 6 * static_cast<Eigen::Index>(k);
      const Vec3 u = mesh.nodes[k].x + h.block(row, 0, 3, n) * w;
      const Vec3 vk = v + omega.cross(u) + h.block(row, 0, 3, n) * wdot;
      const Vec3 ok = omega + h.block(row + 3, 0, 3, n) * wdot;
      for (int c = 0; c < 6; ++c) {
        const int f = a.dofs.full[k][c];
        if (f >= 0) vn[f] = c < 3 ? vk[c] : ok[c - 3];
      }
    }
    const double reference = 0.5 * vn.dot(a.M_full * vn);
    VecX nu(6 + n);
    nu << v, omega, wdot;
    const double energy = 0.5 * nu.dot(MassMatrix(body.invariants, w) * nu);
    EXPECT_NEAR(energy, reference, 1e-12 * reference) << "trial " << trial;
  }
}

// a free body's flexible modes are mass-orthogonal to the rigid motions
// (mean-axis frame): M_vw = 0 and M_ow(0) = 0; a clamped body's are not
TEST(InertiaInvariants, MeanAxisConditionsOfAFreeBody) {
  for (bool clamped : {false, true}) {
    MixedBody b = Mixed(fe::testing::RandomRotation(13));
    if (clamped) b.options.fixed_nodes = {b.grid[19]};
    const ReducedBody body = ReduceCraigBampton(b.model, b.options);
    const InertiaInvariants& inv = body.invariants;
    // |E_a^T M h_i| <= sqrt(m) and |Omega0_a^T M h_i| <= sqrt(J_aa) for M-unit modes
    const double sv = std::sqrt(inv.mvv.trace() / 3.0), so = std::sqrt(inv.moo0.trace());
    if (clamped) {
      EXPECT_GT(MaxAbs(inv.mvw), 1e-2 * sv);
      EXPECT_GT(MaxAbs(inv.mow0), 1e-2 * so);
    } else {
      EXPECT_LE(MaxAbs(inv.mvw), 1e-10 * sv);
      EXPECT_LE(MaxAbs(inv.mow0), 1e-10 * so);
    }
  }
}

// exact symmetries, writing into a block of a larger matrix, bad sizes
TEST(InertiaInvariants, SymmetryAndInPlaceEvaluation) {
  const MixedBody b = Mixed(fe::testing::RandomRotation(17));
  const ReducedBody body = ReduceCraigBampton(b.model, b.options);
  const InertiaInvariants& inv = body.invariants;
  const int n = inv.n;
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(inv.moo1[i], inv.moo1[i].transpose());
    for (int j = 0; j < n; ++j) EXPECT_EQ(inv.moo2[j * n + i], inv.moo2[i * n + j].transpose());
  }
  EXPECT_EQ(inv.mww, inv.mww.transpose());
  std::srand(21);
  const VecX w = 0.05 * VecX::Random(n);
  const MatX m = MassMatrix(inv, w);
  EXPECT_EQ(m, m.transpose());
  // into the middle of a larger matrix, w a segment of a longer vector
  MatX big = MatX::Constant(6 + n + 4, 6 + n + 5, 7.0);
  VecX state = VecX::Random(n + 3);
  state.segment(2, n) = w;
  MassMatrix(inv, state.segment(2, n), big.block(1, 2, 6 + n, 6 + n));
  EXPECT_EQ(MatX(big.block(1, 2, 6 + n, 6 + n)), m);
  EXPECT_EQ(big.row(0), MatX::Constant(1, 6 + n + 5, 7.0));
  EXPECT_EQ(big.col(1), MatX::Constant(6 + n + 4, 1, 7.0));
  MatX wrong(6 + n, 5 + n);
  EXPECT_THROW(MassMatrix(inv, w, wrong), InputError);
  EXPECT_THROW(MassMatrix(inv, VecX::Zero(n + 1)), InputError);
  InertiaInvariants short_moo2 = inv, narrow_mow1 = inv;
  short_moo2.moo2.pop_back();
  narrow_mow1.mow1[1].resize(3, n - 1);
  EXPECT_THROW(MassMatrix(short_moo2, w), InputError);
  EXPECT_THROW(MassMatrix(narrow_mow1, w), InputError);
  const fe::AssembledModel a = AssembleFor(b);
  EXPECT_THROW(ComputeInertiaInvariants(b.model.mesh, a, MatX::Zero(body.modes.rows() - 6, 2)), InputError);
  const MatX wrong_mass = MatX::Identity(n + 1, n + 1);
  EXPECT_THROW(ComputeInertiaInvariants(b.model.mesh, a, body.modes, &wrong_mass), InputError);
}

// ReduceCraigBampton hands in its modal mass y^T M_CB y as mww; formed
// from M_full instead it agrees to round-off, and a given modal mass
// changes nothing else
TEST(InertiaInvariants, GivenModalMassReplacesOnlyMww) {
  const MixedBody b = Mixed(fe::testing::RandomRotation(29));
  const ReducedBody body = ReduceCraigBampton(b.model, b.options);
  const fe::AssembledModel a = AssembleFor(b);
  const int n = body.invariants.n;
  const InertiaInvariants formed = ComputeInertiaInvariants(b.model.mesh, a, body.modes);
  EXPECT_LE(MaxAbs(formed.mww - body.invariants.mww), 1e-13);
  std::srand(31);
  const MatX given = MatX::Random(n, n);
  const InertiaInvariants inv = ComputeInertiaInvariants(b.model.mesh, a, body.modes, &given);
  EXPECT_EQ(inv.mww, MatX(0.5 * (given + given.transpose())));
  const double tol = 1e-14 * MaxAbs(formed.mow0);
  EXPECT_EQ(inv.mvw, formed.mvw);
  EXPECT_EQ(inv.mow0, formed.mow0);
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(inv.mvo1[i], formed.mvo1[i]);
    EXPECT_EQ(inv.moo1[i], formed.moo1[i]);
    EXPECT_LE(MaxAbs(inv.mow1[i] - formed.mow1[i]), tol);
    for (int j = 0; j < n; ++j) EXPECT_EQ(inv.moo2[i * n + j], formed.moo2[i * n + j]);
  }
}

}  // namespace
}  // namespace flexmb::reduction
