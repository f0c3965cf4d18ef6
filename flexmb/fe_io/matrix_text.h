#pragma once
/// \file matrix_text.h
/// Small helpers shared by the matrix and DOF map readers and writers
/// (harwell_boeing, matrix_market, calculix_matrices, dof_map,
/// imported_matrices): whole-token number parsing that never accepts a
/// partial number, shortest exact printing of doubles, whole-file reading,
/// writing through a temporary file that is renamed into place, and the
/// finiteness and symmetry checks of a sparse matrix.

#include <string>
#include <string_view>
#include <vector>

#include "flexmb/fe/assembly.h"

namespace flexmb::io {

/// Parses the whole of `token` as a decimal floating-point number ("1.5",
/// "-2e-3", "+7"). Returns false on anything else, including a trailing
/// character ("1.5D+02") or an empty token. Accepts "nan" and "inf" (callers
/// check finiteness so they can name the entry).
bool ParseDoubleToken(std::string_view token, double& value);

/// Parses the whole of `token` as a decimal integer ("12", "+3", "-4").
bool ParseIntegerToken(std::string_view token, long long& value);

/// The token as it should appear in a message: at most 40 characters,
/// non-printable bytes shown as '?', quoted.
std::string QuoteToken(std::string_view token);

/// Shortest decimal form of x that reads back to the same double (std::to_chars).
std::string FormatExact(double x);

/// Splits `line` at runs of blanks and tabs (and a trailing '\r').
std::vector<std::string_view> SplitFields(std::string_view line);

/// Reads a whole file. Throws InputError naming the path if it cannot be
/// opened or read.
std::string ReadWholeFile(const std::string& path);

/// The lines of `text` without their '\n' (and '\r'); a last line without a
/// newline counts; an empty text has no lines.
std::vector<std::string_view> SplitLines(std::string_view text);

/// Writes `content` to `path` through a temporary file in the same
/// directory that is renamed over `path` when complete. Throws InputError
/// naming the path on failure (the temporary file is removed).
void WriteFileAtomically(const std::string& path, const std::string& content);

/// Largest |A(i,j) - A(j,i)| of a square sparse matrix, the position of
/// that pair and the largest |entry|.
struct Asymmetry {
  double worst = 0.0;    ///< max |A(i,j) - A(j,i)|
  int row = -1, col = -1;  ///< position of the worst pair (0-based), -1 if symmetric
  double max_abs = 0.0;  ///< max |A(i,j)|
};
Asymmetry MeasureAsymmetry(const fe::SparseMat& A);

/// Throws InputError(`message`) naming `path` and the first entry (column
/// by column; 1-based row and column) of A that is not finite.
void CheckFinite(const fe::SparseMat& A, const std::string& path, const std::string& message);

/// Throws InputError naming `path` and the worst pair if the square matrix
/// A is not symmetric within 1e-10 of its largest |entry|.
void CheckSymmetric(const fe::SparseMat& A, const std::string& path);

/// The symmetric matrix whose lower (`lower` true) or upper triangle,
/// diagonal included, is that of A; the other triangle of A is ignored.
/// Values are copied, not summed, so that even the sign of a zero is kept.
fe::SparseMat MirrorTriangle(const fe::SparseMat& A, bool lower);

}  // namespace flexmb::io
