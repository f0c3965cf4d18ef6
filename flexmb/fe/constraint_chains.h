#pragma once
/// \file constraint_chains.h
/// Chains of rigid links and linear constraints (an RBE2 whose independent
/// node is the dependent node of an RBAR, an RBE3 whose independent grids
/// are moved by an RBE2, a rigid link from a grid whose component along a
/// skew displacement axis is constrained): the assembly (fe/assembly.h)
/// eliminates one level of dependent DOF, so a chain is resolved on the
/// mesh first, by rewriting each dependent DOF in terms of DOF that are
/// dependent nowhere.

#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

/// Resolves the chains of `mesh` in place: every rigid link that is part of
/// a chain (its independent node has a dependent DOF, or one of its
/// dependent DOF is an independent DOF of a linear constraint) becomes the
/// equivalent rows of linear constraints (u_d = u_i + theta_i x (x_d - x_i),
/// theta_d = theta_i, one row per component of its mask, card "rigid
/// link", id and origin the link's), and every linear constraint whose terms
/// name a dependent DOF gets that DOF's own terms substituted, recursively.
/// Meshes without chains are left unchanged. Throws InputError naming the
/// cards when the chain closes on itself (a loop).
void ResolveConstraintChains(Mesh& mesh);

}  // namespace flexmb::fe
