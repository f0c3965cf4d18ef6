#pragma once
/// \file statics.h
/// Static equilibrium: find q and lambda with
///   Q(q, 0, t) - B(q)^T lambda = 0,  Phi(q, t) = 0
/// by Newton's method on the tangent stiffness [[K_t, B^T], [B, 0]] with a
/// backtracking line search on the residual norm.

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

/// Settings of the static solver.
struct StaticsSettings {
  int max_iterations = 100;   ///< Newton iterations
  double tolerance = 1e-10;   ///< on the largest tangent correction [m, rad]
  double residual_tol = 1e-8; ///< on the largest force residual, relative to the largest applied force
};

/// Result of a static solve.
struct StaticsResult {
  int iterations = 0;         ///< Newton iterations used
  double residual = 0.0;      ///< final largest force residual [N, N m]
};

/// Moves `s` (velocities set to zero, time fixed) to static equilibrium.
/// The workspace must be initialized (e.g. by MakeConsistent). Throws
/// NumericalError naming the body whose coordinates have no stiffness when
/// the tangent is singular (a free or unloaded mechanism), or when Newton
/// does not converge.
StaticsResult SolveStatics(const Model& model, State& s, Workspace& ws,
                           const StaticsSettings& settings = {});

}  // namespace flexmb
