// Validation of the planar ANCF beam body inside the engine: a cantilever
// clamped to the ground by a fixed joint and loaded at its tip by a
// point_force, both from the model file, solved by the engine's
// SolveStatics (solver/statics.h) with the load factor as time, against
// Mattiasson's elastica (docs/validation.md, "ANCF beams") and against the
// direct solver SolveAncfStatics on the same beam. The same for the 3D
// cable body (its clamp by a fixed joint has one redundant equation: the
// spin about the tangent, which the cable does not have). A slender beam
// (EA/EI = 3e6 1/m^2) at PL^2/EI = 10 in one SolveStatics call: the
// solver's automatic load stepping; one that needs cuts; the error message.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "flexmb/ancf/ancf_statics.h"
#include "flexmb/common/error.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/statics.h"

namespace flexmb::ancf {
namespace ancf_engine_statics_test {

// model-file text of a 1 m cantilever of 8 elements of `type` (EI = 1 N m^2,
// EA/EI = 1200) named `name`, clamped to the ground by a fixed joint at its
// start, loaded at its tip by a point_force `force` (YAML); the model after
// MakeConsistent (`redundant` equations removed, checked) and SolveStatics in
// 10 load steps t = 0.1 .. 1
std::unique_ptr<Model> SolvedCantilever(const std::string& type, const std::string& name, const std::string& force,
                                        size_t redundant, State& s) {
  const std::string text =
      "name: cantilever\n"
      "gravity: [0, 0, 0]\n"
      "ground:\n"
      "  markers:\n"
      "    - {name: clamp, position: [0, 0, 0]}\n"
      "bodies:\n"
      "  - name: " + name + "\n"
      "    type: " + type + "\n"
      "    length: 1.0\n"
      "    elements: 8\n"
      "    section: {area: 1.0e-2, inertia: 8.333333333333333e-6}\n"
      "    material: {E: 1.2e5, rho: 1000}\n"
      "    markers:\n"
      "      - {name: root, end: start}\n"
      "      - {name: tip, end: end}\n"
      "joints:\n"
      "  - {name: clamp, type: fixed, i: ground.clamp, j: " + name + ".root}\n"
      "forces:\n"
      "  - {name: load, type: point_force, marker: " + name + ".tip, force: " + force + "}\n";
  auto model = LoadModelString(text, name + ".yaml");
  s = model->InitialState();
  Workspace ws;
  const ConstraintReport rep = MakeConsistent(*model, s, ws);
  EXPECT_EQ(rep.redundant.size(), redundant);
  for (int k = 1; k <= 10; ++k) {
    s.t = 0.1 * k;
    SolveStatics(*model, s, ws);
  }
  return model;
}

TEST(AncfEngineStatics, ClampedCantileverThroughJointsAndForces) {
  // L = 1 m, EI = 1 N m^2 (E = 1.2e5 Pa, h = 0.1 m square), tip load
  // P = 2 EI / L^2 = 2 N along -y reached at t = 1, in 10 steps of t (the
  // slender beam with automatic load stepping: SlenderElasticaByLoadStepping).
  // The fixed joint on a planar body has 3 redundant equations of its 6
  State s;
  const auto model = SolvedCantilever("ancf_beam", "beam", "[0, {expression: \"-2*t\"}, 0]", 3, s);
  const int b = model->FindBody("beam");
  const auto& beam = dynamic_cast<const AncfBeam2dBody&>(*model->bodies[b]);
  const double* q = s.q.data() + beam.q_offset;
  const Vec3 tip = beam.PositionAt(q, 1.0);
  // Mattiasson (1981) PL^2/EI = 2: w/L = 0.49346, u/L = 0.16064 for an
  // inextensible beam; the axial strain here (up to P/EA = 1.7e-3) moves
  // them by about 1e-3 (measured 0.49420, 0.16018)
  EXPECT_NEAR(-tip.y(), 0.49346, 2e-3);
  EXPECT_NEAR(1.0 - tip.x(), 0.16064, 2e-3);
  // the same beam by the direct solver: the same equilibrium. The clamp by
  // a fixed joint holds the position and the angle of the slope at node 0,
  // not its length (the axial strain there): hold x, y and y'
  VecX qd(beam.nq()), vd(beam.nv());
  beam.InitialCoordinates(qd.data(), vd.data());
  VecX load = VecX::Zero(beam.nv());
  load(4 * 8 + 1) = -2.0;
  SolveAncfStatics(beam, {0, 1, 3}, load, Vec3::Zero(), qd);
  for (int j = 0; j < beam.nq(); ++j) EXPECT_NEAR(q[j], qd(j), 1e-8) << j;
}

TEST(AncfEngineStatics, ClampedCable3dThroughJointsAndForces) {
  // the cantilever above as a 3D cable along x, tip load 2 N along
  // (0, 0.6, -0.8) reached at t = 1
  State s;
  const auto model =
      SolvedCantilever("ancf_cable", "cable", "[0, {expression: \"1.2*t\"}, {expression: \"-1.6*t\"}]", 1, s);
  const auto& cable = dynamic_cast<const AncfCable3dBody&>(*model->bodies[model->FindBody("cable")]);
  const double* q = s.q.data() + cable.q_offset;
  const Vec3 tip = cable.PositionAt(q, 1.0);
  const Vec3 n(0.0, 0.6, -0.8);
  std::printf("3D cable clamped by a fixed joint: w/L %.5f, u/L %.5f\n", tip.dot(n), 1.0 - tip.x());
  // as the planar beam: w/L = 0.49420, u/L = 0.16018 (Mattiasson, inextensible: 0.49346, 0.16064)
  EXPECT_NEAR(tip.dot(n), 0.49346, 2e-3);
  EXPECT_NEAR(1.0 - tip.x(), 0.16064, 2e-3);
  EXPECT_NEAR(tip.dot(Vec3::UnitX().cross(n)), 0.0, 1e-10);
  // the direct solver, holding r_0 and the direction of r'_0 (y', z')
  VecX qd(cable.nq()), vd(cable.nv());
  cable.InitialCoordinates(qd.data(), vd.data());
  VecX load = VecX::Zero(cable.nv());
  load.segment<3>(6 * 8) = 2.0 * n;
  SolveAncfStatics(cable, {0, 1, 2, 4, 5}, load, Vec3::Zero(), qd);
  for (int j = 0; j < cable.nq(); ++j) EXPECT_NEAR(q[j], qd(j), 1e-8) << j;
}

// model-file text of Mattiasson's cantilever for the engine: L = 2 m,
// square section h = L / 1000 (EA/EI = 12 / h^2 = 3e6 1/m^2: axial strain
// P / EA < 1e-5), EI = 1 N m^2, `elements` elements, fixed joint to the
// ground at node 0, constant tip load P [N] along -y (PL^2/EI = 4 P)
std::string SlenderElasticaModel(int elements, double P) {
  return "name: elastica\n"
         "gravity: [0, 0, 0]\n"
         "ground:\n"
         "  markers:\n"
         "    - {name: clamp, position: [0, 0, 0]}\n"
         "bodies:\n"
         "  - name: beam\n"
         "    type: ancf_beam\n"
         "    length: 2.0\n"
         "    elements: " + std::to_string(elements) + "\n"
         "    section: {area: 4.0e-6, inertia: 1.3333333333333333e-12}\n"
         "    material: {E: 7.5e11, rho: 7850}\n"
         "    markers:\n"
         "      - {name: root, end: start}\n"
         "      - {name: tip, end: end}\n"
         "joints:\n"
         "  - {name: clamp, type: fixed, i: ground.clamp, j: beam.root}\n"
         "forces:\n"
         "  - {name: load, type: point_force, marker: beam.tip, force: [0, " + std::to_string(-P) + ", 0]}\n";
}

// checks that the engine's equilibrium q of `beam` (tip load -P along y on
// the last node) equals the direct ANCF solver's, node 0 held in x, y, y',
// with `load_steps` equal load steps
void ExpectEqualsDirectAncfStatics(const AncfBeam2dBody& beam, const double* q, double P, int load_steps) {
  VecX qd(beam.nq()), vd(beam.nv());
  beam.InitialCoordinates(qd.data(), vd.data());
  VecX load = VecX::Zero(beam.nv());
  load(4 * beam.elements() + 1) = -P;
  AncfStaticsSettings set;
  set.load_steps = load_steps;
  SolveAncfStatics(beam, {0, 1, 3}, load, Vec3::Zero(), qd, set);
  for (int j = 0; j < beam.nq(); ++j) EXPECT_NEAR(q[j], qd(j), 1e-7) << j;
}

TEST(AncfEngineStatics, SlenderElasticaByLoadStepping) {
  // the full load from the straight beam in one SolveStatics call: the
  // solver steps the load itself. Mattiasson (1981), PL^2/EI = 10:
  // w/L = 0.81061, u/L = 0.55500 (docs/validation.md, "ANCF beams")
  auto model = LoadModelString(SlenderElasticaModel(16, 2.5), "elastica.yaml");
  State s = model->InitialState();
  Workspace ws;
  MakeConsistent(*model, s, ws);
  const StaticsResult r = SolveStatics(*model, s, ws);
  const auto& beam = dynamic_cast<const AncfBeam2dBody&>(*model->bodies[model->FindBody("beam")]);
  const double* q = s.q.data() + beam.q_offset;
  const Vec3 tip = beam.PositionAt(q, 2.0);
  const double w = -tip.y() / 2.0, u = 1.0 - tip.x() / 2.0;
  std::printf("engine statics, slender elastica PL^2/EI = 10: w/L %.6f (err %.2e), u/L %.6f (err %.2e); "
              "%d increments, %d cuts, %d Newton iterations\n",
              w, w - 0.81061, u, u - 0.55500, r.increments, r.cuts, r.iterations);
  EXPECT_NEAR(w, 0.81061, 1e-4);
  EXPECT_NEAR(u, 0.55500, 1e-4);
  // the same equilibrium as the direct solver holding x, y, y' of node 0
  ExpectEqualsDirectAncfStatics(beam, q, 2.5, 20);
}

TEST(AncfEngineStatics, LargeLoadIsSteppedWithCuts) {
  // PL^2/EI = 50 on 8 elements: Newton from the straight beam at the full
  // load fails, the solver halves the increment and gets there; the
  // equilibrium equals the direct solver's with 50 equal load steps
  auto model = LoadModelString(SlenderElasticaModel(8, 12.5), "elastica.yaml");
  State s = model->InitialState();
  Workspace ws;
  MakeConsistent(*model, s, ws);
  const StaticsResult r = SolveStatics(*model, s, ws);
  std::printf("engine statics, PL^2/EI = 50, 8 elements: %d increments, %d cuts, %d Newton iterations\n",
              r.increments, r.cuts, r.iterations);
  EXPECT_GT(r.cuts, 0);
  EXPECT_GT(r.increments, 1);
  const auto& beam = dynamic_cast<const AncfBeam2dBody&>(*model->bodies[model->FindBody("beam")]);
  ExpectEqualsDirectAncfStatics(beam, s.q.data() + beam.q_offset, 12.5, 50);
}

TEST(AncfEngineStatics, FailureNamesTheLoadFactorAndTheEntity) {
  // without load stepping (smallest increment = the full load) the solve
  // of the case above must fail, with a message naming where
  auto model = LoadModelString(SlenderElasticaModel(8, 12.5), "elastica.yaml");
  State s = model->InitialState();
  Workspace ws;
  MakeConsistent(*model, s, ws);
  StaticsSettings set;
  set.min_increment = 1.0;
  try {
    SolveStatics(*model, s, ws, set);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("load factor 0 of 1"), std::string::npos) << msg;
    EXPECT_TRUE(msg.find("body 'beam'") != std::string::npos || msg.find("joint 'clamp'") != std::string::npos)
        << msg;
  }
  // s holds the last converged state: the straight start
  const auto& beam = *model->bodies[model->FindBody("beam")];
  EXPECT_NEAR(s.q(beam.q_offset + 4 * 8), 2.0, 1e-12);
}

// A stiff steel cantilever (an 18 m boom's box: EA = 3.4e9 N, EI = 3.4e8
// N m^2, 9 ANCF 3D beam elements) under small weights, 1e-3 g down to 1e-5 g:
// the Newton residual cannot fall below the round-off of its internal
// forces (about 2e-6 N, eps |K| |q|; the weights are 4e-3 to 0.4 N per
// node), which the convergence test must allow for (statics.cc). Reference:
// Euler-Bernoulli q L^4 / (8 E I) at the tip (the Hermite elements are exact
// at the nodes under a uniform load; at these loads the geometric
// nonlinearity is below 1e-9), relative 1e-6.
TEST(AncfEngineStatics, StiffBeamUnderASmallLoadConverges) {
  const double L = 18.0, E = 2.1e11, A = 0.016, I = 0.0016, rho = 7850.0;
  for (const double g : {9.81e-3, 9.81e-5}) {
    char gz[32];
    std::snprintf(gz, sizeof gz, "%.17g", -g);
    const std::string text =
        "name: stiff_boom\n"
        "gravity: [0, 0, " + std::string(gz) + "]\n"
        "ground:\n"
        "  markers:\n"
        "    - {name: clamp, position: [1, 0, 3]}\n"
        "bodies:\n"
        "  - {name: boom, type: ancf_beam3d, length: 18, elements: 9, start: [1, 0, 3],\n"
        "     section: {area: 0.016, Iy: 0.0016, Iz: 0.0016, J: 0.002},\n"
        "     material: {E: 2.1e11, nu: 0.3, rho: 7850}, markers: [{name: root, end: start}, {name: tip, end: end}]}\n"
        "joints:\n"
        "  - {name: clamp, type: fixed, i: ground.clamp, j: boom.root}\n";
    auto model = LoadModelString(text, "stiff_boom.yaml");
    State s = model->InitialState();
    Workspace ws;
    MakeConsistent(*model, s, ws);
    const StaticsResult r = SolveStatics(*model, s, ws);
    const Body& boom = *model->bodies[model->FindBody("boom")];
    const double tip_z = s.q(boom.q_offset + 7 * 9 + 2) - 3.0;
    const double w = -rho * A * g * L * L * L * L / (8.0 * E * I);
    EXPECT_NEAR(tip_z, w, 1e-6 * std::abs(w)) << "g " << g << ", residual " << r.residual;
  }
}

}  // namespace ancf_engine_statics_test
}  // namespace flexmb::ancf
