// Marker sensors on a planar pendulum against the analytic kinematics of a
// point on a rotating rod, and the velocity against finite differences of the
// position along a run.

#include "flexmb/sensors/marker_sensors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flexmb/model/workspace.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/simulator.h"
#include "tests/unit/sensors/pendulum_model.h"

namespace flexmb {
namespace {

using namespace test;

/// Angle of the rod from +x [rad] and its rate [rad/s] from the bob's state.
void RodAngle(const State& s, const Body& bob, double& phi, double& omega) {
  const double* q = s.q.data() + bob.q_offset;
  phi = std::atan2(q[1], q[0]);
  omega = s.v(bob.v_offset + 5);  // body z = world z in planar motion
}

TEST(MarkerSensors, AccelerationIsCentripetalPlusTangential) {
  PendulumMarkers mk;
  auto model = Pendulum(mk);
  const MarkerAccelerationSensor* com = nullptr;
  const MarkerAccelerationSensor* tip = nullptr;
  {
    auto a = std::make_unique<MarkerAccelerationSensor>("acc_com", mk.bob_com, true);
    auto b = std::make_unique<MarkerAccelerationSensor>("acc_tip", mk.bob_tip, true);
    com = a.get(), tip = b.get();
    model->AddSensor(std::move(a));
    model->AddSensor(std::move(b));
  }
  model->Finalize();
  ASSERT_EQ(tip->Components().size(), 6u);
  Simulator sim(*model);
  sim.Initialize();
  const Body& bob = *model->bodies[1];
  int checked = 0;
  sim.Run(1.5, 0.01, [&](const State& s, const Workspace& ws) {
    double phi, omega;
    RodAngle(s, bob, phi, omega);
    // theta'' from the moment of gravity about the pin, and the integrator's
    // own angular acceleration (generalized-alpha's O(h^2) error is ~1e-4)
    const double alpha = -kMass * kG * kL * std::cos(phi) / (kMass * kL * kL + kIzz);
    const double alpha_h = ws.vdot(bob.v_offset + 5);
    EXPECT_NEAR(alpha_h, alpha, 1e-3) << "t=" << s.t;
    const Vec3 e(std::cos(phi), std::sin(phi), 0.0), n(-std::sin(phi), std::cos(phi), 0.0);
    for (auto [sensor, r] : {std::pair{com, kL}, std::pair{tip, kL + 0.5}}) {
      double out[6];
      sensor->Evaluate(*model, s, ws, out);
      // rigid-body kinematics from the integrator's centre of mass acceleration
      // (index-3 generalized-alpha meets the acceleration-level constraint
      // only to O(h^2)): a_C + alpha x s - omega^2 s, s = (r - L) e
      const Vec3 a_C = ws.vdot.segment<3>(bob.v_offset);
      const Vec3 a_ref = a_C + (r - kL) * (alpha_h * n - omega * omega * e);
      // the analytic motion about the pin: tangential r alpha n, centripetal -r omega^2 e
      const Vec3 a_dyn = r * alpha * n - r * omega * omega * e;
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(out[k], a_ref(k), 1e-8) << sensor->name() << " t=" << s.t;
        EXPECT_NEAR(out[k], a_dyn(k), 2e-3) << sensor->name() << " t=" << s.t;
      }
      EXPECT_NEAR(out[3], 0.0, 1e-9);
      EXPECT_NEAR(out[4], 0.0, 1e-9);
      EXPECT_NEAR(out[5], alpha_h, 1e-12) << sensor->name() << " t=" << s.t;
    }
    ++checked;
  });
  EXPECT_GT(checked, 100);
}

TEST(MarkerSensors, VelocityIsDerivativeOfPosition) {
  PendulumMarkers mk;
  auto model = Pendulum(mk);
  model->Finalize();
  const MarkerPositionSensor pos("pos", mk.bob_tip);
  const MarkerVelocitySensor vel("vel", mk.bob_tip, true);
  const MarkerOrientationSensor ori("ori", mk.bob_tip, -1, false);
  EXPECT_EQ(vel.Components(), (std::vector<std::string>{"x", "y", "z", "wx", "wy", "wz"}));
  EXPECT_TRUE(ori.ComponentIsAngle(2));
  EXPECT_FALSE(pos.ComponentIsAngle(0));
  Simulator sim(*model);
  sim.Initialize();
  std::vector<double> t;
  std::vector<Vec3> p, yaw_w;
  std::vector<Eigen::Matrix<double, 6, 1>> v;
  sim.Run(1.0, 0.0, [&](const State& s, const Workspace& ws) {
    double x[3], w[6], o[3];
    pos.Evaluate(*model, s, ws, x);
    vel.Evaluate(*model, s, ws, w);
    ori.Evaluate(*model, s, ws, o);
    t.push_back(s.t);
    p.emplace_back(x[0], x[1], x[2]);
    v.push_back(Eigen::Map<Eigen::Matrix<double, 6, 1>>(w));
    yaw_w.emplace_back(o[0], o[1], o[2]);
  });
  ASSERT_GT(t.size(), 900u);
  double max_err = 0.0, max_speed = 0.0;
  for (size_t k = 1; k + 1 < t.size(); ++k) {
    const double h = t[k + 1] - t[k - 1];
    const Vec3 fd = (p[k + 1] - p[k - 1]) / h;
    max_err = std::max(max_err, (fd - v[k].head<3>()).norm());
    max_speed = std::max(max_speed, v[k].head<3>().norm());
    // yaw rate = wz; roll and pitch stay zero
    const double dyaw = std::remainder(yaw_w[k + 1](2) - yaw_w[k - 1](2), 2 * M_PI) / h;
    EXPECT_NEAR(dyaw, v[k](5), 1e-4 * std::max(1.0, std::abs(v[k](5))));
    EXPECT_NEAR(yaw_w[k](0), 0.0, 1e-12);
    EXPECT_NEAR(yaw_w[k](1), 0.0, 1e-12);
  }
  // central difference error h^2/6 |x'''| with h = 1e-3: well below 1e-5 of the speed
  EXPECT_GT(max_speed, 5.0);
  EXPECT_LT(max_err, 1e-5 * max_speed);
}

TEST(MarkerSensors, PositionAndOrientationRelativeToMarker) {
  PendulumMarkers mk;
  auto model = Pendulum(mk);
  model->Finalize();
  // turn the bob to phi about the pin
  const double phi = 2.4;
  State s = model->InitialState();
  const Body& bob = *model->bodies[1];
  const Quat qr(ExpSO3(Vec3(0, 0, phi)));
  double* q = s.q.data() + bob.q_offset;
  q[0] = kL * std::cos(phi), q[1] = kL * std::sin(phi), q[2] = 0.0;
  q[3] = qr.w(), q[4] = qr.x(), q[5] = qr.y(), q[6] = qr.z();
  Workspace ws;
  InitWorkspace(*model, ws);
  EvaluateMarkers(*model, s, ws);

  double out[7];
  MarkerPositionSensor("p_world", mk.bob_tip).Evaluate(*model, s, ws, out);
  EXPECT_NEAR(out[0], 1.5 * std::cos(phi), 1e-14);
  EXPECT_NEAR(out[1], 1.5 * std::sin(phi), 1e-14);
  EXPECT_NEAR(out[2], 0.0, 1e-14);
  // in the ground pin frame, turned by beta: angle phi - beta
  MarkerPositionSensor("p_rel", mk.bob_tip, mk.ground_pin).Evaluate(*model, s, ws, out);
  EXPECT_NEAR(out[0], 1.5 * std::cos(phi - kBeta), 1e-14);
  EXPECT_NEAR(out[1], 1.5 * std::sin(phi - kBeta), 1e-14);
  EXPECT_NEAR(out[2], 0.0, 1e-14);

  // orientation: yaw phi in world, phi - beta relative; quaternion of Rz
  const MarkerOrientationSensor ori("o", mk.bob_tip, -1, true);
  ASSERT_EQ(ori.Components().size(), 7u);
  ori.Evaluate(*model, s, ws, out);
  EXPECT_NEAR(out[0], 0.0, 1e-14);
  EXPECT_NEAR(out[1], 0.0, 1e-14);
  EXPECT_NEAR(out[2], phi, 1e-14);
  EXPECT_NEAR(out[3], std::cos(phi / 2), 1e-14);
  EXPECT_NEAR(out[4], 0.0, 1e-14);
  EXPECT_NEAR(out[5], 0.0, 1e-14);
  EXPECT_NEAR(out[6], std::sin(phi / 2), 1e-14);
  MarkerOrientationSensor("o_rel", mk.bob_tip, mk.ground_pin, false).Evaluate(*model, s, ws, out);
  EXPECT_NEAR(out[2], phi - kBeta, 1e-14);

  // a general orientation: roll, pitch, yaw and quaternion (w >= 0) of R
  const Vec3 rpy(0.4, -0.9, -2.8);
  const Quat qg(FromRollPitchYaw(rpy));
  q[3] = -qg.w(), q[4] = -qg.x(), q[5] = -qg.y(), q[6] = -qg.z();
  EvaluateMarkers(*model, s, ws);
  ori.Evaluate(*model, s, ws, out);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], rpy(k), 1e-12);
  const double sgn = qg.w() < 0 ? -1.0 : 1.0;
  EXPECT_NEAR(out[3], sgn * qg.w(), 1e-14);
  EXPECT_NEAR(out[4], sgn * qg.x(), 1e-14);
  EXPECT_NEAR(out[5], sgn * qg.y(), 1e-14);
  EXPECT_NEAR(out[6], sgn * qg.z(), 1e-14);
  EXPECT_GE(out[3], 0.0);
}

}  // namespace
}  // namespace flexmb
