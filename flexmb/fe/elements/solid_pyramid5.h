#pragma once
/// \file solid_pyramid5.h
/// 5-node linear pyramid: Nastran CPYRAM with 5 grid points, Abaqus C3D5,
/// gmsh type 7, VTK_PYRAMID; 3 DOF per node. Node order as all four: the
/// base quadrilateral 1 2 3 4, counter-clockwise seen from the apex 5.
/// Formulation: the 8-node hexahedron with its top face collapsed into the
/// apex, which on the reference pyramid is the classic rational pyramid
/// (natural coordinates xi, eta, zeta in [-1, 1]^3): base nodes
/// (1 + xi_i xi)(1 + eta_i eta)(1 - zeta) / 8, apex (1 + zeta) / 2. The
/// field is bilinear on the base and linear on the four triangular faces
/// (conforming with 8-node hexahedra and 4-node tetrahedra), and linear
/// fields are reproduced exactly (the patch test). The Jacobian vanishes at
/// the apex, never at an integration point. Details: docs/design.md, "FE:
/// solid elements".

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the 5-node pyramid (its row: fe/element_traits.cc).
inline constexpr ElementType kPyramid5{17};

/// Fills K [N/m] and M [kg] (15 x 15, basic frame, node by node ux uy uz) of
/// a 5-node pyramid, both by 3x3x3 Gauss on the collapsed cube (exact for a
/// pyramid over a parallelogram base: the integrands are then polynomials);
/// MassForm::kLumped by row sums, rho int N_i dV per node (positive, and
/// exact in mass and centre of mass). Throws InputError naming the element if
/// the Jacobian determinant is not positive at a base corner or an
/// integration point (inverted, degenerate, an apex in the base plane), for
/// a missing material or bad material constants.
void SolidPyramid5Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Stress recovery of a 5-node pyramid: fills S (6 x 15) with the map from
/// the nodal displacements (as K) to the stresses (sxx, syy, szz, sxy, syz,
/// szx) [Pa] at the natural centre (0, 0, 0), basic frame.
void SolidPyramid5Stress(const ElementInput& in, MatX& S);

/// Stress recovery at the corner nodes of a 5-node pyramid: fills S (30 x
/// 15) as SolidPyramid5Stress at each corner in node order: the four base
/// corners, and for the apex, where the collapsed mapping is singular and
/// the strain of a non-linear field has no single value, the point
/// (0, 0, 1/2) on the axis, 3/4 of the way up (exact for a linear field,
/// and equal to the centre's value over a parallelogram base).
void SolidPyramid5CornerStress(const ElementInput& in, MatX& S);

/// Geometric (initial-stress) stiffness of a 5-node pyramid under the stress
/// of the nodal displacements `u` (15, as K): fills KG (15 x 15, as K)
/// [N/m], int dN_i^T S dN_j dV I3 over the rule of SolidPyramid5Matrices.
void SolidPyramid5GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
