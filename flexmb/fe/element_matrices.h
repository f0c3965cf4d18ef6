#pragma once
/// \file element_matrices.h
/// The contract between element formulations and the assembler. Each element
/// type lives in its own pair under fe/elements/ and provides one function
/// that fills the element stiffness and mass matrices in the basic frame,
/// ordered node by node with the element's nodal DOF (6 for shells and
/// beams: ux uy uz rx ry rz; 3 for solids: ux uy uz).

#include <Eigen/Core>

#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

using MatX = Eigen::MatrixXd;

/// Mass matrix form.
enum class MassForm { kConsistent, kLumped };

/// Inputs of an element computation, resolved by the assembler.
struct ElementInput {
  const Element* element = nullptr;
  const Vec3* x = nullptr;                 ///< node coordinates, element order
  const Material* material = nullptr;
  const ShellSection* shell = nullptr;     ///< for shells
  const BeamSection* beam = nullptr;       ///< for beams
  MassForm mass_form = MassForm::kConsistent;
};

/// Fills K and M (resized to n x n, n = NodeCount * DofsPerNode) for one
/// element. Throws InputError naming the element (id, file, line) on a
/// degenerate geometry (zero area or volume, inverted element, zero length,
/// orientation vector parallel to the axis) or bad section data.
void ElementMatrices(const ElementInput& in, MatX& K, MatX& M);

}  // namespace flexmb::fe
