// Road surface under a tire (road_surface.h) and the tire on it: the
// surface against the profile's own interpolation and finite differences,
// a flat surface bit-identical to the default flat road, a tire on a
// constant slope against the flat-road tire in the rotated frame (the
// road's plane is the flat road turned by the slope angle), and the
// tangents seeing the road height (translation along a sloped road).
#include "flexmb/vehicle/road_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "flexmb/common/error.h"
#include "flexmb/vehicle/tire.h"
#include "tests/unit/vehicle/tire_test_data.h"

namespace flexmb::vehicle {
namespace {

// a road track of equally spaced samples, z = 0.02 sin(3 x) + 0.01 x (right: cos)
std::shared_ptr<RoadProfile> RoadSurfaceSampleProfile() {
  auto p = std::make_shared<RoadProfile>();
  for (int i = 0; i <= 40; ++i) {
    const double x = -1.0 + 0.1 * i;
    p->x.push_back(x);
    p->z_left.push_back(0.02 * std::sin(3 * x) + 0.01 * x);
    p->z_right.push_back(0.02 * std::cos(3 * x));
  }
  return p;
}

// the wheel of the tire tests: spin axis along world +y, steered and cambered
MarkerState RoadSurfaceWheel(double z) {
  MarkerState m;
  m.p_WM = Vec3(1.3, 2.0, z);
  m.R_WM << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  m.R_WM = (Eigen::AngleAxisd(0.08, Vec3::UnitZ()) * Eigen::AngleAxisd(0.02, Vec3::UnitX())).toRotationMatrix() * m.R_WM;
  m.v_WM = Vec3(14.0, 0.6, -0.05);
  m.w_WM = m.R_WM.col(2) * (1.03 * 14.0 / 0.523) + Vec3(0.01, 0.0, 0.2);
  return m;
}

TEST(RoadSurface, HeightIsTheProfilesInterpolationAndSlopeItsDerivative) {
  const auto p = RoadSurfaceSampleProfile();
  // the same track with an extra sample inside a segment: not equally spaced
  auto q = std::make_shared<RoadProfile>(*p);
  q->x.insert(q->x.begin() + 5, 0.5 * (p->x[4] + p->x[5]));
  q->z_left.insert(q->z_left.begin() + 5, 0.5 * (p->z_left[4] + p->z_left[5]));
  q->z_right.insert(q->z_right.begin() + 5, 0.5 * (p->z_right[4] + p->z_right[5]));
  for (int side = 0; side < 2; ++side) {
    const RoadSurface uniform(p, side), general(q, side);
    for (double x = -1.7; x < 3.7; x += 0.0137) {
      double h = 0, s = 0, hg = 0, sg = 0;
      uniform.Evaluate(x, &h, &s);
      general.Evaluate(x, &hg, &sg);
      EXPECT_NEAR(h, p->Height(side, x), 1e-15) << x;
      EXPECT_NEAR(hg, h, 1e-15) << x;
      EXPECT_NEAR(sg, s, 1e-12) << x;
      // the slope is the derivative of the height (inside a segment)
      const double e = 1e-7;
      const double fd = (p->Height(side, x + e) - p->Height(side, x - e)) / (2 * e);
      EXPECT_NEAR(s, fd, 1e-6) << x;
    }
    // at a sample the segment ahead holds it; level beyond the ends
    double h = 0, s = 0;
    uniform.Evaluate(p->x[7], &h, &s);
    EXPECT_EQ(h, (side == 0 ? p->z_left : p->z_right)[7]);
    uniform.Evaluate(-5.0, &h, &s);
    EXPECT_EQ(s, 0.0);
    uniform.Evaluate(9.0, &h, &s);
    EXPECT_EQ(h, (side == 0 ? p->z_left : p->z_right).back());
    EXPECT_EQ(s, 0.0);
  }
  EXPECT_THROW(RoadSurface(p, 2), InputError);
  EXPECT_THROW(RoadSurface(std::make_shared<RoadProfile>(), 0), InputError);
}

TEST(RoadSurface, TireOnAFlatSurfaceIsBitIdenticalToTheDefaultRoad) {
  auto flat = std::make_shared<RoadProfile>();
  flat->x = {-100.0, 0.0, 100.0};
  flat->z_left = flat->z_right = {0.0, 0.0, 0.0};
  TireData d = Tire11R22();
  d.count = 2;
  const Tire plain("plain", d, 0.8);
  Tire on_road("road", d, 0.8);
  on_road.SetRoad(std::make_shared<RoadSurface>(flat, 0));
  for (double z : {0.50, 0.515, 0.526, 0.53}) {
    const MarkerState m = RoadSurfaceWheel(z);
    ForceEval a, b;
    plain.Evaluate(m, MarkerState{}, 0.0, a);
    on_road.Evaluate(m, MarkerState{}, 0.0, b);
    for (int i = 0; i < 12; ++i) EXPECT_EQ(a.wrench[i], b.wrench[i]) << "z " << z << " entry " << i;
    EXPECT_EQ((a.K - b.K).norm(), 0.0);
    EXPECT_EQ((a.C - b.C).norm(), 0.0);
  }
}

// a tire on the road z = z0 + s x is the flat-road tire in the frame turned
// by the slope angle about y: same wrench, rotated
TEST(RoadSurface, TireOnASlopeIsTheFlatRoadTireTurnedByTheSlope) {
  const double s = 0.12, z0 = 0.3;
  auto ramp = std::make_shared<RoadProfile>();
  ramp->x = {-50.0, 50.0};
  ramp->z_left = ramp->z_right = {z0 - 50 * s, z0 + 50 * s};
  TireData d = Tire11R22();
  d.count = 2;
  const Tire flat("flat", d, 0.8);
  Tire on_road("road", d, 0.8);
  on_road.SetRoad(std::make_shared<RoadSurface>(ramp, 1));
  // Rot maps +z to the road normal n = (-s, 0, 1) / sqrt(1 + s^2)
  const Mat3 rot = Eigen::AngleAxisd(-std::atan(s), Vec3::UnitY()).toRotationMatrix();
  ASSERT_LT((rot.col(2) - Vec3(-s, 0, 1).normalized()).norm(), 1e-15);
  for (double gap : {0.505, 0.515, 0.525}) {
    MarkerState m = RoadSurfaceWheel(0.0);
    m.p_WM.z() = z0 + s * m.p_WM.x() + gap;
    const Vec3 q(m.p_WM.x(), m.p_WM.y(), z0 + s * m.p_WM.x());
    TireContact cr, cf;
    const Vec6 w_road = on_road.Wrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, &cr);
    const Vec6 w_flat = flat.Wrench(rot.transpose() * (m.p_WM - q), rot.transpose() * m.R_WM,
                                    rot.transpose() * m.v_WM, rot.transpose() * m.w_WM, &cf);
    ASSERT_GT(cf.fz, 1e3);
    Vec6 expected;
    expected << rot * w_flat.head<3>(), rot * w_flat.tail<3>();
    EXPECT_LT((w_road - expected).norm(), 1e-9 * w_flat.norm()) << "gap " << gap;
    EXPECT_NEAR(cr.deflection, cf.deflection, 1e-14);
    EXPECT_NEAR(cr.fz, cf.fz, 1e-9 * cf.fz);
  }
}

// on a constant slope the wrench depends on p only through p_z - h(p_x):
// dW/dp_x = -s dW/dp_z; the finite-difference tangents see the road
TEST(RoadSurface, TireTangentsSeeTheRoadHeight) {
  const double s = 0.08;
  auto ramp = std::make_shared<RoadProfile>();
  ramp->x = {-50.0, 50.0};
  ramp->z_left = ramp->z_right = {-50 * s, 50 * s};
  TireData d = Tire11R22();
  d.count = 2;
  Tire on_road("road", d, 0.8);
  on_road.SetRoad(std::make_shared<RoadSurface>(ramp, 0));
  MarkerState m = RoadSurfaceWheel(0.0);
  m.p_WM.z() = s * m.p_WM.x() + 0.515;
  ForceEval e;
  on_road.Evaluate(m, MarkerState{}, 0.0, e);
  const Vec6 kx = e.K.col(0).head<6>(), kz = e.K.col(2).head<6>();
  EXPECT_GT(std::abs(kz[2]), 1e6);
  EXPECT_LT((kx + s * kz).norm(), 1e-5 * kz.norm()) << "dW/dx " << kx.transpose() << "\ndW/dz " << kz.transpose();
  // dFz/dx of the vertical spring alone: k n h' cos(slope) / cos(gamma) in size
  EXPECT_GT(std::abs(kx[2]), 0.5 * s * 2 * d.vertical_stiffness);
}

}  // namespace
}  // namespace flexmb::vehicle
