#pragma once
/// \file solid_wedge6.h
/// 6-node linear wedge (pentahedron, prism): Nastran CPENTA with 6 grid
/// points, Abaqus/CalculiX C3D6, gmsh type 6, VTK_WEDGE; 3 DOF per node.
/// Node order as Nastran and Abaqus: triangle 1 2 3, then 4 5 6 above 1 2 3,
/// numbered so that the Jacobian is positive (1 2 3 counter-clockwise seen
/// from 4 5 6; natural coordinates xi, eta on the triangle, node 1 at
/// (0, 0), 2 at (1, 0), 3 at (0, 1), zeta = -1 at 1 2 3 and +1 at 4 5 6).
/// Shape functions L_i (1 -+ zeta) / 2 with L = (1 - xi - eta, xi, eta).
/// Details: docs/design.md, "FE: solid elements".

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the 6-node wedge (its row: fe/element_traits.cc).
inline constexpr ElementType kWedge6{6};

/// Integration of the 6-node wedge's stiffness and mass.
enum class Wedge6Integration {
  /// Three triangle points (1/6, 2/3) times 2 Gauss points in zeta:
  /// stiffness and mass exact on a right prism.
  kSixPoint,
  /// One triangle point (the centroid) times 2 Gauss points, CalculiX's
  /// C3D6: one spurious zero-energy mode per element; for comparisons.
  kTwoPoint,
};

/// Fills K [N/m] and M [kg] (18 x 18, basic frame, node by node ux uy uz) of
/// a 6-node wedge; MassForm::kLumped by row sums, rho int N_i dV per node
/// (positive, and exact in mass and centre of mass). Throws InputError
/// naming the element if the Jacobian determinant is not positive at a
/// corner or an integration point (inverted, degenerate or too distorted),
/// for a missing material or bad material constants.
void SolidWedge6Matrices(const ElementInput& in, MatX& K, MatX& M,
                         Wedge6Integration integration = Wedge6Integration::kSixPoint);

/// Stress recovery of a 6-node wedge: fills S (6 x 18) with the map from
/// the nodal displacements (basic frame, node by node ux uy uz, as K) to the
/// stresses (sxx, syy, szz, sxy, syz, szx) [Pa] at the centroid (xi = eta =
/// 1/3, zeta = 0), basic frame. Throws InputError as SolidWedge6Matrices for
/// a bad material or a non-positive Jacobian at the centroid.
void SolidWedge6Stress(const ElementInput& in, MatX& S);

/// Stress recovery at the corner nodes of a 6-node wedge: fills S (36 x 18)
/// with the map from the element DOF to the stresses (sxx, syy, szz, sxy,
/// syz, szx) [Pa] in the basic frame at each of its 6 corner nodes, in node
/// order (the strain field evaluated at the node, not extrapolated).
void SolidWedge6CornerStress(const ElementInput& in, MatX& S);

/// Geometric (initial-stress) stiffness of a 6-node wedge under the stress
/// of the nodal displacements `u` (18, as K): fills KG (18 x 18, as K) [N/m]
/// with int dN_i^T S dN_j dV I3, S = D B u at each point of the six-point
/// rule. K + KG is the tangent stiffness of the prestressed element (total
/// Lagrangian, at the undeformed geometry). Throws InputError as
/// SolidWedge6Matrices.
void SolidWedge6GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
