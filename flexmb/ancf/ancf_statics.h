#pragma once
/// \file ancf_statics.h
/// Static equilibrium of one ANCF body (planar beam or 3D cable) under large deflection:
/// Newton's method with load stepping (and optional backtracking). Boundary conditions are held
/// coordinates (e.g. a clamp holds x, y, x', y' of node 0; a pin x, y).
/// The engine's SolveStatics (solver/statics.h) works on whole models (joints
/// as supports, force elements as loads) with automatic load stepping; this
/// solver is the direct tool for one body with held coordinates.

#include <vector>

#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/ancf/ancf_cable3d_body.h"

namespace flexmb::ancf {

/// Settings of the load-stepping Newton solver.
struct AncfStaticsSettings {
  int load_steps = 10;       ///< equal load increments from the initial to the full load
  double initial_load_factor = 0.0;  ///< load factor at which q is in equilibrium on entry (continuation)
  int max_iterations = 50;   ///< Newton iterations per load step
  double tolerance = 1e-10;  ///< on the largest correction, relative to the beam length
  /// Backtracking on the residual norm. Off by default: for stiff axial
  /// behaviour the residual of a good Newton step often grows first.
  bool line_search = false;
};

/// Result of SolveAncfStatics.
struct AncfStaticsResult {
  int iterations = 0;        ///< Newton iterations over all load steps
  double residual = 0.0;     ///< largest free force residual at the end [N]
};

/// Moves q (nq of `body`, start: e.g. its initial coordinates) to the static
/// equilibrium under load factor 1 of: gravity g_W [m/s^2] and the
/// generalized nodal load `load` (nv entries, in the body's coordinates:
/// forces [N] on positions, moments-like terms on slopes [N m]), both
/// scaled by the load factor, plus the body's own distributed load (not
/// scaled). Coordinates listed in `held` keep their values. Throws
/// NumericalError if a load step does not converge or the tangent is
/// singular (an unsupported beam).
AncfStaticsResult SolveAncfStatics(const AncfBeam2dBody& body, const std::vector<int>& held,
                                   const VecX& load, const Vec3& g_W, VecX& q,
                                   const AncfStaticsSettings& settings = {});

/// The same for a 3D cable body (coordinates r_k, r'_k per node, world
/// components; a clamp holds r_0 and the direction of r'_0, a pin r_0).
AncfStaticsResult SolveAncfStatics(const AncfCable3dBody& body, const std::vector<int>& held,
                                   const VecX& load, const Vec3& g_W, VecX& q,
                                   const AncfStaticsSettings& settings = {});

/// The same for any body whose AddForces gives its static forces and
/// tangent; `length` [m] scales the convergence tolerance.
AncfStaticsResult SolveBodyStatics(const Body& body, double length, const std::vector<int>& held,
                                   const VecX& load, const Vec3& g_W, VecX& q,
                                   const AncfStaticsSettings& settings = {});

/// Coordinates of node k in an AncfBeam2dBody: first of (x, y, x', y').
inline int NodeCoordinate(int node) { return 4 * node; }

}  // namespace flexmb::ancf
