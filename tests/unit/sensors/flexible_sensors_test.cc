// Node sensors of a floating-frame flexible body: world position and velocity
// of an FE node against a hand computation from the body's data (frame pose,
// node position rho_k, mode rows) and the velocity against central finite
// differences of the position along the motion.

#include "flexmb/sensors/flexible_sensors.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb {
namespace {

constexpr int kNode = 4;  // off the interface, on the second leg

struct Fixture {
  std::shared_ptr<reduction::ReducedBody> reduced;
  Model model;
  int body = -1;
  FlexibleBodyData data;
};

void Build(Fixture& f) {
  f.reduced = testing::FreeBentBar(3, 3);
  const int n = f.reduced->invariants.n;
  f.data.reduced = f.reduced;
  f.data.p_WB = Vec3(0.3, -0.2, 1.1);
  f.data.R_WB = Eigen::AngleAxisd(0.9, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  f.data.v_WB = Vec3(1.0, -2.0, 0.5);
  f.data.w_WB = Vec3(3.0, 1.5, -2.0);
  f.data.w0 = 1e-2 * VecX::LinSpaced(n, 1.0, -0.5);
  f.data.wd0 = 0.3 * VecX::LinSpaced(n, -1.0, 2.0);
  f.body = f.model.AddBody(std::make_unique<FlexibleBody>("bar", f.data));
  f.model.Finalize();
}

TEST(FlexibleSensors, NodePositionAndVelocityByHand) {
  Fixture f;
  Build(f);
  const State s = f.model.InitialState();
  const Workspace ws;
  double p[3], v[3];
  NodePositionSensor("p", f.body, kNode).Evaluate(f.model, s, ws, p);
  NodeVelocitySensor("v", f.body, kNode).Evaluate(f.model, s, ws, v);
  // by hand: u = rho + H^t w in body axes, p = r + R u, v = v_W + w_W x R u + R H^t wd
  const MatX Ht = f.reduced->modes.middleRows(6 * kNode, 3);
  const Vec3 u = f.reduced->mesh.nodes[kNode].x + Ht * f.data.w0;
  const Vec3 p_ref = f.data.p_WB + f.data.R_WB * u;
  const Vec3 v_ref = f.data.v_WB + f.data.w_WB.cross(f.data.R_WB * u) + f.data.R_WB * (Ht * f.data.wd0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(p[k], p_ref(k), 1e-14 * p_ref.norm());
    EXPECT_NEAR(v[k], v_ref(k), 1e-13 * v_ref.norm());
  }
  // the elastic part is not negligible here
  EXPECT_GT((Ht * f.data.w0).norm(), 1e-4);
  EXPECT_GT((Ht * f.data.wd0).norm(), 1e-3);
}

TEST(FlexibleSensors, NodeVelocityIsTheDerivativeOfNodePosition) {
  Fixture f;
  Build(f);
  const Body& b = *f.model.bodies[f.body];
  const State s = f.model.InitialState();
  const Workspace ws;
  const NodePositionSensor pos("p", f.body, kNode);
  double v[3];
  NodeVelocitySensor("v", f.body, kNode).Evaluate(f.model, s, ws, v);
  // q(t +- h) = q (+) (+-h v): the motion with the current velocities
  const double h = 1e-6;
  State sp = s, sm = s;
  const VecX dx = h * s.v.segment(b.v_offset, b.nv());
  const VecX mdx = -dx;
  b.Retract(s.q.data() + b.q_offset, dx.data(), sp.q.data() + b.q_offset);
  b.Retract(s.q.data() + b.q_offset, mdx.data(), sm.q.data() + b.q_offset);
  double pp[3], pm[3];
  pos.Evaluate(f.model, sp, ws, pp);
  pos.Evaluate(f.model, sm, ws, pm);
  const Vec3 fd = (Vec3(pp[0], pp[1], pp[2]) - Vec3(pm[0], pm[1], pm[2])) / (2 * h);
  EXPECT_LT((fd - Vec3(v[0], v[1], v[2])).norm(), 1e-7 * fd.norm());
}

TEST(FlexibleSensors, StressSensorsNeedStressModes) {
  Fixture f;
  Build(f);
  const auto& body = static_cast<const FlexibleBody&>(*f.model.bodies[f.body]);
  // the bent bar has beams only: section forces, no von Mises, no node average
  const ElementStressSensor e("s", f.body, body, 2);
  ASSERT_EQ(e.Components().size(), 12u);
  EXPECT_EQ(e.Components()[0], "end_a_N");
  EXPECT_EQ(e.Components()[11], "end_b_Mz");
  const State s = f.model.InitialState();
  double out[12];
  e.Evaluate(f.model, s, Workspace(), out);
  const reduction::StressTable& t = f.reduced->stress.beam;
  const VecX ref = t.modes.middleRows(t.Row(2, 0, 0), 12) * f.data.w0;
  for (int k = 0; k < 12; ++k) EXPECT_NEAR(out[k], ref(k), 1e-12 * ref.norm());
  EXPECT_THROW(NodeStressSensor("n", f.body, body, 1), InputError);
  EXPECT_THROW(ElementStressSensor("s", f.body, body, 99), InputError);
}

}  // namespace
}  // namespace flexmb
