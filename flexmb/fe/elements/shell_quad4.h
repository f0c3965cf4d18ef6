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

}  // namespace flexmb::fe
