#pragma once
/// \file linearization.h
/// Linearization of the constrained equations of motion
///   M(q) vdot - Q(q, v, t) + B(q)^T lambda = 0,  Phi(q, t) = 0
/// about a state (q0, v0, lambda0) with accelerations a0, in the tangent
/// increments dx of the velocity coordinates (rigid bodies: the rotation
/// increment in body axes, not quaternion components):
///   M ddx + C ddx/dt + K dx = 0,  B dx = 0,
/// with M the mass matrix, C = -dQ/dv and K = -dQ/dq + d(M a0)/dq +
/// d(B^T lambda0)/dq (the geometric stiffness of the constraint reactions
/// and of the forces). The constraint is removed by an orthonormal basis N
/// of the null space of B (Householder QR of B^T with column pivoting):
/// dx = N z with the independent coordinates z, and
///   Mr = N^T M N,  Cr = N^T C N,  Kr = N^T K N.
/// Dense matrices: meant for the whole machine's modes (hundreds of
/// coordinates), not for large FE models.

#include <string>
#include <vector>

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

/// The linearized system of Linearize (see the file comment).
struct LinearizedSystem {
  MatX M, C, K;       ///< nv x nv, velocity coordinates [kg, kg m^2; N s/m; N/m, N m/rad]
  MatX B;             ///< active constraint Jacobian (n_active x nv)
  MatX N;             ///< nv x n orthonormal basis of the null space of B (n: degrees of freedom)
  MatX Mr, Cr, Kr;    ///< n x n reduced matrices
  int constraint_rank = 0;  ///< numerical rank of B
};

/// Linearizes the model about `s` with the accelerations `a` (nv; zero at
/// an equilibrium). The workspace must be initialized (MakeConsistent);
/// its markers, constraints, forces and iteration matrix are overwritten.
/// Throws InputError when the model has no degrees of freedom left, and
/// NumericalError naming the body when the reduced mass matrix is not
/// positive definite (a body without mass or inertia in a free direction).
LinearizedSystem Linearize(const Model& model, const State& s, const VecX& a, Workspace& ws);

/// A basis of the null space of B by coordinate partitioning: the columns
/// of B that a QR with column pivoting picks first (rank `tol` relative)
/// are the dependent coordinates, the others (ascending, into
/// `independent`) the independent ones, and N(independent, :) = I, so that
/// z are the increments of named velocity coordinates (state-space models).
MatX PartitionedNullSpace(const MatX& B, double tol, std::vector<int>& independent);

/// Replaces sys.N by `N` (nv x n, full column rank, B N = 0) and recomputes
/// Mr, Cr, Kr from it.
void ReduceWithBasis(LinearizedSystem& sys, const MatX& N);

/// "body 'name' (velocity coordinate k)" for the global velocity index c.
std::string VelocityCoordinateName(const Model& model, int c);

}  // namespace flexmb
