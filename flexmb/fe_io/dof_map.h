#pragma once
/// \file dof_map.h
/// flexmb's DOF map file (dof_map.txt, documented in docs/formats.md): the
/// node id and component of every row of imported or exported matrices.
/// One line per matrix row, "ROW NODE COMPONENT" (row 1-based, component
/// 1..6 = ux uy uz rx ry rz), '#' starts a comment line, blank lines are
/// ignored, the rows may come in any order but each of 1..n exactly once.

#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::io {

/// What one matrix row is: a component of a node's displacement.
struct DofMapRow {
  int node_id = 0;    ///< node id of the geometry (> 0)
  int component = 0;  ///< 1..6 = ux uy uz rx ry rz
  int line = 0;       ///< line of the map file that gave it (for messages)
};

/// The rows of a DOF map file: rows[r] describes matrix row r (0-based).
struct MatrixRowMap {
  std::string file;              ///< file it was read from
  std::vector<DofMapRow> rows;
};

/// Reads a DOF map file. Throws InputError naming the file and line for a
/// malformed line, a row outside 1..n or given twice, a node id <= 0 or a
/// component outside 1..6 (n = number of data lines).
MatrixRowMap ReadDofMap(const std::string& path);

/// Writes a DOF map file (rows in order, through a temporary file that is
/// renamed). `rows[r]` describes row r+1.
void WriteDofMap(const std::vector<DofMapRow>& rows, const std::string& path);

/// The DOF map of an assembled model's free numbering: row f describes free
/// DOF f (node id from mesh, component from the slot). Throws InputError if
/// a free DOF has no node slot or two (not a plain free numbering).
std::vector<DofMapRow> FreeDofRows(const fe::Mesh& mesh, const fe::DofMap& dofs);

}  // namespace flexmb::io
