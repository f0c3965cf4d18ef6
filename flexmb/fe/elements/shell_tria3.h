#pragma once
/// \file shell_tria3.h
/// 3-node flat shell with 6 DOF per node, in the spirit of Nastran CTRIA3:
/// constant-strain membrane with a drilling rotation tied to the in-plane
/// rotation (Hughes-Brezzi penalty), Mindlin-Reissner plate bending with
/// MITC3 assumed transverse shear (Lee & Bathe 2004), the shell offset as a
/// rigid link along the normal. Details: docs/design.md, "FE: shell elements".

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Fills K and M (18 x 18, basic frame, node by node ux uy uz rx ry rz) of a
/// 3-node shell; mass forms as for ShellQuad4Matrices. Throws InputError
/// naming the element for zero area, coincident nodes, non-positive
/// thickness, or a missing section or material.
void ShellTria3Matrices(const ElementInput& in, MatX& K, MatX& M);

}  // namespace flexmb::fe
