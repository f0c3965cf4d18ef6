#pragma once
/// \file element_input.h
/// Resolves one mesh element into the inputs of the element routines (node
/// coordinates, section, material), checked, for the reduction's per-element
/// passes (stress modes, geometric stiffness).

#include <vector>

#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::reduction {

/// The inputs of element e of mesh: its node coordinates [m, basic frame]
/// copied into x (in.x points into x, so x must outlive the result), its
/// shell or beam section and its material. Throws InputError naming the
/// element on a wrong node count, a missing node, section or material.
fe::ElementInput ResolveElementInput(const fe::Mesh& mesh, const fe::Element& e, std::vector<fe::Vec3>& x);

}  // namespace flexmb::reduction
