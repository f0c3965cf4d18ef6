#pragma once
/// \file beam2.h
/// 2-node 3D Timoshenko beam with a general section (CBAR / CBEAM / B31
/// like). Element frame (Nastran CBAR convention): x from end A to end B,
/// y in the plane of x and the orientation vector v (Element::orientation),
/// z = x cross y. The ends may be offset from their nodes (Element::offset_a,
/// offset_b, basic frame); the offsets are rigid links, u_end = u_node +
/// theta_node x offset. The stiffness is exact for a prismatic Timoshenko
/// beam without span loads: it is the inverse of the cantilever flexibility
/// of the section compliance (axial EA, shear ky G A and kz G A, torsion G J,
/// bending E [Iy -Iyz; -Iyz Iz] coupled through Iyz), integrated in closed
/// form; with Iyz = 0 it equals the classical matrix with the shear
/// parameter phi = 12 E I / (k G A L^2). ky = kz = 0 gives Euler-Bernoulli
/// bending. The consistent mass uses the same exact static displacement
/// fields as interpolation (cubic Hermite for Euler-Bernoulli, the
/// phi-dependent functions otherwise) with translational inertia
/// (rho A + nsm) and the section's rotary inertia rho [Iy + Iz, Iy, Iz, Iyz].
/// Details: docs/design.md, "FE: beam element".

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Fills K [N/m, N, N m] and M [kg, kg m, kg m^2] (12 x 12, basic frame,
/// node by node ux uy uz rx ry rz) of a 2-node beam. MassForm::kLumped puts
/// half the mass (rho A + nsm) L on each node's translations and half the
/// section's rotary inertia rho L [Iy + Iz, Iy, Iz] on its rotations
/// (element axes, the product Iyz dropped), transformed to the basic frame
/// at the element's ends. Throws InputError naming the element (type, id,
/// file:line) for zero length, an orientation vector zero or parallel to the
/// axis, non-positive A, Iy, Iz or J, Iy Iz <= Iyz^2, negative shear factors,
/// a missing section or material, or bad material constants.
void Beam2Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Section forces of a 2-node beam at its two ends: fills S (12 x 12) with
/// the map from the element's nodal DOF (basic frame, node by node ux uy uz
/// rx ry rz, as K) to (N, Vy, Vz, T, My, Mz) [N, N m] at end A (rows 0-5)
/// and end B (rows 6-11), in the element frame, and `axes` with its axes as
/// columns (basic from element; x from end A to end B, y from the
/// orientation vector). They are the resultants of the stresses on a cut
/// face with outward normal +x (the force and moment, about the section's
/// centre, that the part of the beam beyond the cut exerts on the part
/// before it): N > 0 in tension, T the moment about x, My and Mz about y and
/// z. They come from the end wrenches K_local u_local (moments about the
/// ends): the section forces at B are B's wrench, at A minus A's wrench,
/// exact for the element's Timoshenko stiffness without span loads (the
/// forces vary linearly in between). Throws InputError as Beam2Matrices.
void Beam2SectionForces(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes);

/// Geometric (initial-stress) stiffness of a 2-node beam under a constant
/// axial force N [N] (> 0 tension): fills KG (12 x 12, basic frame, node by
/// node ux uy uz rx ry rz, as K) [N/m, N, N m]. It is the second variation of
/// N/2 int (v'^2 + w'^2) dx + N (Iy + Iz) / (2 A) int phi'^2 dx with the cubic
/// Hermite (Euler-Bernoulli) bending fields in both planes (v' = rz, w' = -ry
/// in the element frame) and the linear twist phi (Przemieniecki's matrix);
/// the shear flexibility and Iyz are not taken into account. The end offsets
/// act as for K (rigid links). K - P KG(1) is singular at the buckling load
/// P of the element chain. Throws InputError as Beam2Matrices.
void Beam2GeometricStiffness(const ElementInput& in, double N, MatX& KG);

/// Geometric stiffness of a 2-node beam prestressed by its element
/// displacements u (12): Beam2GeometricStiffness under the mean of the
/// axial forces at its ends (Beam2SectionForces); *axial_force (if not
/// null) is that force [N]. Throws InputError as Beam2Matrices.
void Beam2GeometricStiffnessUnder(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG, double* axial_force);

}  // namespace flexmb::fe
