#pragma once
// A planar pendulum for the sensor tests: a rigid bob (mass kMass, inertia
// kIzz about its centre of mass) whose centre of mass swings at distance kL
// about a revolute joint at the world origin with axis z, gravity -y, released
// horizontal at rest. The ground marker "pin" is turned by kBeta about z.

#include <memory>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/model/model.h"

namespace flexmb::test {

inline constexpr double kMass = 2.0, kL = 1.0, kIzz = 0.05, kG = 9.81, kBeta = 0.3;

/// Markers of the pendulum (indices into Model::markers).
struct PendulumMarkers {
  int ground_pin, bob_pin, bob_com, bob_tip;
};

/// Builds the pendulum; the bob's body frame is at its centre of mass, and
/// "tip" lies on the rod line 0.5 m beyond the centre of mass.
inline std::unique_ptr<Model> Pendulum(PendulumMarkers& mk) {
  auto m = std::make_unique<Model>();
  m->gravity_W = Vec3(0, -kG, 0);
  RigidBodyData d;
  d.mass = kMass;
  d.inertia_C = Vec3(0.5 * kIzz, 0.5 * kIzz, kIzz).asDiagonal();
  d.p_WB = Vec3(kL, 0, 0);
  const int b = m->AddBody(std::make_unique<RigidBody>("bob", d));
  mk.ground_pin = m->AddMarker(0, "pin", Vec3::Zero(), ExpSO3(Vec3(0, 0, kBeta)));
  mk.bob_pin = m->AddMarker(b, "pin", Vec3(-kL, 0, 0), Mat3::Identity());
  mk.bob_com = m->AddMarker(b, "com", Vec3::Zero(), Mat3::Identity());
  mk.bob_tip = m->AddMarker(b, "tip", Vec3(0.5, 0, 0), Mat3::Identity());
  m->AddJoint(std::make_unique<RevoluteJoint>("pin"), mk.ground_pin, mk.bob_pin);
  m->solver.dt = 1e-3;
  m->solver.rho_inf = 0.8;
  return m;
}

}  // namespace flexmb::test
