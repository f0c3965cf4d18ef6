#include "flexmb/fe_io/abaqus/abaqus_matrix.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
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

// a keyword line ("*MATRIX INPUT, ..."), not a "**" comment
bool KeywordLine(std::string_view line) {
  const size_t p = line.find_first_not_of(" \t\r");
  return p != std::string_view::npos && line[p] == '*' && line.substr(p, 2) != "**";
}

// a node label: a whole number, or INSTANCE.NUMBER (an instance-qualified
// label; `instance` gets the name, empty for a plain one)
bool ParseNodeLabel(std::string_view token, long long& label, std::string_view& instance) {
  const size_t dot = token.rfind('.');
  instance = dot == std::string_view::npos ? std::string_view() : token.substr(0, dot);
  long long number = 0;
  // "10.0" is a decimal number, not instance "10"
  if (dot != std::string_view::npos && (dot == 0 || ParseIntegerToken(instance, number))) return false;
  return ParseIntegerToken(dot == std::string_view::npos ? token : token.substr(dot + 1), label);
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

// one stored entry: its row and column keys (the coordinate format's 1-based
// indices, or node * 8 + DOF of the labelled format) and its line
struct Entry {
  long long row, col;
  double value;
  int line;
};

// the labelled format's key of node `node`, DOF `dof` (1..6)
long long LabelKey(long long node, long long dof) { return node * 8 + dof; }

// reads every entry line: ROW COLUMN VALUE (labelled = false) or NODE, DOF,
// NODE, DOF, VALUE (labelled = true); checks the fields, the indices and
// that no position is given twice
std::vector<Entry> ReadEntries(const std::string& path, bool labelled) {
  const std::string text = ReadWholeFile(path);
  const std::vector<std::string_view> lines = SplitLines(text);
  const size_t fields = labelled ? 5 : 3;
  const char* form = labelled ? "'NODE, DOF, NODE, DOF, VALUE' (Abaqus *MATRIX OUTPUT, FORMAT=MATRIX INPUT)"
                              : "'ROW COLUMN VALUE' (Abaqus *MATRIX OUTPUT, FORMAT=COORDINATE)";
  std::vector<Entry> entries;
  std::string first_instance;
  for (size_t l = 0; l < lines.size(); ++l) {
    if (Skipped(lines[l])) continue;
    const int line = static_cast<int>(l) + 1;
    const std::string entity = "entry " + std::to_string(entries.size() + 1);
    if (KeywordLine(lines[l]))
      throw InputError("a keyword line: the file must hold the data lines of one matrix only, as *MATRIX OUTPUT "
                       "writes it",
                       {path, line, entity});
    const std::vector<std::string_view> f = EntryFields(lines[l]);
    if (f.size() != fields)
      throw InputError(std::string("expected ") + form + ", found " + std::to_string(f.size()) + " fields",
                       {path, line, entity});
    Entry e{0, 0, 0.0, line};
    if (labelled) {
      long long n[2] = {0, 0}, d[2] = {0, 0};
      for (int k = 0; k < 2; ++k) {
        std::string_view instance;
        if (!ParseNodeLabel(f[2 * k], n[k], instance) || !ParseIntegerToken(f[2 * k + 1], d[k]))
          throw InputError("node labels and DOF must be integers, got " + QuoteToken(f[2 * k]) + " " +
                               QuoteToken(f[2 * k + 1]),
                           {path, line, entity});
        // labels of one instance (INSTANCE.LABEL) are the part's labels, as
        // the Abaqus reader takes a deck of one instance
        if (entries.empty() && k == 0) first_instance = std::string(instance);
        if (instance != first_instance)
          throw InputError("node labels of two instances ('" + first_instance + "' and '" + std::string(instance) +
                               "'): only a model of one part instance is read",
                           {path, line, entity});
        if (n[k] < 1 || n[k] > 2147483647LL)
          throw InputError("node label " + std::to_string(n[k]) +
                               (n[k] < 1 ? " is an Abaqus internal node (a Lagrange multiplier, a hybrid element's "
                                           "pressure or a constraint's node), which has no place in the geometry: "
                                           "generate the matrices without such elements and constraints"
                                         : " exceeds 2147483647"),
                           {path, line, entity});
        if (d[k] < 1 || d[k] > 6)
          throw InputError("DOF " + std::to_string(d[k]) + " of node " + std::to_string(n[k]) +
                               " is not a displacement or rotation (1-6): warping, pressure and temperature DOF "
                               "are not supported",
                           {path, line, entity});
      }
      e.row = LabelKey(n[0], d[0]);
      e.col = LabelKey(n[1], d[1]);
    } else {
      if (!ParseIntegerToken(f[0], e.row) || !ParseIntegerToken(f[1], e.col))
        throw InputError("row and column must be integers, got " + QuoteToken(f[0]) + " " + QuoteToken(f[1]),
                         {path, line, entity});
      if (e.row < 1 || e.col < 1 || e.row > kMaxDimension || e.col > kMaxDimension)
        throw InputError("index (" + std::to_string(e.row) + ", " + std::to_string(e.col) + ") outside 1.." +
                             std::to_string(kMaxDimension),
                         {path, line, entity});
    }
    if (!ParseDoubleToken(f[fields - 1], e.value))
      throw InputError("malformed value " + QuoteToken(f[fields - 1]), {path, line, entity});
    if (!std::isfinite(e.value)) throw InputError("value is not finite", {path, line, entity});
    if (std::abs(e.value) >= 1e30)
      throw InputError("value " + std::string(f[fields - 1]) +
                           " is a penalty (Abaqus puts 1e36 on the DOF a boundary condition of the matrix generation "
                           "step fixes): generate the matrices without boundary conditions and fix the nodes with "
                           "'fixed' or --fix",
                       {path, line, entity});
    entries.push_back(e);
  }
  if (entries.empty()) throw InputError(std::string("no entries (expected ") + form + " lines)", {path, 0, "matrix"});
  // each position once (sorted in place: neighbours; no per-entry map for
  // models of millions of entries)
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
    return x.row != y.row ? x.row < y.row : x.col != y.col ? x.col < y.col : x.line < y.line;
  });
  auto name = [&](long long key) {
    return labelled ? std::to_string(key / 8) + " " + std::to_string(key % 8) : std::to_string(key);
  };
  for (size_t k = 1; k < entries.size(); ++k) {
    const Entry &a = entries[k - 1], &e = entries[k];
    if (a.row == e.row && a.col == e.col) {
      const std::string where = "(" + name(e.row) + ", " + name(e.col) + ")";
      throw InputError("position " + where + " given twice (also line " + std::to_string(a.line) + ")",
                       {path, e.line, "entry " + where});
    }
  }
  return entries;
}

// the matrix of the entries (sorted by row, then column key), `index`
// giving each key's row (0-based). An off-diagonal entry whose transposed
// entry the file does not give stands for both (one triangle, in whatever
// order the package numbered its equations, or a mix); where both are given
// each stands for itself (a difference is the symmetry check's to find)
fe::SparseMat MatrixOf(const std::vector<Entry>& entries, int n, const std::function<int(long long)>& index) {
  const auto has = [&](long long row, long long col) {
    const auto it = std::lower_bound(entries.begin(), entries.end(), std::make_pair(row, col),
                                     [](const Entry& e, const std::pair<long long, long long>& p) {
                                       return e.row != p.first ? e.row < p.first : e.col < p.second;
                                     });
    return it != entries.end() && it->row == row && it->col == col;
  };
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(entries.size() * 2);
  for (const Entry& e : entries) {
    const int i = index(e.row), j = index(e.col);
    t.emplace_back(i, j, e.value);
    if (i != j && !has(e.col, e.row)) t.emplace_back(j, i, e.value);
  }
  fe::SparseMat A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// the first line of a file that is neither blank nor a "**" comment
std::string FirstEntryLine(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line))
    if (!Skipped(line) && !KeywordLine(line)) return line;  // a keyword line is named when read
  return "";
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
  return LooksLikeAbaqusCoordinateMatrix(FirstEntryLine(path));  // a banner or anything else is not
}

bool LooksLikeAbaqusLabelledMatrix(std::string_view first_line) {
  const std::vector<std::string_view> f = EntryFields(first_line);
  long long n = 0;
  double v = 0.0;
  std::string_view instance;
  return f.size() == 5 && ParseNodeLabel(f[0], n, instance) && ParseIntegerToken(f[1], n) &&
         ParseNodeLabel(f[2], n, instance) && ParseIntegerToken(f[3], n) && ParseDoubleToken(f[4], v);
}

bool IsAbaqusLabelledMatrixFile(const std::string& path) { return LooksLikeAbaqusLabelledMatrix(FirstEntryLine(path)); }

fe::SparseMat ReadAbaqusCoordinateMatrix(const std::string& path) {
  const std::vector<Entry> entries = ReadEntries(path, false);
  long long n = 0;
  for (const Entry& e : entries) n = std::max({n, e.row, e.col});
  return MatrixOf(entries, static_cast<int>(n), [](long long key) { return static_cast<int>(key - 1); });
}

AbaqusLabelledMatrices ReadAbaqusLabelledMatrices(const std::string& k_path, const std::string& m_path) {
  const std::vector<Entry> k = ReadEntries(k_path, true), m = ReadEntries(m_path, true);
  // rows: every (node, DOF) of either file, in node and DOF order
  std::vector<long long> keys;
  keys.reserve(2 * (k.size() + m.size()));
  for (const std::vector<Entry>* list : {&k, &m})
    for (const Entry& e : *list) {
      keys.push_back(e.row);
      keys.push_back(e.col);
    }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  if (keys.size() > static_cast<size_t>(kMaxDimension))
    throw InputError("more than " + std::to_string(kMaxDimension) + " rows", {k_path, 0, "matrix"});
  const auto index = [&](long long key) {
    return static_cast<int>(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin());
  };
  AbaqusLabelledMatrices out;
  const int n = static_cast<int>(keys.size());
  out.K = MatrixOf(k, n, index);
  out.M = MatrixOf(m, n, index);
  for (long long key : keys) out.dofs.push_back({static_cast<int>(key / 8), static_cast<int>(key % 8)});
  return out;
}

}  // namespace flexmb::io

