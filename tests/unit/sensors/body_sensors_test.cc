// Body sensors: energies against hand-computed values and conservation over a
// run of two free bodies coupled by a spring; body frame pose against the
// initial data.

#include "flexmb/sensors/body_sensors.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

/// Linear spring of zero rest length between two marker origins, force
/// k (p_j - p_i) on marker i; potential energy k |p_j - p_i|^2 / 2.
class TestSpring final : public ForceElement {
 public:
  TestSpring(std::string name, double k) : ForceElement(std::move(name)), k_(k) {}
  const char* type() const override { return "test_spring"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double, ForceEval& e) const override {
    const Vec3 f = k_ * (mj.p_WM - mi.p_WM);
    e.wrench.setZero();
    e.wrench.segment<3>(0) = f;
    e.wrench.segment<3>(6) = -f;
    e.K.setZero();
    const Mat3 kI = k_ * Mat3::Identity();
    e.K.block<3, 3>(0, 0) = -kI;
    e.K.block<3, 3>(0, 6) = kI;
    e.K.block<3, 3>(6, 0) = kI;
    e.K.block<3, 3>(6, 6) = -kI;
    e.C.setZero();
  }
  double PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double) const override {
    return 0.5 * k_ * (mj.p_WM - mi.p_WM).squaredNorm();
  }

 private:
  double k_;
};

constexpr double kSpring = 150.0;

RigidBodyData BodyA() {
  RigidBodyData d;
  d.mass = 3.0;
  d.inertia_C = Vec3(0.2, 0.3, 0.4).asDiagonal();
  d.c_B = Vec3(0.1, -0.05, 0.2);
  d.p_WB = Vec3(0.5, 1.0, 2.0);
  d.R_WB = FromRollPitchYaw(Vec3(0.3, -0.4, 1.1));
  d.v_WB = Vec3(1.0, -2.0, 0.5);
  d.w_WB = Vec3(0.7, -1.2, 2.0);
  return d;
}

RigidBodyData BodyB() {
  RigidBodyData d;
  d.mass = 1.5;
  d.inertia_C = Vec3(0.1, 0.1, 0.15).asDiagonal();
  d.p_WB = Vec3(-0.5, 0.2, 1.0);
  d.v_WB = Vec3(0.0, 1.0, -1.0);
  d.w_WB = Vec3(-3.0, 0.5, 0.2);
  return d;
}

/// Two free bodies joined by a spring between off-centre markers, gravity -z.
std::unique_ptr<Model> SpringPair(int& marker_a, int& marker_b) {
  auto m = std::make_unique<Model>();
  const int a = m->AddBody(std::make_unique<RigidBody>("a", BodyA()));
  const int b = m->AddBody(std::make_unique<RigidBody>("b", BodyB()));
  marker_a = m->AddMarker(a, "s", Vec3(0.3, 0.1, -0.2), Mat3::Identity());
  marker_b = m->AddMarker(b, "s", Vec3(-0.1, 0.2, 0.0), Mat3::Identity());
  m->AddForce(std::make_unique<TestSpring>("spring", kSpring), marker_a, marker_b);
  m->solver.dt = 5e-4;
  m->solver.rho_inf = 1.0;
  m->Finalize();
  return m;
}

TEST(BodySensors, EnergiesAgainstHandComputedValues) {
  int ma, mb;
  auto model = SpringPair(ma, mb);
  State s = model->InitialState();
  Workspace ws;
  InitWorkspace(*model, ws);
  EvaluateMarkers(*model, s, ws);

  // body a by hand: centre of mass velocity v_B + w x (R c), J_C in body axes
  const RigidBodyData A = BodyA(), B = BodyB();
  const Vec3 c_W = A.R_WB * A.c_B;
  const Vec3 v_C = A.v_WB + A.w_WB.cross(c_W);
  const Vec3 w_B = A.R_WB.transpose() * A.w_WB;
  const double ke_a = 0.5 * A.mass * v_C.squaredNorm() + 0.5 * w_B.dot(A.inertia_C * w_B);
  const double pe_a = A.mass * 9.81 * (A.p_WB + c_W).z();
  double out[3];
  BodyEnergySensor("ea", 1).Evaluate(*model, s, ws, out);
  EXPECT_NEAR(out[0], ke_a, 1e-12 * ke_a);
  EXPECT_NEAR(out[1], pe_a, 1e-12 * std::abs(pe_a));

  const double ke_b = 0.5 * B.mass * B.v_WB.squaredNorm() + 0.5 * B.w_WB.dot(B.inertia_C * B.w_WB);
  const double pe_b = B.mass * 9.81 * B.p_WB.z();
  BodyEnergySensor("eb", 2).Evaluate(*model, s, ws, out);
  EXPECT_NEAR(out[0], ke_b, 1e-12 * ke_b);
  EXPECT_NEAR(out[1], pe_b, 1e-12 * std::abs(pe_b));

  // spring: marker positions by hand
  const Vec3 p_a = A.p_WB + A.R_WB * Vec3(0.3, 0.1, -0.2);
  const Vec3 p_b = B.p_WB + Vec3(-0.1, 0.2, 0.0);
  const double pe_s = 0.5 * kSpring * (p_b - p_a).squaredNorm();
  SystemEnergySensor("sys").Evaluate(*model, s, ws, out);
  EXPECT_NEAR(out[0], ke_a + ke_b, 1e-12 * (ke_a + ke_b));
  EXPECT_NEAR(out[1], pe_a + pe_b + pe_s, 1e-12 * (pe_a + pe_b + pe_s));
  EXPECT_NEAR(out[2], ke_a + ke_b + pe_a + pe_b + pe_s, 1e-12 * (ke_a + ke_b + pe_a + pe_b + pe_s));
}

TEST(BodySensors, SystemEnergyCountsElasticEnergyOfEveryBodyType) {
  // a planar ANCF beam stretched uniformly by eps: axial strain eps, no
  // bending, strain energy E A eps^2 L / 2 (Body::ElasticEnergy, no cast);
  // a rigid body beside it adds none
  auto model = std::make_unique<Model>();
  model->gravity_W.setZero();
  ancf::AncfBeam2dData d;
  d.length = 1.5;
  d.elements = 3;
  d.section.E = 2.0e11;
  d.section.A = 1.0e-4;
  d.section.I = 1.0e-9;
  d.section.rho = 7800.0;
  const int beam = model->AddBody(std::make_unique<ancf::AncfBeam2dBody>("beam", d));
  const int rigid = model->AddBody(std::make_unique<RigidBody>("a", BodyA()));
  model->Finalize();
  State s = model->InitialState();
  const double eps = 1e-3, h = d.length / d.elements;
  const Body& b = *model->bodies[beam];
  for (int k = 0; k <= d.elements; ++k) {
    double* e = s.q.data() + b.q_offset + 4 * k;
    e[0] = (1.0 + eps) * k * h, e[1] = 0.0, e[2] = 1.0 + eps, e[3] = 0.0;
  }
  Workspace ws;
  InitWorkspace(*model, ws);
  EvaluateMarkers(*model, s, ws);
  const double strain = 0.5 * d.section.E * d.section.A * eps * eps * d.length;
  EXPECT_NEAR(b.ElasticEnergy(s.q.data() + b.q_offset), strain, 1e-9 * strain);
  EXPECT_EQ(model->bodies[rigid]->ElasticEnergy(s.q.data() + model->bodies[rigid]->q_offset), 0.0);
  double out[3];
  SystemEnergySensor("sys").Evaluate(*model, s, ws, out);
  EXPECT_NEAR(out[1], strain, 1e-9 * strain);
}

TEST(BodySensors, SystemEnergyIsConserved) {
  int ma, mb;
  auto model = SpringPair(ma, mb);
  const SystemEnergySensor sys("sys");
  const BodyEnergySensor ea("ea", 1), eb("eb", 2);
  Simulator sim(*model);
  sim.Initialize();
  double e0 = 0.0, max_dev = 0.0, max_exchange = 0.0, ke0 = 0.0;
  bool first = true;
  sim.Run(2.0, 0.01, [&](const State& s, const Workspace& ws) {
    double e[3], a[2], b[2];
    sys.Evaluate(*model, s, ws, e);
    ea.Evaluate(*model, s, ws, a);
    eb.Evaluate(*model, s, ws, b);
    // the parts add up: system = bodies + spring (>= 0)
    EXPECT_NEAR(e[0], a[0] + b[0], 1e-12 * e[0]);
    EXPECT_GE(e[1] - a[1] - b[1], 0.0);
    if (first) e0 = e[2], ke0 = e[0], first = false;
    max_dev = std::max(max_dev, std::abs(e[2] - e0));
    max_exchange = std::max(max_exchange, std::abs(e[0] - ke0));
  });
  // kinetic energy changes by joules while the total stays put
  EXPECT_GT(max_exchange, 1.0);
  EXPECT_LT(max_dev, 1e-4 * max_exchange);
}

TEST(BodySensors, BodyFramePose) {
  int ma, mb;
  auto model = SpringPair(ma, mb);
  const State s = model->InitialState();
  Workspace ws;
  const BodyPositionSensor pose("pose", 1);
  EXPECT_TRUE(pose.ComponentIsAngle(5));
  EXPECT_FALSE(pose.ComponentIsAngle(0));
  double out[6];
  pose.Evaluate(*model, s, ws, out);
  // the user frame, not the centre of mass (c_B != 0)
  EXPECT_NEAR(out[0], 0.5, 1e-14);
  EXPECT_NEAR(out[1], 1.0, 1e-14);
  EXPECT_NEAR(out[2], 2.0, 1e-14);
  EXPECT_NEAR(out[3], 0.3, 1e-13);
  EXPECT_NEAR(out[4], -0.4, 1e-13);
  EXPECT_NEAR(out[5], 1.1, 1e-13);
}

}  // namespace
}  // namespace flexmb
