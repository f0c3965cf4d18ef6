#pragma once
/// \file solid_tet4.h
/// 4-node linear tetrahedron (CTETRA with 4 nodes, C3D4): constant strain,
/// 3 DOF per node. Node order as Nastran and Abaqus: corners 1 2 3 with
/// (x2 - x1) x (x3 - x1) pointing toward node 4 (positive volume).
/// Details: docs/design.md, "FE: solid elements".

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Fills K [N/m] and M [kg] (12 x 12, basic frame, node by node ux uy uz) of
/// a 4-node tetrahedron: K = V B^T D B (exact, one point); consistent mass
/// rho V / 20 (1 + delta_ij) from the 4-point degree-2 rule (exact);
/// MassForm::kLumped gives rho V / 4 per node (HRZ). Throws InputError naming
/// the element for an inverted (negative volume) or degenerate element, a
/// missing material or bad material constants.
void SolidTet4Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Stress recovery of a 4-node tetrahedron: fills S (6 x 12) with the map
/// from the nodal displacements (basic frame, node by node ux uy uz, as K)
/// to the constant stresses (sxx, syy, szz, sxy, syz, szx) [Pa], basic
/// frame: D B of the stiffness. Throws InputError as SolidTet4Matrices.
void SolidTet4Stress(const ElementInput& in, MatX& S);

/// Stress recovery at the corner nodes of a 4-node tetrahedron: fills S (24 x 12)
/// with the map from the element DOF to the stresses (sxx, syy, szz, sxy,
/// syz, szx) [Pa] in the basic frame at each of its 4 corner nodes, in node
/// order (the strain field evaluated at the node, not extrapolated).
void SolidTet4CornerStress(const ElementInput& in, MatX& S);

/// Geometric (initial-stress) stiffness of a 4-node tetrahedron under the
/// stress of the nodal displacements `u` (12, basic frame, node by node ux
/// uy uz, as K; a static solution of the prestress load case): fills KG
/// (12 x 12, as K) [N/m] with V dN_i^T S dN_j I3, S = D B u the element's
/// constant stress (SolidTet4Stress). K + KG is the tangent stiffness of
/// the prestressed element (total Lagrangian, Green-Lagrange strain, at the
/// undeformed geometry). Throws InputError as SolidTet4Matrices.
void SolidTet4GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
