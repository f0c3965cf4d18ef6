#pragma once
/// \file wedge_rules.h
/// Quadrature on the reference wedge (triangle 0 <= xi, eta, xi + eta <= 1
/// times the line -1 <= zeta <= 1, volume 1) for the wedge elements: a
/// triangle rule times a Gauss-Legendre line rule. Exactness checked in
/// tests/unit/fe/solid_wedge_test.cc.

#include <cmath>
#include <span>

#include "flexmb/fe/elements/solid_common.h"

namespace flexmb::fe::solid {

/// A point of a triangle rule: (xi, eta) and weight (the area 1/2 included).
struct TrianglePoint {
  double xi, eta, w;
};

/// Centroid rule, exact for degree 1.
inline constexpr TrianglePoint kTriangleOnePoint[1] = {{1.0 / 3.0, 1.0 / 3.0, 0.5}};

/// Three interior points (1/6, 2/3), exact for degree 2.
inline constexpr TrianglePoint kTriangleThreePoint[3] = {
    {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0}, {2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0}, {1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0}};

/// Six points with positive weights, exact for degree 4 (Strang and Fix
/// 1973; Dunavant 1985, degree 4).
inline constexpr double kTriangleSixA = 0.445948490915965, kTriangleSixWA = 0.223381589678011 / 2.0;
inline constexpr double kTriangleSixB = 0.091576213509771, kTriangleSixWB = 0.109951743655322 / 2.0;
inline constexpr TrianglePoint kTriangleSixPoint[6] = {
    {kTriangleSixA, kTriangleSixA, kTriangleSixWA},
    {1.0 - 2.0 * kTriangleSixA, kTriangleSixA, kTriangleSixWA},
    {kTriangleSixA, 1.0 - 2.0 * kTriangleSixA, kTriangleSixWA},
    {kTriangleSixB, kTriangleSixB, kTriangleSixWB},
    {1.0 - 2.0 * kTriangleSixB, kTriangleSixB, kTriangleSixWB},
    {kTriangleSixB, 1.0 - 2.0 * kTriangleSixB, kTriangleSixWB}};

/// The product of a triangle rule and the Gauss-Legendre rule of `line`
/// points (1, 2 or 3) in zeta, written to `out` (room for
/// triangle.size() * line points); returns the number of points.
inline int WedgeRule(std::span<const TrianglePoint> triangle, int line, QuadPoint* out) {
  const double g2 = 1.0 / std::sqrt(3.0), g3 = std::sqrt(0.6);
  const double z1[1] = {0.0}, w1[1] = {2.0};
  const double z2[2] = {-g2, g2}, w2[2] = {1.0, 1.0};
  const double z3[3] = {-g3, 0.0, g3}, w3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double* z = line == 1 ? z1 : line == 2 ? z2 : z3;
  const double* w = line == 1 ? w1 : line == 2 ? w2 : w3;
  int k = 0;
  for (const TrianglePoint& t : triangle)
    for (int l = 0; l < line; ++l) out[k++] = {t.xi, t.eta, z[l], t.w * w[l]};
  return k;
}

}  // namespace flexmb::fe::solid
