// Validation of the planar ANCF beam under large deflection: Mattiasson's
// elastica, a cantilever with a tip load of fixed direction normal to its
// axis, PL^2/EI = 1..10 (docs/validation.md, "ANCF beams"). Solved by the
// load-stepping Newton solver of flexmb/ancf/ancf_statics. The same for the
// 3D ANCF cable body bent in a plane not aligned with the world planes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "flexmb/ancf/ancf_statics.h"

namespace flexmb::ancf {
namespace ancf_elastica_test {

// Mattiasson (1981), Table 1: tip deflection w/L and axial shortening u/L
// (reproduced to 6 digits by scripts/ancf_elastica_reference.py)
constexpr double kRefW[10] = {0.30172, 0.49346, 0.60325, 0.66996, 0.71379,
                              0.74457, 0.76737, 0.78498, 0.79906, 0.81061};
constexpr double kRefU[10] = {0.05643, 0.16064, 0.25442, 0.32894, 0.38763,
                              0.43459, 0.47293, 0.50483, 0.53182, 0.55500};

// largest deviation of w/L and u/L from the table over the 10 load levels
double MaxError(int elements, const QuadratureOrder& order) {
  // slender square section h = L / 1000: the axial strain (< 1e-6) does not
  // change the inextensible elastica values at the 1e-5 level
  const double L = 2.0, h = L / 1000.0;
  AncfBeam2dData d;
  d.length = L;
  d.elements = elements;
  d.section.E = 2.1e11;
  d.section.A = h * h;
  d.section.I = h * h * h * h / 12.0;
  d.section.rho = 7850.0;
  d.order = order;
  const AncfBeam2dBody beam("cantilever", d);
  const double EI = d.section.E * d.section.I;
  VecX q(beam.nq()), v(beam.nv());
  beam.InitialCoordinates(q.data(), v.data());
  const int tip = NodeCoordinate(elements);
  double err = 0.0;
  for (int k = 1; k <= 10; ++k) {
    VecX load = VecX::Zero(beam.nv());
    load(tip + 1) = -k * EI / (L * L);
    // continuation from the previous load level
    AncfStaticsSettings s;
    s.load_steps = 2;
    s.initial_load_factor = (k - 1.0) / k;
    // clamp: position and slope direction of node 0 (not the slope length)
    SolveAncfStatics(beam, {0, 1, 3}, load, Vec3::Zero(), q, s);
    const double w = -q(tip + 1) / L, u = 1.0 - q(tip) / L;
    err = std::max({err, std::abs(w - kRefW[k - 1]), std::abs(u - kRefU[k - 1])});
  }
  return err;
}

TEST(AncfElastica, MattiassonCantileverTipLoad) {
  // the table has 5 digits: 16 elements are converged well below 1e-4 L
  // (measured 6.8e-6 with 16 elements, 4.1e-5 with 8)
  const double err16 = MaxError(16, {});
  EXPECT_LT(err16, 2e-5);
  // and the error falls with the element count (about h^3 to h^4)
  const double err8 = MaxError(8, {});
  EXPECT_LT(err8, 1e-4);
  EXPECT_GT(err8, 4.0 * err16);
}

TEST(AncfElastica, FullAxialIntegrationLocks) {
  // with 5-point integration of the axial energy the slender cubic element
  // locks (membrane locking): at 8 elements its error is > 10x that of the
  // default selective reduced integration (docs/design.md "ANCF beams")
  QuadratureOrder full;
  full.axial = 5;
  full.bending = 4;
  EXPECT_GT(MaxError(8, full), 10.0 * MaxError(8, {}));
}

TEST(AncfElastica, Cable3dInASkewPlane) {
  // the 3D cable body: axis along x, tip load along n = (0, 0.6, -0.8);
  // clamp holds r_0 and the y, z components of r'_0 (its direction)
  const double L = 2.0, h = L / 1000.0;
  const int n_el = 16;
  AncfCable3dData d;
  d.length = L;
  d.elements = n_el;
  d.section.E = 2.1e11;
  d.section.A = h * h;
  d.section.I = h * h * h * h / 12.0;
  d.section.rho = 7850.0;
  const AncfCable3dBody cable("cantilever", d);
  const double EI = d.section.E * d.section.I;
  const Vec3 n(0.0, 0.6, -0.8), b = Vec3::UnitX().cross(n);
  VecX q(cable.nq()), v(cable.nv());
  cable.InitialCoordinates(q.data(), v.data());
  const int tip = 6 * n_el;
  double err = 0.0, off_plane = 0.0;
  for (int k = 1; k <= 10; ++k) {
    VecX load = VecX::Zero(cable.nv());
    load.segment<3>(tip) = (k * EI / (L * L)) * n;
    AncfStaticsSettings s;
    s.load_steps = 2;
    s.initial_load_factor = (k - 1.0) / k;
    SolveAncfStatics(cable, {0, 1, 2, 4, 5}, load, Vec3::Zero(), q, s);
    const Vec3 r = q.segment<3>(tip);
    const double w = r.dot(n) / L, u = 1.0 - r.x() / L;
    err = std::max({err, std::abs(w - kRefW[k - 1]), std::abs(u - kRefU[k - 1])});
    off_plane = std::max(off_plane, std::abs(r.dot(b)) / L);
  }
  std::printf("3D cable elastica, 16 elements: largest error %.3e L, out of plane %.3e L\n", err, off_plane);
  EXPECT_LT(err, 2e-5);
  EXPECT_LT(off_plane, 1e-10);
}

}  // namespace ancf_elastica_test
}  // namespace flexmb::ancf
