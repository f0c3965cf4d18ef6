#pragma once
/// \file mesh_checks.h
/// Checks of an FE model after reading that the readers cannot make card by
/// card: the connected parts of the model (a part that nothing joins to the
/// rest adds rigid-body modes) and the nodes that nothing uses. Inverted or
/// collapsed elements are errors of the element routines (at assembly).

#include <string>
#include <vector>

#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

/// One connected part: nodes joined by elements, springs, rigid links and
/// linear constraints (a node with only a point mass is a part of its own).
struct MeshPart {
  int elements = 0;             ///< elements in the part
  int nodes = 0;                ///< nodes in the part
  int first_element = -1;       ///< index of its first element, -1 if none
  int first_node = -1;          ///< index of its first node
  bool supported = false;       ///< a node of it has a single-point constraint
};

/// What CheckMesh found.
struct MeshCheck {
  std::vector<MeshPart> parts;    ///< largest first (by elements, then nodes)
  std::vector<int> unused_nodes;  ///< node indices nothing refers to (no DOF, no mass)
};

/// The connected parts and unused nodes of `mesh` (empty for a mesh
/// without elements: imported matrices carry their own connectivity).
MeshCheck CheckMesh(const Mesh& mesh);

/// The warnings for `check` (none for one part and no unused node): the
/// parts with their sizes, each named by its first element (id, file and
/// line) or node, and how many rigid-body modes the unsupported ones add;
/// the count and the first ids of the unused nodes. `file` names the model.
std::vector<std::string> MeshCheckWarnings(const Mesh& mesh, const MeshCheck& check, const std::string& file);

}  // namespace flexmb::fe
