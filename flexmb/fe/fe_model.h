#pragma once
/// \file fe_model.h
/// A part's FE model as it comes from any supported source: a mesh with
/// elements (assembled by fe::Assemble), or matrices imported from another FE
/// package (Harwell-Boeing, Matrix Market, CalculiX matrix storage) with the
/// mesh holding only geometry (nodes, display cells, sets).

#include <optional>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

/// One part's FE model.
struct FeModel {
  Mesh mesh;                                ///< geometry, elements (if any), sets
  /// Set when K and M were imported: free == full numbering (T = identity),
  /// nothing constrained yet; dofs.full may cover fewer nodes than the mesh
  /// (nodes added by an FE model file). Empty when the mesh has elements to assemble.
  std::optional<AssembledModel> imported;
};

/// The assembled matrices of a model: fe::Assemble for a mesh with elements,
/// the imported matrices otherwise; in both cases with the listed node
/// indices fixed in all their DOF and the mesh's own single-point
/// constraints applied (options.apply_constraints). For imported matrices
/// options.mass_form has no effect and the constrained DOF are removed as
/// by FixNodes (component by component for a partial constraint); where the
/// mesh adds nodes, rigid links, point masses, springs or linear constraints
/// to them, they are assembled with them by AssembleImported (numbered node
/// by node). Throws InputError for a node index out of range.
AssembledModel BuildMatrices(const FeModel& model, const AssemblyOptions& options);

/// Removes the DOF of the given nodes (all components) from an assembled
/// model: rows and columns of K and M, columns of T, and the free numbering
/// (M_full, on the full numbering, is kept as it is). The remaining free
/// DOF keep their order, so the result equals assembling with the nodes in
/// AssemblyOptions::extra_fixed_nodes. DOF already constrained or inactive
/// are skipped. Throws InputError for an index out of range or a node with
/// a DOF that is dependent in a rigid link.
AssembledModel FixNodes(const AssembledModel& model, const std::vector<int>& node_indices);

}  // namespace flexmb::fe
