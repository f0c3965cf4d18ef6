#pragma once
/// \file initial_conditions.h
/// Consistent initial conditions for the index-3 DAE: redundant constraint
/// detection, position assembly, velocity projection and the initial
/// accelerations and multipliers.

#include <string>
#include <vector>

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

class SparseLu;

/// Global indices of constraint equations that are linearly dependent on the
/// others at state s (relative tolerance `tol` on the rank decision). Earlier
/// joints' equations are kept; later ones that add nothing are reported.
/// Only the loops of the joint graph are examined (tree branches cannot be
/// redundant), so the cost grows with the size of the loops, not the model.
std::vector<int> FindRedundantEquations(const Model& model, const State& s, double tol);

/// Moves q to satisfy Phi(q, t) = 0 with the smallest correction in the mass
/// metric. Throws NumericalError naming the joint with the largest residual
/// if it fails.
void AssemblePositions(const Model& model, State& s, Workspace& ws, SparseLu& lu);

/// Projects v onto B v + Phi_t = 0 (smallest correction in the mass metric).
void ProjectVelocities(const Model& model, State& s, Workspace& ws, SparseLu& lu);

/// Solves [[M, B^T], [B, 0]] [vdot; lambda] = [Q; -(dB/dt v + Phi_tt)] for the
/// accelerations (into ws.vdot) and multipliers (into s.lambda).
void InitialAccelerations(const Model& model, State& s, Workspace& ws, SparseLu& lu);

/// Summary of the constraint analysis of MakeConsistent.
struct ConstraintReport {
  int equations = 0;                 ///< all constraint equations
  std::vector<int> redundant;        ///< removed equations (global indices)
  std::vector<std::string> messages; ///< one per joint with removed equations, naming them
  int dof = 0;                       ///< degrees of freedom nv - rank(B)
};

/// The whole sequence: redundancy detection (one warning per joint naming its
/// removed equations), initialization
/// of ws, position assembly, a consistency check of the removed equations
/// (InputError if the model is over-constrained inconsistently), velocity
/// projection and initial accelerations.
ConstraintReport MakeConsistent(const Model& model, State& s, Workspace& ws);

}  // namespace flexmb
