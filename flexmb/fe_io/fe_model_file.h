#pragma once
/// \file fe_model_file.h
/// Loading a part's FE model from whatever the user has: a mesh file with
/// elements and properties (Nastran .bdf/.nas/.dat/.blk, Abaqus/CalculiX
/// .inp), a mesh without properties plus an FE model file (.yaml) that
/// assigns materials and sections to its groups (gmsh .msh, VTK), an
/// exchange-set directory, or imported matrices described in an FE model
/// file. The FE model file format is documented in docs/model-file.md.

#include <string>

#include "flexmb/fe/fe_model.h"

namespace flexmb::io {

/// Loads an FE model, choosing the reader by the file's extension (or a
/// directory as an exchange set). Throws InputError naming the file, line
/// and entity.
fe::FeModel LoadFeModel(const std::string& path);

/// Node indices named on the command line: a comma-separated list of node
/// ids ("12,13,40") or the name of a node set (a set of that exact name wins
/// over reading it as ids). Ids are returned in the given order without
/// repeats. Throws InputError naming the mesh file (mesh.source) and the id
/// or set that does not exist, an empty set or a malformed list.
std::vector<int> ResolveNodeList(const fe::Mesh& mesh, const std::string& ids_or_set);

}  // namespace flexmb::io
