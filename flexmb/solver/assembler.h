#pragma once
/// \file assembler.h
/// Evaluation of the model at a state and assembly of the global vectors and
/// sparse matrices of the DAE
///   M(q) vdot + B(q)^T lambda = Q(q, v, t),   Phi(q, t) = 0,
/// where B = dPhi/dx is taken with respect to tangent increments dx (the
/// components of v), so Phi(q (+) dx) = Phi(q) + B dx + O(dx^2).

#include <vector>

#include "flexmb/model/model.h"
#include "flexmb/model/state.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

/// Sizes every workspace buffer and builds the sparse patterns, with the
/// equations listed in `removed_equations` (global equation indices) left out.
void InitWorkspace(const Model& model, Workspace& ws, const std::vector<int>& removed_equations = {});

/// Marker states of all markers at (q, v).
void EvaluateMarkers(const Model& model, const State& state, Workspace& ws);

/// Constraint values phi, phi_t and the Jacobian B at the marker states.
void EvaluateConstraints(const Model& model, const State& state, Workspace& ws);

/// Generalized forces Q; with `tangents`, also the body and force element
/// derivative blocks used by AssembleIterationMatrix.
void EvaluateForces(const Model& model, const State& state, Workspace& ws, bool tangents);

/// For bodies with a configuration-dependent mass, subtracts d(M(q) a)/dq
/// from their force derivative blocks (after EvaluateForces with tangents),
/// so that the stiffness part of the iteration matrix is the tangent of the
/// residual M(q) a - Q at the acceleration a (nv).
void AddMassTangents(const Model& model, const State& state, const VecX& a, Workspace& ws);

/// Coefficients of the top-left block of the iteration matrix:
/// A = mass * M + damping * (-dQ/dv) + stiffness * (-dQ/dq + d(B^T lambda)/dq).
struct MatrixCoefficients {
  double mass = 1.0;
  double damping = 0.0;
  double stiffness = 0.0;
  bool geometric = true;  ///< include d(B^T lambda)/dq
};

/// Assembles S = [[A, B^T], [B, 0]] into ws.S. Needs EvaluateMarkers,
/// EvaluateConstraints and (for damping/stiffness) EvaluateForces(tangents).
void AssembleIterationMatrix(const Model& model, const State& state, Workspace& ws,
                             const MatrixCoefficients& c);

/// r = M(q) a (nv), using the body mass blocks in ws (EvaluateForces fills them).
void MassTimes(const Model& model, const Workspace& ws, const VecX& a, VecX& r);

/// q_out = q (+) dx for all bodies.
void RetractAll(const Model& model, const VecX& q, const VecX& dx, VecX& q_out);

/// Constraint reactions: adds B^T lambda (the active multipliers) to r.
void AddConstraintForces(const Model& model, const Workspace& ws, const VecX& lambda, VecX& r);

/// Global equation index -> "joint 'name' (equation text)", for messages.
std::string DescribeEquation(const Model& model, int global_eq);

}  // namespace flexmb
