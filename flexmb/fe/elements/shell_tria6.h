#pragma once
/// \file shell_tria6.h
/// 6-node triangular shell (Nastran CTRIA6, Abaqus/CalculiX S6 and STRI65,
/// gmsh type 9, VTK_QUADRATIC_TRIANGLE), 6 DOF per node. Node order as
/// Abaqus and Nastran: corners 1-3, then the mid-edge nodes 4 (edge 1-2),
/// 5 (2-3), 6 (3-1). The element is the four 3-node shells (MITC3,
/// shell_tria3.h) its mid-edge nodes cut it into (shell_macro.h): a
/// second-order mesh behaves as a 3-node mesh of twice the density
/// (docs/design.md, "FE: second-order shells").

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the 6-node shell (its row: fe/element_traits.cc).
inline constexpr ElementType kTria6{13};

/// Fills K and M (36 x 36, basic frame, node by node ux uy uz rx ry rz) of
/// a 6-node shell with the mass form of `in`. Throws InputError naming the
/// element for what the 3-node shell refuses in one of its parts.
void ShellTria6Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Surface stresses (6 x 36, bottom then top, in `axes`, e1 along the edge
/// 1-2): the parts' stresses, area-weighted.
void ShellTria6Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes);

/// Geometric stiffness (36 x 36) under the element displacements u.
void ShellTria6GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG);

}  // namespace flexmb::fe
