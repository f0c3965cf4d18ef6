#pragma once
/// \file rod2.h
/// 2-node rod (Nastran CROD, CONROD, CTUBE; Abaqus/CalculiX T3D2): axial
/// stiffness E A / L and torsional stiffness G J / L about the element axis
/// e (from node 1 to node 2), no bending or transverse shear stiffness. Its
/// section is a BeamSection (mesh.h) with A, J, nsm and the material; Iy, Iz
/// and Iyz are zero (a rod section). J = 0 is a pure truss (T3D2). The
/// element has 6 DOF per node (ux uy uz rx ry rz, basic frame) like a beam,
/// but activates only the translations of its nodes (as solids do): its
/// torsion enters the assembly only where both nodes' rotations are active
/// through other elements (beams, shells), and is dropped otherwise, which
/// is the exact static condensation of a massless twist without moment
/// load (fe/assembly.h). Mass: the translational inertia (rho A + nsm) L
/// only (as Nastran CROD and CalculiX T3D2), consistent (linear shape
/// functions in all three directions, m / 6 [2 1; 1 2] per direction) or
/// lumped (m / 2 per node); no torsional inertia. Details: docs/design.md,
/// "FE: rod element".

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the 2-node rod (its row: fe/element_traits.cc).
inline constexpr ElementType kRod2{10};

/// True for a section without bending stiffness (Iy = Iz = Iyz = 0): the
/// section of a rod.
inline bool IsRodSection(const BeamSection& s) { return s.Iy == 0.0 && s.Iz == 0.0 && s.Iyz == 0.0; }

/// Fills K [N/m, N m] and M [kg] (12 x 12, basic frame, node by node ux uy
/// uz rx ry rz) of a 2-node rod: K = [k -k; -k k] with the translational
/// block E A / L e e^T and the rotational block G J / L e e^T (G = E / (2 (1
/// + nu)) if the material gives none); M as the file comment (mass form of
/// `in`). Throws InputError naming the element (type, id, file:line) for
/// zero length, A <= 0, J < 0, a section with bending moments (not a rod
/// section), negative density or nsm, a missing section or material, or E
/// <= 0.
void Rod2Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Section forces of a 2-node rod at its two ends, as Beam2SectionForces
/// (fe/elements/beam2.h): S (12 x 12) maps the element DOF to (N, Vy, Vz, T,
/// My, Mz) [N, N m] at end A (rows 0-5) and end B (rows 6-11), element
/// frame `axes` (x = e from node 1 to node 2, y perpendicular to x: the
/// basic axis least aligned with x, made orthogonal; z = x cross y). N = E
/// A / L e.(u2 - u1) (tension > 0) and T = G J / L e.(theta2 - theta1) at
/// both ends; Vy, Vz, My, Mz are zero. Throws InputError as Rod2Matrices.
void Rod2SectionForces(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes);

/// Geometric stiffness of a 2-node rod under the axial force N [N] (> 0
/// tension): the string stiffness N / L (I - e e^T) on the translations
/// (12 x 12 as K, rotations zero). Throws InputError as Rod2Matrices.
void Rod2GeometricStiffness(const ElementInput& in, double N, MatX& KG);

/// Stresses of a rod from its section forces (N, T) [N, N m]: the axial
/// stress sigma = N / A [Pa] and, as Nastran's CROD/CONROD stress output,
/// the torsional shear stress tau = C T / J [Pa], C the stress recovery
/// distance (the section's first stress point's distance from the axis;
/// the readers store Nastran's C as the point (C, 0)); tau = 0 if C or J is
/// zero. Throws InputError naming the section if A <= 0.
Eigen::Vector2d RodStresses(const BeamSection& section, double N, double T);

}  // namespace flexmb::fe
