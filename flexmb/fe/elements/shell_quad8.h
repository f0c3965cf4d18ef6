#pragma once
/// \file shell_quad8.h
/// 8-node quadrilateral shell (Nastran CQUAD8, Abaqus/CalculiX S8 and S8R,
/// gmsh type 16, VTK_QUADRATIC_QUAD), 6 DOF per node. Node order as Abaqus
/// and Nastran: corners 1-4, then the mid-edge nodes 5 (edge 1-2), 6
/// (2-3), 7 (3-4), 8 (4-1). The element is four 4-node shells (MITC4,
/// shell_quad4.h) around an internal node at its centre (placed by the
/// serendipity shape functions there, -1/4 at each corner and 1/2 at each
/// mid-edge node) that is condensed statically: shell_macro.h. A
/// second-order mesh thus behaves as a 4-node mesh of twice the density;
/// it converges to the same shell theory as Abaqus's and Nastran's
/// quadratic elements, with a different discretization error
/// (docs/design.md, "FE: second-order shells").

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the 8-node shell (its row: fe/element_traits.cc).
inline constexpr ElementType kQuad8{12};

/// Fills K [N/m, N, N m] and M [kg, kg m, kg m^2] (48 x 48, basic frame,
/// node by node ux uy uz rx ry rz) of an 8-node shell with the mass form of
/// `in`. Throws InputError naming the element for what the 4-node shell
/// refuses in one of its quarters (zero area, non-convex, badly warped).
void ShellQuad8Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Surface stresses (6 x 48: sxx syy sxy at the bottom, then the top, in
/// `axes`, e1 along the edge 1-2): the quarters' stresses, area-weighted.
void ShellQuad8Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes);

/// Geometric stiffness (48 x 48) under the element displacements u: the
/// quarters'.
void ShellQuad8GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
