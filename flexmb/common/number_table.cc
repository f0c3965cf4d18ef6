#include "flexmb/common/number_table.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "flexmb/common/error.h"

namespace flexmb {
namespace {

// "two" for 2 (the column counts of the tables read), digits otherwise
std::string NumberTableCount(int n) {
  static const char* const kWords[] = {"zero", "one", "two", "three", "four", "five", "six"};
  return n >= 0 && n <= 6 ? kWords[n] : std::to_string(n);
}

}  // namespace

NumberTable ReadNumberTable(const std::string& path, int columns, const std::string& what,
                            const std::string& layout) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot open the " + what, {path, 0, ""});
  NumberTable table;
  std::string line, token, rest;
  std::vector<double> row(static_cast<size_t>(columns));
  bool title_allowed = true;
  for (int ln = 1; std::getline(in, line); ++ln) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    for (char& ch : line) {
      if (ch == ',' || ch == ';') ch = ' ';
    }
    std::istringstream fields(line);
    bool ok = true;
    for (int i = 0; ok && i < columns; ++i) {
      ok = static_cast<bool>(fields >> token);
      if (!ok) break;
      char* end = nullptr;
      row[static_cast<size_t>(i)] = std::strtod(token.c_str(), &end);
      ok = end != token.c_str() && *end == '\0';
    }
    ok = ok && !(fields >> rest);
    if (!ok) {
      if (title_allowed && table.rows.empty()) {
        title_allowed = false;
        continue;
      }
      throw InputError(what + ": expected " + NumberTableCount(columns) + " numbers '" + layout + "'", {path, ln, ""});
    }
    title_allowed = false;
    for (double v : row) {
      if (!std::isfinite(v)) throw InputError(what + ": NaN or infinite value", {path, ln, ""});
    }
    table.rows.push_back(row);
    table.lines.push_back(ln);
  }
  return table;
}

}  // namespace flexmb
