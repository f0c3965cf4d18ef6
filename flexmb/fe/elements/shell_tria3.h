#pragma once
/// \file shell_tria3.h
/// 3-node flat shell with 6 DOF per node, in the spirit of Nastran CTRIA3:
/// constant-strain membrane with a drilling rotation tied to the in-plane
/// rotation (Hughes-Brezzi penalty), Mindlin-Reissner plate bending with
/// MITC3 assumed transverse shear (Lee & Bathe 2004), the shell offset as a
/// rigid link along the normal. Details: docs/design.md, "FE: shell elements".

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Fills K and M (18 x 18, basic frame, node by node ux uy uz rx ry rz) of a
/// 3-node shell; mass forms as for ShellQuad4Matrices. Throws InputError
/// naming the element for zero area, coincident nodes, non-positive
/// thickness, or a missing section or material.
void ShellTria3Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Stress recovery of a 3-node shell: fills S (6 x 18) with the map from the
/// element's nodal DOF (basic frame, as K) to the in-plane stresses (sxx,
/// syy, sxy) [Pa] of the bottom (rows 0-2) and top (rows 3-5) surfaces, z =
/// -t/2 and +t/2 from the (offset) mid-surface along e3, in the element
/// frame, and `axes` with its axes as columns (basic from element): e3 the
/// unit normal along (x2 - x1) x (x3 - x1), e1 along the edge from node 1 to
/// node 2, e2 = e3 x e1. Membrane strain and curvature are constant over the
/// element (those of the stiffness). Throws InputError as ShellTria3Matrices.
void ShellTria3Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes);

/// Geometric (initial-stress) stiffness of a 3-node shell under the
/// membrane stress of the nodal displacements `u` (18, basic frame, as K):
/// fills KG (18 x 18, as K) with A dN_i^T [Nxx Nxy; Nxy Nyy] dN_j on each
/// local translation (u, v, w), N the element's constant membrane
/// resultants; no initial-stress terms on the rotations (as
/// ShellQuad4GeometricStiffness). Throws InputError as ShellTria3Matrices.
void ShellTria3GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
