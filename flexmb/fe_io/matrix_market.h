#pragma once
/// \file matrix_market.h
/// Matrix Market exchange format, coordinate matrices: the banner
/// "%%MatrixMarket matrix coordinate FIELD SYMMETRY" (read case-insensitively)
/// with FIELD real, double or integer and SYMMETRY general or symmetric,
/// '%' comment lines, a size line "ROWS COLS ENTRIES", then one "I J VALUE"
/// line per entry with 1-based indices. Described in docs/formats.md.

#include <string>

#include "flexmb/fe/assembly.h"

namespace flexmb::io {

/// A matrix read from a Matrix Market file.
struct MatrixMarketMatrix {
  fe::SparseMat A;          ///< full storage: a symmetric file's triangle is mirrored
  bool symmetric = false;   ///< the banner said "symmetric"
  int duplicates = 0;       ///< entries that repeated an earlier (row, column) and were summed into it
};

/// Reads a coordinate Matrix Market file. Entries given more than once are
/// summed (the count is returned in `duplicates`). A symmetric file must
/// give each off-diagonal entry once, all in the lower triangle (as the
/// format says) or all in the upper one; it is mirrored. Throws InputError
/// naming the file, the line and the entry for a missing or wrong banner,
/// an unsupported kind (array, pattern, complex, skew-symmetric, Hermitian),
/// a malformed size or entry line, an index out of range, a value that is
/// not finite, entries in both triangles of a symmetric file, or fewer or
/// more entries than the size line says.
MatrixMarketMatrix ReadMatrixMarket(const std::string& path);

/// Options of WriteMatrixMarket.
struct MatrixMarketWriteOptions {
  /// Write the lower triangle with a "symmetric" banner (A must be symmetric
  /// to 1e-10 of its largest entry); false writes every entry ("general").
  bool symmetric = true;
  std::string comment = "written by flexmb";  ///< one '%' comment line (empty: none)
};

/// Writes A in coordinate format ("real"), entries column by column, each
/// value in the shortest form that reads back to the same double, so that
/// writing and reading back is bit for bit. Written through a temporary
/// file that is renamed. Throws InputError naming the path for a
/// non-finite value or an asymmetric matrix with `symmetric` set.
void WriteMatrixMarket(const fe::SparseMat& A, const std::string& path, const MatrixMarketWriteOptions& options = {});

}  // namespace flexmb::io
