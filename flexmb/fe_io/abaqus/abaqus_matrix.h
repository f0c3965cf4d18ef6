#pragma once
/// \file abaqus_matrix.h
/// The matrices Abaqus writes for *MATRIX GENERATE with *MATRIX OUTPUT
/// (job_STIF1.mtx, job_MASS1.mtx), in two of its formats:
/// - FORMAT=COORDINATE: one "ROW COLUMN VALUE" line per stored entry, 1-based
///   global equation numbers (the nodes' DOF in node order);
/// - FORMAT=MATRIX INPUT (Abaqus's default, the format *MATRIX INPUT reads):
///   one "NODE, DOF, NODE, DOF, VALUE" line per stored entry, so the file
///   names the node and component of every row itself.
/// Fields are blank- or comma-separated, there is no header, lines starting
/// with "**" are comments. An off-diagonal entry whose transposed entry is
/// not given stands for both (one triangle, in any equation order); a value
/// of magnitude 1e30 or more is a penalty of a constrained DOF and an error.
/// The extension .mtx is shared with Matrix Market: a .mtx file without the
/// "%%MatrixMarket" banner is told by its first entry line (three or five
/// numbers). Described in docs/formats.md.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "flexmb/fe/assembly.h"

namespace flexmb::io {

/// True if `first_line` (the file's first line that is neither blank nor a
/// "**" comment) looks like an entry of Abaqus's coordinate format: three
/// fields, two positive integers and a number.
bool LooksLikeAbaqusCoordinateMatrix(std::string_view first_line);

/// True if the file at `path` is in Abaqus's coordinate format by its first
/// line that is neither blank nor a "**" comment (LooksLikeAbaqusCoordinateMatrix;
/// a Matrix Market banner is not); reads only up to that line. False for a
/// file that cannot be opened (the reader then names the problem).
bool IsAbaqusCoordinateMatrixFile(const std::string& path);

/// Reads an Abaqus coordinate-format matrix; its size is the largest index.
/// Throws InputError naming the file, line and entry for a malformed line,
/// an index < 1 or too large, a non-finite value, a position given twice
/// ((i, j) again, or (j, i) twice), or an empty file.
fe::SparseMat ReadAbaqusCoordinateMatrix(const std::string& path);

/// True if `first_line` looks like an entry of Abaqus's labelled format
/// (FORMAT=MATRIX INPUT): five fields, node label (a whole number or
/// INSTANCE.NUMBER), DOF, node label, DOF, and a number.
bool LooksLikeAbaqusLabelledMatrix(std::string_view first_line);

/// True if the file at `path` is in Abaqus's labelled format by its first
/// line that is neither blank nor a "**" comment; reads only up to it.
bool IsAbaqusLabelledMatrixFile(const std::string& path);

/// A stiffness and a mass matrix in Abaqus's labelled format, on the union
/// of the (node, DOF) pairs the two files name, sorted by node label, then
/// DOF: row r is node dofs[r].first, component dofs[r].second (1..6).
struct AbaqusLabelledMatrices {
  fe::SparseMat K, M;
  std::vector<std::pair<int, int>> dofs;
};

/// Reads the two labelled files. Throws InputError naming the file, line and
/// entry for a malformed line, a keyword line, a node label < 1 (an Abaqus
/// internal node: a Lagrange multiplier or a constraint's node), labels of
/// two part instances, a DOF outside 1..6 (warping, pressure, temperature),
/// a non-finite value or a penalty, a position given twice, or an empty
/// file. An instance-qualified label INSTANCE.N is node N.
AbaqusLabelledMatrices ReadAbaqusLabelledMatrices(const std::string& k_path, const std::string& m_path);

}  // namespace flexmb::io
