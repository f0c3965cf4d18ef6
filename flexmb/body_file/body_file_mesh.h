#pragma once
/// \file body_file_mesh.h
/// Internal part of the body file (body_file.cc): the group /mesh, i.e. the
/// FE mesh with nodes, elements, materials, sections, point masses, rigid
/// links, constraints and node and element sets. Layout in docs/formats.md,
/// section "Flexible body file (.h5)". Not a public header.

#include <string>

#include "flexmb/fe/mesh.h"
#include "flexmb/body_file/hdf5_file.h"

namespace flexmb::io {

/// Whether the file has a code for element type `type` (else the body
/// cannot be written).
bool HasBodyFileTypeCode(fe::ElementType type);

/// Writes the group /mesh. The element types must have codes.
void WriteBodyMesh(hdf5::Writer& w, const fe::Mesh& mesh);

/// Reads the group /mesh of a body file with `nn` nodes and `ne` elements
/// (from /counts); entities get `origin` = (`path`, 0). Throws InputError
/// naming the dataset for a missing or malformed dataset, a duplicate or
/// non-positive node id, an index out of range, an unknown element type
/// code, a node count that does not fit the element type or a set given
/// twice.
fe::Mesh ReadBodyMesh(const hdf5::Reader& r, int nn, int ne, const std::string& path);

}  // namespace flexmb::io
