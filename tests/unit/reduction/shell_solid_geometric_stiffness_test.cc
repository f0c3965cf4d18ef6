// Geometric stiffness of the shells and solids (Shell*/Solid*GeometricStiffness
// through reduction::AssembleGeometricStiffness and ComputeGeometricStiffness):
// - solids: K + KG against the central-difference tangent of an independent
//   total-Lagrangian internal force with an initial stress,
//   f = int (I + grad v) (S0 + D E(v)) dN dV (E Green-Lagrange), written here;
// - linearized buckling (K + P KG(1)) of a cantilever column of hex8 and of
//   tet10 against Euler's P = pi^2 E I / (4 L^2) with Engesser's shear
//   correction (nu = 0: with nu > 0 the clamped base face restrains the
//   Poisson contraction over the first element, a stiffening of order h / L
//   that only vanishes once h < b), of a cantilever plate strip of quad4 and of tria3 shells
//   against pi^2 E b t^3 / (48 L^2) (nu = 0), of a simply supported square
//   plate of quad4 under uniaxial compression against N = 4 pi^2 D / b^2
//   (Timoshenko and Gere, Theory of Elastic Stability, 2nd ed., 1961, sec. 9.2);
//   mesh-convergence shows the tolerances;
// - the flapping frequencies of a spinning cantilever meshed with shells and
//   with solids against the published beam values (Hodges and Rutkowski 1981,
//   docs/validation.md "Rotating beam: geometric stiffening"; the beam model
//   reproduces them to 2e-4 in geometric_stiffness_test.cc), absolute and as
//   the ratio to the non-rotating frequency (mesh error cancels).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe/elements/solid_tet10.h"
#include "flexmb/fe/elements/solid_tet4.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/geometric_stiffness.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::reduction {
namespace {

using GsField = std::function<fe::Vec3(const fe::Vec3&)>;

// ---------------------------------------------------------------- meshes

int GsAddShellSection(fe::Mesh& mesh, int material, double t) {
  fe::ShellSection s;
  s.id = static_cast<int>(mesh.shell_sections.size()) + 1;
  s.material = material;
  s.thickness = t;
  mesh.shell_sections.push_back(s);
  return static_cast<int>(mesh.shell_sections.size()) - 1;
}

int GsAddSolidSection(fe::Mesh& mesh, int material) {
  fe::SolidSection s;
  s.id = static_cast<int>(mesh.solid_sections.size()) + 1;
  s.material = material;
  mesh.solid_sections.push_back(s);
  return static_cast<int>(mesh.solid_sections.size()) - 1;
}

// grid of nodes (nx+1) (ny+1) (nz+1) over [0,a] x [0,b] x [0,c]; index i + (nx+1)(j + (ny+1) k)
std::vector<int> GsGridNodes(fe::Mesh& mesh, int nx, int ny, int nz, double a, double b, double c) {
  std::vector<int> id;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        id.push_back(fe::testing::AddNode(mesh, fe::Vec3(a * i / std::max(nx, 1), b * j / std::max(ny, 1),
                                                         c * k / std::max(nz, 1))));
  return id;
}

// box [0,a] x [0,b] x [0,L] of hex8 (or, `tet10`, six 10-node tetrahedra per cell)
fe::Mesh GsSolidColumn(int nx, int ny, int nz, double a, double b, double L, double E, double nu, double rho,
                       bool tet10) {
  fe::Mesh mesh;
  mesh.source = "column.bdf";
  const int sec = GsAddSolidSection(mesh, fe::testing::AddMaterial(mesh, E, nu, rho));
  const std::vector<int> id = GsGridNodes(mesh, nx, ny, nz, a, b, L);
  auto node = [&](int i, int j, int k) { return id[i + (nx + 1) * (j + (ny + 1) * k)]; };
  std::map<std::pair<int, int>, int> mid;
  auto midnode = [&](int p, int q) {
    const std::pair<int, int> key(std::min(p, q), std::max(p, q));
    auto it = mid.find(key);
    if (it != mid.end()) return it->second;
    const int m = fe::testing::AddNode(mesh, 0.5 * (mesh.nodes[p].x + mesh.nodes[q].x));
    mid[key] = m;
    return m;
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int c[8] = {node(i, j, k),         node(i + 1, j, k),         node(i + 1, j + 1, k),
                          node(i, j + 1, k),     node(i, j, k + 1),         node(i + 1, j, k + 1),
                          node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)};
        if (!tet10) {
          fe::testing::AddElement(mesh, fe::ElementType::kHex8, sec, std::vector<int>(c, c + 8));
          continue;
        }
        // six tetrahedra around the diagonal 0-6 (conforming between equal cells)
        const int tets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
        for (const auto& t : tets) {
          int v[4] = {c[t[0]], c[t[1]], c[t[2]], c[t[3]]};
          const fe::Vec3 x0 = mesh.nodes[v[0]].x;
          if ((mesh.nodes[v[1]].x - x0).cross(mesh.nodes[v[2]].x - x0).dot(mesh.nodes[v[3]].x - x0) < 0.0)
            std::swap(v[1], v[2]);
          fe::testing::AddElement(mesh, fe::ElementType::kTet10, sec,
                                  {v[0], v[1], v[2], v[3], midnode(v[0], v[1]), midnode(v[1], v[2]),
                                   midnode(v[2], v[0]), midnode(v[0], v[3]), midnode(v[1], v[3]),
                                   midnode(v[2], v[3])});
        }
      }
  return mesh;
}

// flat plate [0,a] x [0,b] in the x-y plane of quad4 (or two tria3 per cell)
fe::Mesh GsPlate(int nx, int ny, double a, double b, double t, double E, double nu, double rho, bool tria) {
  fe::Mesh mesh;
  mesh.source = "plate.bdf";
  const int sec = GsAddShellSection(mesh, fe::testing::AddMaterial(mesh, E, nu, rho), t);
  const std::vector<int> id = GsGridNodes(mesh, nx, ny, 0, a, b, 0.0);
  auto node = [&](int i, int j) { return id[i + (nx + 1) * j]; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int p = node(i, j), q = node(i + 1, j), r = node(i + 1, j + 1), s = node(i, j + 1);
      if (tria) {
        fe::testing::AddElement(mesh, fe::ElementType::kTria3, sec, {p, q, r});
        fe::testing::AddElement(mesh, fe::ElementType::kTria3, sec, {p, r, s});
      } else {
        fe::testing::AddElement(mesh, fe::ElementType::kQuad4, sec, {p, q, r, s});
      }
    }
  return mesh;
}

// ---------------------------------------------------------------- buckling

// lowest P with (K + P KG) x = 0, KG the geometric stiffness of the prestress
// field `field` (translations of every node; rotations zero), the model held
// by `options`: P = 1 / mu for the largest mu of -KG x = mu K x (power
// iteration on the dense Cholesky factor of K, Rayleigh quotient)
double GsLowestBucklingFactor(const fe::Mesh& mesh, const fe::AssemblyOptions& options, const GsField& field) {
  const fe::AssembledModel a = fe::Assemble(mesh, options);
  Eigen::VectorXd u_full = Eigen::VectorXd::Zero(a.dofs.n_full);
  for (size_t k = 0; k < mesh.nodes.size(); ++k) {
    const fe::Vec3 u = field(mesh.nodes[k].x);
    for (int c = 0; c < 3; ++c) {
      if (a.dofs.full[k][c] >= 0) u_full(a.dofs.full[k][c]) = u(c);
    }
  }
  const fe::SparseMat kg_full = AssembleGeometricStiffness(mesh, a.dofs, u_full);
  const Eigen::MatrixXd G = -Eigen::MatrixXd(a.T.transpose() * kg_full * a.T);
  const Eigen::MatrixXd K(a.K);
  const Eigen::LLT<Eigen::MatrixXd> llt(K);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(K.rows());
  double mu = 0.0, mu_old = 1.0;
  for (int it = 0; it < 500 && std::abs(mu - mu_old) > 1e-13 * std::abs(mu); ++it) {
    const Eigen::VectorXd y = llt.solve(G * x);
    mu_old = mu;
    mu = y.dot(K * y) > 0.0 ? y.dot(G * y) / y.dot(K * y) : 0.0;
    x = y / y.norm();
  }
  return 1.0 / mu;
}

// nodes with x(axis) == value
std::vector<int> GsNodesAt(const fe::Mesh& mesh, int axis, double value) {
  std::vector<int> out;
  for (size_t k = 0; k < mesh.nodes.size(); ++k) {
    if (std::abs(mesh.nodes[k].x(axis) - value) < 1e-12) out.push_back(static_cast<int>(k));
  }
  return out;
}

constexpr double kGsE = 2.0e11, kGsNu = 0.3;

// cantilever column b x b x L along z clamped at z = 0 under a homogeneous
// axial compression of 1 N (uniaxial stress: u = eps (nu x, nu y, -z))
double GsColumnBuckling(int n_section, int nz, bool tet10, double b, double L, double nu) {
  const fe::Mesh mesh = GsSolidColumn(n_section, n_section, nz, b, b, L, kGsE, nu, 7850.0, tet10);
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = GsNodesAt(mesh, 2, 0.0);
  const double eps = 1.0 / (kGsE * b * b);
  return GsLowestBucklingFactor(mesh, o, [eps, nu](const fe::Vec3& x) {
    return fe::Vec3(nu * eps * x.x(), nu * eps * x.y(), -eps * x.z());
  });
}

// Euler's load with Engesser's shear correction P = P_E / (1 + P_E / (k G A)), k = 5/6
double GsColumnReference(double b, double L, double nu) {
  const double pe = M_PI * M_PI * kGsE * std::pow(b, 4) / 12.0 / (4.0 * L * L);
  const double kga = 5.0 / 6.0 * kGsE / (2.0 * (1.0 + nu)) * b * b;
  return pe / (1.0 + pe / kga);
}

// measured P / P_ref - 1 (b = 0.05, L = 1, nu = 0; one element across):
// hex8 +1.63 % (5 along), +0.38 % (10), +0.072 % (20), 2 x 2 across the
// same; tet10 (6 per cell) +0.63 % (5), +0.092 % (10), -0.011 % (20):
// second order. With nu = 0.3: hex8 +1.13 %, +0.47 % (10, 20), first order
// (the clamped face's Poisson restraint), docs/validation.md.
TEST(ShellSolidGeometricStiffness, Hex8ColumnBucklesAtTheEulerLoad) {
  const double b = 0.05, L = 1.0, ref = GsColumnReference(b, L, 0.0);
  const double coarse = GsColumnBuckling(1, 10, false, b, L, 0.0) / ref - 1.0;
  const double fine = GsColumnBuckling(1, 20, false, b, L, 0.0) / ref - 1.0;
  std::printf("hex8 column: P / P_Euler-Engesser - 1 = %.5f (1 x 1 x 10), %.5f (1 x 1 x 20)\n", coarse, fine);
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_NEAR(fine, 0.0, 2e-3) << "coarse " << coarse;
}

TEST(ShellSolidGeometricStiffness, Tet10ColumnBucklesAtTheEulerLoad) {
  const double b = 0.05, L = 1.0, ref = GsColumnReference(b, L, 0.0);
  const double coarse = GsColumnBuckling(1, 5, true, b, L, 0.0) / ref - 1.0;
  const double fine = GsColumnBuckling(1, 10, true, b, L, 0.0) / ref - 1.0;
  std::printf("tet10 column: P / P_Euler-Engesser - 1 = %.5f (1 x 1 x 5 cells), %.5f (1 x 1 x 10)\n", coarse, fine);
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_NEAR(fine, 0.0, 2e-3) << "coarse " << coarse;
}

// cantilever strip L x b x t (x along L), clamped at x = 0, axial compression 1 N, nu = 0
double GsStripBuckling(int nx, bool tria, double L, double b, double t) {
  const fe::Mesh mesh = GsPlate(nx, 2, L, b, t, kGsE, 0.0, 7850.0, tria);
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = GsNodesAt(mesh, 0, 0.0);
  const double eps = 1.0 / (kGsE * b * t);
  return GsLowestBucklingFactor(mesh, o, [eps](const fe::Vec3& x) { return fe::Vec3(-eps * x.x(), 0.0, 0.0); });
}

TEST(ShellSolidGeometricStiffness, ShellStripBucklesAtTheEulerLoad) {
  const double L = 1.0, b = 0.1, t = 0.005;
  const double ref = M_PI * M_PI * kGsE * b * t * t * t / 12.0 / (4.0 * L * L);
  // measured: +0.41 % (10 elements), +0.10 % (20), +0.024 % (40) for both: second order
  for (bool tria : {false, true}) {
    const double coarse = GsStripBuckling(10, tria, L, b, t) / ref - 1.0;
    const double fine = GsStripBuckling(20, tria, L, b, t) / ref - 1.0;
    std::printf("%s strip: P / P_Euler - 1 = %.5f (10 x 2), %.5f (20 x 2)\n", tria ? "tria3" : "quad4", coarse, fine);
    EXPECT_GT(coarse / fine, 3.0) << (tria ? "tria3" : "quad4");
    EXPECT_NEAR(fine, 0.0, 2e-3) << (tria ? "tria3" : "quad4") << " coarse " << coarse;
  }
}

// simply supported square plate a x a under uniaxial compression Nxx
double GsPlateBuckling(int n, double a, double t) {
  const fe::Mesh mesh = GsPlate(n, n, a, a, t, kGsE, kGsNu, 7850.0, false);
  fe::AssemblyOptions o;
  fe::Mesh held = mesh;
  for (size_t k = 0; k < held.nodes.size(); ++k) {
    const fe::Vec3& x = held.nodes[k].x;
    const bool edge = std::abs(x.x()) < 1e-12 || std::abs(x.y()) < 1e-12 || std::abs(x.x() - a) < 1e-12 ||
                      std::abs(x.y() - a) < 1e-12;
    // edges: w = 0; u, v and the drilling rotation held there (no effect on the flat plate's bending)
    if (edge) fe::testing::AddConstraint(held, static_cast<int>(k), 0b100111);
  }
  // Nxx = -1 N/m: eps_xx = -eps, eps_yy = nu eps, Nyy = 0
  const double eps = 1.0 / (kGsE * t);
  return GsLowestBucklingFactor(held, o, [eps](const fe::Vec3& x) {
    return fe::Vec3(-eps * x.x(), kGsNu * eps * x.y(), 0.0);
  });
}

TEST(ShellSolidGeometricStiffness, SimplySupportedPlateBucklesAtTimoshenkosLoad) {
  const double a = 1.0, t = 0.01;
  const double D = kGsE * t * t * t / (12.0 * (1.0 - kGsNu * kGsNu));
  const double ref = 4.0 * M_PI * M_PI * D / (a * a);
  // measured: +3.8 % (6 x 6), +0.79 % (12 x 12), +0.20 % (18 x 18)
  const double coarse = GsPlateBuckling(6, a, t) / ref - 1.0;
  const double fine = GsPlateBuckling(12, a, t) / ref - 1.0;
  std::printf("simply supported plate: N / N_Timoshenko - 1 = %.5f (6 x 6), %.5f (12 x 12)\n", coarse, fine);
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_NEAR(fine, 0.0, 1e-2) << "coarse " << coarse;
}

// ------------------------------------------------- finite-difference check

// independent total-Lagrangian internal force of one solid element with the
// initial stress S0 (3 x 3), Green-Lagrange strain, quadrature points with
// weights and natural shape derivatives given by `shape`
using GsShapeFn = std::function<void(const fe::Vec3& p, Eigen::MatrixXd& dn)>;

Eigen::VectorXd GsInternalForce(const std::vector<fe::Vec3>& x, const Eigen::VectorXd& v, const Eigen::Matrix3d& s0,
                                const Eigen::Matrix<double, 6, 6>& d, const std::vector<fe::Vec3>& pts,
                                const std::vector<double>& w, const GsShapeFn& shape) {
  const int n = static_cast<int>(x.size());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * n);
  Eigen::MatrixXd dn;
  for (size_t g = 0; g < pts.size(); ++g) {
    shape(pts[g], dn);
    Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
    for (int i = 0; i < n; ++i) j += dn.col(i) * x[i].transpose();
    const Eigen::MatrixXd dx = j.inverse() * dn;
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();  // grad v, h(a, b) = d v_a / d X_b
    for (int i = 0; i < n; ++i) h += v.segment<3>(3 * i) * dx.col(i).transpose();
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + h;
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    Eigen::Matrix<double, 6, 1> ev;
    ev << E(0, 0), E(1, 1), E(2, 2), 2.0 * E(0, 1), 2.0 * E(1, 2), 2.0 * E(2, 0);
    const Eigen::Matrix<double, 6, 1> sv = d * ev;
    Eigen::Matrix3d S;
    S << sv(0), sv(3), sv(5), sv(3), sv(1), sv(4), sv(5), sv(4), sv(2);
    const Eigen::Matrix3d P = F * (S + s0);
    for (int i = 0; i < n; ++i) f.segment<3>(3 * i) += P * dx.col(i) * (w[g] * j.determinant());
  }
  return f;
}

Eigen::Matrix<double, 6, 6> GsElasticity(double E, double nu) {
  const double lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = E / (2.0 * (1.0 + nu));
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.topLeftCorner<3, 3>().setConstant(lam);
  for (int i = 0; i < 3; ++i) {
    d(i, i) += 2.0 * mu;
    d(3 + i, 3 + i) = mu;
  }
  return d;
}

// checks K + KG(u_p) against the central-difference tangent of the internal force
void GsExpectTangent(fe::ElementType type, const std::vector<fe::Vec3>& x, const std::vector<fe::Vec3>& pts,
                     const std::vector<double>& w, const GsShapeFn& shape) {
  fe::Mesh mesh;
  const int mat = fe::testing::AddMaterial(mesh, 2.0e11, 0.3, 7850.0);
  fe::Element e;
  e.id = 7;
  e.type = type;
  e.nodes.resize(x.size());
  fe::ElementInput in;
  in.element = &e;
  in.x = x.data();
  in.material = &mesh.materials[mat];
  MatX K, M, KG;
  if (type == fe::ElementType::kHex8) {
    fe::SolidHex8Matrices(in, K, M, fe::Hex8Formulation::kFullIntegration);
  } else if (type == fe::ElementType::kTet10) {
    fe::SolidTet10Matrices(in, K, M);
  } else {
    fe::SolidTet4Matrices(in, K, M);
  }
  // homogeneous prestress of the displacement field u_p = G X
  Eigen::Matrix3d grad;
  grad << 1.0, -0.4, 0.3, 0.2, -0.7, 0.5, -0.6, 0.1, 0.8;
  grad *= 1e-3;
  const int n = static_cast<int>(x.size());
  Eigen::VectorXd up(3 * n);
  for (int i = 0; i < n; ++i) up.segment<3>(3 * i) = grad * x[i];
  ElementGeometricStiffness(in, up, KG);
  const Eigen::Matrix3d eps = 0.5 * (grad + grad.transpose());
  Eigen::Matrix<double, 6, 1> ev;
  ev << eps(0, 0), eps(1, 1), eps(2, 2), 2.0 * eps(0, 1), 2.0 * eps(1, 2), 2.0 * eps(2, 0);
  const Eigen::Matrix<double, 6, 6> d = GsElasticity(2.0e11, 0.3);
  const Eigen::Matrix<double, 6, 1> sv = d * ev;
  Eigen::Matrix3d s0;
  s0 << sv(0), sv(3), sv(5), sv(3), sv(1), sv(4), sv(5), sv(4), sv(2);
  const double h = 1e-7;
  MatX tangent(3 * n, 3 * n);
  for (int j = 0; j < 3 * n; ++j) {
    Eigen::VectorXd vp = Eigen::VectorXd::Zero(3 * n), vm = vp;
    vp(j) = h;
    vm(j) = -h;
    tangent.col(j) = (GsInternalForce(x, vp, s0, d, pts, w, shape) - GsInternalForce(x, vm, s0, d, pts, w, shape)) / (2.0 * h);
  }
  const MatX kg_fd = tangent - K;
  EXPECT_GT(KG.norm(), 1e-6 * K.norm());  // not trivially zero: |S0| / E ~ 1e-3
  EXPECT_LT((KG - kg_fd).norm(), 1e-5 * KG.norm()) << fe::TypeName(type);
  EXPECT_LT((KG - KG.transpose()).norm(), 1e-14 * KG.norm());
}

TEST(ShellSolidGeometricStiffness, SolidsMatchTheTangentOfThePrestressedInternalForce) {
  // tet4: one point, constant derivatives
  auto tet_lin = [](const fe::Vec3&, Eigen::MatrixXd& dn) {
    dn.resize(3, 4);
    dn << -1.0, 1.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0;
  };
  const std::vector<fe::Vec3> xt = {fe::Vec3(0.1, 0.0, 0.05), fe::Vec3(1.2, 0.1, 0.0), fe::Vec3(0.3, 0.9, 0.2),
                                    fe::Vec3(0.2, 0.3, 1.1)};
  GsExpectTangent(fe::ElementType::kTet4, xt, {fe::Vec3(0.25, 0.25, 0.25)}, {1.0 / 6.0}, tet_lin);
  // tet10: straight edges, the 4-point degree-2 rule is exact for the homogeneous prestress
  std::vector<fe::Vec3> x10 = xt;
  const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (const auto& ed : edges) x10.push_back(0.5 * (xt[ed[0]] + xt[ed[1]]));
  auto tet_quad = [&](const fe::Vec3& p, Eigen::MatrixXd& dn) {
    const double l[4] = {1.0 - p.x() - p.y() - p.z(), p.x(), p.y(), p.z()};
    const double dl[4][3] = {{-1.0, -1.0, -1.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
    dn.resize(3, 10);
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) dn(c, i) = (4.0 * l[i] - 1.0) * dl[i][c];
    for (int k = 0; k < 6; ++k)
      for (int c = 0; c < 3; ++c)
        dn(c, 4 + k) = 4.0 * (dl[edges[k][0]][c] * l[edges[k][1]] + l[edges[k][0]] * dl[edges[k][1]][c]);
  };
  const double ta = 0.5854101966249685, tb = 0.1381966011250105;
  GsExpectTangent(fe::ElementType::kTet10, x10,
                  {fe::Vec3(tb, tb, tb), fe::Vec3(ta, tb, tb), fe::Vec3(tb, ta, tb), fe::Vec3(tb, tb, ta)},
                  {1.0 / 24.0, 1.0 / 24.0, 1.0 / 24.0, 1.0 / 24.0}, tet_quad);
  // hex8: distorted brick, 2x2x2 Gauss (as the full-integration stiffness)
  const std::vector<fe::Vec3> xh = {fe::Vec3(0.0, 0.0, 0.0), fe::Vec3(1.1, 0.05, 0.0), fe::Vec3(1.0, 0.9, 0.1),
                                    fe::Vec3(-0.1, 1.0, 0.0), fe::Vec3(0.05, 0.0, 0.8), fe::Vec3(1.0, -0.1, 1.0),
                                    fe::Vec3(1.2, 1.1, 0.9), fe::Vec3(0.0, 0.9, 1.0)};
  const double sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
               sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  auto hex = [&](const fe::Vec3& p, Eigen::MatrixXd& dn) {
    dn.resize(3, 8);
    for (int i = 0; i < 8; ++i) {
      const double a = 1.0 + p.x() * sx[i], b = 1.0 + p.y() * sy[i], c = 1.0 + p.z() * sz[i];
      dn(0, i) = 0.125 * sx[i] * b * c;
      dn(1, i) = 0.125 * sy[i] * a * c;
      dn(2, i) = 0.125 * sz[i] * a * b;
    }
  };
  std::vector<fe::Vec3> g8;
  const double g = 1.0 / std::sqrt(3.0);
  for (int i = 0; i < 8; ++i) g8.emplace_back(sx[i] * g, sy[i] * g, sz[i] * g);
  GsExpectTangent(fe::ElementType::kHex8, xh, g8, std::vector<double>(8, 1.0), hex);
}

TEST(ShellSolidGeometricStiffness, RigidTranslationGivesNoGeometricStiffness) {
  const fe::Mesh mesh = GsPlate(2, 2, 1.0, 0.5, 0.01, kGsE, kGsNu, 7850.0, false);
  fe::AssembledModel a = fe::Assemble(mesh);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(a.dofs.n_full);
  for (size_t k = 0; k < mesh.nodes.size(); ++k)
    for (int c = 0; c < 3; ++c) u(a.dofs.full[k][c]) = 0.1 * (c + 1);
  EXPECT_LT(AssembleGeometricStiffness(mesh, a.dofs, u).norm(), 1e-6);
}

// --------------------------------------------------- spinning cantilevers

// lowest two flapping frequencies omega sqrt(rho A L^4 / E I) of a cantilever
// along x spinning about z at lambda = Om sqrt(rho A L^4 / E I), from the
// reduced K + Om^2 Kg_zz of the mesh, clamped at x = 0
std::vector<double> GsSpinningFrequencies(const fe::Mesh& mesh, double rho_a, double ei, double L,
                                          const std::vector<double>& lambdas) {
  fe::FeModel model;
  model.mesh = mesh;
  ReductionOptions o;
  o.fixed_nodes = GsNodesAt(mesh, 0, 0.0);
  o.normal_modes = 8;
  o.geometric_stiffening = true;
  const ReducedBody body = ReduceCraigBampton(model, o);
  const double scale = std::sqrt(rho_a * std::pow(L, 4) / ei);
  std::vector<double> out;
  for (double lam : lambdas) {
    const double om = lam / scale;
    const MatX kt = body.stiffness + om * om * body.geometric_stiffness[2];
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<MatX>(0.5 * (kt + kt.transpose())).eigenvalues();
    out.push_back(std::sqrt(ev(0)) * scale);
  }
  return out;
}

TEST(ShellSolidGeometricStiffness, SpinningShellAndSolidCantileversStiffenAsTheBeam) {
  // Hodges and Rutkowski 1981, flapping, hub radius 0: lambda = 0, 1, 2
  const std::vector<double> lambdas = {0.0, 1.0, 2.0}, ref = {3.5160, 3.6816, 4.1373};
  const double L = 1.0, E = 2.0e11, rho = 7850.0;
  // strip b x t in the x-y plane flapping along z (nu = 0: beam bending E b t^3 / 12)
  {
    const double b = 0.04, t = 0.004;
    const fe::Mesh mesh = GsPlate(24, 2, L, b, t, E, 0.0, rho, false);
    const std::vector<double> f = GsSpinningFrequencies(mesh, rho * b * t, E * b * t * t * t / 12.0, L, lambdas);
    std::printf("quad4 strip flapping: %.4f %.4f %.4f at lambda 0 1 2\n", f[0], f[1], f[2]);
    for (size_t k = 0; k < lambdas.size(); ++k) {
      EXPECT_NEAR(f[k], ref[k], 3e-3 * ref[k]) << "quad4 strip, lambda " << lambdas[k];
      EXPECT_NEAR(f[k] / f[0], ref[k] / ref[0], 5e-4) << "quad4 strip, lambda " << lambdas[k];
    }
  }
  // square bar of hex8 (both bending planes alike; the lowest is a flapping frequency)
  {
    const double b = 0.02;
    fe::Mesh mesh = GsSolidColumn(1, 1, 24, b, b, L, E, 0.0, rho, false);
    for (fe::Node& n : mesh.nodes) n.x = fe::Vec3(n.x.z(), n.x.x(), n.x.y());  // axis along x
    const std::vector<double> f = GsSpinningFrequencies(mesh, rho * b * b, E * std::pow(b, 4) / 12.0, L, lambdas);
    std::printf("hex8 bar flapping: %.4f %.4f %.4f at lambda 0 1 2\n", f[0], f[1], f[2]);
    for (size_t k = 0; k < lambdas.size(); ++k) {
      EXPECT_NEAR(f[k], ref[k], 3e-3 * ref[k]) << "hex8 bar, lambda " << lambdas[k];
      EXPECT_NEAR(f[k] / f[0], ref[k] / ref[0], 5e-4) << "hex8 bar, lambda " << lambdas[k];
    }
  }
}

}  // namespace
}  // namespace flexmb::reduction
