#pragma once
/// \file solid_tet10.h
/// 10-node quadratic tetrahedron (CTETRA with 10 nodes, C3D10), 3 DOF per
/// node. Node order as Nastran and Abaqus: corners 1-4 (positive volume as
/// for the tet4), then mid-edge nodes 5 (1-2), 6 (2-3), 7 (3-1), 8 (1-4),
/// 9 (2-4), 10 (3-4). Mid-edge nodes may be off the straight edge (curved
/// isoparametric element). Details: docs/design.md, "FE: solid elements".

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Fills K [N/m] and M [kg] (30 x 30, basic frame, node by node ux uy uz) of
/// a 10-node tetrahedron: stiffness by the 4-point degree-2 rule (exact for
/// straight edges), consistent mass by a 14-point degree-5 rule (exact for
/// the quartic N_i N_j on straight edges); MassForm::kLumped is HRZ lumping
/// (corners 1/36, mid-edge nodes 4/27 of the mass each, all positive).
/// Throws InputError naming the element if the Jacobian determinant is not
/// positive at a corner or an integration point (inverted, degenerate or
/// badly curved), for a missing material or bad material constants.
void SolidTet10Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Stress recovery of a 10-node tetrahedron: fills S (6 x 30) with the map
/// from the nodal displacements (basic frame, node by node ux uy uz, as K)
/// to the stresses (sxx, syy, szz, sxy, syz, szx) [Pa] at the centroid
/// (volume coordinates 1/4), basic frame: D B of the stiffness there. Throws
/// InputError as SolidTet10Matrices for a bad material or a non-positive
/// Jacobian at the centroid.
void SolidTet10Stress(const ElementInput& in, MatX& S);

/// Stress recovery at the corner nodes of a 10-node tetrahedron: fills S (24 x 30)
/// with the map from the element DOF to the stresses (sxx, syy, szz, sxy,
/// syz, szx) [Pa] in the basic frame at each of its 4 corner nodes, in node
/// order (the strain field evaluated at the node, not extrapolated).
void SolidTet10CornerStress(const ElementInput& in, MatX& S);

/// Geometric (initial-stress) stiffness of a 10-node tetrahedron under the
/// stress of the nodal displacements `u` (30, basic frame, node by node ux
/// uy uz, as K): fills KG (30 x 30, as K) [N/m] with int dN_i^T S dN_j dV
/// I3, S = D B u at each point of the 14-point degree-5 rule (the linearly
/// varying stress of the element, integrated exactly on straight edges).
/// K + KG is the tangent stiffness of the prestressed element (total
/// Lagrangian, at the undeformed geometry). Throws InputError as
/// SolidTet10Matrices.
void SolidTet10GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
