#pragma once
/// \file flexible_body_fixture.h
/// Setup shared by the floating-frame flexible body validation tests
/// (tests/validation/flexible_body_*_test.cc): FE models built in code, their
/// Craig-Bampton reduction, the reference integrator settings.

#include <memory>
#include <string>
#include <vector>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/math/rotation.h"
#include "flexmb/model/model.h"
#include "flexmb/model/state.h"
#include "flexmb/reduction/craig_bampton.h"
#include "tests/unit/bodies/flexible_test_bodies.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::testing {

/// A straight beam of round section (radius [m]) along the basic x axis:
/// `elements` 2-node beams from x = 0 to `length` [m], element y axis along
/// basic y; node indices 0 .. elements (ids 1 .. elements + 1). Material E
/// [Pa], nu, rho [kg/m^3].
inline fe::FeModel RoundBeamAlongX(int elements, double length, double radius, double E, double rho,
                                   double nu = 0.3) {
  fe::FeModel model;
  fe::Mesh& mesh = model.mesh;
  mesh.source = "beam.bdf";
  const int mat = fe::testing::AddMaterial(mesh, E, nu, rho);
  const int sec = fe::testing::AddRoundBar(mesh, mat, radius);
  for (int k = 0; k <= elements; ++k) fe::testing::AddNode(mesh, fe::Vec3(length * k / elements, 0, 0));
  for (int k = 0; k < elements; ++k) fe::testing::AddBeam(mesh, sec, k, k + 1, fe::Vec3(0, 1, 0));
  return model;
}

/// Craig-Bampton reduction of `model` with the interface `nodes` (indices)
/// and `normal` fixed-interface modes (free body: rigid modes removed).
inline std::shared_ptr<reduction::ReducedBody> Reduced(const fe::FeModel& model, std::vector<int> nodes,
                                                       int normal) {
  reduction::ReductionOptions o;
  o.interface_nodes = std::move(nodes);
  o.normal_modes = normal;
  return std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(model, o));
}

/// Integrator of the reference runs: step h [s], no numerical dissipation
/// (rho_inf = 1: the trapezoidal rule for a linear system), tight Newton
/// tolerance.
inline void UseReferenceIntegrator(Model& m, double h) {
  m.solver.dt = h;
  m.solver.rho_inf = 1.0;
  m.solver.newton_tol = 1e-12;
}

/// Adds a free flexible body `name` of the reduced data to m, its body frame
/// at a fixed general pose (p_WB = (0.5, -1, 2) m, R_WB = Exp((0.3, 0.2,
/// -0.4)) rad) and modal state w0 [sqrt(kg) m], and finalizes m. Returns the
/// body's index. For the stress sensor tests: stresses do not depend on the
/// frame, so a general pose checks that nothing mixes it in.
inline int AddFinalizedPosedFlexibleBody(Model& m, const std::string& name,
                                         std::shared_ptr<reduction::ReducedBody> reduced, const VecX& w0) {
  FlexibleBodyData d;
  d.reduced = std::move(reduced);
  d.p_WB = Vec3(0.5, -1.0, 2.0);
  d.R_WB = ExpSO3(Vec3(0.3, 0.2, -0.4));
  d.w0 = w0;
  const int b = m.AddBody(std::make_unique<FlexibleBody>(name, d));
  m.Finalize();
  return b;
}

/// Data of a free body of `reduced` in a general rigid motion, undeformed
/// and undamped: frame at (0.1, 0.2, 0.3) m turned by Exp((0.3, -0.2, 0.5))
/// rad, moving at (0.5, -0.3, 0.2) m/s and spinning at (2, 6, -3) rad/s
/// (the conservation tests).
inline FlexibleBodyData TumblingBodyData(std::shared_ptr<const reduction::ReducedBody> reduced) {
  FlexibleBodyData d;
  const int n = reduced->invariants.n;
  d.reduced = std::move(reduced);
  d.p_WB = Vec3(0.1, 0.2, 0.3);
  d.R_WB = ExpSO3(Vec3(0.3, -0.2, 0.5));
  d.v_WB = Vec3(0.5, -0.3, 0.2);
  d.w_WB = Vec3(2.0, 6.0, -3.0);
  d.damping = MatX::Zero(n, n);
  return d;
}

/// Kinetic plus strain energy of the flexible body in state s [J].
inline double TotalEnergy(const FlexibleBody& body, const State& s) {
  const double* q = s.q.data() + body.q_offset;
  return body.KineticEnergy(q, s.v.data() + body.v_offset) + body.StrainEnergy(q);
}

/// Linear [kg m/s] and angular momentum about the world origin [kg m^2/s]
/// of the flexible body in state s.
inline Vec6 BodyMomentum(const FlexibleBody& body, const State& s) {
  return body.Momentum(s.q.data() + body.q_offset, s.v.data() + body.v_offset);
}

}  // namespace flexmb::testing
