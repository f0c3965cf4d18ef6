#pragma once
/// \file results_csv.h
/// Reads a results.csv written by `flexmb run` / `flexmb statics` (a header
/// of column names, then rows of numbers) for the end-to-end tests.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace flexmb::testing {

/// Header and rows of a results.csv.
struct ResultsCsv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  /// Index of the column named `col`; fails the test (and returns -1) if absent.
  int Column(const std::string& col) const {
    for (size_t c = 0; c < header.size(); ++c)
      if (header[c] == col) return static_cast<int>(c);
    ADD_FAILURE() << "no column " << col;
    return -1;
  }
  /// Value of column `col` in row `row` (NaN and a test failure if absent).
  double At(size_t row, const std::string& col) const {
    const int c = Column(col);
    return c < 0 ? NAN : rows.at(row).at(static_cast<size_t>(c));
  }
  /// All values of column `col`.
  std::vector<double> Values(const std::string& col) const {
    std::vector<double> v;
    const int c = Column(col);
    if (c >= 0)
      for (const auto& r : rows) v.push_back(r.at(static_cast<size_t>(c)));
    return v;
  }
};

/// A cell's number: strtod, which (unlike std::stod) also takes subnormal
/// values such as 4.9e-324 (a force that is zero to round-off); throws on
/// text that is not a number.
inline double ParseCell(const std::string& cell) {
  char* end = nullptr;
  const double x = std::strtod(cell.c_str(), &end);
  if (end == cell.c_str()) throw std::invalid_argument("results.csv: not a number: '" + cell + "'");
  return x;
}

/// Reads the file `p` (an empty table if it cannot be read).
inline ResultsCsv ReadResultsCsv(const std::filesystem::path& p) {
  ResultsCsv t;
  std::istringstream in(ReadFile(p));
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string cell;
    std::vector<double> row;
    while (std::getline(ls, cell, ',')) {
      if (first)
        t.header.push_back(cell);
      else
        row.push_back(ParseCell(cell));
    }
    if (!first) t.rows.push_back(row);
    first = false;
  }
  return t;
}

}  // namespace flexmb::testing
