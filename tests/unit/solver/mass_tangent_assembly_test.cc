// The stiffness part of the iteration matrix for a floating-frame flexible
// body, whose mass matrix depends on its configuration, against central
// differences of the residual r(q) = M(q) a - Q(q, v) over tangent
// increments (RetractAll): with AddMassTangents it is the residual's
// tangent to 1e-4 of the mass term; without it, the whole mass term is
// missing (so the check can fail).

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/assembler.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb {
namespace {

// r = M(q) a - Q(q, v) at the state
VecX MassTangentResidual(const Model& m, const State& s, const VecX& a, Workspace& ws) {
  EvaluateMarkers(m, s, ws);
  EvaluateForces(m, s, ws, false);
  VecX r(m.nv);
  MassTimes(m, ws, a, r);
  return r - ws.Q;
}

TEST(MassTangentAssembly, IterationMatrixIsTheTangentOfTheResidual) {
  Model m;
  const FlexibleBodyData d = testing::SpinningDeformedBentBar();
  m.AddBody(std::make_unique<FlexibleBody>("bar", d));
  m.Finalize();
  Workspace ws;
  InitWorkspace(m, ws);
  State s = m.InitialState();
  // a large acceleration, so that d(M a)/dq matters
  VecX a = VecX::LinSpaced(m.nv, 30.0, -20.0);

  // central differences of r over the tangent increments
  MatX fd(m.nv, m.nv);
  const double eps = 1e-6;
  State sp = s;
  for (int j = 0; j < m.nv; ++j) {
    VecX dx = VecX::Zero(m.nv);
    dx[j] = eps;
    RetractAll(m, s.q, dx, sp.q);
    const VecX rp = MassTangentResidual(m, sp, a, ws);
    RetractAll(m, s.q, -dx, sp.q);
    const VecX rm = MassTangentResidual(m, sp, a, ws);
    fd.col(j) = (rp - rm) / (2 * eps);
  }

  // stiffness part of the iteration matrix, with and without the mass tangent
  auto analytic = [&](bool with_mass_tangent) {
    EvaluateMarkers(m, s, ws);
    EvaluateConstraints(m, s, ws);
    EvaluateForces(m, s, ws, true);
    if (with_mass_tangent) AddMassTangents(m, s, a, ws);
    AssembleIterationMatrix(m, s, ws, MatrixCoefficients{0.0, 0.0, 1.0, false});
    return MatX(MatX(ws.S).topLeftCorner(m.nv, m.nv));
  };
  // d(M a)/dq is small beside the modal stiffness in |d r/dq|: measure the
  // error against the size of the mass term itself
  const MatX with = analytic(true), without = analytic(false);
  const double mass_term = (with - without).norm();
  const double err_with = (with - fd).norm() / mass_term, err_without = (without - fd).norm() / mass_term;
  std::printf("|S_q - d r/dq| / |d(M a)/dq|: with the mass tangent %.2e, without %.2e (|d(M a)/dq| / |d r/dq| = %.2e)\n",
              err_with, err_without, mass_term / fd.norm());
  EXPECT_LT(err_with, 1e-4);
  EXPECT_GT(err_without, 0.5);
}

}  // namespace
}  // namespace flexmb
