// The hoisting rope of changing length (flexmb/ancf/ancf_hoist_rope_body.h)
// in the engine, read from model files, against closed forms and balances:
// - the static stretch of a rope hanging under its own weight and a hook
//   load at a free length held by the winch: L + F L / EA + rho A g L^2 / (2 EA)
//   (engineering strain: the force is linear in the stretch);
// - a free-running winch (no drive, no brake): the hook and the span's
//   weight pull the rope off the drum; the rigid-rope limit of the same
//   closed system is M L'' = (m_hook + rho A L) g with
//   M = m_hook + rho A L_total + J / R^2, solved in closed form
//   L(t) = -m_h / rho A + (L0 + m_h / rho A) cosh(omega t),
//   omega^2 = rho A g / M; and the total energy is conserved;
// - a winch driven by a varying torque for 20 s: the work of the drive
//   equals the change of kinetic, potential and strain energy;
// - lowering at a prescribed speed: the hook follows the winch;
// - bad input in the model file names the file, line and entity.
// Derivations and measured values: docs/validation.md, "Hoisting rope of
// changing length".

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "example_model.h"
#include "flexmb/ancf/ancf_hoist_rope_body.h"
#include "flexmb/common/error.h"
#include "flexmb/sensors/joint_sensors.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/solver/statics.h"

namespace flexmb::validation {
namespace hoist_rope_test {

// steel wire rope: A = 2e-4 m^2, E = 1e11 Pa (EA = 2e7 N), rho A = 1.56 kg/m
constexpr double kA = 2e-4, kE = 1e11, kRho = 7800.0, kG = 9.81;
constexpr double kRhoA = kRho * kA, kEA = kE * kA;

// a rope hanging from the ground marker `sheave` at the origin, the drum
// at the sheave's height; `hook` is either a rigid body on a spherical
// joint or a point force at the rope's end; `extra` adds entries
std::string RopeModel(double L0, double stored, double drum_inertia, double damping, const std::string& hook,
                      const std::string& extra, int elements = 8) {
  return "gravity: [0, 0, -9.81]\n"
         "ground:\n"
         "  markers:\n"
         "    - {name: sheave, position: [0, 0, 0]}\n"
         "bodies:\n"
         "  - name: rope\n"
         "    type: ancf_hoist_rope\n"
         "    free_length: " + ExactNumber(L0) + "\n"
         "    stored_length: " + ExactNumber(stored) + "\n"
         "    elements: " + std::to_string(elements) + "\n"
         "    section: {area: 2e-4, inertia: 3e-9}\n"
         "    material: {E: 1e11, rho: 7800}\n"
         "    damping: " + ExactNumber(damping) + "\n"
         "    start: [0, 0, 0]\n"
         "    direction: [0, 0, -1]\n"
         "    drum: {position: [-3, 0, 0], radius: 0.2, inertia: " + ExactNumber(drum_inertia) + "}\n"
         "    markers:\n"
         "      - {name: top, end: start}\n"
         "      - {name: hook, end: end}\n" +
         hook +
         "joints:\n"
         "  - {name: sheave, type: spherical, i: ground.sheave, j: rope.top}\n" + extra;
}

// a hook block of mass m [kg] hanging on the rope's end at depth L0
std::string HookBody(double m, double L0) {
  return "  - name: hook\n"
         "    mass: " + ExactNumber(m) + "\n"
         "    inertia: [2, 2, 2]\n"
         "    position: [0, 0, " + ExactNumber(-L0) + "]\n"
         "    markers:\n"
         "      - {name: eye, position: [0, 0, 0]}\n";
}

const std::string kHookJoint = "  - {name: eye, type: spherical, i: rope.hook, j: hook.eye}\n";

const ancf::AncfHoistRopeBody& Rope(const Model& model) {
  return dynamic_cast<const ancf::AncfHoistRopeBody&>(*model.bodies[model.FindBody("rope")]);
}

double TotalEnergy(const Model& model, const State& s) {
  double E = 0.0;
  for (const auto& b : model.bodies) {
    const double* q = s.q.data() + b->q_offset;
    const double* v = s.v.data() + b->v_offset;
    E += b->KineticEnergy(q, v) + b->GravityPotential(q, model.gravity_W) + b->ElasticEnergy(q);
  }
  return E;
}

TEST(HoistRope, StaticStretchUnderHookLoadAndOwnWeight) {
  const double L0 = 30.0, F = 5000.0;
  auto model = LoadModelString(
      RopeModel(L0, 20.0, 1.0, 0.0, "",
                "drivers:\n  - {name: winch, type: winch, rope: rope}\n"
                "forces:\n  - {name: load, type: point_force, marker: rope.hook, force: [0, 0, -5000]}\n"),
      "stretch.yaml");
  State s = model->InitialState();
  Workspace ws;
  MakeConsistent(*model, s, ws);
  SolveStatics(*model, s, ws);
  const auto& rope = Rope(*model);
  const double* q = s.q.data() + rope.q_offset;
  const double stretch = F * L0 / kEA + kRhoA * kG * L0 * L0 / (2.0 * kEA);
  const double z_hook = q[6 * rope.elements() + 2];
  std::printf("static stretch %.9f m, closed form %.9f m\n", -z_hook - L0, stretch);
  EXPECT_NEAR(rope.FreeLength(q), L0, 1e-12);
  // the winch holds the rope's pull on the drum line: the hook load and the
  // span's weight (Q_L = lambda at equilibrium), to the stretch's order
  const double pull = s.lambda(model->joints[model->FindJoint("winch")]->lambda_offset);
  std::printf("winch pull %.3f N, load and span weight %.3f N\n", pull, F + kRhoA * kG * L0);
  EXPECT_NEAR(pull, F + kRhoA * kG * L0, 1e-3 * (F + kRhoA * kG * L0));
  // a joint_reaction sensor on the winch reports that pull (it read 0 when
  // the equation left out the driver's ground marker)
  double reaction[6];
  JointReactionSensor("pull", model->FindJoint("winch"), true).Evaluate(*model, s, ws, reaction);
  EXPECT_NEAR(reaction[0], pull, 1e-9 * pull);
  EXPECT_NEAR(-z_hook - L0, stretch, 1e-4 * stretch);
  // the rope stays straight below the sheave
  EXPECT_LT(std::hypot(q[6 * rope.elements()], q[6 * rope.elements() + 1]), 1e-9);
}

TEST(HoistRope, FreeRunningWinchFollowsTheClosedSystemAndConservesEnergy) {
  const double L0 = 10.0, stored = 40.0, J = 2.0, R = 0.2, m = 50.0;
  auto model = LoadModelString(RopeModel(L0, stored, J, 0.0, HookBody(m, L0), kHookJoint +
                                             "solver: {dt: 1e-3, rho_inf: 0.9}\n"),
                               "free_running.yaml");
  Simulator sim(*model);
  sim.Initialize();
  const auto& rope = Rope(*model);
  const double E0 = TotalEnergy(*model, sim.state());
  double drift = 0.0;
  sim.Run(2.0, 0.0, [&](const State& s, const Workspace&) {
    drift = std::max(drift, std::abs(TotalEnergy(*model, s) - E0));
  });
  const double M = m + kRhoA * (L0 + stored) + J / (R * R);
  const double omega = std::sqrt(kRhoA * kG / M), c = m / kRhoA;
  const double L_ref = -c + (L0 + c) * std::cosh(omega * 2.0);
  const double L = rope.FreeLength(sim.state().q.data() + rope.q_offset);
  const double E_scale = m * kG * (L_ref - L0);
  std::printf("free-running winch: L(2 s) %.6f m, rigid-rope closed form %.6f m; energy drift %.3e of %.1f J\n",
              L, L_ref, drift / E_scale, E_scale);
  EXPECT_NEAR(L - L0, L_ref - L0, 2e-3 * (L_ref - L0));
  EXPECT_LT(drift, 1e-4 * E_scale);
}

TEST(HoistRope, DrivenWinchWorkEqualsTheChangeOfEnergy) {
  // the winch hauls in and pays out, L(t) = 10 - 4 sin(0.6 t) (1 - e^-t)
  // (up to 2.4 m/s), 20 s; its work is that of the driver's reaction on the
  // rope line: the constraint force -lambda on L times L'
  const double L0 = 10.0, m = 50.0;
  auto model = LoadModelString(
      RopeModel(L0, 40.0, 2.0, 0.0, HookBody(m, L0),
                kHookJoint +
                    "drivers:\n  - {name: winch, type: winch, rope: rope, free_length: "
                    "{expression: \"10 - 4 * sin(0.6 * t) * (1 - exp(-t))\"}}\n"
                    "solver: {dt: 1e-3, rho_inf: 0.9}\n"),
      "driven.yaml");
  Simulator sim(*model);
  sim.Initialize();
  const auto& rope = Rope(*model);
  const int lam = model->joints[model->FindJoint("winch")]->lambda_offset;
  auto power = [&](const State& s) { return -s.lambda(lam) * s.v(rope.v_offset + rope.LengthIndex()); };
  const double E0 = TotalEnergy(*model, sim.state());
  double work = 0.0, t_last = 0.0, p_last = power(sim.state()), worst = 0.0, scale = 0.0, Lmin = L0, Lmax = L0;
  sim.Run(20.0, 0.0, [&](const State& s, const Workspace&) {
    const double p = power(s);
    work += 0.5 * (p + p_last) * (s.t - t_last);
    t_last = s.t, p_last = p;
    const double L = rope.FreeLength(s.q.data() + rope.q_offset);
    Lmin = std::min(Lmin, L), Lmax = std::max(Lmax, L);
    worst = std::max(worst, std::abs(TotalEnergy(*model, s) - E0 - work));
    scale = std::max(scale, std::abs(work));
  });
  std::printf("driven winch: L in [%.3f, %.3f] m over 20 s; |E - E0 - W| <= %.3e of max |W| = %.1f J\n", Lmin,
              Lmax, worst / scale, scale);
  EXPECT_LT(Lmin, 7.0);
  EXPECT_GT(Lmax, 13.0);
  EXPECT_LT(worst, 1e-3 * scale);
}

TEST(HoistRope, LoweringAtConstantSpeedHookFollowsTheWinch) {
  const double L0 = 10.0, m = 50.0, v = 0.5, T = 10.0;
  auto model = LoadModelString(
      RopeModel(L0, 40.0, 2.0, 2e-3, HookBody(m, L0),
                kHookJoint + "drivers:\n  - {name: winch, type: winch, rope: rope, hoist_speed: -0.5}\n"
                             "solver: {dt: 2e-3}\n"),
      "lowering.yaml");
  Simulator sim(*model);
  sim.Initialize();
  sim.Run(T, 0.0, nullptr);
  const auto& rope = Rope(*model);
  const double L = rope.FreeLength(sim.state().q.data() + rope.q_offset);
  const double z = sim.state().q(model->bodies[model->FindBody("hook")]->q_offset + 2);
  const double stretch = m * kG * L / kEA + kRhoA * kG * L * L / (2.0 * kEA);
  std::printf("lowering: L %.9f m (winch %.9f m); hook %.6f m below L, static stretch %.6f m\n", L, L0 + v * T,
              -z - L, stretch);
  EXPECT_NEAR(L, L0 + v * T, 1e-9);
  EXPECT_NEAR(-z - L, stretch, 0.05 * stretch);
}

TEST(HoistRope, BadInputNamesFileLineAndEntity) {
  const std::string good = RopeModel(10.0, 40.0, 2.0, 0.0, HookBody(50.0, 10.0),
                                     kHookJoint + "drivers:\n  - {name: winch, type: winch, rope: rope}\n");
  struct Case {
    const char* from;
    const char* to;
    const char* expect;
  };
  const Case cases[] = {
      {"radius: 0.2", "radius: 0", "bad.yaml:"},
      {"radius: 0.2", "radius: -1", "radius"},
      {"free_length: 10\n", "free_length: -3\n", "free_length"},
      {"stored_length: 40", "stored_length: -1", "stored_length"},
      {"rope: rope}", "rope: hook}", "is not an ancf_hoist_rope"},
      {"rope: rope}", "rope: rope, hoist_speed: 1, free_length: 3}", "not both"},
      {"rope: rope}", "rope: rope, free_length: {expression: \"10 - t\"}, hoist_speed: 2}", "not both"},
      {"{name: hook, end: end}", "{name: hook, end: end, position: [0.1, 0, 0]}", "position"},
      {"drum: {position: [-3, 0, 0], radius: 0.2, inertia: 2}", "drum: {radius: 0.2}", "position"},
  };
  for (const Case& c : cases) {
    std::string text = good;
    const size_t at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, std::string(c.from).size(), c.to);
    std::string what;
    try {
      auto model = LoadModelString(text, "bad.yaml");
      Simulator sim(*model);
      sim.Initialize();
    } catch (const Error& e) {
      what = e.what();
    }
    EXPECT_NE(what.find(c.expect), std::string::npos) << c.to << ": " << what;
    EXPECT_NE(what.find("bad.yaml"), std::string::npos) << c.to << ": " << what;
  }
}

}  // namespace hoist_rope_test
}  // namespace flexmb::validation
