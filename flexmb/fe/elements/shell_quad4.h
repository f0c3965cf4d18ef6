#pragma once
/// \file shell_quad4.h
/// 4-node flat shell with 6 DOF per node, in the spirit of Nastran CQUAD4:
/// incompatible-mode membrane (QM6, Taylor's patch-test-passing form) with a
/// drilling rotation tied to the in-plane rotation (Hughes-Brezzi penalty),
/// Mindlin-Reissner plate bending with MITC4 assumed transverse shear
/// (Bathe & Dvorkin 1985), 2x2 Gauss. A slightly warped quad is projected on
/// its mean plane and joined to its nodes by rigid offsets; the shell
/// offset (Element::shell_offset) is handled the same way.
/// Details and constants: docs/design.md, "FE: shell elements".

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Fills K [N/m, N, N m] and M [kg, kg m, kg m^2] (24 x 24, basic frame,
/// node by node ux uy uz rx ry rz) of a 4-node shell. Consistent mass carries
/// translational (rho t + nsm), rotary (rho t^3 / 12) and a drilling inertia
/// rho t^3 / 12 on (theta_z - omega), which vanishes in rigid motion;
/// MassForm::kLumped gives per node the area share int N_i dA times
/// (rho t + nsm) on the translations and rho t^3 / 12 on all three
/// rotations. Throws InputError naming the element for zero area,
/// coincident nodes, a non-convex or badly warped quad, non-positive
/// thickness, or a missing section or material.
void ShellQuad4Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Stress recovery of a 4-node shell: fills S (6 x 24) with the map from the
/// element's nodal DOF (basic frame, node by node ux uy uz rx ry rz, as K) to
/// the in-plane stresses (sxx, syy, sxy) [Pa] at the centroid of the bottom
/// (rows 0-2) and top (rows 3-5) surfaces, z = -t/2 and +t/2 from the
/// (offset) mid-surface along e3, in the element frame, and `axes` with its
/// axes as columns (basic from element): e3 the unit normal of the mean
/// plane along (x3 - x1) x (x4 - x2), e1 the edge from node 1 to node 2
/// projected on the mean plane, e2 = e3 x e1. The strains are those of the
/// stiffness at the centroid (membrane B at xi = eta = 0, where the
/// incompatible modes have no strain; curvatures of the bilinear rotations).
/// Throws InputError as ShellQuad4Matrices for a bad element.
void ShellQuad4Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes);

/// Geometric (initial-stress) stiffness of a 4-node shell under the
/// membrane stress of the nodal displacements `u` (24, basic frame, node by
/// node ux uy uz rx ry rz, as K; a static solution of the prestress load
/// case): fills KG (24 x 24, as K) [N/m, N, N m] with the mid-surface term
/// int dN_i^T [Nxx Nxy; Nxy Nyy] dN_j dA on each local translation (u, v,
/// w), 2x2 Gauss with the bilinear derivatives, the resultants N =
/// MembraneMatrix eps0 taken at the centroid (the membrane strain of
/// ShellQuad4Stress, where the incompatible modes have none) and held
/// constant over the element. The rotations get no initial-stress terms (the
/// through-thickness terms of order t^2 / 12 and the bending moments'
/// contribution are neglected), so it is the classical plate-buckling
/// matrix. Transformed to the nodes like K (warping projection, offset).
/// Throws InputError as ShellQuad4Matrices.
void ShellQuad4GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
