#pragma once
/// \file gmsh_reader.h
/// gmsh .msh files, formats 4.1 and 2.2 (ASCII): nodes, elements of the
/// supported families, physical groups as named node and element sets.
/// A gmsh mesh carries no materials or sections: those come from an FE
/// model file (flexmb/fe_io/fe_model_file.h) that assigns them to groups.

#include <string>

#include "flexmb/fe/mesh.h"

namespace flexmb::io {

/// Reads a .msh file. Elements get property -1 (unassigned). Physical
/// groups become node sets (all nodes of the group's elements) and element
/// sets, named by the physical name or "group<tag>". Throws InputError
/// naming the file, line and entity on malformed input. The details
/// (element types, 10-node tetrahedron node order, boundary elements of
/// unsupported types, 2.2 element copies) are in docs/formats.md.
fe::Mesh ReadGmsh(const std::string& path);

}  // namespace flexmb::io
