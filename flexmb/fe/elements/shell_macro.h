#pragma once
/// \file shell_macro.h
/// Second-order shells (8-node quadrilateral, 6-node triangle) as macro
/// elements of the 4- and 3-node shells: the element is cut along the lines
/// through its mid-edge nodes into flat sub-elements (four MITC4 quads
/// around a centre point, or four MITC3 triangles), whose matrices are
/// summed. A point that is not a node of the element (the quad's centre,
/// placed where the element's shape functions put it) is an internal node
/// condensed statically: T = [I; -Kcc^-1 Kcn] maps the element's DOF to all
/// points', K = T^T K_sub T and M = T^T M_sub T (Guyan). The sub-elements'
/// patch tests carry over (a free interior node), rigid motions are kept
/// exactly, the edges stay compatible with neighbouring second-order
/// elements (each edge is two straight segments through its mid node), and
/// no zero-energy mode is added. Details and why: docs/design.md, "FE:
/// second-order shells".

#include <vector>

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe::shell {

/// How a second-order shell is cut.
struct MacroLayout {
  int nodes = 0;  ///< the element's nodes
  /// Extra points (condensed internal nodes): their place as weights over
  /// the element's nodes' coordinates (the shape functions there); extra
  /// point k is point nodes + k of `subs`.
  std::vector<std::vector<double>> extra;
  /// The sub-elements' points (3 or 4 each, counter-clockwise as the
  /// element's, the first edge along the element's first edge where the
  /// element is a parallelogram).
  std::vector<std::vector<int>> subs;
  /// Corners of the element (for its frame: normal from the diagonals of a
  /// quadrilateral or the corner triangle, e1 along corner 1 to corner 2).
  int corners = 0;
};

/// Fills K and M (6 n x 6 n, n = layout.nodes, basic frame, node by node ux
/// uy uz rx ry rz) of the element of `in` cut as `layout`, with the mass
/// form of `in`. Throws InputError naming the element for what the 3- and
/// 4-node shells refuse in a sub-element (zero area, a non-convex or badly
/// warped quad, a missing section or material).
void MacroMatrices(const ElementInput& in, const MacroLayout& layout, MatX& K, MatX& M);

/// Surface stresses of the element: the sub-elements' bottom and top
/// stresses (ShellQuad4Stress, ShellTria3Stress) turned to the element's
/// axes and averaged with the sub-elements' areas as weights. S (6 x 6 n),
/// rows sxx syy sxy at the bottom, then at the top; `axes` the element's
/// (e1 along corner 1 to corner 2 in the element's plane, e3 its normal).
void MacroStress(const ElementInput& in, const MacroLayout& layout, MatX& S, Eigen::Matrix3d& axes);

/// Geometric stiffness of the element under its displacements u (6 n): the
/// sub-elements' under their part of u, summed as K.
void MacroGeometricStiffness(const ElementInput& in, const MacroLayout& layout, const Eigen::VectorXd& u,
                             MatX& KG);

}  // namespace flexmb::fe::shell
