#pragma once
/// \file element_traits.h
/// The FE element types described by one table: one row per type with its
/// node count, section family, the names and node orders it has in the file
/// formats (Nastran, Abaqus/CalculiX, gmsh, VTK, the body file) and its
/// kernels (element matrices, stress recovery, geometric stiffness). Readers,
/// writers and consumers look a type up here instead of switching over
/// ElementType, so a new element is its file pair under fe/elements/, its
/// test and one row in element_traits.cc (docs/design.md, "FE element traits
/// table").
///
/// Node orders: flexmb keeps an element's nodes in one order per type (that
/// of Abaqus/CalculiX). A format order `order` lists, for each flexmb node k,
/// the position order[k] of that node in the format's list (empty: the same
/// order).

#include <Eigen/Core>
#include <array>
#include <span>
#include <string_view>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Section family of an element type: the section list its property indexes
/// (Mesh::shell_sections, beam_sections, solid_sections) and its nodal DOF
/// (6 for shells and beams, 3 for solids).
enum class ElementFamily { kShell, kBeam, kSolid };

/// How an Abaqus element name relates to the flexmb type it is read as.
enum class AbaqusVariant {
  kSame,            ///< the same element
  kEulerBernoulli,  ///< a beam without shear flexibility (B33): sections get ky = kz = 0
  kOther,           ///< another formulation, read as this one with a warning (`note`)
  kMembrane,        ///< a membrane (M3D4, M3D3): this shell under a *MEMBRANE SECTION, no bending
};

/// An Abaqus/CalculiX element name read as a flexmb type.
struct AbaqusName {
  const char* name = "";                      ///< upper case ("C3D10")
  AbaqusVariant variant = AbaqusVariant::kSame;
  const char* note = nullptr;                 ///< kOther: the warning's text after "<name> elements are "
};

/// An Abaqus element face for element-based surfaces: its label ("S1") and
/// its nodes (1-based positions in the element, at most 8).
struct AbaqusFace {
  const char* label = "";
  int count = 0;
  std::array<int, 8> nodes{};
};

/// The description of one element type.
struct ElementTraits {
  ElementType type{};              ///< its id; rows are stored in id order
  const char* name = "";           ///< short name ("tet10"): the body file's enum member
  const char* description = "";    ///< for messages ("10-node tetrahedron")
  int nodes = 0;                   ///< node count
  int corners = 0;                 ///< corner nodes (the first ones; the 3-node beam: its ends)
  ElementFamily family = ElementFamily::kSolid;
  /// Nastran connectivity cards ("CBAR", "CBEAM"). A solid card is read as
  /// the row whose `nodes` grid points it gives.
  std::span<const char* const> nastran_cards = {};
  int nastran_card_grids = 0;      ///< solids: grid fields G1..Gn the card has (CHEXA: 20)
  std::span<const int> nastran_order = {};
  std::span<const AbaqusName> abaqus = {};   ///< names read as this type; the first is written
  std::span<const AbaqusFace> abaqus_faces = {};
  int gmsh_code = 0;               ///< gmsh element type (0: none)
  std::span<const int> gmsh_order = {};
  int vtk_code = 0;                ///< VTK cell type
  std::span<const int> vtk_order = {};
  int body_file_code = -1;         ///< code in the body file's element type enum
  /// Stiffness K and mass M (ElementMatrices checks inputs and sizes).
  void (*matrices)(const ElementInput& in, MatX& K, MatX& M) = nullptr;
  /// Stress recovery: S maps the element DOF to the values of its family's
  /// stress table (reduction/stress_modes.h); `axes` is the frame of the
  /// values (left as the caller set it, identity, for solids).
  void (*stress)(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) = nullptr;
  /// Solids: stress recovery at the corner nodes, S (6 per corner) x
  /// element DOF, corners in node order (the solid_node stress table);
  /// null for shells and beams.
  void (*corner_stress)(const ElementInput& in, MatX& S) = nullptr;
  /// Geometric stiffness KG under the element displacements `u`; beams
  /// also return their axial force [N] in *axial_force (if not null).
  void (*geometric_stiffness)(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG,
                              double* axial_force) = nullptr;

  /// Rods (fe/elements/rod2.h) and the shear panel (fe/elements/shear4.h):
  /// 6 DOF per node, but only the translations of its nodes are activated
  /// by it; a rod's torsion is assembled only where both nodes' rotations
  /// are all active, a panel's rotational terms never (fe/assembly.cc).
  bool translations_only = false;

  /// Nodal DOF: 6 for shells and beams, 3 for solids.
  int DofsPerNode() const { return family == ElementFamily::kSolid ? 3 : 6; }
};

/// Every row of the table, in id order.
std::span<const ElementTraits> AllElementTraits();

/// The row of `type`; throws InputError for an id without a row.
const ElementTraits& Traits(ElementType type);

/// Section family name for messages: "shell", "beam" or "solid".
const char* FamilyName(ElementFamily family);

/// Position in a format's node list of flexmb node k (see the file comment).
inline int FormatNode(std::span<const int> order, int k) { return order.empty() ? k : order[k]; }

}  // namespace flexmb::fe
