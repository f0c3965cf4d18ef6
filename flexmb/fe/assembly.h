#pragma once
/// \file assembly.h
/// Global DOF numbering and sparse assembly of the stiffness and mass
/// matrices of a Mesh, with rigid links and linear constraints (RBE3)
/// eliminated and single-point constraints removed.

#include <Eigen/SparseCore>
#include <vector>

#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

using SparseMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Global numbering: every node has 6 DOF slots (ux uy uz rx ry rz). A slot
/// is active if some element, mass, spring or link gives it stiffness or mass
/// (rotations of nodes used only by solids are inactive). Active slots that
/// are neither constrained nor dependent (rigid links) are the free DOF.
struct DofMap {
  std::vector<std::array<int, 6>> full;  ///< node, component -> full-system index or -1
  std::vector<std::array<int, 6>> free;  ///< node, component -> free DOF index or -1
  int n_full = 0;                        ///< active DOF before links and constraints
  int n_free = 0;                        ///< free DOF
  std::vector<int> node_ids;             ///< node -> the user's node id (for messages)
};

/// The assembled model. K and M are symmetric, free DOF only (upper and
/// lower parts stored). T maps free DOF to the full system, u_full = T u_free
/// (it carries the rigid-link elimination).
struct AssembledModel {
  DofMap dofs;
  SparseMat K, M;   ///< free x free
  SparseMat T;      ///< full x free
  /// Mass matrix of all active DOF before rigid-link elimination and
  /// constraints (n_full x n_full, numbered by DofMap::full, upper and lower
  /// parts stored), so that M = T^T M_full T restricted to the free DOF. It
  /// keeps the element and point mass carried by dependent (rigid-link) and
  /// constrained nodes node by node, which the inertia invariants need (T^T
  /// M_full T is exact for the kinetic energy but mixes nodes). Imported
  /// matrices: M_full = M as imported (full = free numbering), or, with what
  /// an FE model file adds to them (AssembleImported), M and the point
  /// masses on the node-by-node full numbering.
  SparseMat M_full;
};

/// Options of the assembly.
struct AssemblyOptions {
  MassForm mass_form = MassForm::kConsistent;
  bool apply_constraints = true;   ///< remove the mesh's single-point constraints
  std::vector<int> extra_fixed_nodes;  ///< node indices fixed in all 6 DOF (e.g. --fix)
  /// Node indices whose DOF must stay independent although a linear
  /// constraint (RBE3) makes them dependent: the constraint is rewritten
  /// with other DOF dependent (fe::MakeNodesIndependent), e.g. for an RBE3
  /// reference node that is an interface node of a reduction.
  std::vector<int> independent_nodes;
  /// Assemble only some blocks (for a distributed assembly: each process
  /// its share). Blocks are the elements, then the point masses, then the
  /// scalar springs, in mesh order; block b is added where block_subset[b]
  /// != 0. Empty: all. The DOF map and T are those of the whole model, so
  /// the matrices of a partition of the blocks sum to the whole model's
  /// (K, M and M_full alike). Its size must then be the number of blocks.
  std::vector<char> block_subset;
};

/// Numbers the DOF, computes every element's matrices and assembles K and M
/// (with the point masses and the scalar springs),
/// then eliminates rigid links (K_free = T^T K T) and constraints. Throws
/// InputError naming the element or link at fault.
AssembledModel Assemble(const Mesh& mesh, const AssemblyOptions& options = {});

/// Assembles a model whose stiffness and mass come from another FE package:
/// `matrices` holds K and M (upper and lower parts) on the rows that
/// matrices.dofs.full names node by node (node indices of `mesh`, which may
/// have more nodes than the DOF map, e.g. a reference node added for a rigid
/// link). The mesh's elements are display cells and are not assembled; its
/// point masses, scalar springs, rigid links, linear constraints and
/// single-point constraints, and the options (except block_subset and
/// mass_form), act as in Assemble: K_free = T^T (K_imported + K_extra) T,
/// numbered node by node. M_full holds the imported M on the full numbering
/// plus the point masses. Throws InputError as Assemble does.
AssembledModel AssembleImported(const Mesh& mesh, const AssembledModel& matrices, const AssemblyOptions& options = {});

/// True for an element that acts on its nodes' translations only: a rod
/// (ElementTraits::translations_only) or a shell of a membrane section
/// (ShellLaminate::membrane_only). Its nodes get rotational DOF only from
/// other elements.
bool ActsOnTranslationsOnly(const Mesh& mesh, const Element& e);

/// Total mass [kg], centre of mass [m] and inertia about it [kg m^2] from
/// the assembled (unconstrained) mass matrix and the node positions, via the
/// six rigid-body modes: exact for consistent and lumped mass alike.
struct MassProperties {
  double mass = 0.0;
  Vec3 center = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
};
MassProperties ComputeMassProperties(const Mesh& mesh, const AssembledModel& model);

/// R^T M R for the six rigid-body motions R of the free DOF about x0 (the
/// mean of the node positions, returned): translations first, rotations
/// about x0. For a constrained model it is the rigid-body mass of what the
/// free DOF carry (the constrained DOF's mass left out).
Eigen::Matrix<double, 6, 6> RigidBodyMass(const Mesh& mesh, const AssembledModel& model, Vec3& x0);

}  // namespace flexmb::fe
