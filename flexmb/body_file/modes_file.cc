#include "flexmb/body_file/modes_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <string_view>
#include <utility>

#include "flexmb/common/error.h"
#include "flexmb/common/text.h"
#include "flexmb/fe_io/matrix_text.h"

namespace flexmb::io {

namespace {

namespace fs = std::filesystem;

constexpr const char* kArrayBanner = "%%MatrixMarket matrix array real general";
constexpr int kModesVersion = 1;
std::string DofName(const DofMapRow& r) {
  return "node " + std::to_string(r.node_id) + " " +
         (r.component >= 1 && r.component <= 6 ? fe::kDofComponentNames[r.component - 1] : "?");
}

// whole-token integer in [lo, hi]
bool IntField(std::string_view token, long long lo, long long hi, long long& v) {
  return ParseIntegerToken(token, v) && v >= lo && v <= hi;
}

}  // namespace

void WriteModesFile(const ExchangeModes& m, const std::string& path) {
  const int ns = m.StaticModes(), nf = m.NormalModes();
  if (m.modes.cols() != ns + nf) {
    throw InputError("the modes have " + std::to_string(m.modes.cols()) + " columns, but " + std::to_string(ns) +
                         " static DOF and " + std::to_string(nf) + " normal-mode frequencies are named",
                     {path, 0, "modes file"});
  }
  if (m.modes.rows() == 0) throw InputError("the modes have no rows", {path, 0, "modes file"});
  for (int k = 0; k < ns; ++k) {
    const DofMapRow& d = m.static_dofs[k];
    if (d.node_id <= 0 || d.component < 1 || d.component > 6) {
      throw InputError("static mode " + std::to_string(k + 1) + ": invalid node id " + std::to_string(d.node_id) +
                           " or component " + std::to_string(d.component),
                       {path, 0, "modes file"});
    }
  }
  for (int k = 0; k < nf; ++k) {
    if (!std::isfinite(m.normal_frequencies_hz[k])) {
      throw InputError("normal mode " + std::to_string(k + 1) + ": the frequency is not finite",
                       {path, 0, "modes file"});
    }
  }
  std::string out;
  out.reserve(static_cast<size_t>(m.modes.size()) * 24 + 64 * static_cast<size_t>(ns + nf) + 512);
  out += kArrayBanner;
  out += "\n% flexmb modes version " + std::to_string(kModesVersion) + "\n";
  out += "% Craig-Bampton basis: rows = the DOF of dof_map.txt, in order; columns = static modes, then normal modes\n";
  out += "% static " + std::to_string(ns) + "\n";
  out += "% normal " + std::to_string(nf) + "\n";
  for (int k = 0; k < ns; ++k) {
    out += "% column " + std::to_string(k + 1) + " static node " + std::to_string(m.static_dofs[k].node_id) +
           " component " + std::to_string(m.static_dofs[k].component) + "\n";
  }
  for (int k = 0; k < nf; ++k) {
    out += "% column " + std::to_string(ns + k + 1) + " normal " + std::to_string(k + 1) + " frequency_hz " +
           FormatExact(m.normal_frequencies_hz[k]) + "\n";
  }
  out += std::to_string(m.modes.rows()) + " " + std::to_string(m.modes.cols()) + "\n";
  char buf[64];
  for (Eigen::Index j = 0; j < m.modes.cols(); ++j) {
    for (Eigen::Index i = 0; i < m.modes.rows(); ++i) {
      const double v = m.modes(i, j);
      if (!std::isfinite(v)) {
        throw InputError("the value at row " + std::to_string(i + 1) + ", column " + std::to_string(j + 1) +
                             " is not finite",
                         {path, 0, "modes file"});
      }
      const auto [ptr, ec] = std::to_chars(buf, buf + sizeof(buf), v);
      out.append(buf, ptr);
      out += '\n';
    }
  }
  WriteFileAtomically(path, out);
}

ExchangeModes ReadModesFile(const std::string& path) {
  const std::string text = ReadWholeFile(path);
  std::string_view rest = text;
  int line = 0;
  // next line of the text (false at the end)
  auto next_line = [&](std::string_view& l) {
    if (rest.empty()) return false;
    const size_t end = rest.find('\n');
    l = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    ++line;
    return true;
  };
  auto fail = [&](const std::string& message, int at, const std::string& entity = "") {
    throw InputError(message, {path, at, entity});
  };

  std::string_view l;
  if (!next_line(l)) fail("empty file: expected the banner '" + std::string(kArrayBanner) + "'", 0);
  {
    const std::vector<std::string_view> f = SplitFields(l);
    std::string banner;
    for (std::string_view x : f) banner += (banner.empty() ? "" : " ") + AsciiLower(x);
    if (banner != AsciiLower(kArrayBanner)) {
      fail("expected the banner '" + std::string(kArrayBanner) + "' (a dense Matrix Market array), found " +
               QuoteToken(l),
           line);
    }
  }

  ExchangeModes m;
  long long ns = -1, nf = -1;
  int version_line = 0;
  struct Column {
    bool normal = false;
    long long node = 0, component = 0, index = 0;
    double frequency = 0.0;
    int line = 0;
  };
  std::map<long long, Column> columns;
  long long rows = -1, cols = -1;
  int size_line = 0;
  while (next_line(l)) {
    const std::vector<std::string_view> f = SplitFields(l);
    if (f.empty()) continue;
    if (f[0].front() != '%') {
      // the size line
      if (f.size() != 2 || !IntField(f[0], 1, 2147483647LL, rows) || !IntField(f[1], 0, 2147483647LL, cols)) {
        fail("expected the size line 'ROWS COLUMNS', found " + QuoteToken(l), line);
      }
      size_line = line;
      break;
    }
    // header comments: '%' alone or glued to the first word
    std::vector<std::string_view> w;
    if (f[0].size() > 1) w.push_back(f[0].substr(1));
    w.insert(w.end(), f.begin() + 1, f.end());
    if (w.size() >= 2 && w[0] == "flexmb" && w[1] == "modes") {
      long long v = 0;
      if (w.size() != 4 || w[2] != "version" || !ParseIntegerToken(w[3], v)) {
        fail("expected '% flexmb modes version N', found " + QuoteToken(l), line);
      }
      if (v != kModesVersion) {
        fail("modes file version " + std::to_string(v) + ", this flexmb reads version " +
                 std::to_string(kModesVersion),
             line);
      }
      version_line = line;
    } else if (w.size() == 2 && (w[0] == "static" || w[0] == "normal")) {
      long long& count = w[0] == "static" ? ns : nf;
      if (count >= 0) fail("'" + std::string(w[0]) + "' count given twice", line);
      if (!IntField(w[1], 0, 2147483647LL, count)) {
        fail("the " + std::string(w[0]) + " mode count " + QuoteToken(w[1]) + " is not a non-negative integer", line);
      }
    } else if (!w.empty() && w[0] == "column") {
      Column c;
      c.line = line;
      long long j = 0;
      bool ok = w.size() >= 2 && IntField(w[1], 1, 2147483647LL, j);
      if (ok && w.size() == 7 && w[2] == "static" && w[3] == "node" && w[5] == "component") {
        ok = IntField(w[4], 1, 2147483647LL, c.node) && IntField(w[6], 1, 6, c.component);
      } else if (ok && w.size() == 6 && w[2] == "normal" && w[4] == "frequency_hz") {
        c.normal = true;
        ok = IntField(w[3], 1, 2147483647LL, c.index) && ParseDoubleToken(w[5], c.frequency) &&
             std::isfinite(c.frequency);
      } else {
        ok = false;
      }
      if (!ok) {
        fail("expected '% column J static node ID component C' (C = 1..6) or '% column J normal K frequency_hz F', "
             "found " + QuoteToken(l),
             line);
      }
      if (!columns.emplace(j, c).second) {
        fail("column " + std::to_string(j) + " is described twice (also at line " + std::to_string(columns[j].line) +
                 ")",
             line);
      }
    }
  }
  if (size_line == 0) fail("no size line 'ROWS COLUMNS' after the header", line);
  if (version_line == 0) fail("not a flexmb modes file: the header line '% flexmb modes version 1' is missing", 0);
  if (ns < 0 || nf < 0) fail("the header must give '% static N' and '% normal N'", 0);
  if (ns + nf != cols) {
    fail(std::to_string(ns) + " static + " + std::to_string(nf) + " normal modes, but the size line has " +
             std::to_string(cols) + " columns",
         size_line);
  }
  m.static_dofs.resize(ns);
  m.normal_frequencies_hz.resize(nf);
  for (long long j = 1; j <= cols; ++j) {
    const auto it = columns.find(j);
    if (it == columns.end()) fail("column " + std::to_string(j) + " has no '% column' header line", 0);
    const Column& c = it->second;
    const std::string entity = "column " + std::to_string(j);
    if (j <= ns) {
      if (c.normal) {
        fail("expected a static mode (the first " + std::to_string(ns) + " columns), found a normal mode", c.line,
             entity);
      }
      m.static_dofs[j - 1] = DofMapRow{static_cast<int>(c.node), static_cast<int>(c.component), c.line};
    } else {
      if (!c.normal) fail("expected a normal mode (static modes come first), found a static mode", c.line, entity);
      if (c.index != j - ns) {
        fail("normal mode " + std::to_string(c.index) + " in this column, expected " + std::to_string(j - ns), c.line,
             entity);
      }
      m.normal_frequencies_hz[j - ns - 1] = c.frequency;
    }
  }
  if (columns.size() != static_cast<size_t>(cols)) {
    fail("header lines describe column " + std::to_string(columns.rbegin()->first) + ", but there are only " +
             std::to_string(cols) + " columns",
         columns.rbegin()->second.line);
  }

  // the values, column by column, any number per line
  m.modes.resize(rows, cols);
  double* out = m.modes.data();
  const long long total = rows * cols;
  long long k = 0;
  while (next_line(l)) {
    for (std::string_view t : SplitFields(l)) {
      if (k == total) fail("more values than the " + std::to_string(total) + " of the size line", line);
      const std::string entity = "row " + std::to_string(k % rows + 1) + ", column " + std::to_string(k / rows + 1);
      double v = 0.0;
      if (!ParseDoubleToken(t, v)) fail("value " + QuoteToken(t) + " is not a number", line, entity);
      if (!std::isfinite(v)) fail("value " + QuoteToken(t) + " is not finite", line, entity);
      out[k++] = v;
    }
  }
  if (k != total) {
    fail("the file ends after " + std::to_string(k) + " of " + std::to_string(total) + " values (" +
             std::to_string(rows) + " rows x " + std::to_string(cols) + " columns)",
         line);
  }
  return m;
}

void CheckModesAgainstDofMap(const ExchangeModes& m, const MatrixRowMap& map, const std::string& path) {
  const Eigen::Index n = static_cast<Eigen::Index>(map.rows.size());
  if (m.modes.rows() != n) {
    throw InputError("the modes have " + std::to_string(m.modes.rows()) + " rows, the DOF map " + map.file + " has " +
                         std::to_string(n),
                     {path, 0, "modes file"});
  }
  std::map<std::pair<int, int>, int> row_of;
  for (Eigen::Index r = 0; r < n; ++r) row_of[{map.rows[r].node_id, map.rows[r].component}] = static_cast<int>(r);
  const int ns = m.StaticModes();
  std::vector<int> static_rows(ns);
  std::map<int, int> column_of_row;
  for (int k = 0; k < ns; ++k) {
    const DofMapRow& d = m.static_dofs[k];
    const std::string entity = "column " + std::to_string(k + 1);
    const auto it = row_of.find({d.node_id, d.component});
    if (it == row_of.end()) {
      throw InputError("static mode of " + DofName(d) + ": the DOF map " + map.file + " has no row for it",
                       {path, d.line, entity});
    }
    if (!column_of_row.emplace(it->second, k).second) {
      throw InputError("static mode of " + DofName(d) + ": the same DOF as column " +
                           std::to_string(column_of_row[it->second] + 1),
                       {path, d.line, entity});
    }
    static_rows[k] = it->second;
  }
  for (Eigen::Index j = 0; j < m.modes.cols(); ++j) {
    const double scale = std::max(1.0, m.modes.col(j).cwiseAbs().maxCoeff());
    const std::string entity = "column " + std::to_string(j + 1);
    for (int k = 0; k < ns; ++k) {
      const double want = j == k ? 1.0 : 0.0;
      const double v = m.modes(static_rows[k], j);
      if (std::abs(v - want) > 1e-6 * scale) {
        const std::string kind = j < ns ? "static mode of " + DofName(m.static_dofs[j]) : "normal mode";
        throw InputError(kind + ": the value at row " + std::to_string(static_rows[k] + 1) + " (" +
                             DofName(m.static_dofs[k]) + ", an interface DOF) is " + FormatExact(v) + ", expected " +
                             (j == k ? "1" : "0") + " (Craig-Bampton modes are [I 0] on the interface DOF)",
                         {path, 0, entity});
      }
    }
  }
}

ExchangeModes ReadExchangeSetModes(const std::string& dir) {
  const std::string path = (fs::path(dir) / kModesFileName).string();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("modes file of the exchange set is missing", {path, 0, "exchange set"});
  const MatrixRowMap map = ReadDofMap((fs::path(dir) / "dof_map.txt").string());
  ExchangeModes m = ReadModesFile(path);
  CheckModesAgainstDofMap(m, map, path);
  return m;
}

ExchangeModes ModesOfBasis(const reduction::CraigBamptonBasis& basis, const fe::Mesh& mesh, const fe::DofMap& dofs) {
  const std::vector<DofMapRow> rows = FreeDofRows(mesh, dofs);
  ExchangeModes m;
  for (int b : basis.boundary) m.static_dofs.push_back(DofMapRow{rows[b].node_id, rows[b].component, 0});
  m.normal_frequencies_hz = basis.fixed_interface_hz;
  m.modes = basis.Expand(Eigen::MatrixXd::Identity(basis.size(), basis.size()));
  return m;
}

reduction::CraigBamptonBasis BasisOfModes(const ExchangeModes& m, const fe::Mesh& mesh, const fe::AssembledModel& a,
                                          const std::string& path) {
  const int n = a.dofs.n_free, ns = m.StaticModes(), nf = m.NormalModes();
  if (m.modes.rows() != n || m.modes.cols() != ns + nf) {
    throw InputError("the modes are " + std::to_string(m.modes.rows()) + " x " + std::to_string(m.modes.cols()) +
                         ", the model has " + std::to_string(n) + " free DOF and the header names " +
                         std::to_string(ns + nf) + " modes",
                     {path, 0, "modes file"});
  }
  // free DOF of each static column, then the columns in ascending DOF order
  std::vector<std::pair<int, int>> dof_column;
  for (int k = 0; k < ns; ++k) {
    const DofMapRow& d = m.static_dofs[k];
    const int node = mesh.NodeIndex(d.node_id);
    const int f = node >= 0 && node < static_cast<int>(a.dofs.free.size()) ? a.dofs.free[node][d.component - 1] : -1;
    if (f < 0) {
      throw InputError("static mode of " + DofName(d) + ": not a free DOF of the model",
                       {path, d.line, "column " + std::to_string(k + 1)});
    }
    dof_column.emplace_back(f, k);
  }
  std::sort(dof_column.begin(), dof_column.end());
  reduction::CraigBamptonBasis b;
  std::vector<bool> is_boundary(n, false);
  for (const auto& [f, k] : dof_column) {
    b.boundary.push_back(f);
    is_boundary[f] = true;
  }
  for (int f = 0; f < n; ++f) {
    if (!is_boundary[f]) b.interior.push_back(f);
  }
  const Eigen::Index ni = static_cast<Eigen::Index>(b.interior.size());
  b.psi.resize(ni, ns);
  b.phi.resize(ni, nf);
  Eigen::MatrixXd h(n, ns + nf);
  for (int j = 0; j < ns; ++j) h.col(j) = m.modes.col(dof_column[j].second);
  h.rightCols(nf) = m.modes.rightCols(nf);
  for (Eigen::Index r = 0; r < ni; ++r) {
    b.psi.row(r) = h.row(b.interior[r]).head(ns);
    b.phi.row(r) = h.row(b.interior[r]).tail(nf);
  }
  b.fixed_interface_hz = m.normal_frequencies_hz;
  const Eigen::MatrixXd mh = a.M * h, kh = a.K * h;
  b.mass = h.transpose() * mh;
  b.stiffness = h.transpose() * kh;
  b.mass = (0.5 * (b.mass + b.mass.transpose())).eval();
  b.stiffness = (0.5 * (b.stiffness + b.stiffness.transpose())).eval();
  b.stiffness_scale = reduction::StiffnessScale(a.K, a.M);
  return b;
}

}  // namespace flexmb::io
