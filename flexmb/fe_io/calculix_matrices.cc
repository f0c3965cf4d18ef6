#include "flexmb/fe_io/calculix_matrices.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <tuple>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/matrix_text.h"

namespace flexmb::io {

MatrixRowMap ReadCalculixDofs(const std::string& path) {
  const std::string text = ReadWholeFile(path);
  const std::vector<std::string_view> lines = SplitLines(text);
  MatrixRowMap map;
  map.file = path;
  for (size_t l = 0; l < lines.size(); ++l) {
    const int line = static_cast<int>(l) + 1;
    const std::vector<std::string_view> f = SplitFields(lines[l]);
    if (f.empty()) continue;
    const std::string entity = "row " + std::to_string(map.rows.size() + 1);
    if (f.size() != 1) {
      throw InputError("expected one 'NODE.DIRECTION' field, found " + std::to_string(f.size()), {path, line, entity});
    }
    const size_t dot = f[0].find('.');
    long long node = 0, dir = 0;
    if (dot == std::string_view::npos || !ParseIntegerToken(f[0].substr(0, dot), node) ||
        !ParseIntegerToken(f[0].substr(dot + 1), dir)) {
      throw InputError(QuoteToken(f[0]) + " is not 'NODE.DIRECTION'", {path, line, entity});
    }
    if (node <= 0 || node > 2147483647LL) throw InputError("node id " + std::to_string(node) + " is not positive", {path, line, entity});
    if (dir == 0) {
      throw InputError("direction 0 (temperature) is not a structural DOF", {path, line, entity});
    }
    if (dir < 1 || dir > 6) throw InputError("direction " + std::to_string(dir) + " is not 1..6", {path, line, entity});
    map.rows.push_back(DofMapRow{static_cast<int>(node), static_cast<int>(dir), line});
  }
  if (map.rows.empty()) throw InputError("no DOF lines ('NODE.DIRECTION')", {path, 0, ""});
  return map;
}

fe::SparseMat ReadCalculixMatrix(const std::string& path, int n) {
  if (n < 1) throw InputError("the matrix size must be positive, got " + std::to_string(n), {path, 0, ""});
  const std::string text = ReadWholeFile(path);
  const std::vector<std::string_view> lines = SplitLines(text);
  struct Entry {
    int row, col;  // 0-based, row <= col
    int line;
    double value;
  };
  std::vector<Entry> entries;
  entries.reserve(lines.size());
  for (size_t l = 0; l < lines.size(); ++l) {
    const int line = static_cast<int>(l) + 1;
    const std::vector<std::string_view> f = SplitFields(lines[l]);
    if (f.empty()) continue;
    const std::string number = "entry " + std::to_string(entries.size() + 1);
    if (f.size() != 3) {
      throw InputError("expected 'ROW COLUMN VALUE', found " + std::to_string(f.size()) + " fields", {path, line, number});
    }
    long long i = 0, j = 0;
    double v = 0.0;
    if (!ParseIntegerToken(f[0], i)) throw InputError("row " + QuoteToken(f[0]) + " is not an integer", {path, line, number});
    if (!ParseIntegerToken(f[1], j)) throw InputError("column " + QuoteToken(f[1]) + " is not an integer", {path, line, number});
    const std::string entity = number + " (row " + std::to_string(i) + ", column " + std::to_string(j) + ")";
    if (i < 1 || i > n || j < 1 || j > n) {
      throw InputError("index out of range 1.." + std::to_string(n) + " (the .dof file has " + std::to_string(n) +
                           " rows)",
                       {path, line, entity});
    }
    if (!ParseDoubleToken(f[2], v)) throw InputError("value " + QuoteToken(f[2]) + " is not a number", {path, line, entity});
    if (!std::isfinite(v)) throw InputError("value " + QuoteToken(f[2]) + " is not finite", {path, line, entity});
    entries.push_back(Entry{static_cast<int>(std::min(i, j) - 1), static_cast<int>(std::max(i, j) - 1), line, v});
  }
  if (entries.empty()) throw InputError("no matrix entries ('ROW COLUMN VALUE')", {path, 0, ""});

  std::vector<size_t> order(entries.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::tie(entries[a].col, entries[a].row, entries[a].line) <
           std::tie(entries[b].col, entries[b].row, entries[b].line);
  });
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(2 * entries.size());
  for (size_t k = 0; k < order.size(); ++k) {
    const Entry& e = entries[order[k]];
    if (k > 0) {
      const Entry& p = entries[order[k - 1]];
      if (p.row == e.row && p.col == e.col) {
        throw InputError("position (" + std::to_string(e.row + 1) + "," + std::to_string(e.col + 1) +
                             ") given twice (also line " + std::to_string(p.line) +
                             "); a symmetric matrix stores each position once",
                         {path, e.line, ""});
      }
    }
    triplets.emplace_back(e.row, e.col, e.value);
    if (e.row != e.col) triplets.emplace_back(e.col, e.row, e.value);
  }
  fe::SparseMat A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  A.makeCompressed();
  return A;
}

CalculixMatrices ReadCalculixMatrixStorage(const std::string& job) {
  CalculixMatrices out;
  out.dofs = ReadCalculixDofs(job + ".dof");
  const int n = static_cast<int>(out.dofs.rows.size());
  out.K = ReadCalculixMatrix(job + ".sti", n);
  out.M = ReadCalculixMatrix(job + ".mas", n);
  return out;
}

}  // namespace flexmb::io
