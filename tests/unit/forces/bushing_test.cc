#include "flexmb/forces/bushing.h"

#include <gtest/gtest.h>

#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

using namespace flexmb::testing;

BushingData Anisotropic() {
  BushingData d;
  d.translational_stiffness = Vec3(1e4, 2e4, 5e3);
  d.rotational_stiffness = Vec3(300, 150, 800);
  d.translational_damping = Vec3(40, 25, 60);
  d.rotational_damping = Vec3(3, 7, 2);
  d.preload_force = Vec3(10, -5, 20);
  d.preload_torque = Vec3(-1, 2, 0.5);
  return d;
}

// j near i: offsets up to 0.3 m and relative rotations up to ~1.5 rad
MarkerState Near(const MarkerState& mi, std::mt19937& rng) {
  MarkerState mj = RandomMarker(rng);
  mj.p_WM = mi.p_WM + RandomVec(rng, 0.3);
  mj.R_WM = mi.R_WM * ExpSO3(RandomVec(rng, 0.9));
  return mj;
}

TEST(Bushing, TangentsMatchFiniteDifferences) {
  std::mt19937 rng(5);
  const Bushing b("b", Anisotropic());
  for (int trial = 0; trial < 20; ++trial) {
    const MarkerState mi = RandomMarker(rng);
    const MarkerState mj = Near(mi, rng);
    ExpectTangents(b, mi, mj, 0.0);
    ExpectThirdLaw(b, mi, mj, 0.0);
  }
}

TEST(Bushing, PotentialGradientIsMinusWrench) {
  // conservative case: isotropic rotational stiffness, no preload torque, no damping
  BushingData d;
  d.translational_stiffness = Vec3(1e4, 2e4, 5e3);
  d.rotational_stiffness = Vec3(400, 400, 400);
  d.preload_force = Vec3(10, -5, 20);
  const Bushing b("b", d);
  std::mt19937 rng(9);
  for (int trial = 0; trial < 10; ++trial) {
    const MarkerState mi = RandomMarker(rng);
    const MarkerState mj = Near(mi, rng);
    ExpectPotentialGradient(b, mi, mj, 0.0);
  }
}

TEST(Bushing, KnownSmallDeflection) {
  // i rotated 90 deg about world z; j displaced 1 mm along x_i (= world y) and
  // turned 0.01 rad about z_i: f_j = -kx * 1e-3 world y, m_j = -kz_rot * 0.01 world z
  const BushingData d = Anisotropic();
  BushingData s;
  s.translational_stiffness = d.translational_stiffness;
  s.rotational_stiffness = d.rotational_stiffness;
  const Bushing b("b", s);
  MarkerState mi, mj;
  mi.R_WM = ExpSO3(Vec3(0, 0, M_PI / 2));
  mj.p_WM = Vec3(0, 1e-3, 0);
  mj.R_WM = mi.R_WM * ExpSO3(Vec3(0, 0, 0.01));
  const Vec12 w = Wrench(b, mi, mj, 0.0);
  EXPECT_NEAR((w.segment<3>(6) - Vec3(0, -1e4 * 1e-3, 0)).norm(), 0.0, 1e-10);
  EXPECT_NEAR((w.segment<3>(9) - Vec3(0, 0, -800 * 0.01)).norm(), 0.0, 1e-10);
  EXPECT_NEAR((w.segment<3>(0) - Vec3(0, 1e4 * 1e-3, 0)).norm(), 0.0, 1e-10);
  // reaction moment on i about p_i: -m_j - d x f_j (d parallel to f_j here)
  EXPECT_NEAR((w.segment<3>(3) - Vec3(0, 0, 800 * 0.01)).norm(), 0.0, 1e-10);
  EXPECT_NEAR(b.PotentialEnergy(mi, mj, 0.0), 0.5 * 1e4 * 1e-6 + 0.5 * 800 * 1e-4, 1e-12);
}

TEST(Bushing, DampingInMarkerAxes) {
  // j moving along z_i (= world x) at 0.1 m/s and turning about x_i at 0.2 rad/s
  BushingData d;
  d.translational_damping = Vec3(1, 2, 3);
  d.rotational_damping = Vec3(4, 5, 6);
  const Bushing b("b", d);
  MarkerState mi, mj;
  mi.R_WM = ExpSO3(Vec3(0, M_PI / 2, 0));  // x_i = -z, z_i = +x
  mj.v_WM = Vec3(0.1, 0, 0);
  mj.w_WM = Vec3(0, 0, -0.2);
  const Vec12 w = Wrench(b, mi, mj, 0.0);
  EXPECT_NEAR((w.segment<3>(6) - Vec3(-3 * 0.1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((w.segment<3>(9) - Vec3(0, 0, 4 * 0.2)).norm(), 0.0, 1e-12);
}

TEST(Bushing, NegativeStiffnessRejected) {
  BushingData d;
  d.rotational_damping = Vec3(1, -1, 1);
  EXPECT_THROW(Bushing("b", d), InputError);
}

}  // namespace
}  // namespace flexmb
