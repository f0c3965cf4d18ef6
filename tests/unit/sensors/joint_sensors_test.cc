// Joint sensors on a planar pendulum: the pin reaction against Newton's law
// for the bob's centre of mass with the analytic acceleration (and against
// m g + m v^2 / L at the bottom), the joint angle against the bob's position.

#include "flexmb/sensors/joint_sensors.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/simulator.h"
#include "tests/unit/sensors/pendulum_model.h"

namespace flexmb {
namespace {

using namespace test;

TEST(JointSensors, PinReactionOfPendulum) {
  PendulumMarkers mk;
  auto model = Pendulum(mk);
  model->Finalize();
  const JointReactionSensor world("r_world", 0, true), local("r_local", 0, false);
  EXPECT_EQ(world.Components().size(), 6u);
  Simulator sim(*model);
  sim.Initialize();
  const Body& bob = *model->bodies[1];
  const Mat3 R_i = ExpSO3(Vec3(0, 0, kBeta));
  double y_prev = 0.0, x_prev = 1.0;
  int bottoms = 0, checked = 0;
  sim.Run(2.0, 0.0, [&](const State& s, const Workspace& ws) {
    const double* q = s.q.data() + bob.q_offset;
    const double phi = std::atan2(q[1], q[0]), omega = s.v(bob.v_offset + 5);
    const double alpha = -kMass * kG * kL * std::cos(phi) / (kMass * kL * kL + kIzz);
    const Vec3 e(std::cos(phi), std::sin(phi), 0.0), n(-std::sin(phi), std::cos(phi), 0.0);
    // force of the pin on the bob: m a_C - m g
    const Vec3 a_C = kL * alpha * n - kL * omega * omega * e;
    const Vec3 f_ref = kMass * a_C - kMass * Vec3(0, -kG, 0);
    double w[6], l[6];
    world.Evaluate(*model, s, ws, w);
    local.Evaluate(*model, s, ws, l);
    const Vec3 f_w(w[0], w[1], w[2]), f_l(l[0], l[1], l[2]);
    // Newton for the centre of mass with the integrator's accelerations holds
    // to the Newton tolerance; the analytic value to generalized-alpha's
    // O(h^2) error in lambda (~3e-4 N at h = 1e-3)
    const Vec3 f_h = kMass * ws.vdot.segment<3>(bob.v_offset) - kMass * Vec3(0, -kG, 0);
    EXPECT_LT((f_w - f_h).norm(), 1e-8 * kMass * kG) << "t=" << s.t;
    EXPECT_LT((f_l - R_i.transpose() * f_h).norm(), 1e-8 * kMass * kG) << "t=" << s.t;
    EXPECT_LT((f_w - f_ref).norm(), 1e-3) << "t=" << s.t;
    // no moment about the pin: free about z, planar motion about a principal axis
    EXPECT_LT(Vec3(w[3], w[4], w[5]).norm(), 1e-8) << "t=" << s.t;
    ++checked;
    // at the bottom (x changes sign below the pin): m g + m v^2 / L, with v
    // from energy conservation
    if (q[1] < 0 && y_prev < 0 && x_prev * q[0] <= 0.0 && s.t > 0) {
      ++bottoms;
      const double v2 = 2.0 * kG * kL * kMass * kL * kL / (kMass * kL * kL + kIzz);
      const double f_bottom = kMass * kG + kMass * v2 / kL;
      // within one step (angle ~5e-3 rad) of the bottom the magnitude changes
      // by O(1e-5) relative; the direction by the angle
      EXPECT_NEAR(f_w.norm(), f_bottom, 1e-3 * f_bottom) << "t=" << s.t;
      EXPECT_NEAR(std::atan2(f_w(0), f_w(1)), 0.0, 1e-2) << "t=" << s.t;
    }
    y_prev = q[1];
    x_prev = q[0];
  });
  EXPECT_GE(bottoms, 2);
  EXPECT_GT(checked, 1000);
}

TEST(JointSensors, RevoluteAngleAndRate) {
  PendulumMarkers mk;
  auto model = Pendulum(mk);
  model->Finalize();
  const JointCoordinateSensor angle("angle", 0, *model->joints[0], 0);
  EXPECT_TRUE(angle.ComponentIsAngle(0));
  EXPECT_FALSE(angle.ComponentIsAngle(1));
  EXPECT_THROW(JointCoordinateSensor("bad", 0, *model->joints[0], 1), InputError);
  Simulator sim(*model);
  sim.Initialize();
  const Body& bob = *model->bodies[1];
  double min_angle = 10.0;
  sim.Run(1.5, 0.01, [&](const State& s, const Workspace& ws) {
    const double* q = s.q.data() + bob.q_offset;
    // rod angle from the position of the centre of mass, relative to the turned pin
    const double ref = std::atan2(q[1], q[0]) - kBeta;
    double out[2];
    angle.Evaluate(*model, s, ws, out);
    EXPECT_NEAR(std::remainder(out[0] - ref, 2 * M_PI), 0.0, 1e-9) << "t=" << s.t;
    EXPECT_NEAR(out[1], s.v(bob.v_offset + 5), 1e-9) << "t=" << s.t;
    min_angle = std::min(min_angle, out[0]);
  });
  // the bob swings down to the far horizontal: -pi - beta, wrapped
  EXPECT_GT(min_angle, -M_PI);
}

}  // namespace
}  // namespace flexmb
