#pragma once
/// \file solid_wedge15.h
/// 15-node quadratic wedge (serendipity pentahedron): Nastran CPENTA with 15
/// grid points, Abaqus/CalculiX C3D15, gmsh type 18, VTK_QUADRATIC_WEDGE; 3
/// DOF per node. Node order as Abaqus and CalculiX: corners 1-6 as the
/// 6-node wedge (solid_wedge6.h), then mid-edge nodes 7 (1-2), 8 (2-3),
/// 9 (3-1), 10 (4-5), 11 (5-6), 12 (6-4), 13 (1-4), 14 (2-5), 15 (3-6).
/// Nastran numbers the vertical edges before the top ones (G10-G12 on 1-4,
/// 2-5, 3-6; G13-G15 on 4-5, 5-6, 6-4); the reader reorders them. Mid-edge
/// nodes may be off the straight edge (curved isoparametric element).
/// Details: docs/design.md, "FE: solid elements".

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the 15-node wedge (its row: fe/element_traits.cc).
inline constexpr ElementType kWedge15{7};

/// Mid-edge nodes 7..15 (local 6..14) of the 15-node wedge: the corners
/// (local 0..5) at the ends of their edges, in that order.
inline constexpr int kWedge15EdgeCorners[9][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5},
                                                  {5, 3}, {0, 3}, {1, 4}, {2, 5}};

/// Integration of the 15-node wedge's consistent mass.
enum class Wedge15Mass {
  /// Six triangle points (degree 4) times 3 Gauss points in zeta: exact on
  /// a right prism with straight edges.
  kExact,
  /// The stiffness rule (3 triangle points times 3 Gauss points), CalculiX's
  /// C3D15 mass; for comparisons.
  kNinePoint,
};

/// Fills K [N/m] and M [kg] (45 x 45, basic frame, node by node ux uy uz)
/// of a 15-node wedge: stiffness by 3 triangle points (1/6, 2/3) times 3
/// Gauss points in zeta (9 points, CalculiX's and Abaqus's C3D15 rule; no
/// spurious zero-energy mode), consistent mass as `mass` says;
/// MassForm::kLumped is HRZ lumping (the row sums of the corners are
/// negative). Throws InputError naming the element if the Jacobian
/// determinant is not positive at a corner or an integration point
/// (inverted, degenerate or badly curved), for a missing material or bad
/// material constants.
void SolidWedge15Matrices(const ElementInput& in, MatX& K, MatX& M, Wedge15Mass mass = Wedge15Mass::kExact);

/// Stress recovery of a 15-node wedge: fills S (6 x 45) with the map from
/// the nodal displacements (basic frame, node by node ux uy uz, as K) to the
/// stresses (sxx, syy, szz, sxy, syz, szx) [Pa] at the centroid (xi = eta =
/// 1/3, zeta = 0), basic frame. Throws InputError as SolidWedge15Matrices
/// for a bad material or a non-positive Jacobian at the centroid.
void SolidWedge15Stress(const ElementInput& in, MatX& S);

/// Stress recovery at the corner nodes of a 15-node wedge: fills S (36 x 45)
/// with the map from the element DOF to the stresses (sxx, syy, szz, sxy,
/// syz, szx) [Pa] in the basic frame at each of its 6 corner nodes, in node
/// order (the strain field evaluated at the node, not extrapolated).
void SolidWedge15CornerStress(const ElementInput& in, MatX& S);

/// Geometric (initial-stress) stiffness of a 15-node wedge under the stress
/// of the nodal displacements `u` (45, as K): fills KG (45 x 45, as K)
/// [N/m] with int dN_i^T S dN_j dV I3, S = D B u at each point of the
/// 18-point rule of the exact mass. K + KG is the tangent stiffness of the
/// prestressed element (total Lagrangian, at the undeformed geometry).
/// Throws InputError as SolidWedge15Matrices.
void SolidWedge15GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
