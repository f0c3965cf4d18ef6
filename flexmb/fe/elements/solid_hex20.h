#pragma once
/// \file solid_hex20.h
/// 20-node quadratic hexahedron (serendipity brick), in two integrations:
/// full (Abaqus/CalculiX C3D20, Nastran CHEXA with 20 grid points, gmsh
/// type 17, VTK_QUADRATIC_HEXAHEDRON) and reduced (C3D20R); 3 DOF per
/// node. Node order as Abaqus and CalculiX: corners 1-8 as the 8-node
/// hexahedron (solid_hex8.h), then mid-edge nodes 9-12 on the bottom edges
/// (1-2, 2-3, 3-4, 4-1), 13-16 on the top edges (5-6, 6-7, 7-8, 8-5) and
/// 17-20 on the vertical edges (1-5, 2-6, 3-7, 4-8). Nastran numbers the
/// vertical edges before the top ones; the reader reorders them. Mid-edge
/// nodes may be off the straight edge (curved isoparametric element).
/// Details: docs/design.md, "FE: solid elements".

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the 20-node hexahedron with full integration (C3D20; its row:
/// fe/element_traits.cc).
inline constexpr ElementType kHex20{8};
/// Type id of the 20-node hexahedron with reduced integration (C3D20R).
inline constexpr ElementType kHex20R{9};

/// Mid-edge nodes 9..20 (local 8..19) of the 20-node hexahedron: the
/// corners (local 0..7) at the ends of their edges, in that order.
inline constexpr int kHex20EdgeCorners[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                 {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

/// Integration of the 20-node hexahedron's stiffness.
enum class Hex20Integration {
  kFull,     ///< 3 x 3 x 3 Gauss points (C3D20): no zero-energy mode
  kReduced,  ///< 2 x 2 x 2 Gauss points (C3D20R): softer, one element alone has
             ///< zero-energy modes that a mesh of two or more does not
};

/// Fills K [N/m] and M [kg] (60 x 60, basic frame, node by node ux uy uz)
/// of a 20-node hexahedron: stiffness with `integration`, consistent mass
/// with 3 x 3 x 3 points (exact on a parallelepiped) for both;
/// MassForm::kLumped is HRZ lumping (the corner row sums of the consistent
/// mass are negative). Throws InputError naming the element if the
/// Jacobian determinant is not positive at a corner or an integration point
/// (inverted, degenerate or badly curved), for a missing material or bad
/// material constants.
void SolidHex20Matrices(const ElementInput& in, MatX& K, MatX& M, Hex20Integration integration);

/// Stress recovery of a 20-node hexahedron: fills S (6 x 60) with the map
/// from the nodal displacements (as K) to the stresses (sxx, syy, szz, sxy,
/// syz, szx) [Pa] at the centroid (xi = eta = zeta = 0), basic frame.
/// Throws InputError as SolidHex20Matrices.
void SolidHex20Stress(const ElementInput& in, MatX& S);

/// Stress recovery at the corner nodes of a 20-node hexahedron: fills S (48 x 60)
/// with the map from the element DOF to the stresses (sxx, syy, szz, sxy,
/// syz, szx) [Pa] in the basic frame at each of its 8 corner nodes, in node
/// order (the strain field evaluated at the node, not extrapolated).
void SolidHex20CornerStress(const ElementInput& in, MatX& S);

/// Geometric (initial-stress) stiffness of a 20-node hexahedron under the
/// stress of the nodal displacements `u` (60, as K): fills KG (60 x 60, as
/// K) [N/m] with int dN_i^T S dN_j dV I3, S = D B u at the 27 points. K +
/// KG is the tangent stiffness of the prestressed element (total
/// Lagrangian, at the undeformed geometry). Throws InputError as
/// SolidHex20Matrices.
void SolidHex20GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
