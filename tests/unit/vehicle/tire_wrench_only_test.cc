// Tire force element asked for the wrench only (ForceEval::tangents false,
// residual evaluations with a kept iteration matrix): the same wrench as
// with tangents, and K, C left as they were.
#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {
namespace {

TEST(TireWrenchOnly, SameWrenchAsWithTangentsAndTangentsUntouched) {
  TireData d;
  d.count = 2;
  d.unloaded_radius = 0.527;
  d.vertical_stiffness = 9e5;
  d.vertical_damping = 1.5e3;
  d.nominal_load = 25e3;
  const Tire tire("t", d, 0.8);
  // rolling at 15 m/s with 3 degrees of slip angle and some longitudinal slip
  MarkerState m;
  m.p_WM = Vec3(1.0, 2.0, 0.515);
  m.R_WM << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  m.v_WM = Vec3(15.0, 15.0 * std::tan(3.0 * M_PI / 180), 0.0);
  m.w_WM = Vec3(0, 15.0 / 0.51, 0);
  ForceEval full;
  tire.Evaluate(m, MarkerState{}, 0.0, full);
  ASSERT_GT(full.wrench.head<3>().norm(), 1e3);
  ASSERT_GT(full.K.norm(), 0.0);
  ForceEval only;
  only.tangents = false;
  only.K.setConstant(7.0);
  only.C.setConstant(-3.0);
  tire.Evaluate(m, MarkerState{}, 0.0, only);
  EXPECT_EQ((only.wrench - full.wrench).norm(), 0.0);
  EXPECT_EQ(only.K, Mat12::Constant(7.0));
  EXPECT_EQ(only.C, Mat12::Constant(-3.0));
}

}  // namespace
}  // namespace flexmb::vehicle
