#include "flexmb/forces/point_force.h"

#include <gtest/gtest.h>

#include "flexmb/forces/point_torque.h"
#include "tests/unit/forces/force_test_util.h"

namespace flexmb {
namespace {

using namespace flexmb::testing;

using Components = std::array<std::shared_ptr<const ScalarFunction>, 3>;

// components: constant 3, a linear table in t, constant -5
Components Loads() {
  return {std::make_shared<ConstantFunction>(3.0),
          std::make_shared<TableFunction>(std::vector<double>{0, 1, 2}, std::vector<double>{-2, 4, 1},
                                          TableFunction::Interpolation::kLinear, false),
          std::make_shared<ConstantFunction>(-5.0)};
}

TEST(PointLoads, KnownValuesInWorldAndMarkerAxes) {
  MarkerState m;
  m.p_WM = Vec3(1, 2, 3);
  m.R_WM = ExpSO3(Vec3(0, 0, M_PI / 2));  // x_M = world y, y_M = -world x
  const MarkerState none;
  const double t = 0.5;  // table: -2 + 0.5 * 6 = 1
  const Vec12 fw = Wrench(PointForce("f", Loads(), LoadFrame::kWorld), m, none, t);
  const Vec12 fm = Wrench(PointForce("f", Loads(), LoadFrame::kMarker), m, none, t);
  const Vec12 tw = Wrench(PointTorque("m", Loads(), LoadFrame::kWorld), m, none, t);
  const Vec12 tm = Wrench(PointTorque("m", Loads(), LoadFrame::kMarker), m, none, t);
  EXPECT_NEAR((fw.head<3>() - Vec3(3, 1, -5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((fm.head<3>() - Vec3(-1, 3, -5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((tw.segment<3>(3) - Vec3(3, 1, -5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((tm.segment<3>(3) - Vec3(-1, 3, -5)).norm(), 0.0, 1e-12);
  EXPECT_EQ(fw.tail<9>().norm() + fm.tail<9>().norm(), 0.0);
  EXPECT_EQ(tw.head<3>().norm() + tw.tail<6>().norm() + tm.head<3>().norm() + tm.tail<6>().norm(), 0.0);
}

TEST(PointLoads, TangentsMatchFiniteDifferences) {
  std::mt19937 rng(13);
  for (LoadFrame frame : {LoadFrame::kWorld, LoadFrame::kMarker}) {
    const PointForce f("f", Loads(), frame);
    const PointTorque m("m", Loads(), frame);
    for (int trial = 0; trial < 5; ++trial) {
      const MarkerState mi = RandomMarker(rng);
      ExpectTangents(f, mi, MarkerState{}, 1.3, 6);
      ExpectTangents(m, mi, MarkerState{}, 1.3, 6);
    }
  }
  // a follower load has stiffness
  ForceEval e;
  PointForce("f", Loads(), LoadFrame::kMarker).Evaluate(RandomMarker(rng), MarkerState{}, 0.0, e);
  EXPECT_GT(e.K.norm(), 1.0);
}

TEST(PointLoads, MissingComponentRejected) {
  Components c = Loads();
  c[1] = nullptr;
  EXPECT_THROW(PointForce("f", c, LoadFrame::kWorld), InputError);
  EXPECT_THROW(PointTorque("m", c, LoadFrame::kWorld), InputError);
}

}  // namespace
}  // namespace flexmb
