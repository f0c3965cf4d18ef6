#pragma once
/// \file abaqus_matrix.h
/// The matrices Abaqus writes for *MATRIX GENERATE with *MATRIX OUTPUT,
/// FORMAT=COORDINATE (job_STIF1.mtx, job_MASS1.mtx): one "ROW COLUMN VALUE"
/// line per stored entry, blank- or comma-separated, 1-based global
/// equation numbers (the nodes' DOF in node order), no header; lines
/// starting with "**" are comments. Both triangles are usually written; a
/// file with one triangle only is mirrored. The extension .mtx is shared
/// with Matrix Market: a .mtx file without the "%%MatrixMarket" banner whose
/// first entry line has three numbers is read as this format. Described in
/// docs/formats.md.

#include <string>
#include <string_view>

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

}  // namespace flexmb::io
