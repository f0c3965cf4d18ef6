// Solid stresses at the corner nodes (StressModes::solid_node, reduce
// --solid-corner-stress) against exact elasticity fields: one element of
// each solid type, its reference shape mapped by a random affine map (so
// the isoparametric map is affine and polynomial fields stay polynomials of
// the same degree):
// - linear elements (tet4, hex8, wedge6) under the uniform uniaxial field
//   u = eps (x, -nu y, -nu z): sxx = E eps at every corner, the rest 0;
// - quadratic elements (tet10, hex20, wedge15) under the pure-bending field
//   u = kappa (x z, -nu y z, -x^2 / 2 + nu (y^2 - z^2) / 2), whose strains
//   are (kappa z, -nu kappa z, -nu kappa z, 0, 0, 0) (e.g. Timoshenko and
//   Goodier, Theory of Elasticity, pure bending of prismatic bars): sxx =
//   E kappa z at each corner (z of that corner), the rest 0. The
//   quadratic elements reproduce this field exactly, so the corner values
//   are exact up to rounding;
// - the table's layout: tetrahedra and wedges repeat their last corner up
//   to the 8 locations of the hexahedra; without the option no table.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <vector>

#include "flexmb/durability/stress_recovery.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/solid_hex20.h"
#include "flexmb/fe/elements/solid_wedge6.h"
#include "flexmb/fe/elements/solid_wedge15.h"
#include "flexmb/reduction/stress_modes.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::reduction {
namespace {

using fe::Vec3;

constexpr double kCornerE = 2.1e11, kCornerNu = 0.3;

// reference nodes of each type (corners, then mid-edge nodes)
std::vector<Vec3> CornerTestReference(fe::ElementType type) {
  std::vector<Vec3> c;
  std::vector<std::array<int, 2>> edges;
  switch (type) {
    case fe::ElementType::kTet4:
    case fe::ElementType::kTet10:
      c = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      if (type == fe::ElementType::kTet10)
        for (const auto& e : fe::kTet10EdgeCorners) edges.push_back({e[0], e[1]});
      break;
    case fe::kWedge6:
    case fe::kWedge15:
      c = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
      if (type == fe::kWedge15)
        for (const auto& e : fe::kWedge15EdgeCorners) edges.push_back({e[0], e[1]});
      break;
    default:
      c = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
      if (type == fe::kHex20)
        for (const auto& e : fe::kHex20EdgeCorners) edges.push_back({e[0], e[1]});
  }
  for (const auto& e : edges) c.push_back(0.5 * (c[e[0]] + c[e[1]]));
  return c;
}

// one element of `type` placed by x = c + A xi, and the field as its mode
struct CornerTestElement {
  fe::Mesh mesh;
  MatX mode;
};

CornerTestElement MakeCornerTestElement(fe::ElementType type, bool bending, double scale) {
  CornerTestElement t;
  const int mat = fe::testing::AddMaterial(t.mesh, kCornerE, kCornerNu, 7850.0);
  fe::SolidSection sec;
  sec.id = 1;
  sec.material = mat;
  t.mesh.solid_sections.push_back(sec);
  Eigen::Matrix3d A;
  A << 0.31, 0.05, -0.02, -0.04, 0.22, 0.03, 0.06, -0.01, 0.18;
  const Vec3 c(0.4, -0.3, 0.2);
  std::vector<int> nodes;
  for (const Vec3& xi : CornerTestReference(type)) nodes.push_back(fe::testing::AddNode(t.mesh, c + A * xi));
  fe::testing::AddElement(t.mesh, type, 0, nodes);
  t.mode = MatX::Zero(6 * static_cast<Eigen::Index>(nodes.size()), 1);
  for (size_t n = 0; n < nodes.size(); ++n) {
    const Vec3& x = t.mesh.nodes[n].x;
    const double nu = kCornerNu;
    const Vec3 u = bending ? Vec3(x.x() * x.z(), -nu * x.y() * x.z(),
                                  -0.5 * x.x() * x.x() + 0.5 * nu * (x.y() * x.y() - x.z() * x.z()))
                           : Vec3(x.x(), -nu * x.y(), -nu * x.z());
    t.mode.block<3, 1>(6 * static_cast<Eigen::Index>(n), 0) = scale * u;
  }
  return t;
}

TEST(SolidCornerStress, ExactFieldsAtTheCornersOfEveryType) {
  struct Case {
    fe::ElementType type;
    bool bending;
  };
  const Case cases[] = {{fe::ElementType::kTet4, false},   {fe::ElementType::kHex8, false},
                        {fe::kWedge6, false}, {fe::ElementType::kTet10, true},
                        {fe::kHex20, true},   {fe::kWedge15, true},
                        {fe::kHex20, false}};
  for (const Case& k : cases) {
    const double scale = 1e-3;  // eps or kappa [1/m]
    const CornerTestElement t = MakeCornerTestElement(k.type, k.bending, scale);
    const StressModes sm = ComputeStressModes(t.mesh, t.mode, true);
    const StressTable& s = sm.solid_node;
    ASSERT_EQ(s.elements.size(), 1u);
    const int corners = fe::Traits(k.type).corners;
    ASSERT_EQ(s.Locations(), corners);
    EXPECT_EQ(s.locations.front(), "n1");
    const double ref_scale = kCornerE * scale * 0.5;
    for (int c = 0; c < corners; ++c) {
      const Vec3& x = t.mesh.nodes[t.mesh.elements[0].nodes[c]].x;
      const double sxx = kCornerE * scale * (k.bending ? x.z() : 1.0);
      EXPECT_NEAR(s.modes(s.Row(0, c, 0), 0), sxx, 1e-9 * ref_scale) << fe::Traits(k.type).name << " corner " << c;
      for (int comp = 1; comp < 6; ++comp)
        EXPECT_NEAR(s.modes(s.Row(0, c, comp), 0), 0.0, 1e-9 * ref_scale)
            << fe::Traits(k.type).name << " corner " << c << " component " << comp;
    }
    // without the option: no corner table, the centroid table as before
    const StressModes plain = ComputeStressModes(t.mesh, t.mode);
    EXPECT_TRUE(plain.solid_node.elements.empty());
    EXPECT_EQ(plain.solid.elements.size(), 1u);
  }
}

TEST(SolidCornerStress, MixedTypesPadToTheMostCorners) {
  CornerTestElement t = MakeCornerTestElement(fe::ElementType::kHex8, false, 1e-3);
  const CornerTestElement tet = MakeCornerTestElement(fe::ElementType::kTet4, false, 1e-3);
  // append the tetrahedron (its own nodes) to the hexahedron's mesh
  const int base = static_cast<int>(t.mesh.nodes.size());
  for (const fe::Node& n : tet.mesh.nodes) fe::testing::AddNode(t.mesh, n.x);
  std::vector<int> nodes;
  for (int n : tet.mesh.elements[0].nodes) nodes.push_back(base + n);
  fe::testing::AddElement(t.mesh, fe::ElementType::kTet4, 0, nodes);
  MatX mode(t.mode.rows() + tet.mode.rows(), 1);
  mode << t.mode, tet.mode;
  const StressTable s = ComputeStressModes(t.mesh, mode, true).solid_node;
  ASSERT_EQ(s.elements.size(), 2u);
  ASSERT_EQ(s.Locations(), 8);
  for (int c = 4; c < 8; ++c)
    for (int comp = 0; comp < 6; ++comp) EXPECT_EQ(s.modes(s.Row(1, c, comp), 0), s.modes(s.Row(1, 3, comp), 0));
  // post-processing reads every corner: uniaxial E eps at each, at two instants
  Eigen::MatrixXd W(1, 2);
  W << 1.0, -0.5;
  durability::StressRecovery rec(s, W);
  ASSERT_EQ(rec.Points(), 8);
  EXPECT_STREQ(rec.PointName(7), "n8");
  rec.Recover(0, 2);
  for (int k = 0; k < 2; ++k)
    for (int c = 0; c < 8; ++c) {
      EXPECT_NEAR(rec.At(k, c, 0).max_principal, kCornerE * 1e-3, 1e-6);
      EXPECT_NEAR(rec.At(k, c, 1).min_principal, -0.5 * kCornerE * 1e-3, 1e-6);
    }
}

}  // namespace
}  // namespace flexmb::reduction
