#pragma once
/// \file format_registry.h
/// The one table of FE file formats by extension: which reader reads a mesh
/// (Nastran, Abaqus/CalculiX, gmsh, VTK) and which reads a matrix
/// (Harwell-Boeing, Matrix Market, CalculiX .sti/.mas). Every place that
/// picks a reader by a file's extension asks here; a new format is its
/// reader pair and one row (fe_io/format_registry.cc).

#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::io {

/// Reads a mesh file; throws InputError naming file, line and entity.
using MeshReader = fe::Mesh (*)(const std::string& path);
/// Reads a sparse matrix file; `what` names the matrix in messages ("K"),
/// `n_dof` is the matrix size where the format does not store it (CalculiX;
/// <= 0 if unknown).
using MatrixReader = fe::SparseMat (*)(const std::string& path, const std::string& what, int n_dof);

/// One file format.
struct FeFileFormat {
  std::string name;                     ///< e.g. "Nastran"
  std::vector<std::string> extensions;  ///< lower case with the dot, e.g. ".bdf"
  MeshReader read_mesh = nullptr;       ///< null if the format holds no mesh
  MatrixReader read_matrix = nullptr;   ///< null if the format holds no matrix
};

/// Every format, in the order listed in messages.
const std::vector<FeFileFormat>& FeFileFormats();

/// The mesh format of `path` by its extension (case-insensitive), or nullptr.
const FeFileFormat* FindMeshFormat(const std::string& path);
/// The matrix format of `path` by its extension, or nullptr.
const FeFileFormat* FindMatrixFormat(const std::string& path);

/// The mesh formats for messages: ".bdf, .nas, ... (Nastran), .inp (Abaqus/CalculiX), ...".
std::string MeshFormatList();
/// The matrix formats for messages, in the same form.
std::string MatrixFormatList();

}  // namespace flexmb::io
