#pragma once
/// \file inertia_invariants.h
/// Inertia invariants of a reduced flexible body (THEORY section 4): the
/// coefficient matrices of M(w) = sum_k sum_l L_k(w)^T M_kl L_l(w), computed
/// once from the FE model's node-by-node mass matrix and the mode shapes, and
/// the evaluation of M(w) from them (O(n^2) per call, independent of the
/// mesh size, no allocation).

#include <Eigen/Core>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb::reduction {

/// Computes the inertia invariants of the mode shapes `modes` (6 rows per
/// node of `mesh`, ux uy uz rx ry rz in the body frame = the FE basic frame,
/// n columns; rows of inactive DOF are ignored) with the mass matrix
/// `model.M_full` (all active DOF before rigid-link elimination and
/// constraints, numbered by model.dofs.full, symmetric with both triangles
/// stored) in its general form: translational, rotational and coupling 6 x 6
/// blocks M_kl for every pair of nodes k, l it couples. Node positions rho_k
/// are mesh.nodes[k].x. The result is exact to round-off for any modes (no
/// orthonormality assumed). Cost: dense products of about 36 N n^2 flops (N
/// nodes; moo2 alone 18 N n^2, mow1 12 N n^2, mww 6 N n^2), on two threads
/// when the machine has two cores, plus sparse gathers of about 130 n flops
/// per stored 6 x 6 block.
/// `modal_mass`, if given, is H^T M_full H known to the caller (n x n; the
/// reduction has it as the reduced mass of the delivered modes) and becomes
/// mww (symmetrized) instead of being formed here, which saves 6 N n^2 of
/// the flops and half the gathers. Throws InputError if the sizes of mesh,
/// model, modes and modal_mass disagree or M_full has an entry on a DOF
/// that belongs to no node.
/// The invariants are linear in M_full, so a model assembled in shares
/// (fe::AssemblyOptions::block_subset) gives them as the sum over the
/// shares, provided the point masses are in one share: the offset point
/// masses move their mass between node blocks (see inertia_invariants.cc),
/// which the other shares must not do (`offset_point_masses` false there).
InertiaInvariants ComputeInertiaInvariants(const fe::Mesh& mesh, const fe::AssembledModel& model,
                                           const MatX& modes, const MatX* modal_mass = nullptr,
                                           bool offset_point_masses = true);

/// The generalized mass matrix M(w) of THEORY section 4, (6 + n) square for
/// nu = (v, omega, wdot) (body components; units of the invariants), from
/// the invariants at modal coordinates w (size n). Written into `out`, which
/// must be (6 + n) x (6 + n) already (a block of a larger matrix is fine):
/// allocates nothing. Symmetric to the last bit. Throws InputError for
/// wrong sizes.
void MassMatrix(const InertiaInvariants& inv, const Eigen::Ref<const VecX>& w, Eigen::Ref<MatX> out);

/// As above, returning a new (6 + n) x (6 + n) matrix (allocates).
MatX MassMatrix(const InertiaInvariants& inv, const Eigen::Ref<const VecX>& w);

}  // namespace flexmb::reduction
