#pragma once
/// \file vtk_mesh.h
/// Legacy VTK unstructured grids (ASCII, "# vtk DataFile Version 2.0" to
/// 5.1): read geometry (points, cells of the supported families) and write a
/// mesh back. The point ids of the FE model travel as POINT_DATA field
/// "node_id" and cell ids as CELL_DATA "element_id", so a round trip keeps
/// them.

#include <string>

#include "flexmb/fe/mesh.h"

namespace flexmb::io {

/// Reads a legacy VTK unstructured grid. Without a "node_id" array nodes are
/// numbered 1..n in file order; without an "element_id" array an element's
/// id is its cell number + 1. Vertex cells are skipped; elements get
/// property -1 (unassigned). Throws InputError naming file, line and the
/// point or cell. The format details are in docs/formats.md.
fe::Mesh ReadVtk(const std::string& path);

/// Writes the mesh's nodes and elements (ASCII legacy format, full double
/// precision so that reading back is bit for bit).
void WriteVtk(const fe::Mesh& mesh, const std::string& path);

}  // namespace flexmb::io
