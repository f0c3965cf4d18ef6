#include "flexmb/fe_io/matrix_text.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "flexmb/common/error.h"

namespace flexmb::io {

namespace {

// drops one leading '+'; false if nothing is left or a sign follows it
bool StripPlus(std::string_view& token) {
  if (!token.empty() && token.front() == '+') {
    token.remove_prefix(1);
    if (token.empty() || token.front() == '-' || token.front() == '+') return false;
  }
  return !token.empty();
}

}  // namespace

bool ParseDoubleToken(std::string_view token, double& value) {
  if (!StripPlus(token)) return false;
  const char* first = token.data();
  const char* last = first + token.size();
  const auto [ptr, ec] = std::from_chars(first, last, value, std::chars_format::general);
  if (ptr != last) return false;
  if (ec == std::errc::result_out_of_range) {
    // overflow or underflow: let strtod give +-inf or the (sub)normal / zero
    const std::string copy(token);
    char* end = nullptr;
    value = std::strtod(copy.c_str(), &end);
    return end == copy.c_str() + copy.size();
  }
  return ec == std::errc();
}

bool ParseIntegerToken(std::string_view token, long long& value) {
  if (!StripPlus(token)) return false;
  const char* first = token.data();
  const char* last = first + token.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && ptr == last;
}

std::string QuoteToken(std::string_view token) {
  std::string out = "'";
  const size_t n = token.size() < 40 ? token.size() : 40;
  for (size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  }
  if (token.size() > n) out += "...";
  return out + "'";
}

std::string FormatExact(double x) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof(buf), x);
  return ec == std::errc() ? std::string(buf, ptr) : std::string("nan");
}

std::vector<std::string_view> SplitFields(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  const size_t n = line.size();
  while (i < n) {
    while (i < n && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < n && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::string ReadWholeFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError("is a directory, expected a file", {path, 0, ""});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open file for reading", {path, 0, ""});
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError("error while reading the file", {path, 0, ""});
  return s.str();
}

std::vector<std::string_view> SplitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

void WriteFileAtomically(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp" + std::to_string(getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError("cannot open file for writing", {tmp, 0, ""});
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      out.close();
      std::remove(tmp.c_str());
      throw InputError("error while writing the file", {tmp, 0, ""});
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw InputError("cannot rename " + tmp + " to the file: " + ec.message(), {path, 0, ""});
  }
}

Asymmetry MeasureAsymmetry(const fe::SparseMat& A) {
  Asymmetry a;
  const fe::SparseMat At = A.transpose();
  const fe::SparseMat D = A - At;
  for (int j = 0; j < A.outerSize(); ++j) {
    for (fe::SparseMat::InnerIterator it(A, j); it; ++it) a.max_abs = std::max(a.max_abs, std::fabs(it.value()));
  }
  for (int j = 0; j < D.outerSize(); ++j) {
    for (fe::SparseMat::InnerIterator it(D, j); it; ++it) {
      const double d = std::fabs(it.value());
      if (d > a.worst || std::isnan(d)) {
        a.worst = d;
        a.row = static_cast<int>(it.row());
        a.col = static_cast<int>(it.col());
        if (std::isnan(d)) return a;
      }
    }
  }
  return a;
}

void CheckFinite(const fe::SparseMat& A, const std::string& path, const std::string& message) {
  for (int j = 0; j < A.outerSize(); ++j) {
    for (fe::SparseMat::InnerIterator it(A, j); it; ++it) {
      if (!std::isfinite(it.value())) {
        throw InputError(message, {path, 0,
                         "entry (row " + std::to_string(it.row() + 1) + ", column " + std::to_string(it.col() + 1) + ")"});
      }
    }
  }
}

void CheckSymmetric(const fe::SparseMat& A, const std::string& path) {
  const Asymmetry a = MeasureAsymmetry(A);
  if (a.worst > 1e-10 * a.max_abs) {
    throw InputError("matrix is not symmetric: A(" + std::to_string(a.row + 1) + "," + std::to_string(a.col + 1) +
                         ") - A(" + std::to_string(a.col + 1) + "," + std::to_string(a.row + 1) + ") = " +
                         FormatExact(a.worst) + ", more than 1e-10 of the largest entry " + FormatExact(a.max_abs),
                     {path, 0, ""});
  }
}

fe::SparseMat MirrorTriangle(const fe::SparseMat& A, bool lower) {
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(2 * static_cast<size_t>(A.nonZeros()));
  for (int j = 0; j < A.outerSize(); ++j) {
    for (fe::SparseMat::InnerIterator it(A, j); it; ++it) {
      const int r = static_cast<int>(it.row()), c = static_cast<int>(it.col());
      if (lower ? r < c : r > c) continue;
      t.emplace_back(r, c, it.value());
      if (r != c) t.emplace_back(c, r, it.value());
    }
  }
  fe::SparseMat S(A.rows(), A.cols());
  S.setFromTriplets(t.begin(), t.end());
  S.makeCompressed();
  return S;
}

}  // namespace flexmb::io
