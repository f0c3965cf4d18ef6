// Stress modes (ComputeStressModes) against independent references, with
// static FE solutions of the full model fed in as "modes": a cantilever beam
// under tip loads (section forces from statics: shear F, moment F (L - x),
// axial force, torque), a plate strip in uniform tension (sxx = F / (b t) =
// E eps with eps the measured end displacement / length, syy = sxy = 0, plane
// stress with nu), a plate in pure bending under edge moments m per width
// (top and bottom surfaces +-6 m / t^2), quads and the same plate in
// triangles, a solid bar in uniaxial tension (hex8 by a static solve,
// tet4 / tet10 by the exact uniaxial field: sxx = E eps, others 0); zero
// stress for a random rigid motion of a mesh holding every element type;
// linearity in the modes; table layout (rows, elements, frames); errors;
// von Mises and the beam normal stress against hand formulas and the
// resultants of a discretized section.

#include "flexmb/reduction/stress_modes.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/shell_quad4.h"
#include "tests/unit/fe/fe_test_models.h"
#include "tests/unit/reduction/reduction_test_models.h"

namespace flexmb::reduction {
namespace {

using fe::testing::AddConstraint;
using fe::testing::AddElement;
using fe::testing::AddMaterial;
using fe::testing::AddNode;
using fe::testing::ExpectInputErrorWith;
using testing::AddPlate;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// static solution K u = f of the free DOF (loads per node, 6 components),
// expanded to 6 rows per node (constrained and inactive DOF zero)
VecX StaticMode(const fe::Mesh& mesh, const std::map<int, Vec6>& loads) {
  const fe::AssembledModel a = fe::Assemble(mesh);
  VecX f = VecX::Zero(a.dofs.n_free);
  for (const auto& [node, load] : loads)
    for (int c = 0; c < 6; ++c)
      if (a.dofs.free[node][c] >= 0) f(a.dofs.free[node][c]) += load(c);
  const VecX u = Eigen::MatrixXd(a.K).ldlt().solve(f);
  VecX out = VecX::Zero(6 * static_cast<Eigen::Index>(mesh.nodes.size()));
  for (size_t n = 0; n < mesh.nodes.size(); ++n)
    for (int c = 0; c < 6; ++c)
      if (a.dofs.free[n][c] >= 0) out(6 * n + c) = u(a.dofs.free[n][c]);
  return out;
}

// cantilever along x (L = 2 m, 8 elements, orientation y), clamped at x = 0:
// tip load case 1 Fz; case 2 axial P, shear Fy and torque T
TEST(StressModes, CantileverSectionForcesFromStatics) {
  fe::Mesh mesh;
  const int steel = AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  fe::BeamSection sec;
  sec.id = 1;
  sec.material = steel;
  sec.A = 4.0e-3;
  sec.Iy = 6.0e-6;
  sec.Iz = 2.0e-6;
  sec.J = 3.0e-6;
  sec.ky = sec.kz = 0.85;
  mesh.beam_sections.push_back(sec);
  const double L = 2.0;
  const int ne = 8;
  for (int i = 0; i <= ne; ++i) AddNode(mesh, fe::Vec3(L * i / ne, 0.0, 0.0));
  for (int i = 0; i < ne; ++i) fe::testing::AddBeam(mesh, 0, i, i + 1, fe::Vec3(0.0, 1.0, 0.0));
  AddConstraint(mesh, 0, 0b111111);
  const double Fz = 1500.0, P = 8000.0, Fy = -700.0, T = 120.0;
  Vec6 l1, l2;
  l1 << 0.0, 0.0, Fz, 0.0, 0.0, 0.0;
  l2 << P, Fy, 0.0, T, 0.0, 0.0;
  MatX modes(6 * (ne + 1), 2);
  modes.col(0) = StaticMode(mesh, {{ne, l1}});
  modes.col(1) = StaticMode(mesh, {{ne, l2}});
  const StressModes sm = ComputeStressModes(mesh, modes);
  const StressTable& b = sm.beam;
  ASSERT_EQ(b.elements.size(), static_cast<size_t>(ne));
  EXPECT_TRUE(sm.shell.elements.empty());
  EXPECT_EQ(sm.shell.modes.rows(), 0);
  EXPECT_EQ(sm.shell.modes.cols(), 2);
  ASSERT_EQ(b.modes.rows(), ne * 2 * 6);
  for (int k = 0; k < ne; ++k) {
    EXPECT_LT((b.axes[k] - Mat3::Identity()).norm(), 1e-15);
    for (int end = 0; end < 2; ++end) {
      const double x = L * (k + end) / ne;
      Vec6 r1, r2;  // N Vy Vz T My Mz
      r1 << 0.0, 0.0, Fz, 0.0, -Fz * (L - x), 0.0;
      r2 << P, Fy, 0.0, T, 0.0, Fy * (L - x);
      const Vec6 g1 = b.modes.block<6, 1>(b.Row(k, end, 0), 0);
      const Vec6 g2 = b.modes.block<6, 1>(b.Row(k, end, 0), 1);
      EXPECT_LT((g1 - r1).cwiseAbs().maxCoeff(), 1e-8 * Fz * L) << k << " " << end << ": " << g1.transpose();
      EXPECT_LT((g2 - r2).cwiseAbs().maxCoeff(), 1e-8 * P) << k << " " << end << ": " << g2.transpose();
    }
  }
  // root: shear F, moment F L
  EXPECT_NEAR(b.modes(b.Row(0, 0, 2), 0), Fz, 1e-8 * Fz);
  EXPECT_NEAR(b.modes(b.Row(0, 0, 4), 0), -Fz * L, 1e-8 * Fz * L);
}

// each quad of the plate split into two counter-clockwise triangles
void SplitQuads(fe::Mesh& mesh) {
  std::vector<fe::Element> out;
  for (const fe::Element& e : mesh.elements) {
    fe::Element a = e, b = e;
    a.type = b.type = fe::ElementType::kTria3;
    a.nodes = {e.nodes[0], e.nodes[1], e.nodes[2]};
    b.nodes = {e.nodes[0], e.nodes[2], e.nodes[3]};
    b.id = e.id + 100000;
    out.push_back(a);
    out.push_back(b);
  }
  mesh.elements = out;
}

// the plane stress tensor of shell k (position in the table), surface
// `side`, column 0, in the basic frame (the triangles' frames differ)
Mat3 Tensor(const StressTable& s, size_t k, int side) {
  const int kk = static_cast<int>(k);
  const double sxx = s.modes(s.Row(kk, side, 0), 0), syy = s.modes(s.Row(kk, side, 1), 0),
               sxy = s.modes(s.Row(kk, side, 2), 0);
  Mat3 local;
  local << sxx, sxy, 0.0, sxy, syy, 0.0, 0.0, 0.0, 0.0;
  return s.axes[k] * local * s.axes[k].transpose();
}

// constrains node (i, j) of the (nx + 1) x (ny + 1) grid of a strip of width
// b with mask(i, j) (bits: DOF 1..6) and loads the nodes of column i with
// the edge load per unit width edge(i) (force, moment) as consistent nodal
// loads (half on the two corner nodes); returns the nodal loads
template <typename Mask, typename Edge>
std::map<int, Vec6> HoldAndLoadStrip(fe::Mesh& mesh, const std::vector<int>& grid, int nx, int ny, double b,
                                     Mask&& mask, Edge&& edge) {
  std::map<int, Vec6> loads;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const int n = grid[j * (nx + 1) + i];
      AddConstraint(mesh, n, mask(i, j));
      const Vec6 per_width = edge(i);
      if (!per_width.isZero()) loads[n] = per_width * (b / ny) * (j == 0 || j == ny ? 0.5 : 1.0);
    }
  }
  return loads;
}

// 1.2 x 0.4 m strip, t = 10 mm, steel; x = 0 edge held in x, one corner in
// y, out-of-plane DOF fixed; traction s0 on the x = a edge as consistent
// nodal forces. Exact: sxx = s0 = E u(a) / a, syy = sxy = 0 on both surfaces.
TEST(StressModes, PlateStripInUniformTension) {
  for (bool trias : {false, true}) {
    fe::Mesh mesh;
    const int nx = 6, ny = 3;
    const double a = 1.2, b = 0.4, t = 0.01, s0 = 5.0e7;
    const std::vector<int> grid = AddPlate(mesh, nx, ny, a, b, t);
    if (trias) SplitQuads(mesh);
    Vec6 traction = Vec6::Zero();
    traction(0) = s0 * t;
    const std::map<int, Vec6> loads = HoldAndLoadStrip(
        mesh, grid, nx, ny, b,
        [](int i, int j) { return 0b011100 | (i == 0 ? 0b000001 : 0) | (i == 0 && j == 0 ? 0b000010 : 0); },
        [&](int i) { return i == nx ? traction : Vec6::Zero(); });
    const VecX u = StaticMode(mesh, loads);
    const double eps = u(6 * grid[nx]) / a;
    const double E = 2.1e11;
    EXPECT_NEAR(E * eps, s0, 1e-9 * s0);
    const StressModes sm = ComputeStressModes(mesh, u);
    const StressTable& s = sm.shell;
    ASSERT_EQ(s.elements.size(), mesh.elements.size());
    const Mat3 ref = Eigen::Vector3d(E * eps, 0.0, 0.0).asDiagonal();
    for (size_t k = 0; k < s.elements.size(); ++k) {
      EXPECT_LT((s.axes[k].col(2) - fe::Vec3::UnitZ()).norm(), 1e-15);
      if (!trias) EXPECT_LT((s.axes[k] - Mat3::Identity()).norm(), 1e-15);
      for (int side = 0; side < 2; ++side)
        EXPECT_LT((Tensor(s, k, side) - ref).norm(), 1e-9 * s0) << (trias ? "tria " : "quad ") << k;
    }
  }
}

// the same strip, in-plane DOF fixed, w fixed at three corners; edge
// moments m per width (moment vector +-y on the x = a and x = 0 edges) as
// nodal moments: constant moment mx = m, my = mxy = 0 (free anticlastic
// curvature), sxx = +-6 m / t^2 on the top (+z) and bottom surfaces
TEST(StressModes, PlateInPureBending) {
  for (bool trias : {false, true}) {
    fe::Mesh mesh;
    const int nx = 6, ny = 3;
    const double a = 1.2, b = 0.4, t = 0.01, m = 300.0;
    const std::vector<int> grid = AddPlate(mesh, nx, ny, a, b, t);
    if (trias) SplitQuads(mesh);
    const std::map<int, Vec6> loads = HoldAndLoadStrip(
        mesh, grid, nx, ny, b,
        [&](int i, int j) {
          const bool corner = (i == 0 && j == 0) || (i == nx && j == 0) || (i == 0 && j == ny);
          return 0b100011 | (corner ? 0b000100 : 0);
        },
        [&](int i) {
          Vec6 f = Vec6::Zero();
          if (i == 0 || i == nx) f(4) = i == nx ? m : -m;
          return f;
        });
    const StressModes sm = ComputeStressModes(mesh, StaticMode(mesh, loads));
    const StressTable& s = sm.shell;
    const double ref = 6.0 * m / (t * t);
    const Mat3 top = Eigen::Vector3d(ref, 0.0, 0.0).asDiagonal();
    for (size_t k = 0; k < s.elements.size(); ++k) {
      EXPECT_LT((Tensor(s, k, 1) - top).norm(), 1e-8 * ref) << (trias ? "tria " : "quad ") << k;
      EXPECT_LT((Tensor(s, k, 0) + top).norm(), 1e-8 * ref) << (trias ? "tria " : "quad ") << k;
    }
    // von Mises after the sum: |sxx| on both surfaces
    const VecX vm = PointVonMises(s, s.modes.col(0));
    EXPECT_NEAR(vm.maxCoeff(), ref, 1e-8 * ref);
    EXPECT_NEAR(vm.minCoeff(), ref, 1e-8 * ref);
    // per element: the larger of its two surfaces, from the modal coordinates
    VecX values, element_vm;
    ElementVonMises(s, VecX::Unit(s.modes.cols(), 0), values, element_vm);
    ASSERT_EQ(element_vm.size(), static_cast<Eigen::Index>(s.elements.size()));
    for (Eigen::Index k = 0; k < element_vm.size(); ++k)
      EXPECT_EQ(element_vm(k), std::max(vm(2 * k), vm(2 * k + 1)));
  }
}

// adds a solid section of material `mat` and returns its index
int AddSolidSection(fe::Mesh& mesh, int mat) {
  fe::SolidSection s;
  s.id = static_cast<int>(mesh.solid_sections.size()) + 1;
  s.material = mat;
  mesh.solid_sections.push_back(s);
  return static_cast<int>(mesh.solid_sections.size()) - 1;
}

// nodes of an (nx + 1) x (ny + 1) x (nz + 1) grid over a box, x fastest
std::vector<int> BoxGrid(fe::Mesh& mesh, int nx, int ny, int nz, const fe::Vec3& size) {
  std::vector<int> g;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        g.push_back(AddNode(mesh, fe::Vec3(size.x() * i / nx, size.y() * j / ny, size.z() * k / nz)));
  return g;
}

// bar 1.0 x 0.1 x 0.08 m of 5 x 1 x 1 hex8, aluminium; x = 0 face held in
// x, two of its corners in y and z; axial force F at x = L, F / 4 per
// corner: sxx = F / A = E u(L) / L, others 0
TEST(StressModes, SolidBarInUniaxialTension) {
  fe::Mesh mesh;
  const double E = 7.0e10, L = 1.0, w = 0.1, h = 0.08, F = 4.0e5;
  const int sec = AddSolidSection(mesh, AddMaterial(mesh, E, 0.33, 2700.0));
  const int nx = 5;
  const std::vector<int> g = BoxGrid(mesh, nx, 1, 1, fe::Vec3(L, w, h));
  auto at = [&](int i, int j, int k) { return g[(k * 2 + j) * (nx + 1) + i]; };
  for (int i = 0; i < nx; ++i)
    AddElement(mesh, fe::ElementType::kHex8, sec,
               {at(i, 0, 0), at(i + 1, 0, 0), at(i + 1, 1, 0), at(i, 1, 0), at(i, 0, 1),
                at(i + 1, 0, 1), at(i + 1, 1, 1), at(i, 1, 1)});
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) AddConstraint(mesh, at(0, j, k), 0b000001);
  AddConstraint(mesh, at(0, 0, 0), 0b000110);
  AddConstraint(mesh, at(0, 1, 0), 0b000100);
  std::map<int, Vec6> loads;
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) loads[at(nx, j, k)] = (Vec6() << F / 4.0, 0, 0, 0, 0, 0).finished();
  const VecX u = StaticMode(mesh, loads);
  const double s0 = F / (w * h), eps = u(6 * at(nx, 0, 0)) / L;
  EXPECT_NEAR(E * eps, s0, 1e-9 * s0);
  const StressTable& s = ComputeStressModes(mesh, u).solid;
  ASSERT_EQ(s.elements.size(), static_cast<size_t>(nx));
  for (size_t k = 0; k < s.elements.size(); ++k) {
    EXPECT_EQ(s.axes[k], Mat3::Identity());
    EXPECT_NEAR(s.modes(s.Row(k, 0, 0), 0), s0, 1e-9 * s0);
    for (int c = 1; c < 6; ++c) EXPECT_NEAR(s.modes(s.Row(k, 0, c), 0), 0.0, 1e-9 * s0);
  }
}

// a box of 2 x 1 x 1 cubes, each split into six tetrahedra around its main
// diagonal (positive volume), with mid-edge nodes for tet10
void TetBox(fe::Mesh& mesh, bool quadratic) {
  const int sec = AddSolidSection(mesh, AddMaterial(mesh, 7.0e10, 0.33, 2700.0));
  const int nx = 2;
  const std::vector<int> g = BoxGrid(mesh, nx, 1, 1, fe::Vec3(0.6, 0.3, 0.3));
  std::map<std::pair<int, int>, int> mid;
  auto midpoint = [&](int a, int b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = mid.find(key);
    if (it != mid.end()) return it->second;
    const int n = AddNode(mesh, 0.5 * (mesh.nodes[a].x + mesh.nodes[b].x));
    mid[key] = n;
    return n;
  };
  const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int i = 0; i < nx; ++i) {
    auto at = [&](int di, int dj, int dk) { return g[(dk * 2 + dj) * (nx + 1) + i + di]; };
    for (const auto& p : perm) {
      // path from corner (0,0,0) to (1,1,1) stepping along axes p[0], p[1], p[2]
      int c[3] = {0, 0, 0};
      std::vector<int> tet = {at(0, 0, 0)};
      for (int s = 0; s < 3; ++s) {
        c[p[s]] = 1;
        tet.push_back(at(c[0], c[1], c[2]));
      }
      const fe::Vec3 x0 = mesh.nodes[tet[0]].x;
      if ((mesh.nodes[tet[1]].x - x0).cross(mesh.nodes[tet[2]].x - x0).dot(mesh.nodes[tet[3]].x - x0) < 0)
        std::swap(tet[1], tet[2]);
      if (quadratic) {
        const auto& e = flexmb::fe::kTet10EdgeCorners;
        const std::vector<int> corners = tet;
        for (const auto& edge : e) tet.push_back(midpoint(corners[edge[0]], corners[edge[1]]));
      }
      AddElement(mesh, quadratic ? fe::ElementType::kTet10 : fe::ElementType::kTet4, sec, tet);
    }
  }
}

TEST(StressModes, TetBarUnderTheExactUniaxialField) {
  for (bool quadratic : {false, true}) {
    fe::Mesh mesh;
    TetBox(mesh, quadratic);
    const double E = 7.0e10, nu = 0.33, eps = 1.0e-3;
    VecX u = VecX::Zero(6 * static_cast<Eigen::Index>(mesh.nodes.size()));
    for (size_t n = 0; n < mesh.nodes.size(); ++n) {
      const fe::Vec3& x = mesh.nodes[n].x;
      u.segment<3>(6 * n) = fe::Vec3(eps * x.x(), -nu * eps * x.y(), -nu * eps * x.z());
    }
    const StressTable& s = ComputeStressModes(mesh, u).solid;
    ASSERT_EQ(s.elements.size(), 12u);
    for (size_t k = 0; k < s.elements.size(); ++k) {
      EXPECT_NEAR(s.modes(s.Row(k, 0, 0), 0), E * eps, 1e-10 * E * eps);
      for (int c = 1; c < 6; ++c) EXPECT_NEAR(s.modes(s.Row(k, 0, c), 0), 0.0, 1e-10 * E * eps);
    }
    const VecX vm = PointVonMises(s, s.modes.col(0));
    EXPECT_NEAR(vm.minCoeff(), E * eps, 1e-10 * E * eps);
  }
}

// one element of every type, scattered in space: warped quad with offset,
// tria, beam with offsets and an unsymmetric section, tet4, curved tet10, hex8
fe::Mesh MixedMesh() {
  fe::Mesh mesh;
  const int steel = AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  fe::ShellSection ss;
  ss.id = 1;
  ss.material = steel;
  ss.thickness = 0.01;
  mesh.shell_sections.push_back(ss);
  fe::BeamSection bs;
  bs.id = 1;
  bs.material = steel;
  bs.A = 3e-3;
  bs.Iy = 4e-6;
  bs.Iz = 9e-6;
  bs.Iyz = 2e-6;
  bs.J = 2.5e-6;
  bs.ky = 0.8;
  bs.kz = 0.6;
  mesh.beam_sections.push_back(bs);
  const int solid = AddSolidSection(mesh, steel);
  const Mat3 R = fe::testing::RandomRotation(17);
  auto add = [&](const fe::Vec3& c, std::vector<fe::Vec3> local) {
    std::vector<int> nodes;
    for (const fe::Vec3& p : local) nodes.push_back(AddNode(mesh, c + R * p));
    return nodes;
  };
  int e = AddElement(mesh, fe::ElementType::kHex8, solid,
                     add({2.0, 0.0, 0.0}, {{-0.3, -0.2, -0.1}, {0.32, -0.2, -0.12}, {0.3, 0.22, -0.1},
                                           {-0.3, 0.2, -0.1}, {-0.28, -0.2, 0.1}, {0.3, -0.2, 0.1},
                                           {0.3, 0.2, 0.13}, {-0.3, 0.21, 0.1}}));
  e = AddElement(mesh, fe::ElementType::kQuad4, 0,
                 add({0.0, 1.0, 0.0}, {{0.0, 0.0, 0.01}, {1.1, 0.1, -0.01}, {0.9, 0.8, 0.01}, {-0.1, 0.7, -0.01}}));
  mesh.elements[e].shell_offset = 0.004;
  e = AddElement(mesh, fe::ElementType::kTria3, 0, add({0.0, -1.0, 0.5}, {{0.0, 0.0, 0.0}, {0.8, 0.1, 0.0}, {0.3, 0.6, 0.0}}));
  mesh.elements[e].shell_offset = -0.003;
  e = fe::testing::AddBeam(mesh, 0, AddNode(mesh, fe::Vec3(-1.0, 0.0, 0.3)),
                           AddNode(mesh, fe::Vec3(-0.2, 0.4, 0.9)), fe::Vec3(0.0, 0.0, 1.0));
  mesh.elements[e].offset_a = fe::Vec3(0.05, -0.1, 0.02);
  mesh.elements[e].offset_b = fe::Vec3(-0.03, 0.07, 0.01);
  AddElement(mesh, fe::ElementType::kTet4, solid,
             add({1.0, 2.0, -1.0}, {{0.0, 0.0, 0.0}, {1.2, 0.1, -0.1}, {0.2, 0.9, 0.1}, {0.1, 0.2, 1.1}}));
  std::vector<fe::Vec3> c = {{0.0, 0.0, 0.0}, {1.0, 0.1, 0.0}, {0.1, 0.9, 0.1}, {0.0, 0.1, 1.0}};
  const auto& edges = flexmb::fe::kTet10EdgeCorners;
  for (const auto& ed : edges) c.push_back(0.5 * (c[ed[0]] + c[ed[1]]) + fe::Vec3(0.02, -0.01, 0.015));
  AddElement(mesh, fe::ElementType::kTet10, solid, add({-2.0, 1.0, 1.0}, c));
  return mesh;
}

// column 0 a random rigid motion u = a + theta x x, rotation theta; column
// 1 random nodal values of the same size: every table's rigid column is
// zero to round-off relative to the random one
TEST(StressModes, RigidMotionGivesZeroStressForEveryElementType) {
  const fe::Mesh mesh = MixedMesh();
  const Eigen::Index nn = static_cast<Eigen::Index>(mesh.nodes.size());
  std::srand(3);
  const fe::Vec3 a = fe::Vec3::Random(), theta = fe::Vec3::Random();
  MatX modes(6 * nn, 2);
  for (Eigen::Index n = 0; n < nn; ++n) {
    modes.block<3, 1>(6 * n, 0) = a + theta.cross(mesh.nodes[n].x);
    modes.block<3, 1>(6 * n + 3, 0) = theta;
  }
  modes.col(1) = VecX::Random(6 * nn);
  const StressModes sm = ComputeStressModes(mesh, modes);
  for (const StressTable* t : {&sm.shell, &sm.beam, &sm.solid}) {
    ASSERT_GT(t->modes.rows(), 0) << t->name;
    EXPECT_LT(t->modes.col(0).norm(), 1e-12 * t->modes.col(1).norm()) << t->name;
  }
  EXPECT_EQ(sm.shell.elements, (std::vector<int>{1, 2}));
  EXPECT_EQ(sm.beam.elements, (std::vector<int>{3}));
  EXPECT_EQ(sm.solid.elements, (std::vector<int>{0, 4, 5}));
}

// stress of a combination of modes = the combination of the stress modes;
// rows laid out as Row(k, l, c) with the element routine's matrix
TEST(StressModes, LinearInTheModesAndLaidOutByRow) {
  const fe::Mesh mesh = MixedMesh();
  const Eigen::Index nn = static_cast<Eigen::Index>(mesh.nodes.size());
  std::srand(5);
  const MatX modes = MatX::Random(6 * nn, 4);
  const VecX w = VecX::Random(4);
  const StressModes sm = ComputeStressModes(mesh, modes);
  const StressModes one = ComputeStressModes(mesh, modes * w);
  for (const auto& [t, t1] : {std::make_pair(&sm.shell, &one.shell), std::make_pair(&sm.beam, &one.beam),
                              std::make_pair(&sm.solid, &one.solid)}) {
    EXPECT_EQ(t->modes.cols(), 4);
    EXPECT_EQ(t->modes.rows(),
              static_cast<Eigen::Index>(t->elements.size()) * t->Locations() * t->Components());
    EXPECT_LT((t->modes * w - t1->modes.col(0)).norm(), 1e-13 * t1->modes.norm()) << t->name;
  }
  EXPECT_EQ(sm.shell.components, (std::vector<std::string>{"sxx", "syy", "sxy"}));
  EXPECT_EQ(sm.shell.locations, (std::vector<std::string>{"bottom", "top"}));
  EXPECT_EQ(sm.beam.components, (std::vector<std::string>{"N", "Vy", "Vz", "T", "My", "Mz"}));
  EXPECT_EQ(sm.solid.locations, (std::vector<std::string>{"centroid"}));
  // the quad (element 1, first shell): its routine's matrix times its rows
  const fe::Element& q = mesh.elements[1];
  std::vector<fe::Vec3> x;
  MatX ue(24, 4);
  for (int i = 0; i < 4; ++i) {
    x.push_back(mesh.nodes[q.nodes[i]].x);
    ue.middleRows(6 * i, 6) = modes.middleRows(6 * q.nodes[i], 6);
  }
  fe::ElementInput in;
  in.element = &q;
  in.x = x.data();
  in.material = &mesh.materials[0];
  in.shell = &mesh.shell_sections[0];
  MatX S;
  Mat3 axes;
  fe::ShellQuad4Stress(in, S, axes);
  EXPECT_LT((sm.shell.modes.middleRows(sm.shell.Row(0, 0, 0), 6) - S * ue).norm(), 1e-14 * (S * ue).norm());
  EXPECT_EQ(sm.shell.axes[0], axes);
}

TEST(StressModes, BadInputIsAnInputError) {
  fe::Mesh mesh = MixedMesh();
  const Eigen::Index nn = static_cast<Eigen::Index>(mesh.nodes.size());
  ExpectInputErrorWith([&] { ComputeStressModes(mesh, MatX::Zero(3 * nn, 2)); },
                       {"6 per node", std::to_string(6 * nn)});
  mesh.elements[2].property = 7;
  ExpectInputErrorWith([&] { ComputeStressModes(mesh, MatX::Zero(6 * nn, 2)); },
                       {"test.bdf:1003", "3-node", "no shell section"});
  StressTable beam;
  beam.name = "beam";
  beam.components = {"N", "Vy", "Vz", "T", "My", "Mz"};
  ExpectInputErrorWith([&] { PointVonMises(beam, VecX()); }, {"beam", "stress vectors"});
  const StressModes sm = ComputeStressModes(MixedMesh(), MatX::Zero(6 * nn, 1));
  ExpectInputErrorWith([&] { PointVonMises(sm.solid, VecX::Zero(5)); }, {"solid", "expected 18"});
  VecX values, element_vm;
  ExpectInputErrorWith([&] { ElementVonMises(beam, VecX(), values, element_vm); }, {"beam", "stress vectors"});
  ExpectInputErrorWith([&] { ElementVonMises(sm.solid, VecX::Zero(3), values, element_vm); },
                       {"solid", "3 modal coordinates", "of 1 modes"});
}

// hand formulas: uniaxial, pure shear (sqrt 3 tau), hydrostatic (0), and
// the plane form equal to the 3-D one with szz = syz = szx = 0
TEST(StressModes, VonMises) {
  EXPECT_NEAR(VonMises(Eigen::Vector3d(250.0, 0.0, 0.0)), 250.0, 1e-12);
  EXPECT_NEAR(VonMises(Eigen::Vector3d(0.0, 0.0, 100.0)), 100.0 * std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(VonMises((Vec6() << 70.0, 70.0, 70.0, 0.0, 0.0, 0.0).finished()), 0.0, 1e-12);
  EXPECT_NEAR(VonMises((Vec6() << 0.0, 0.0, 0.0, 0.0, 40.0, 0.0).finished()), 40.0 * std::sqrt(3.0), 1e-12);
  const Eigen::Vector3d p(120.0, -45.0, 33.0);
  EXPECT_NEAR(VonMises(p), VonMises((Vec6() << p(0), p(1), 0.0, p(2), 0.0, 0.0).finished()), 1e-12);
}

// a 60 x 20 mm rectangle rotated by 30 degrees in the y-z plane (Iyz != 0),
// discretized in 300 x 100 cells: with A, Iy, Iz, Iyz summed over the same
// cells, the normal stress integrates back to N = sum s dA,
// My = sum z s dA and Mz = -sum y s dA
TEST(StressModes, BeamNormalStressResultants) {
  const double bw = 0.06, bh = 0.02, phi = M_PI / 6.0;
  const int nb = 300, nh = 100;
  const double dA = bw * bh / (nb * nh);
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < nb; ++i)
    for (int j = 0; j < nh; ++j) {
      const double p = (i + 0.5) / nb * bw - 0.5 * bw, q = (j + 0.5) / nh * bh - 0.5 * bh;
      pts.emplace_back(std::cos(phi) * p - std::sin(phi) * q, std::sin(phi) * p + std::cos(phi) * q);
    }
  fe::BeamSection s;
  s.A = dA * pts.size();
  for (const auto& y : pts) {
    s.Iy += y.y() * y.y() * dA;
    s.Iz += y.x() * y.x() * dA;
    s.Iyz += y.x() * y.y() * dA;
  }
  Vec6 f;
  f << 1.2e4, 300.0, -200.0, 50.0, 800.0, -450.0;
  double N = 0.0, My = 0.0, Mz = 0.0;
  for (const auto& y : pts) {
    const double sig = BeamNormalStress(f, s, y.x(), y.y());
    N += sig * dA;
    My += y.y() * sig * dA;
    Mz -= y.x() * sig * dA;
  }
  EXPECT_NEAR(N, f(0), 1e-9 * f(0));
  EXPECT_NEAR(My, f(4), 1e-9 * f(4));
  EXPECT_NEAR(Mz, f(5), 1e-9 * std::abs(f(5)));
}

}  // namespace
}  // namespace flexmb::reduction
