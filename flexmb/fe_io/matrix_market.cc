#include "flexmb/fe_io/matrix_market.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/text.h"
#include "flexmb/fe_io/matrix_text.h"

namespace flexmb::io {

namespace {

bool IsBlankOrComment(std::string_view line) {
  const size_t p = line.find_first_not_of(" \t\r");
  return p == std::string_view::npos || line[p] == '%';
}

const char* const kBanner = "%%MatrixMarket matrix coordinate real general";

// column pointers are allocated for every column, so the size is bounded
constexpr long long kMaxDimension = 50000000;

}  // namespace

MatrixMarketMatrix ReadMatrixMarket(const std::string& path) {
  const std::string text = ReadWholeFile(path);
  const std::vector<std::string_view> lines = SplitLines(text);
  MatrixMarketMatrix out;

  // banner
  if (lines.empty()) throw InputError(std::string("empty file, expected the banner '") + kBanner + "'", {path, 1, "banner"});
  const std::vector<std::string_view> banner = SplitFields(lines[0]);
  if (banner.empty() || AsciiLower(banner[0]) != "%%matrixmarket") {
    throw InputError(std::string("not a Matrix Market file: the first line must be a banner like '") + kBanner +
                         "' (a .mtx file of Abaqus's *MATRIX OUTPUT, FORMAT=COORDINATE has 'ROW COLUMN VALUE' lines; "
                         "its FORMAT=MATRIX INPUT, 'node, dof, node, dof, value', is not read)",
                     {path, 1, "banner"});
  }
  if (banner.size() != 5) {
    throw InputError("the banner needs 4 words after %%MatrixMarket (object format field symmetry), found " +
                         std::to_string(banner.size() - 1),
                     {path, 1, "banner"});
  }
  const std::string object = AsciiLower(banner[1]), format = AsciiLower(banner[2]), field = AsciiLower(banner[3]),
                    symmetry = AsciiLower(banner[4]);
  if (object != "matrix") throw InputError("object " + QuoteToken(banner[1]) + " is not supported, expected 'matrix'", {path, 1, "banner"});
  if (format == "array") {
    throw InputError("array (dense) format is not supported, expected 'coordinate'", {path, 1, "banner"});
  }
  if (format != "coordinate") throw InputError("format " + QuoteToken(banner[2]) + " is unknown, expected 'coordinate'", {path, 1, "banner"});
  if (field == "pattern") {
    throw InputError("pattern matrices have no values; a 'real' or 'integer' matrix is needed", {path, 1, "banner"});
  }
  if (field == "complex") throw InputError("complex matrices are not supported, expected 'real' or 'integer'", {path, 1, "banner"});
  if (field != "real" && field != "double" && field != "integer") {
    throw InputError("field " + QuoteToken(banner[3]) + " is unknown, expected 'real' or 'integer'", {path, 1, "banner"});
  }
  if (symmetry == "skew-symmetric" || symmetry == "hermitian") {
    throw InputError("symmetry " + QuoteToken(banner[4]) + " is not supported, expected 'general' or 'symmetric'",
                     {path, 1, "banner"});
  }
  if (symmetry != "general" && symmetry != "symmetric") {
    throw InputError("symmetry " + QuoteToken(banner[4]) + " is unknown, expected 'general' or 'symmetric'",
                     {path, 1, "banner"});
  }
  out.symmetric = symmetry == "symmetric";
  const bool integer = field == "integer";

  // size line
  size_t l = 1;
  while (l < lines.size() && IsBlankOrComment(lines[l])) ++l;
  if (l >= lines.size()) throw InputError("file ends before the size line 'ROWS COLS ENTRIES'", {path, static_cast<int>(lines.size()), "size line"});
  const int size_line = static_cast<int>(l) + 1;
  const std::vector<std::string_view> size = SplitFields(lines[l]);
  if (size.size() != 3) {
    throw InputError("expected the size line 'ROWS COLS ENTRIES', found " + std::to_string(size.size()) + " fields",
                     {path, size_line, "size line"});
  }
  long long rows = 0, cols = 0, entries = 0;
  if (!ParseIntegerToken(size[0], rows) || rows < 1) {
    throw InputError("ROWS " + QuoteToken(size[0]) + " is not a positive integer", {path, size_line, "size line"});
  }
  if (!ParseIntegerToken(size[1], cols) || cols < 1) {
    throw InputError("COLS " + QuoteToken(size[1]) + " is not a positive integer", {path, size_line, "size line"});
  }
  if (rows > kMaxDimension || cols > kMaxDimension) {
    throw InputError("a " + std::to_string(rows) + " x " + std::to_string(cols) + " matrix is larger than the " +
                         std::to_string(kMaxDimension) + " rows and columns supported",
                     {path, size_line, "size line"});
  }
  if (!ParseIntegerToken(size[2], entries) || entries < 0) {
    throw InputError("ENTRIES " + QuoteToken(size[2]) + " is not a non-negative integer", {path, size_line, "size line"});
  }
  if (out.symmetric && rows != cols) {
    throw InputError("a symmetric matrix must be square, the size line says " + std::to_string(rows) + " x " +
                         std::to_string(cols),
                     {path, size_line, "size line"});
  }
  // every entry line takes at least 6 bytes ("1 1 1\n")
  if (entries > static_cast<long long>(text.size()) / 6 + 1) {
    throw InputError("file too short for " + std::to_string(entries) + " entries (truncated file?)",
                     {path, size_line, "size line"});
  }

  // entries
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<size_t>(entries));
  int lower_line = 0, upper_line = 0;
  long long k = 0;
  for (++l; l < lines.size(); ++l) {
    if (IsBlankOrComment(lines[l])) continue;
    const int line = static_cast<int>(l) + 1;
    const std::vector<std::string_view> f = SplitFields(lines[l]);
    if (k == entries) {
      throw InputError("more entries than the " + std::to_string(entries) + " of the size line (line " +
                           std::to_string(size_line) + ")",
                       {path, line, "entry " + std::to_string(k + 1)});
    }
    ++k;
    if (f.size() != 3) {
      throw InputError("expected 'I J VALUE', found " + std::to_string(f.size()) + " fields",
                       {path, line, "entry " + std::to_string(k)});
    }
    long long i = 0, j = 0;
    if (!ParseIntegerToken(f[0], i)) throw InputError("row index " + QuoteToken(f[0]) + " is not an integer", {path, line, "entry " + std::to_string(k)});
    if (!ParseIntegerToken(f[1], j)) throw InputError("column index " + QuoteToken(f[1]) + " is not an integer", {path, line, "entry " + std::to_string(k)});
    const std::string entity =
        "entry " + std::to_string(k) + " (row " + std::to_string(i) + ", column " + std::to_string(j) + ")";
    if (i < 1 || i > rows) throw InputError("row index out of range 1.." + std::to_string(rows), {path, line, entity});
    if (j < 1 || j > cols) throw InputError("column index out of range 1.." + std::to_string(cols), {path, line, entity});
    double v = 0.0;
    if (integer) {
      long long iv = 0;
      if (!ParseIntegerToken(f[2], iv)) throw InputError("value " + QuoteToken(f[2]) + " of an integer matrix is not an integer", {path, line, entity});
      v = static_cast<double>(iv);
    } else if (!ParseDoubleToken(f[2], v)) {
      throw InputError("value " + QuoteToken(f[2]) + " is not a number", {path, line, entity});
    }
    if (!std::isfinite(v)) throw InputError("value " + QuoteToken(f[2]) + " is not finite", {path, line, entity});
    if (out.symmetric && i != j) {
      int& mine = i > j ? lower_line : upper_line;
      const int other = i > j ? upper_line : lower_line;
      if (other != 0) {
        throw InputError(std::string("entry in the ") + (i > j ? "lower" : "upper") +
                             " triangle, but line " + std::to_string(other) + " has one in the " +
                             (i > j ? "upper" : "lower") +
                             ": a symmetric file gives each off-diagonal entry once, in one triangle",
                         {path, line, entity});
      }
      if (mine == 0) mine = line;
    }
    triplets.emplace_back(static_cast<int>(i - 1), static_cast<int>(j - 1), v);
  }
  if (k < entries) {
    throw InputError("file ends after " + std::to_string(k) + " of " + std::to_string(entries) +
                         " entries (truncated file?)",
                     {path, static_cast<int>(lines.size()), "entry " + std::to_string(k + 1)});
  }

  fe::SparseMat S(static_cast<int>(rows), static_cast<int>(cols));
  S.setFromTriplets(triplets.begin(), triplets.end());
  S.makeCompressed();
  out.duplicates = static_cast<int>(static_cast<long long>(triplets.size()) - S.nonZeros());
  if (out.symmetric) {
    out.A = MirrorTriangle(S, upper_line == 0);
  } else {
    out.A = std::move(S);
  }
  out.A.makeCompressed();
  CheckFinite(out.A, path, "sum of the duplicate entries is not finite");
  return out;
}

void WriteMatrixMarket(const fe::SparseMat& A_in, const std::string& path, const MatrixMarketWriteOptions& options) {
  fe::SparseMat A = A_in;
  A.makeCompressed();
  CheckFinite(A, path, "value is not finite");
  if (options.symmetric) {
    if (A.rows() != A.cols()) {
      throw InputError("a symmetric matrix must be square, this one is " + std::to_string(A.rows()) + " x " +
                           std::to_string(A.cols()),
                       {path, 0, ""});
    }
    CheckSymmetric(A, path);
  }
  long long count = 0;
  for (int j = 0; j < A.outerSize(); ++j) {
    for (fe::SparseMat::InnerIterator it(A, j); it; ++it) {
      if (!options.symmetric || it.row() >= it.col()) ++count;
    }
  }
  std::string out;
  out.reserve(static_cast<size_t>(count) * 32 + 256);
  out += "%%MatrixMarket matrix coordinate real ";
  out += options.symmetric ? "symmetric\n" : "general\n";
  if (!options.comment.empty()) {
    std::string c = options.comment;
    std::replace(c.begin(), c.end(), '\n', ' ');
    out += "% " + c + "\n";
  }
  out += std::to_string(A.rows()) + " " + std::to_string(A.cols()) + " " + std::to_string(count) + "\n";
  for (int j = 0; j < A.outerSize(); ++j) {
    for (fe::SparseMat::InnerIterator it(A, j); it; ++it) {
      if (options.symmetric && it.row() < it.col()) continue;
      out += std::to_string(it.row() + 1);
      out += ' ';
      out += std::to_string(it.col() + 1);
      out += ' ';
      out += FormatExact(it.value());
      out += '\n';
    }
  }
  WriteFileAtomically(path, out);
}

}  // namespace flexmb::io
