#pragma once
/// \file statics.h
/// Static equilibrium: find q and lambda with
///   Q(q, 0, t) - B(q)^T lambda = 0,  Phi(q, t) = 0
/// by Newton's method on the tangent stiffness [[K_t, B^T], [B, 0]], made
/// robust for large deflection (slender ANCF beams, cables):
/// - load stepping by residual continuation: with r_0 the residual at the
///   start (q_0, lambda_0), the solver follows the equilibria of
///   r(q, lambda) = (1 - mu) r_0 for the load factor mu from 0 to 1. At
///   mu = 0 the start solves it, at mu = 1 it is the true problem; for a
///   start without stress (a straight beam) this is proportional loading of
///   all applied forces. Increments grow after easy steps and are halved
///   when Newton fails (no convergence, a non-finite residual or an element
///   that collapses), down to StaticsSettings::min_increment;
/// - full Newton steps, halved while the residual they lead to is not
///   finite; optionally (StaticsSettings::line_search) a line search on the
///   directional derivative of the total potential (Lagrangian) along the
///   Newton direction, s(a) = d . r(x + a d) (Crisfield, Non-linear Finite
///   Element Analysis of Solids and Structures, vol. 1, 1991, section 9.4).
///   It is off by default: along the straight Newton direction a large
///   rotation of an ANCF beam stretches it, so both the residual norm (the
///   former backtracking, which stalled) and s(a) ask for short steps,
///   while the full step is corrected by the next iteration (measured on
///   the 16-element slender elastica, PL^2/EI = 10, full load at once:
///   9 iterations with full steps, 1871 with the line search;
///   docs/design.md, "Engine statics");
/// - directions held by damping only: where the tangent stiffness K_t is
///   singular, the iteration matrix becomes K_t + C / tau (C the damping
///   tangent, tau = StaticsSettings::damping_hold_time). A load standing on
///   the ground is held sideways only by its (regularized) friction, a
///   vehicle on its tires by their slip damping: as at rest in reality, the
///   damping keeps these directions where they are while the stiff ones
///   settle. The residual stays the true one, so an equilibrium found is an
///   equilibrium. Where K_t + C / tau is singular too, M / (10 tau)^2 is
///   added (a pseudo-transient step): a direction with neither stiffness
///   nor damping but no load along it either (a load hanging on one hook
///   turns freely about the rope; a slack rope's load at load factor 0)
///   stays where it is; one with a load along it (a free body under
///   gravity) never settles and is reported as a free motion.

#include <functional>
#include <string>

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

/// Result of a static solve.
struct StaticsResult {
  int iterations = 0;         ///< Newton iterations used (all increments, failed ones included)
  double residual = 0.0;      ///< final largest force residual [N, N m]
  int increments = 0;         ///< converged load increments
  int cuts = 0;               ///< failed increments (each halved the increment)
  /// With StaticsSettings::hold_always: the coordinate of the largest
  /// residual when the iteration stopped on the residual before its steps
  /// converged (a creep: a force that no displacement removes, e.g. a
  /// contact patch's weight along its slide spinning a free wheel, which a
  /// body at rest moves under at force / damping); empty when the steps
  /// converged.
  std::string creep;
};

/// Settings of the static solver.
struct StaticsSettings {
  int max_iterations = 30;    ///< Newton iterations per load increment before the increment is halved
  int max_total_iterations = 5000;  ///< Newton iterations over all increments
  double tolerance = 1e-10;   ///< on the largest tangent correction [m, rad]
  double residual_tol = 1e-8; ///< on the largest force residual, relative to the largest applied force
  double initial_increment = 1.0;  ///< first load-factor increment (1: the full load at once)
  double min_increment = 1e-5;     ///< smallest load-factor increment before giving up
  bool line_search = false;   ///< line search on s(a) (see the file comment); false: full Newton steps
  /// Time tau [s] of the damping that holds directions without stiffness
  /// (see the file comment); 0: none (a singular K_t is an error at once).
  double damping_hold_time = 1.0;
  /// The pseudo-transient iteration matrix K_t + C / tau + M / (10 tau)^2
  /// from the first iteration, not only once K_t is found singular: for a
  /// system whose directions without stiffness round-off can hide from the
  /// singularity test (a vehicle on its tires, free to roll at rest, with an
  /// elastic frame whose stiff static modes set the pivots' scale). The
  /// residual stays the true one, so the fixed point is the same
  /// equilibrium, reached at a linear rate where the damping terms matter;
  /// stiff directions converge as by Newton. The steps of the held
  /// directions (residual / damping) need not vanish, so the residual
  /// decides: converged when it is below residual_tol at two iterations in a
  /// row (StaticsResult::creep names where the largest one stands when the
  /// steps had not converged).
  bool hold_always = false;
  /// Called after every converged load increment with the load factor
  /// reached (in (0, 1]), the Newton iterations of that increment and the
  /// statistics so far; the state passed to SolveStatics then holds that
  /// equilibrium (multipliers included) and the workspace's markers,
  /// constraints and forces are evaluated at it. Empty: not called.
  std::function<void(double load_factor, int iterations, const StaticsResult&)> on_increment;
};

/// The settings of a model's static equilibrium from its solver settings
/// (statics_hold_always, statics_residual_tol); the rest default.
StaticsSettings StaticsSettingsOf(const SolverSettings& solver);

/// Moves `s` (velocities set to zero, time fixed) to static equilibrium.
/// The workspace must be initialized (e.g. by MakeConsistent). Throws
/// NumericalError naming the body whose coordinates have no stiffness when
/// the tangent is singular (a free or unloaded mechanism), and, when the
/// load increment falls below min_increment or the iteration budget is
/// spent, naming the load factor reached and the body coordinate or joint
/// equation with the largest residual; `s` then holds the last converged
/// equilibrium of the continuation.
StaticsResult SolveStatics(const Model& model, State& s, Workspace& ws,
                           const StaticsSettings& settings = {});

/// Throws NumericalError naming the first joint whose coordinate lies
/// outside its limits (`Joint::coordinate_min/max`, a cylinder's stroke),
/// read from the markers of `ws` (evaluated at the state of time `t`); the
/// message ends "at t = T s", or with `statics` "at the static equilibrium
/// (t = T s)". SolveStatics checks its equilibrium, the Simulator every step.
void CheckJointLimits(const Model& model, const Workspace& ws, double t, bool statics = false);

}  // namespace flexmb
