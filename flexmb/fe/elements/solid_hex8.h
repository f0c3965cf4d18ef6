#pragma once
/// \file solid_hex8.h
/// 8-node trilinear hexahedron (CHEXA with 8 nodes, C3D8 / C3D8I), 3 DOF per
/// node. Node order as Nastran and Abaqus: face 1 2 3 4, then 5 6 7 8 above
/// 1 2 3 4, numbered so that the Jacobian is positive (natural corners
/// (-1,-1,-1), (1,-1,-1), (1,1,-1), (-1,1,-1), then the same at zeta = +1).
/// Default: incompatible modes (Wilson, Taylor, Doherty, Ghaboussi 1973;
/// Taylor, Beresford, Wilson 1976),
/// which remove shear locking in bending. Details: docs/design.md,
/// "FE: solid elements".

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Stiffness formulation of the 8-node hexahedron.
enum class Hex8Formulation {
  /// Full 2x2x2 integration plus the nine incompatible modes (1 - xi_a^2)
  /// per displacement component, with Taylor's correction (derivatives from
  /// the centre Jacobian J0, scaled by det J0 / det J) so that the patch test
  /// passes on distorted elements; the modes are condensed out (C3D8I-like).
  kIncompatibleModes,
  /// Plain full 2x2x2 integration (CalculiX's C3D8); locks in bending.
  kFullIntegration,
  /// Selectively reduced integration (Abaqus's C3D8): 2x2x2 points with the
  /// volumetric strain replaced by its mean over the element (Hughes's
  /// B-bar, mean dilatation).
  kSelectiveReduced,
};

/// Type id of the 8-node hexahedron with plain full integration (CalculiX's
/// C3D8; its row: fe/element_traits.cc). The default row, ElementType::kHex8,
/// has the incompatible modes (Nastran CHEXA, Abaqus C3D8I).
inline constexpr ElementType kHex8Full{15};

/// Type id of the 8-node hexahedron with selectively reduced integration
/// (Abaqus's C3D8, read from decks written by Abaqus/CAE; its row:
/// fe/element_traits.cc). It has no Abaqus name of its own: the writer
/// writes it as C3D8 under an Abaqus/CAE header line.
inline constexpr ElementType kHex8Selective{16};

/// Fills K [N/m] and M [kg] (24 x 24, basic frame, node by node ux uy uz) of
/// an 8-node hexahedron; consistent mass by 3x3x3 Gauss (exact for any
/// trilinear geometry), MassForm::kLumped by row sums, rho int N_i dV per
/// node (one eighth of the mass on a parallelepiped; positive, and exact in
/// mass and centre of mass on any valid hexahedron, which HRZ lumping is not
/// on a tapered one). Throws InputError naming the element
/// if the Jacobian determinant is not positive at an integration point
/// (2x2x2 and 3x3x3; inverted, degenerate or too distorted), for a missing
/// material or bad material constants. Corners are not checked: the
/// MacNeal-Harder patch elements have slightly negative corner Jacobians.
void SolidHex8Matrices(const ElementInput& in, MatX& K, MatX& M,
                       Hex8Formulation formulation = Hex8Formulation::kIncompatibleModes);

/// Stress recovery of an 8-node hexahedron: fills S (6 x 24) with the map
/// from the nodal displacements (basic frame, node by node ux uy uz, as K)
/// to the stresses (sxx, syy, szz, sxy, syz, szx) [Pa] at the centre (xi =
/// eta = zeta = 0), basic frame: D B of the trilinear field there. The
/// incompatible modes of the default formulation have no strain at the
/// centre (their Taylor-corrected derivatives vanish there), so both
/// formulations share this recovery. Throws InputError as SolidHex8Matrices
/// for a bad material or a non-positive Jacobian at the centre.
void SolidHex8Stress(const ElementInput& in, MatX& S);

/// Stress recovery at the corner nodes of a 8-node hexahedron: fills S (48 x 24)
/// with the map from the element DOF to the stresses (sxx, syy, szz, sxy,
/// syz, szx) [Pa] in the basic frame at each of its 8 corner nodes, in node
/// order (the strain field evaluated at the node, not extrapolated).
void SolidHex8CornerStress(const ElementInput& in, MatX& S);

/// Geometric (initial-stress) stiffness of an 8-node hexahedron under the
/// stress of the nodal displacements `u` (24, basic frame, node by node ux
/// uy uz, as K): fills KG (24 x 24, as K) [N/m] with int dN_i^T S dN_j dV
/// I3 by 2x2x2 Gauss, S the stress at the centre (SolidHex8Stress, held
/// constant over the element: exact for a homogeneous stress, the midpoint
/// value of a varying one). K + KG is the tangent stiffness of the
/// prestressed element (total Lagrangian, at the undeformed geometry).
/// Throws InputError as SolidHex8Matrices.
void SolidHex8GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
