#include "flexmb/fe_io/abaqus/abaqus_matrix.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/matrix_text.h"

namespace flexmb::io {
namespace {

// column pointers are allocated for every column, so the size is bounded
constexpr long long kMaxDimension = 50000000;

bool Skipped(std::string_view line) {
  const size_t p = line.find_first_not_of(" \t\r");
  return p == std::string_view::npos || line.substr(p, 2) == "**";
}

// the fields of an entry line: blanks, tabs or commas between them
std::vector<std::string_view> EntryFields(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == ',' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != ',' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

}  // namespace

bool LooksLikeAbaqusCoordinateMatrix(std::string_view first_line) {
  const std::vector<std::string_view> f = EntryFields(first_line);
  long long i = 0, j = 0;
  double v = 0.0;
  return f.size() == 3 && ParseIntegerToken(f[0], i) && ParseIntegerToken(f[1], j) && ParseDoubleToken(f[2], v) &&
         i >= 1 && j >= 1;
}

bool IsAbaqusCoordinateMatrixFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line)) {
    if (Skipped(line)) continue;
    return LooksLikeAbaqusCoordinateMatrix(line);  // a banner or anything else is not
  }
  return false;
}

fe::SparseMat ReadAbaqusCoordinateMatrix(const std::string& path) {
  const std::string text = ReadWholeFile(path);
  const std::vector<std::string_view> lines = SplitLines(text);
  struct Entry {
    long long row, col;
    double value;
    int line;
  };
  std::vector<Entry> entries;
  long long n = 0;
  bool lower = false, upper = false;
  for (size_t l = 0; l < lines.size(); ++l) {
    if (Skipped(lines[l])) continue;
    const int line = static_cast<int>(l) + 1;
    const std::string entity = "entry " + std::to_string(entries.size() + 1);
    const std::vector<std::string_view> f = EntryFields(lines[l]);
    if (f.size() != 3)
      throw InputError("expected 'ROW COLUMN VALUE' (Abaqus *MATRIX OUTPUT, FORMAT=COORDINATE), found " +
                           std::to_string(f.size()) + " fields",
                       {path, line, entity});
    Entry e{0, 0, 0.0, line};
    if (!ParseIntegerToken(f[0], e.row) || !ParseIntegerToken(f[1], e.col))
      throw InputError("row and column must be integers, got " + QuoteToken(f[0]) + " " + QuoteToken(f[1]),
                       {path, line, entity});
    if (e.row < 1 || e.col < 1 || e.row > kMaxDimension || e.col > kMaxDimension)
      throw InputError("index (" + std::to_string(e.row) + ", " + std::to_string(e.col) + ") outside 1.." +
                           std::to_string(kMaxDimension),
                       {path, line, entity});
    if (!ParseDoubleToken(f[2], e.value)) throw InputError("malformed value " + QuoteToken(f[2]), {path, line, entity});
    if (!std::isfinite(e.value)) throw InputError("value is not finite", {path, line, entity});
    n = std::max({n, e.row, e.col});
    lower = lower || e.row > e.col;
    upper = upper || e.row < e.col;
    entries.push_back(e);
  }
  if (entries.empty()) throw InputError("no entries (expected 'ROW COLUMN VALUE' lines)", {path, 0, "matrix"});
  // each position once (sorted: neighbours; no per-entry map for models of
  // millions of entries); one triangle only is mirrored
  const bool mirror = !(lower && upper);
  std::vector<size_t> order(entries.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const Entry &x = entries[a], &y = entries[b];
    return x.row != y.row ? x.row < y.row : x.col != y.col ? x.col < y.col : x.line < y.line;
  });
  for (size_t k = 1; k < order.size(); ++k) {
    const Entry &a = entries[order[k - 1]], &e = entries[order[k]];
    if (a.row == e.row && a.col == e.col)
      throw InputError("position (" + std::to_string(e.row) + ", " + std::to_string(e.col) +
                           ") given twice (also line " + std::to_string(a.line) + ")",
                       {path, e.line, "entry (" + std::to_string(e.row) + ", " + std::to_string(e.col) + ")"});
  }
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(entries.size() * (mirror ? 2 : 1));
  for (const Entry& e : entries) {
    t.emplace_back(static_cast<int>(e.row - 1), static_cast<int>(e.col - 1), e.value);
    if (mirror && e.row != e.col) t.emplace_back(static_cast<int>(e.col - 1), static_cast<int>(e.row - 1), e.value);
  }
  fe::SparseMat A(static_cast<int>(n), static_cast<int>(n));
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

}  // namespace flexmb::io
