#pragma once
/// \file element_common.h
/// Checks and small helpers shared by all element routines (shells, beams,
/// solids): the error context naming an element, the node and material
/// checks every routine starts with, and the cross-product matrix.

#include <Eigen/Core>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Context naming an element in the errors of the element routines:
/// "<type name> <id>" (e.g. "4-node shell 17") at the element's file:line.
ErrorContext ElementContext(const Element& element);

/// Checks that `in` carries an element with `n_nodes` nodes and their
/// (finite) coordinates; returns the element. Throws InputError naming the
/// element otherwise ("<family> element input without an element" if there
/// is none at all).
const Element& CheckElementNodes(const ElementInput& in, int n_nodes, const char* family);

/// Checks Young's modulus E > 0 (finite) and Poisson's ratio nu in
/// (-1, 0.5) of an isotropic material; throws InputError with `ctx`.
void CheckElasticConstants(const Material& material, const ErrorContext& ctx);

/// Cross-product matrix: Skew(v) w = v x w.
Eigen::Matrix3d Skew(const Vec3& v);

}  // namespace flexmb::fe
