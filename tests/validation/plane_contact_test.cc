// Unilateral contact of points with the ground (forces/plane_contact.h)
// against closed forms of rigid-body mechanics (docs/validation.md,
// "Contact with the ground"):
// - a mass dropped on an undamped contact spring k under gravity g: while
//   in contact, x - x_e = A cos(w t + psi) with w = sqrt(k/m) and the static
//   penetration delta = m g / k, so the contact lasts (2 pi - 2 psi0) / w
//   with psi0 = atan2(v0 / w, delta) (pi / w for delta -> 0) and the mass
//   leaves at the impact speed v0 (no dissipation);
// - a box standing on four corner contacts: each corner sinks m g / (4 k);
// - a box sliding on four corner contacts with Coulomb friction mu stops
//   after v0^2 / (2 mu g) (the normal forces sum to m g; the friction,
//   regularized below v_s << v0, decelerates at mu g).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/forces/plane_contact.h"
#include "flexmb/sensors/force_sensors.h"
#include "flexmb/solver/simulator.h"

namespace plane_contact_test {

using flexmb::Mat3;
using flexmb::Model;
using flexmb::PlaneContact;
using flexmb::PlaneContactLaw;
using flexmb::RigidBody;
using flexmb::RigidBodyData;
using flexmb::Simulator;
using flexmb::State;
using flexmb::Vec3;
using flexmb::Workspace;
using flexmb::ForceElementSensor;

// a box of mass m with contacts of stiffness k, damping c and friction mu
// at its four lower corners (half sizes a, a, b), its centre at height z0
// with velocity v
struct ContactBox {
  Model model;
  int body = -1, probe = -1;
};

void BuildBox(ContactBox& box, double m, double k, double c, double mu, double z0, const Vec3& v) {
  const double a = 0.5, b = 0.25;
  RigidBodyData d;
  d.mass = m;
  d.inertia_C = Mat3(Vec3(m * (a * a + b * b) / 3, m * (a * a + b * b) / 3, m * 2 * a * a / 3).asDiagonal());
  d.p_WB = Vec3(0, 0, z0);
  d.v_WB = v;
  box.body = box.model.AddBody(std::make_unique<RigidBody>("box", d));
  box.probe = box.model.AddMarker(box.body, "centre", Vec3::Zero(), Mat3::Identity());
  PlaneContactLaw law;
  law.stiffness = k;
  law.damping = c;
  law.friction = mu;
  law.slip_velocity = 1e-3;
  int n = 0;
  for (const double x : {-a, a})
    for (const double y : {-a, a}) {
      const std::string name = "corner" + std::to_string(n++);
      box.model.AddForce(std::make_unique<PlaneContact>(name, law),
                         box.model.AddMarker(box.body, name, Vec3(x, y, -b), Mat3::Identity()), -1);
    }
  box.model.Finalize();
}

TEST(PlaneContact, UndampedDropLastsTheHalfPeriodAndReboundsElastically) {
  const double m = 10.0, k = 1e6, v0 = 1.0;
  Model model;
  model.solver.dt = 2e-5;
  model.solver.rho_inf = 1.0;  // no numerical dissipation
  const double g = -model.gravity_W.z();
  RigidBodyData d;
  d.mass = m;
  d.inertia_C = Mat3::Identity() * 0.1;
  d.p_WB = Vec3(0, 0, 1e-3);
  d.v_WB = Vec3(0, 0, -std::sqrt(v0 * v0 - 2 * g * 1e-3));  // reaches the ground at v0
  const int ball = model.AddBody(std::make_unique<RigidBody>("ball", d));
  PlaneContactLaw law;
  law.stiffness = k;
  const int foot = model.AddMarker(ball, "foot", Vec3::Zero(), Mat3::Identity());
  model.AddForce(std::make_unique<PlaneContact>("ground", law), foot, -1);
  model.Finalize();

  // contact start and end from the sign changes of the height, linearly interpolated
  double t_prev = 0.0, z_prev = 1e-3, t_in = NAN, t_out = NAN, v_out = NAN;
  Simulator sim(model);
  sim.Initialize();
  sim.Run(0.03, 0.0, [&](const State& st, const Workspace& ws) {
    const double z = ws.markers[foot].p_WM.z();
    if (z_prev > 0 && z <= 0 && std::isnan(t_in)) t_in = t_prev + (st.t - t_prev) * z_prev / (z_prev - z);
    if (z_prev <= 0 && z > 0 && std::isnan(t_out)) {
      t_out = t_prev + (st.t - t_prev) * z_prev / (z_prev - z);
      v_out = ws.markers[foot].v_WM.z();
    }
    t_prev = st.t, z_prev = z;
  });
  const double w = std::sqrt(k / m), delta = m * g / k;
  const double duration = (2 * std::numbers::pi - 2 * std::atan2(v0 / w, delta)) / w;
  std::printf("contact %.6f ms against %.6f ms, rebound %.5f m/s against %.5f m/s\n", (t_out - t_in) * 1e3,
              duration * 1e3, v_out, v0);
  EXPECT_NEAR((t_out - t_in) / duration, 1.0, 1e-4);  // measured 3.5e-6
  // the speed at the first step above the plane (gravity over a part step: 2e-4 m/s at most)
  EXPECT_NEAR(v_out, v0, 5e-4 * v0);  // measured 4e-5
}

TEST(PlaneContact, BoxRestsOnItsCornersAtTheStaticPenetration) {
  const double m = 400.0, k = 2e6;
  ContactBox box;
  box.model.solver.dt = 1e-3;
  BuildBox(box, m, k, 2 * std::sqrt(k * m / 4), 0.0, 0.25, Vec3::Zero());  // critically damped per corner
  const double g = -box.model.gravity_W.z();
  double z = NAN, fz = NAN;
  Simulator sim(box.model);
  sim.Initialize();
  sim.Run(1.0, 0.0, [&](const State& st, const Workspace& ws) {
    z = ws.markers[box.probe].p_WM.z();
    // the corners' loads as the force_element sensor reports them
    fz = 0.0;
    for (int c = 0; c < 4; ++c) {
      double out[7];
      ForceElementSensor("load", c).Evaluate(box.model, st, ws, out);
      fz += out[2];
      EXPECT_EQ(out[6], std::abs(out[2]));
    }
  });
  const double sink = 0.25 - z, expected = m * g / (4 * k);
  std::printf("box sinks %.6e m against m g / (4 k) = %.6e m; corner loads sum to %.6f N (m g = %.6f N)\n", sink,
              expected, fz, m * g);
  EXPECT_NEAR(sink / expected, 1.0, 1e-6);
  EXPECT_NEAR(fz / (m * g), 1.0, 1e-6);
}

TEST(PlaneContact, SlidingBoxStopsAfterTheCoulombDistance) {
  const double m = 400.0, k = 2e6, mu = 0.3, v0 = 2.0;
  ContactBox box;
  box.model.solver.dt = 1e-3;
  const double g = -box.model.gravity_W.z();
  const double z0 = 0.25 - m * g / (4 * k);  // start in static equilibrium
  BuildBox(box, m, k, 2 * std::sqrt(k * m / 4), mu, z0, Vec3(v0, 0, 0));
  double x_stop = NAN;
  const double v_end = 0.01;
  Simulator sim(box.model);
  sim.Initialize();
  sim.Run(1.0, 0.0, [&](const State&, const Workspace& ws) {
    const auto& c = ws.markers[box.probe];
    if (std::isnan(x_stop) && c.v_WM.x() < v_end) x_stop = c.p_WM.x();
  });
  const double expected = (v0 * v0 - v_end * v_end) / (2 * mu * g);
  std::printf("box slides %.5f m against (v0^2 - v_end^2) / (2 mu g) = %.5f m\n", x_stop, expected);
  EXPECT_NEAR(x_stop / expected, 1.0, 1e-3);  // measured 1.5e-5
}

}  // namespace plane_contact_test
