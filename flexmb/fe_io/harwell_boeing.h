#pragma once
/// \file harwell_boeing.h
/// Harwell-Boeing and Rutherford-Boeing sparse matrices (compressed column
/// storage, "CCS"), read and written with SuiteSparse's RBio. Assembled real
/// matrices: RSA (symmetric, lower triangle stored), RUA (unsymmetric), and
/// the pattern (PSA, PUA) and integer (ISA, IUA) types RBio writes when all
/// values are 1 or integers. Both headers are read: classic Harwell-Boeing
/// (line 2 with five card counts, an optional right-hand-side line 5) and
/// Rutherford-Boeing (four card counts). The format is described in
/// docs/formats.md.

#include <string>

#include "flexmb/fe/assembly.h"

namespace flexmb::io {

/// A matrix read from a Harwell-Boeing file.
struct HarwellBoeingMatrix {
  fe::SparseMat A;           ///< full storage: a symmetric file's triangle is mirrored
  std::string type;          ///< the file's type, upper case ("RSA", "RUA", "PSA", ...)
  std::string title;         ///< title (first 72 columns of line 1, trimmed)
  std::string key;           ///< key (columns 73-80 of line 1, trimmed)
  bool symmetric = false;    ///< the file stored one triangle (?SA)
  bool pattern = false;      ///< pattern file (P??): no values, every entry is 1
};

/// Reads an assembled, square, real, integer or pattern matrix. Before RBio
/// reads the file, every token is checked the way RBio will read it, so that
/// a value RBio would misread is an error rather than a wrong number:
/// blank-separated tokens only (no packed fixed-width fields, no Fortran
/// "D" exponents), lines of at most 4094 characters. Throws InputError
/// naming the file, the line and the entry (its row and column) for an
/// unsupported type (complex, rectangular, elemental, Hermitian, skew), a
/// malformed header or token, a truncated file, a column pointer or row
/// index out of range, duplicate or unsorted row indices, an entry above
/// the diagonal of a symmetric file, or a value that is not finite.
HarwellBoeingMatrix ReadHarwellBoeing(const std::string& path);

/// Options of WriteHarwellBoeing.
struct HarwellBoeingWriteOptions {
  std::string title = "flexmb matrix";  ///< at most 71 characters are kept
  std::string key = "flexmb";           ///< at most 8 characters are kept
  /// Write one triangle (RSA): the lower triangle of A is written (A must be
  /// symmetric to 1e-10 of its largest entry); false writes A whole (RUA).
  bool symmetric = true;
};

/// Writes a square matrix with RBio (Rutherford-Boeing header), through a
/// temporary file that is renamed to `path`. RBio prints every value with
/// the fewest digits (up to 17 significant, or 19 for huge or tiny ones)
/// that read back to the same double, so writing and reading back is bit
/// for bit; it picks the type from the values: RSA/RUA, or ISA/IUA when all
/// are integers, PSA/PUA when all are 1. The integer format has no negative
/// zero: a -0.0 in an integer-valued matrix reads back as +0.0. Throws InputError naming the path
/// for a non-square or empty matrix, a non-finite value, an asymmetric
/// matrix with `symmetric` set, or an I/O failure.
void WriteHarwellBoeing(const fe::SparseMat& A, const std::string& path,
                        const HarwellBoeingWriteOptions& options = {});

}  // namespace flexmb::io
