#include "flexmb/fe_io/harwell_boeing.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/matrix_text.h"

// 64-bit off_t is the default on the platforms flexmb builds on; RBio.h
// would otherwise redefine the large-file macros after the system headers
#define NLARGEFILE
#include <RBio.h>

namespace flexmb::io {

namespace {

// RBio reads lines with fgets into a 4096-byte buffer: longer lines would be
// split in the middle of a token
constexpr size_t kMaxLineLength = 4094;

const char* RbioStatusText(int status) {
  switch (status) {
    case RBIO_CP_INVALID: return "column pointers are invalid";
    case RBIO_ROW_INVALID: return "row indices are out of range";
    case RBIO_DUPLICATE: return "duplicate entry";
    case RBIO_EXTRANEOUS: return "entries above the diagonal of a symmetric matrix";
    case RBIO_TYPE_INVALID: return "matrix type invalid";
    case RBIO_DIM_INVALID: return "matrix dimensions invalid";
    case RBIO_JUMBLED: return "row indices not sorted";
    case RBIO_ARG_ERROR: return "invalid arguments";
    case RBIO_OUT_OF_MEMORY: return "out of memory";
    case RBIO_MKIND_INVALID: return "matrix kind invalid";
    case RBIO_UNSUPPORTED: return "finite-element form unsupported";
    case RBIO_HEADER_IOERROR: return "I/O error in the header";
    case RBIO_CP_IOERROR: return "I/O error in the column pointers";
    case RBIO_ROW_IOERROR: return "I/O error in the row indices";
    case RBIO_VALUE_IOERROR: return "I/O error in the values";
    case RBIO_FILE_IOERROR: return "cannot open the file";
    default: return "unknown error";
  }
}

struct FreeDeleter {
  void operator()(void* p) const { SuiteSparse_free(p); }
};

// walks the data section token by token the way RBio does: tokens are
// separated by blanks, a section may continue over several lines, the rest
// of the line after a section's last token is skipped
class TokenScanner {
 public:
  TokenScanner(const std::string& path, const std::vector<std::string_view>& lines, size_t first_line)
      : path_(path), lines_(lines), next_line_(first_line) {}

  // next token of the current section, or throws naming `what`; `index` of
  // `count` tokens of the section have been read
  std::string_view Next(const std::string& what, long long index, long long count) {
    while (true) {
      while (pos_ < cur_.size() && cur_[pos_] == ' ') ++pos_;
      if (pos_ < cur_.size()) {
        const size_t start = pos_;
        while (pos_ < cur_.size() && cur_[pos_] != ' ') ++pos_;
        return cur_.substr(start, pos_ - start);
      }
      if (next_line_ >= lines_.size()) {
        throw InputError("file ends early: " + std::to_string(index) + " of " + std::to_string(count) + " " + what +
                             " read (truncated file?)",
                         {path_, static_cast<int>(lines_.size()), ""});
      }
      cur_ = lines_[next_line_];
      line_ = static_cast<int>(next_line_) + 1;
      ++next_line_;
      pos_ = 0;
      if (cur_.find_first_not_of(' ') == std::string_view::npos) {
        throw InputError("blank line inside the " + what + " (" + std::to_string(count - index) + " of " +
                             std::to_string(count) + " still to read)",
                         {path_, line_, ""});
      }
    }
  }

  // the current section is complete: nothing else may follow on its line
  void EndSection(const std::string& what, long long count) {
    while (pos_ < cur_.size() && cur_[pos_] == ' ') ++pos_;
    if (pos_ < cur_.size()) {
      throw InputError("more " + what + " than the header's " + std::to_string(count) + " (next token " +
                           QuoteToken(cur_.substr(pos_)) + ")",
                       {path_, line_, ""});
    }
    cur_ = {};
    pos_ = 0;
  }

  int line() const { return line_; }

 private:
  const std::string& path_;
  const std::vector<std::string_view>& lines_;
  size_t next_line_;
  std::string_view cur_;
  size_t pos_ = 0;
  int line_ = 0;
};

// an integer the way RBio reads it (a number with an integral value)
bool ParseRbioInteger(std::string_view token, long long& value) {
  double x = 0.0;
  if (!ParseDoubleToken(token, x) || !std::isfinite(x) || x != std::floor(x) || std::fabs(x) > 2.0e9) return false;
  value = static_cast<long long>(x);
  return true;
}

std::string Trimmed(std::string_view s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return std::string(s.substr(b, e - b));
}

// the blank-separated tokens of a header line (RBio splits at ' ' only)
std::vector<std::string_view> BlankTokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && line[i] == ' ') ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// printable ASCII only, so that a title cannot break the header
std::string Printable(const std::string& s) {
  std::string out = s;
  for (char& c : out) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u < 32 || u > 126) c = ' ';
  }
  return out;
}

std::string EntryName(long long k, long long row, long long col) {
  return "entry " + std::to_string(k) + " (row " + std::to_string(row) + ", column " + std::to_string(col) + ")";
}

}  // namespace

HarwellBoeingMatrix ReadHarwellBoeing(const std::string& path) {
  const std::string text = ReadWholeFile(path);

  // raw lines (RBio keeps '\r' inside the last token; it is stripped here)
  std::vector<std::string_view> lines;
  {
    const std::string_view all(text);
    size_t start = 0;
    while (start < all.size()) {
      size_t end = all.find('\n', start);
      if (end == std::string_view::npos) end = all.size();
      std::string_view line = all.substr(start, end - start);
      const int number = static_cast<int>(lines.size()) + 1;
      if (line.size() > kMaxLineLength) {
        throw InputError("line longer than " + std::to_string(kMaxLineLength) + " characters", {path, number, ""});
      }
      if (line.find('\0') != std::string_view::npos) throw InputError("NUL byte in the line", {path, number, ""});
      while (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      lines.push_back(line);
      start = end + 1;
    }
  }
  if (lines.size() < 5) {
    throw InputError("file ends inside the header (a Harwell-Boeing header has 4 or 5 lines)",
                     {path, static_cast<int>(lines.size()), "header"});
  }

  HarwellBoeingMatrix out;
  out.title = Trimmed(lines[0].substr(0, std::min<size_t>(72, lines[0].size())));
  if (!out.title.empty() && out.title.back() == '|') out.title = Trimmed(out.title.substr(0, out.title.size() - 1));
  if (lines[0].size() > 72) out.key = Trimmed(lines[0].substr(72, 8));

  // line 2: TOTCRD PTRCRD INDCRD VALCRD [RHSCRD]
  const std::vector<std::string_view> cards = BlankTokens(lines[1]);
  if (cards.size() < 4) {
    throw InputError("line 2 needs the card counts TOTCRD PTRCRD INDCRD VALCRD [RHSCRD], found " +
                         std::to_string(cards.size()) + " fields",
                     {path, 2, "header"});
  }
  long long rhscrd = 0;
  for (size_t i = 0; i < cards.size() && i < 5; ++i) {
    long long v = 0;
    if (!ParseRbioInteger(cards[i], v) || v < 0) {
      throw InputError("card count " + QuoteToken(cards[i]) + " is not a non-negative integer", {path, 2, "header"});
    }
    if (i == 4) rhscrd = v;
  }

  // line 3: MXTYPE NROW NCOL NNZERO [NELTVL]
  const std::string_view line3 = lines[2];
  std::string type(line3.substr(0, std::min<size_t>(3, line3.size())));
  for (char& c : type) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  out.type = type;
  const std::string type_entity = "matrix type " + QuoteToken(type);
  if (type.size() != 3) throw InputError("line 3 must start with the 3-letter matrix type", {path, 3, "header"});
  if (type[0] == 'C') throw InputError("complex matrices are not supported (RSA, RUA, PSA expected)", {path, 3, type_entity});
  if (type[0] != 'R' && type[0] != 'P' && type[0] != 'I') {
    throw InputError("unknown value kind (RSA, RUA, PSA expected)", {path, 3, type_entity});
  }
  if (type[1] == 'R') throw InputError("rectangular matrices are not supported (RSA, RUA, PSA expected)", {path, 3, type_entity});
  if (type[1] == 'H' || type[1] == 'Z') {
    throw InputError("Hermitian and skew-symmetric matrices are not supported (RSA, RUA, PSA expected)",
                     {path, 3, type_entity});
  }
  if (type[1] != 'S' && type[1] != 'U') throw InputError("unknown symmetry (RSA, RUA, PSA expected)", {path, 3, type_entity});
  if (type[2] == 'E') {
    throw InputError("elemental (unassembled) matrices are not supported (RSA, RUA, PSA expected)",
                     {path, 3, type_entity});
  }
  if (type[2] != 'A') throw InputError("unknown storage (RSA, RUA, PSA expected)", {path, 3, type_entity});
  out.symmetric = type[1] == 'S';
  out.pattern = type[0] == 'P';

  const std::vector<std::string_view> dims = BlankTokens(line3.substr(3));
  if (dims.size() < 3) {
    throw InputError("line 3 needs NROW NCOL NNZERO after the type, found " + std::to_string(dims.size()) + " fields",
                     {path, 3, "header"});
  }
  long long nrow = 0, ncol = 0, nnz = 0;
  const char* const dim_names[3] = {"NROW", "NCOL", "NNZERO"};
  long long* const dim_values[3] = {&nrow, &ncol, &nnz};
  for (int i = 0; i < 3; ++i) {
    if (!ParseRbioInteger(dims[static_cast<size_t>(i)], *dim_values[i]) || *dim_values[i] <= 0) {
      throw InputError(std::string(dim_names[i]) + " " + QuoteToken(dims[static_cast<size_t>(i)]) +
                           " is not a positive integer",
                       {path, 3, "header"});
    }
  }
  if (nrow != ncol) {
    throw InputError("matrix is " + std::to_string(nrow) + " x " + std::to_string(ncol) + ", must be square",
                     {path, 3, "header"});
  }
  if (out.symmetric ? nnz > nrow * (nrow + 1) / 2 : nnz > nrow * ncol) {
    throw InputError("NNZERO " + std::to_string(nnz) + " is more than a " + std::to_string(nrow) + " x " +
                         std::to_string(ncol) + (out.symmetric ? " triangle" : " matrix") + " holds",
                     {path, 3, "header"});
  }
  if (out.symmetric && 2 * nnz - 1 > 2147483647LL) throw InputError("matrix too large", {path, 3, "header"});
  // every token takes at least two bytes (itself and a blank or newline)
  const long long tokens = ncol + 1 + (type[0] == 'P' ? 1 : 2) * nnz;
  if (2 * tokens - 1 > static_cast<long long>(text.size())) {
    throw InputError("file too short for NCOL = " + std::to_string(ncol) + " and NNZERO = " + std::to_string(nnz) +
                         " (truncated file?)",
                     {path, 3, "header"});
  }

  // line 4: formats (RBio reads blank-separated tokens and ignores them);
  // line 5 is the right-hand-side header if it starts with F or M
  size_t first_data = 4;
  const char c5 = lines[4].empty() ? ' ' : lines[4][0];
  if (c5 == 'F' || c5 == 'f' || c5 == 'M' || c5 == 'm') {
    first_data = 5;
  } else if (rhscrd > 0) {
    throw InputError("RHSCRD is " + std::to_string(rhscrd) +
                         " but line 5 is not a right-hand-side header (RHSTYP starting with F or M)",
                     {path, 5, "header"});
  }

  // column pointers
  TokenScanner scan(path, lines, first_data);
  const std::string ptr_what = "column pointers";
  std::vector<long long> ap(static_cast<size_t>(ncol) + 1);
  for (long long j = 0; j <= ncol; ++j) {
    const std::string_view tok = scan.Next(ptr_what, j, ncol + 1);
    const std::string entity = "column pointer " + std::to_string(j + 1);
    long long v = 0;
    if (!ParseRbioInteger(tok, v)) throw InputError(QuoteToken(tok) + " is not an integer", {path, scan.line(), entity});
    if (j == 0 && v != 1) throw InputError("the first column pointer must be 1, found " + std::to_string(v), {path, scan.line(), entity});
    if (j > 0 && v < ap[static_cast<size_t>(j - 1)]) {
      throw InputError("column pointers decrease (" + std::to_string(ap[static_cast<size_t>(j - 1)]) + " then " +
                           std::to_string(v) + ")",
                       {path, scan.line(), entity});
    }
    if (v > nnz + 1) {
      throw InputError("column pointer " + std::to_string(v) + " beyond NNZERO + 1 = " + std::to_string(nnz + 1),
                       {path, scan.line(), entity});
    }
    ap[static_cast<size_t>(j)] = v;
  }
  if (ap.back() != nnz + 1) {
    throw InputError("the last column pointer must be NNZERO + 1 = " + std::to_string(nnz + 1) + ", found " +
                         std::to_string(ap.back()),
                     {path, scan.line(), "column pointer " + std::to_string(ncol + 1)});
  }
  scan.EndSection(ptr_what, ncol + 1);

  // row indices: in range, increasing within a column, lower triangle if symmetric
  const std::string ind_what = "row indices";
  std::vector<int> ai(static_cast<size_t>(nnz));
  for (long long j = 0; j < ncol; ++j) {
    long long last = 0;
    for (long long k = ap[static_cast<size_t>(j)] - 1; k < ap[static_cast<size_t>(j) + 1] - 1; ++k) {
      const std::string_view tok = scan.Next(ind_what, k, nnz);
      long long i = 0;
      if (!ParseRbioInteger(tok, i)) {
        throw InputError("row index " + QuoteToken(tok) + " is not an integer",
                         {path, scan.line(), "entry " + std::to_string(k + 1) + " (column " + std::to_string(j + 1) + ")"});
      }
      const std::string entity = EntryName(k + 1, i, j + 1);
      if (i < 1 || i > nrow) {
        throw InputError("row index out of range 1.." + std::to_string(nrow), {path, scan.line(), entity});
      }
      if (i == last) throw InputError("duplicate entry in the column", {path, scan.line(), entity});
      if (i < last) {
        throw InputError("row indices of the column not increasing (row " + std::to_string(i) + " after row " +
                             std::to_string(last) + ")",
                         {path, scan.line(), entity});
      }
      if (out.symmetric && i < j + 1) {
        throw InputError("entry above the diagonal: a symmetric (" + type + ") file stores the lower triangle",
                         {path, scan.line(), entity});
      }
      last = i;
      ai[static_cast<size_t>(k)] = static_cast<int>(i);
    }
  }
  scan.EndSection(ind_what, nnz);

  // values: numbers RBio reads exactly, finite
  if (!out.pattern) {
    const std::string val_what = "values";
    for (long long j = 0; j < ncol; ++j) {
      for (long long k = ap[static_cast<size_t>(j)] - 1; k < ap[static_cast<size_t>(j) + 1] - 1; ++k) {
        const std::string_view tok = scan.Next(val_what, k, nnz);
        const std::string entity = EntryName(k + 1, ai[static_cast<size_t>(k)], j + 1);
        double x = 0.0;
        if (!ParseDoubleToken(tok, x)) {
          throw InputError("value " + QuoteToken(tok) +
                               " is not a number (values must be separated by blanks; Fortran D exponents are not read)",
                           {path, scan.line(), entity});
        }
        if (type[0] == 'I' && x != std::floor(x)) {
          throw InputError("value " + QuoteToken(tok) + " of an integer (" + type + ") matrix is not an integer",
                           {path, scan.line(), entity});
        }
        if (!std::isfinite(x)) throw InputError("value " + QuoteToken(tok) + " is not finite", {path, scan.line(), entity});
      }
    }
    scan.EndSection(val_what, nnz);
  }

  // the checked file read by RBio, upper triangle built for symmetric ones
  char title[73] = {0}, key[9] = {0}, mtype[4] = {0};
  int rb_nrow = 0, rb_ncol = 0, mkind = 0, skind = 0, asize = 0, znz = 0;
  int *p_ap = nullptr, *p_ai = nullptr, *p_zp = nullptr, *p_zi = nullptr;
  double *p_ax = nullptr, *p_az = nullptr;
  std::string filename = path;
  const int status = RBread_i(filename.data(), 1, 0, title, key, mtype, &rb_nrow, &rb_ncol, &mkind, &skind, &asize,
                              &znz, &p_ap, &p_ai, &p_ax, &p_az, &p_zp, &p_zi);
  const std::unique_ptr<int, FreeDeleter> own_ap(p_ap), own_ai(p_ai), own_zp(p_zp), own_zi(p_zi);
  const std::unique_ptr<double, FreeDeleter> own_ax(p_ax), own_az(p_az);
  if (status < 0) throw InputError(std::string("RBio cannot read the file: ") + RbioStatusText(status), {path, 0, ""});
  if (rb_nrow != nrow || rb_ncol != ncol || p_ap == nullptr || p_ai == nullptr) {
    throw InputError("RBio read a different matrix than the header describes (file changed while reading?)",
                     {path, 0, ""});
  }
  const int n = static_cast<int>(ncol);
  const int stored = p_ap[n];
  if (!out.pattern && p_ax == nullptr) throw InputError("RBio returned no values", {path, 0, ""});

  out.A.resize(n, n);
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<size_t>(stored));
  for (int j = 0; j < n; ++j) {
    for (int p = p_ap[j]; p < p_ap[j + 1]; ++p) {
      const double x = out.pattern ? 1.0 : p_ax[p];
      if (!std::isfinite(x)) throw InputError("value is not finite", {path, 0, EntryName(p + 1, p_ai[p] + 1, j + 1)});
      triplets.emplace_back(p_ai[p], j, x);
    }
  }
  out.A.setFromTriplets(triplets.begin(), triplets.end());
  out.A.makeCompressed();
  return out;
}

void WriteHarwellBoeing(const fe::SparseMat& A_in, const std::string& path, const HarwellBoeingWriteOptions& options) {
  if (A_in.rows() != A_in.cols()) {
    throw InputError("matrix is " + std::to_string(A_in.rows()) + " x " + std::to_string(A_in.cols()) +
                         ", must be square",
                     {path, 0, ""});
  }
  fe::SparseMat A = A_in;
  A.makeCompressed();
  CheckFinite(A, path, "value is not finite");
  if (A.nonZeros() == 0) throw InputError("matrix has no stored entries", {path, 0, ""});

  fe::SparseMat W;
  if (options.symmetric) {
    CheckSymmetric(A, path);
    // the lower triangle mirrored: exactly symmetric, so RBio writes it as ?SA
    W = MirrorTriangle(A, true);
  } else {
    W = A;
  }
  W.makeCompressed();

  std::vector<int> ap(W.outerIndexPtr(), W.outerIndexPtr() + W.outerSize() + 1);
  std::vector<int> ai(W.innerIndexPtr(), W.innerIndexPtr() + W.nonZeros());
  std::vector<double> ax(W.valuePtr(), W.valuePtr() + W.nonZeros());
  std::string title = Printable(options.title.substr(0, 71));
  std::string key = Printable(options.key.substr(0, 8));
  const std::string tmp = path + ".tmp" + std::to_string(getpid());
  std::string tmp_name = tmp;
  char mtype[4] = {0};
  const int status = RBwrite_i(tmp_name.data(), title.data(), key.data(), static_cast<int>(W.rows()),
                               static_cast<int>(W.cols()), ap.data(), ai.data(), ax.data(), nullptr, nullptr, nullptr,
                               0, mtype);
  if (status < 0) {
    std::remove(tmp.c_str());
    throw InputError(std::string("RBio cannot write the matrix: ") + RbioStatusText(status), {path, 0, ""});
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw InputError("cannot rename " + tmp + " to the file: " + ec.message(), {path, 0, ""});
  }
}

}  // namespace flexmb::io
