// A quarter car rolling over a sine road (vehicle/road_surface.h, the
// tire following the road): a cart driven along x at constant speed V
// carries the sprung mass and the axle on vertical slides, the suspension
// spring-damper between them, the wheel on a bearing on the axle with a
// Tire (vertical stiffness k_t, damping c_t) on the road h(x) = A sin(2 pi
// x / lambda). After the start transient the sprung mass and the tire
// force follow the closed-form steady state of the linear two-mass quarter
// car under the base excitation z_r(t) = A sin(omega t), omega = 2 pi V /
// lambda (the 2 x 2 complex system of the equations of motion, e.g.
// Wong, "Theory of Ground Vehicles", 4th ed., sec. 7.2; Gillespie,
// "Fundamentals of Vehicle Dynamics", ch. 5): amplitude within 1 %, phase
// within 0.01 rad, at 2.5 Hz (near the body's resonance) and 12.5 Hz (near
// wheel hop). docs/validation.md, "Rough roads".
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/math/scalar_function.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/vehicle/road_surface.h"
#include "flexmb/vehicle/tire.h"

namespace road_quarter_car_test {

using flexmb::Mat3;
using flexmb::MarkerState;
using flexmb::Model;
using flexmb::MotionDriver;
using flexmb::PrismaticJoint;
using flexmb::RevoluteJoint;
using flexmb::RigidBody;
using flexmb::RigidBodyData;
using flexmb::Simulator;
using flexmb::SpringDamper;
using flexmb::SpringDamperLaw;
using flexmb::State;
using flexmb::TableFunction;
using flexmb::Vec3;
using flexmb::Workspace;
using flexmb::vehicle::RoadProfile;
using flexmb::vehicle::RoadSurface;
using flexmb::vehicle::Tire;
using flexmb::vehicle::TireContact;
using flexmb::vehicle::TireData;
using Cplx = std::complex<double>;

constexpr double kMs = 1000.0, kAxle = 20.0, kWheel = 80.0;  // sprung, axle, wheel [kg]
constexpr double kKs = 1e5, kCs = 8e3;                       // suspension [N/m, N s/m]
constexpr double kKt = 8e5, kCt = 1e3;                       // tire [N/m, N s/m]
constexpr double kR0 = 0.5, kV = 10.0, kA = 0.005;           // radius [m], speed [m/s], road amplitude [m]

// steady complex amplitudes of the sprung mass and of the tire force for
// z_r = A e^{i omega t}
struct QuarterCarAmplitudes {
  Cplx zs, ft;
};

QuarterCarAmplitudes ClosedForm(double omega) {
  const double mu = kAxle + kWheel;
  const Cplx i(0, 1);
  const Cplx s = kKs + i * omega * kCs, t = kKt + i * omega * kCt;
  // [s - w^2 ms, -s; -s, s + t - w^2 mu] [zs; zu] = [0; t A]
  const Cplx a11 = s - omega * omega * kMs, a12 = -s, a22 = s + t - omega * omega * mu;
  const Cplx det = a11 * a22 - a12 * a12;
  const Cplx zs = -a12 * t * kA / det, zu = a11 * t * kA / det;
  return {zs, t * (kA - zu)};
}

// least-squares fit y = c0 + a sin(w t) + b cos(w t); returns the complex
// amplitude of e^{i w t} with y = Im(Z e^{i w t}): Z = a + i b
Cplx FitHarmonic(const std::vector<double>& t, const std::vector<double>& y, double w) {
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < t.size(); ++k) {
    const Eigen::Vector3d phi(1.0, std::sin(w * t[k]), std::cos(w * t[k]));
    N += phi * phi.transpose();
    r += phi * y[k];
  }
  const Eigen::Vector3d c = N.ldlt().solve(r);
  return {c[1], c[2]};
}

struct QuarterCarRun {
  Cplx zs, ft;
};

// simulates the quarter car on h = A sin(2 pi x / lambda) and fits the
// response over [t_fit, t_end]
QuarterCarRun Simulate(double lambda) {
  Model m;
  const double g = -m.gravity_W.z();
  m.solver.dt = 5e-4;
  m.solver.rho_inf = 0.9;
  TireData td;
  td.unloaded_radius = kR0;
  td.vertical_stiffness = kKt;
  td.vertical_damping = kCt;
  td.rolling_resistance = 0.0;
  td.nominal_load = 1e4;
  const double zc = kR0 - (kMs + kAxle + kWheel) * g / kKt;
  const Vec3 c(0, 0, zc), top(0, 0, zc + 0.5), v(kV, 0, 0);
  Mat3 axis_x, spin;
  axis_x << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  spin << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  const double re = kR0 - td.rolling_radius_factor * (kR0 - zc);
  auto body = [&](const char* name, double mass, const Vec3& cg, const Vec3& w) {
    RigidBodyData b;
    b.mass = mass;
    b.inertia_C = Mat3::Identity() * (0.1 * mass);
    b.c_B = cg;
    b.v_WB = v - w.cross(cg);
    b.w_WB = w;
    return m.AddBody(std::make_unique<RigidBody>(name, b));
  };
  const int cart = body("cart", 100.0, c, Vec3::Zero());
  const int sprung = body("sprung", kMs, top, Vec3::Zero());
  const int axle = body("axle", kAxle, c, Vec3::Zero());
  const int wheel = body("wheel", kWheel, c, Vec3(0, kV / re, 0));
  const int slide = m.AddJoint(std::make_unique<PrismaticJoint>("slide"), m.AddMarker(0, "rail", c, axis_x),
                               m.AddMarker(cart, "rail", c, axis_x));
  auto ramp = std::make_shared<TableFunction>(std::vector<double>{0.0, 1.0}, std::vector<double>{0.0, kV},
                                              TableFunction::Interpolation::kLinear, true);
  m.AddJoint(std::make_unique<MotionDriver>("drive", m.joints[slide].get(), 0, ramp), m.joints[slide]->marker_i,
             m.joints[slide]->marker_j);
  m.AddJoint(std::make_unique<PrismaticJoint>("body_slide"), m.AddMarker(cart, "body", top, Mat3::Identity()),
             m.AddMarker(sprung, "slide", top, Mat3::Identity()));
  m.AddJoint(std::make_unique<PrismaticJoint>("axle_slide"), m.AddMarker(cart, "axle", c, Mat3::Identity()),
             m.AddMarker(axle, "slide", c, Mat3::Identity()));
  m.AddJoint(std::make_unique<RevoluteJoint>("bearing"), m.AddMarker(axle, "bearing", c, spin),
             m.AddMarker(wheel, "bearing", c, spin));
  SpringDamperLaw law;
  law.free_length = 0.5;
  law.stiffness = kKs;
  law.damping = kCs;
  law.preload = -kMs * g;
  m.AddForce(std::make_unique<SpringDamper>("suspension", law), m.AddMarker(axle, "spring", c, Mat3::Identity()),
             m.AddMarker(sprung, "spring", top, Mat3::Identity()));
  const int wm = m.AddMarker(wheel, "centre", c, spin);
  auto tire = std::make_unique<Tire>("tire", td, 0.8);
  auto road = std::make_shared<RoadProfile>();
  for (int k = 0; k <= 12000; ++k) {
    const double x = -1.0 + 0.005 * k;
    road->x.push_back(x);
    road->z_left.push_back(x > 0 ? kA * std::sin(2 * std::numbers::pi * x / lambda) : 0.0);
  }
  road->z_right = road->z_left;
  tire->SetRoad(std::make_shared<RoadSurface>(road, 0));
  const Tire* tp = tire.get();
  m.AddForce(std::move(tire), wm, -1);
  const int sm = m.AddMarker(sprung, "probe", top, Mat3::Identity());
  m.Finalize();

  const double t_fit = 2.8, t_end = 4.0;
  std::vector<double> ts, zs, ft;
  Simulator sim(m);
  sim.Initialize();
  sim.Run(t_end, 1e-3, [&](const State& st, const Workspace& ws) {
    if (st.t < t_fit - 1e-9) return;
    const MarkerState& w = ws.markers[wm];
    TireContact tc;
    tp->Wrench(w.p_WM, w.R_WM, w.v_WM, w.w_WM, &tc);
    ts.push_back(st.t);
    zs.push_back(ws.markers[sm].p_WM.z());
    ft.push_back(tc.fz);
  });
  const double omega = 2 * std::numbers::pi * kV / lambda;
  return {FitHarmonic(ts, zs, omega), FitHarmonic(ts, ft, omega)};
}

void ExpectSteadyState(double lambda) {
  const double omega = 2 * std::numbers::pi * kV / lambda;
  const QuarterCarAmplitudes ref = ClosedForm(omega);
  const QuarterCarRun run = Simulate(lambda);
  std::printf("lambda %.1f m (%.2f Hz): sprung |Z| %.4f mm against %.4f mm (phase %+.4f rad), tire |F| %.1f N against %.1f N "
              "(phase %+.4f rad)\n",
              lambda, omega / (2 * std::numbers::pi), std::abs(run.zs) * 1e3, std::abs(ref.zs) * 1e3,
              std::arg(run.zs / ref.zs), std::abs(run.ft), std::abs(ref.ft), std::arg(run.ft / ref.ft));
  EXPECT_NEAR(std::abs(run.zs) / std::abs(ref.zs), 1.0, 0.01) << "sprung " << run.zs << " closed form " << ref.zs;
  EXPECT_NEAR(std::arg(run.zs / ref.zs), 0.0, 0.01);
  EXPECT_NEAR(std::abs(run.ft) / std::abs(ref.ft), 1.0, 0.01) << "tire " << run.ft << " closed form " << ref.ft;
  EXPECT_NEAR(std::arg(run.ft / ref.ft), 0.0, 0.01);
}

TEST(RoadQuarterCar, SineRoadNearBodyResonanceMatchesClosedForm) { ExpectSteadyState(4.0); }

TEST(RoadQuarterCar, SineRoadNearWheelHopMatchesClosedForm) { ExpectSteadyState(0.8); }

}  // namespace road_quarter_car_test
