// Beam fibre stresses (StressModes::beam_fibre) against independent
// references:
// - an imposed displacement field of uniform axial strain eps0 and uniform
//   curvatures kappa_y, kappa_z (u = eps0 x, v = kappa_z x^2 / 2,
//   w = kappa_y x^2 / 2, rotations theta_y = -w', theta_z = v'), which the
//   cubic beam reproduces exactly: the normal stress at every fibre (y, z)
//   is E (eps0 - y kappa_z - z kappa_y) (Euler-Bernoulli kinematics). This
//   does not use the moment-curvature law or the section's inertia, so it
//   checks the fibre formula of an unsymmetric section (Iyz != 0) as well;
// - the convex hulls of the Nastran library shapes (their corners, drawn
//   from the shapes' dimensions by hand) and the circle points;
// - the uniaxial stress measures (von Mises |s|, principal s and 0) and the
//   damage of a sinusoidal history against the closed form of the S-N
//   curve (one cycle of range 2 A per period).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flexmb/durability/element_fatigue.h"
#include "flexmb/durability/stress_recovery.h"
#include "flexmb/fe_io/nastran/nastran_sections.h"
#include "flexmb/reduction/stress_modes.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::reduction {
namespace {

using Point2 = std::array<double, 2>;

// the L section of the Nastran library (b 0.08 z, h 0.12 y, t1 0.01, t2 0.008)
io::nastran::ShapeProperties FibreTestLSection() {
  io::nastran::ShapeProperties p;
  EXPECT_EQ(io::nastran::ComputeShape("L", {0.08, 0.12, 0.01, 0.008}, 0.3, &p), "");
  return p;
}

// true if the two point sets are equal up to order, to 1e-12
bool SamePoints(std::vector<Point2> a, std::vector<Point2> b) {
  if (a.size() != b.size()) return false;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  for (size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i][0] - b[i][0]) > 1e-12 || std::abs(a[i][1] - b[i][1]) > 1e-12) return false;
  return true;
}

// a cantilever of 6 beams along x (L = 1.5 m) whose section is `sec`,
// and the imposed field (eps0, kappa_y, kappa_z) as its single mode
struct FibreTestBeam {
  fe::Mesh mesh;
  MatX mode;
};

FibreTestBeam MakeFibreTestBeam(const fe::BeamSection& sec, double eps0, double ky, double kz) {
  FibreTestBeam b;
  const int steel = fe::testing::AddMaterial(b.mesh, 2.1e11, 0.3, 7850.0);
  fe::BeamSection s = sec;
  s.material = steel;
  b.mesh.beam_sections.push_back(s);
  const int ne = 6;
  const double L = 1.5;
  b.mode = MatX::Zero(6 * (ne + 1), 1);
  for (int i = 0; i <= ne; ++i) {
    const double x = L * i / ne;
    fe::testing::AddNode(b.mesh, fe::Vec3(x, 0.0, 0.0));
    b.mode(6 * i + 0, 0) = eps0 * x;
    b.mode(6 * i + 1, 0) = 0.5 * kz * x * x;
    b.mode(6 * i + 2, 0) = 0.5 * ky * x * x;
    b.mode(6 * i + 4, 0) = -ky * x;  // theta_y = -w'
    b.mode(6 * i + 5, 0) = kz * x;   // theta_z = v'
  }
  for (int i = 0; i < ne; ++i) fe::testing::AddBeam(b.mesh, 0, i, i + 1, fe::Vec3(0.0, 1.0, 0.0));
  return b;
}

TEST(BeamFibreStress, ImposedStrainFieldOfAnUnsymmetricSection) {
  const io::nastran::ShapeProperties p = FibreTestLSection();
  ASSERT_GT(std::abs(p.I12), 1e-8);  // an unsymmetric section
  fe::BeamSection sec;
  sec.id = 7;
  sec.A = p.A, sec.Iz = p.I1, sec.Iy = p.I2, sec.Iyz = p.I12, sec.J = p.J;
  sec.stress_points = p.points;
  const double E = 2.1e11, eps0 = 2e-4, ky = 3e-3, kz = -5e-3;
  const FibreTestBeam b = MakeFibreTestBeam(sec, eps0, ky, kz);
  const StressModes sm = ComputeStressModes(b.mesh, b.mode);
  const StressTable& t = sm.beam_fibre;
  ASSERT_EQ(t.elements.size(), 6u);
  ASSERT_EQ(t.Components(), 1);
  ASSERT_EQ(t.Locations(), 2 * static_cast<int>(p.points.size()));
  EXPECT_EQ(t.locations.front(), "end_a_p1");
  EXPECT_EQ(t.locations.back(), "end_b_p" + std::to_string(p.points.size()));
  double peak = 0.0;
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < t.Locations(); ++l) {
      const Point2& yz = p.points[l % p.points.size()];
      const double ref = E * (eps0 - yz[0] * kz - yz[1] * ky);
      peak = std::max(peak, std::abs(ref));
      EXPECT_NEAR(t.modes(t.Row(k, l, 0), 0), ref, 1e-7 * std::abs(E * kz * 0.1)) << k << " " << l;
    }
  EXPECT_GT(peak, 5e7);
}

TEST(BeamFibreStress, OnlyBeamsWithStressPointsAndPaddedPointLists) {
  fe::BeamSection rect;
  rect.id = 1;
  rect.A = 0.02 * 0.04, rect.Iy = 0.02 * std::pow(0.04, 3) / 12, rect.Iz = 0.04 * std::pow(0.02, 3) / 12;
  rect.J = 1e-8;
  rect.stress_points = {{0.01, 0.02}, {-0.01, 0.02}};  // two points only
  FibreTestBeam b = MakeFibreTestBeam(rect, 1e-4, 2e-3, 1e-3);
  fe::BeamSection none = b.mesh.beam_sections[0];  // with the material
  none.id = 2;
  none.stress_points.clear();
  fe::BeamSection round = b.mesh.beam_sections[0];
  round.id = 3;
  round.stress_points.clear();
  for (int k = 0; k < 8; ++k) round.stress_points.push_back({0.01 * std::cos(k * M_PI / 4), 0.01 * std::sin(k * M_PI / 4)});
  b.mesh.beam_sections.push_back(none);
  b.mesh.beam_sections.push_back(round);
  b.mesh.elements[1].property = 1;
  b.mesh.elements[2].property = 2;
  const StressModes sm = ComputeStressModes(b.mesh, b.mode);
  const StressTable& t = sm.beam_fibre;
  EXPECT_EQ(t.elements, (std::vector<int>{0, 2, 3, 4, 5}));  // element 1 has no points
  ASSERT_EQ(t.Locations(), 16);                              // 8 points of the round section per end
  // the two-point section repeats its last point
  for (int l = 2; l < 8; ++l) EXPECT_EQ(t.modes(t.Row(0, l, 0), 0), t.modes(t.Row(0, 1, 0), 0));
  EXPECT_NE(t.modes(t.Row(0, 0, 0), 0), t.modes(t.Row(0, 1, 0), 0));
}

TEST(BeamFibreStress, HullsOfTheLibraryShapes) {
  // L: legs along +z (b, t1) and +y (h, t2); hull corners (y, z) about the centroid
  const io::nastran::ShapeProperties l = FibreTestLSection();
  const double b = 0.08, h = 0.12, t1 = 0.01, t2 = 0.008;
  const double a1 = b * t1, a2 = t2 * (h - t1);
  const double yc = (a1 * 0.5 * t1 + a2 * (t1 + 0.5 * (h - t1))) / (a1 + a2);
  const double zc = (a1 * 0.5 * b + a2 * 0.5 * t2) / (a1 + a2);
  std::vector<Point2> ref = {{0, 0}, {0, b}, {t1, b}, {h, t2}, {h, 0}};
  for (Point2& q : ref) q = {q[0] - yc, q[1] - zc};
  EXPECT_TRUE(SamePoints(l.points, ref));
  // I with equal flanges: the four flange tips
  io::nastran::ShapeProperties i;
  ASSERT_EQ(io::nastran::ComputeShape("I", {0.3, 0.15, 0.15, 0.01, 0.02, 0.02}, 0.3, &i), "");
  EXPECT_TRUE(SamePoints(i.points, {{0.15, 0.075}, {0.15, -0.075}, {-0.15, 0.075}, {-0.15, -0.075}}));
  // T: flange (b 0.1, tf 0.01) on top of the web (tw 0.006), height 0.08: six corners
  io::nastran::ShapeProperties tee;
  ASSERT_EQ(io::nastran::ComputeShape("T", {0.1, 0.08, 0.01, 0.006}, 0.3, &tee), "");
  const double af = 0.1 * 0.01, aw = 0.006 * 0.07;
  const double yt = (af * 0.075 + aw * 0.035) / (af + aw);
  std::vector<Point2> tref = {{0.08, 0.05}, {0.08, -0.05}, {0.07, 0.05}, {0.07, -0.05}, {0, 0.003}, {0, -0.003}};
  for (Point2& q : tref) q[0] -= yt;
  EXPECT_TRUE(SamePoints(tee.points, tref));
  // ROD: 8 points on the circle
  io::nastran::ShapeProperties rod;
  ASSERT_EQ(io::nastran::ComputeShape("ROD", {0.02}, 0.3, &rod), "");
  ASSERT_EQ(rod.points.size(), 8u);
  for (const Point2& q : rod.points) EXPECT_NEAR(std::hypot(q[0], q[1]), 0.02, 1e-15);
}

TEST(BeamFibreStress, UniaxialMeasuresAndSinusoidDamage) {
  const durability::PointStress s = durability::UniaxialStressMeasures(-3e7);
  EXPECT_EQ(s.von_mises, 3e7);
  EXPECT_EQ(s.signed_von_mises, -3e7);
  EXPECT_EQ(s.max_principal, 0.0);
  EXPECT_EQ(s.min_principal, -3e7);
  EXPECT_EQ(s.max_abs_principal, -3e7);
  // one element, two points (1e8 and -0.5e8 Pa per unit coordinate); w = A cos over 10
  // periods: 20 reversals, all ranges 2 A, counted as 20 half cycles (ASTM E1049-85 5.4.4)
  StressTable t;
  t.name = "beam_fibre";
  t.components = {"sxx"};
  t.locations = {"end_a_p1", "end_a_p2"};
  t.elements = {0};
  t.axes = {Mat3::Identity()};
  t.modes = MatX(2, 1);
  t.modes << 1e8, -0.5e8;
  const int per = 40, periods = 10;
  const double A = 1.5;
  MatX W(1, per * periods + 1);
  for (int r = 0; r < W.cols(); ++r) W(0, r) = A * std::cos(2.0 * M_PI * r / per);
  durability::StressRecovery rec(t, W);
  EXPECT_EQ(rec.Points(), 2);
  EXPECT_STREQ(rec.PointName(1), "end_a_p2");
  durability::FatigueOptions fo;
  fo.curve = durability::SnCurve::Eurocode(71);
  const durability::ElementResults r = durability::AnalyzeElements(rec, fo);
  EXPECT_NEAR(r.max_von_mises[0], A * 1e8, 1e-6);
  EXPECT_EQ(r.max_von_mises_point[0], 0);
  const double closed = periods * fo.curve->Damage(2.0 * A * 1e8);
  EXPECT_NEAR(r.damage[0], closed, 1e-9 * closed);
}

}  // namespace
}  // namespace flexmb::reduction
