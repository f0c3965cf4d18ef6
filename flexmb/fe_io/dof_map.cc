#include "flexmb/fe_io/dof_map.h"

#include <string_view>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/matrix_text.h"

namespace flexmb::io {

MatrixRowMap ReadDofMap(const std::string& path) {
  const std::string text = ReadWholeFile(path);
  const std::vector<std::string_view> lines = SplitLines(text);

  struct Parsed {
    long long row, node, component;
    int line;
  };
  std::vector<Parsed> parsed;
  for (size_t l = 0; l < lines.size(); ++l) {
    const int line = static_cast<int>(l) + 1;
    const std::vector<std::string_view> f = SplitFields(lines[l]);
    if (f.empty() || f[0].front() == '#') continue;
    if (f.size() != 3) {
      throw InputError("expected 'ROW NODE COMPONENT', found " + std::to_string(f.size()) + " fields",
                       {path, line, ""});
    }
    Parsed p{0, 0, 0, line};
    if (!ParseIntegerToken(f[0], p.row)) throw InputError("row " + QuoteToken(f[0]) + " is not an integer", {path, line, ""});
    const std::string entity = "row " + std::to_string(p.row);
    if (!ParseIntegerToken(f[1], p.node) || p.node <= 0 || p.node > 2147483647LL) {
      throw InputError("node id " + QuoteToken(f[1]) + " is not a positive integer", {path, line, entity});
    }
    if (!ParseIntegerToken(f[2], p.component) || p.component < 1 || p.component > 6) {
      throw InputError("component " + QuoteToken(f[2]) + " is not 1..6 (ux uy uz rx ry rz)", {path, line, entity});
    }
    parsed.push_back(p);
  }
  if (parsed.empty()) throw InputError("no rows in the DOF map", {path, 0, ""});

  const long long n = static_cast<long long>(parsed.size());
  MatrixRowMap map;
  map.file = path;
  map.rows.assign(parsed.size(), DofMapRow{});
  for (const Parsed& p : parsed) {
    const std::string entity = "row " + std::to_string(p.row);
    if (p.row < 1 || p.row > n) {
      throw InputError("row out of range: the map has " + std::to_string(n) + " lines, so rows are 1.." +
                           std::to_string(n) + ", each once",
                       {path, p.line, entity});
    }
    DofMapRow& r = map.rows[static_cast<size_t>(p.row - 1)];
    if (r.line != 0) {
      throw InputError("listed twice (also at line " + std::to_string(r.line) + ")", {path, p.line, entity});
    }
    r.node_id = static_cast<int>(p.node);
    r.component = static_cast<int>(p.component);
    r.line = p.line;
  }
  return map;
}

void WriteDofMap(const std::vector<DofMapRow>& rows, const std::string& path) {
  std::string out;
  out.reserve(rows.size() * 16 + 128);
  out += "# flexmb DOF map: matrix row -> node id, component (1..6 = ux uy uz rx ry rz)\n";
  out += "# row node component\n";
  for (size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].node_id <= 0 || rows[r].component < 1 || rows[r].component > 6) {
      throw InputError("row " + std::to_string(r + 1) + ": invalid node id " + std::to_string(rows[r].node_id) +
                           " or component " + std::to_string(rows[r].component),
                       {path, 0, ""});
    }
    out += std::to_string(r + 1);
    out += ' ';
    out += std::to_string(rows[r].node_id);
    out += ' ';
    out += std::to_string(rows[r].component);
    out += '\n';
  }
  WriteFileAtomically(path, out);
}

std::vector<DofMapRow> FreeDofRows(const fe::Mesh& mesh, const fe::DofMap& dofs) {
  if (dofs.free.size() != mesh.nodes.size()) {
    throw InputError("DOF numbering has " + std::to_string(dofs.free.size()) + " nodes, the mesh " +
                     std::to_string(mesh.nodes.size()));
  }
  std::vector<DofMapRow> rows(static_cast<size_t>(dofs.n_free));
  for (size_t i = 0; i < dofs.free.size(); ++i) {
    for (int c = 0; c < 6; ++c) {
      const int f = dofs.free[i][c];
      if (f < 0) continue;
      if (f >= dofs.n_free) throw InputError("free DOF index " + std::to_string(f) + " out of range", {"", 0, ""});
      DofMapRow& r = rows[static_cast<size_t>(f)];
      if (r.node_id != 0) {
        throw InputError("free DOF " + std::to_string(f + 1) + " belongs to two node slots (node " +
                         std::to_string(r.node_id) + " and node " + std::to_string(mesh.nodes[i].id) + ")");
      }
      r.node_id = mesh.nodes[i].id;
      r.component = c + 1;
    }
  }
  for (size_t f = 0; f < rows.size(); ++f) {
    if (rows[f].node_id == 0) throw InputError("free DOF " + std::to_string(f + 1) + " belongs to no node slot");
  }
  return rows;
}

}  // namespace flexmb::io
