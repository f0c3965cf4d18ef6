#pragma once
/// \file shear4.h
/// 4-node shear panel (Nastran CSHEAR with PSHEAR): a flat quadrilateral
/// sheet that carries one uniform stress state, the in-plane shear along
/// its edges, and nothing else (no normal stress, no bending). Its stress
/// is sigma = tau S with S = d_a d_b^T + d_b d_a^T, d_a and d_b the unit
/// directions of its two edge pairs (1-2 with 4-3, 1-4 with 2-3, each the
/// mean of its pair), so that the normal traction on every edge of a
/// parallelogram vanishes; tau is work-conjugate to g = S : eps_avg, the
/// exact mean strain of the panel from its corner displacements (the
/// boundary integral of sym(u n) with u linear along the edges), and the
/// energy is t A g^2 / (2 c) with the compliance c = S : C^-1 : S of the
/// plane-stress material. For a rectangle this is G t A gamma^2 / 2: the
/// constant-shear-flow panel, exact for any parallelogram; for other
/// shapes an approximation (the reader warns, docs/formats.md). The panel
/// is a Section of the shell family (thickness, material, nsm) with 6 DOF
/// per node, but it activates only its nodes' translations (as rods do).
/// Mass: the translations' (rho t + nsm) times each corner's area share
/// int N_i dA, for both mass forms (Nastran lumps a shear panel's mass).
/// Details: docs/design.md, "FE: shear panel".

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the shear panel (its row: fe/element_traits.cc).
inline constexpr ElementType kShear4{14};

/// Fills K [N/m] and M [kg] (24 x 24, basic frame, node by node ux uy uz rx
/// ry rz; the rotational rows zero). Throws InputError naming the element
/// for a bad geometry (as the 4-node shell), non-positive thickness or
/// modulus, or a missing section or material.
void Shear4Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Stress recovery: S (6 x 24) maps the element DOF to (sxx, syy, sxy) [Pa]
/// of the panel's uniform stress in its local frame, the same at the bottom
/// (rows 0-2) and top (rows 3-5) surfaces; `axes` the local frame (as the
/// 4-node shell's).
void Shear4Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes);

/// Geometric stiffness under the element displacements `u` (24, basic):
/// t int grad(N)^T sigma grad(N) dA on each translation, with the panel's
/// stress sigma (2 x 2 Gauss on the bilinear geometry).
void Shear4GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
