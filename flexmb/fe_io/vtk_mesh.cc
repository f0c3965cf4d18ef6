#include "flexmb/fe_io/vtk_mesh.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io {
namespace {

using fe::ElementType;

// VTK cell type of a vertex (skipped on reading)
constexpr int kVertex = 1;

// the row of fe/element_traits.h of a VTK cell type (the first row with the
// code: hex20, not hex20r), or null for an unsupported one
const fe::ElementTraits* FromVtk(int code) {
  for (const fe::ElementTraits& t : fe::AllElementTraits())
    if (t.vtk_code == code) return &t;
  return nullptr;
}

// the supported cell types for messages: "1 vertex (ignored), 3 beam2, ..."
std::string VtkSupported() {
  std::string s = "1 vertex (ignored)";
  for (const fe::ElementTraits& t : fe::AllElementTraits())
    if (t.vtk_code > 0 && FromVtk(t.vtk_code) == &t) s += ", " + std::to_string(t.vtk_code) + " (" + t.description + ")";
  return s;
}

bool EqualNoCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'a' && x <= 'z') x = static_cast<char>(x - 'a' + 'A');
    if (y >= 'a' && y <= 'z') y = static_cast<char>(y - 'a' + 'A');
    if (x != y) return false;
  }
  return true;
}

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

struct Cell {
  int code = 0;
  int64_t first = 0;   // position in the connectivity
  int count = 0;
  int line = 0;
};

class VtkParser {
 public:
  explicit VtkParser(const std::string& path) : s_(path) {}

  fe::Mesh Parse() {
    ReadHeader();
    std::string_view key;
    while (s_.NextToken(key)) {
      s_.SetEntity("");
      if (EqualNoCase(key, "DATASET")) {
        const std::string_view type = s_.Token("a dataset type");
        if (!EqualNoCase(type, "UNSTRUCTURED_GRID"))
          s_.Fail("only DATASET UNSTRUCTURED_GRID is supported, got " + Printable(type));
        have_dataset_ = true;
      } else if (EqualNoCase(key, "POINTS")) {
        NeedDataset(key);
        ReadPoints();
      } else if (EqualNoCase(key, "CELLS")) {
        NeedDataset(key);
        ReadCells();
      } else if (EqualNoCase(key, "CELL_TYPES")) {
        NeedDataset(key);
        ReadCellTypes();
      } else if (EqualNoCase(key, "POINT_DATA")) {
        StartAttributes(kPointData, "POINT_DATA", "point", points_.size());
      } else if (EqualNoCase(key, "CELL_DATA")) {
        StartAttributes(kCellData, "CELL_DATA", "cell", cells_.size());
      } else if (EqualNoCase(key, "FIELD")) {
        ReadField();
      } else if (EqualNoCase(key, "METADATA")) {
        SkipMetadata();
      } else if (attribute_ != kNone && ReadAttribute(key)) {
      } else {
        s_.Fail("unexpected '" + Printable(key) + "' (not a legacy VTK keyword this reader knows)");
      }
    }
    s_.SetEntity("");
    if (!have_dataset_) s_.FailAt(0, "no DATASET UNSTRUCTURED_GRID in the file");
    if (!have_types_ && !cells_.empty()) s_.FailAt(0, "CELLS without CELL_TYPES");
    return Build();
  }

 private:
  enum Attribute { kNone, kPointData, kCellData };

  void ReadHeader() {
    std::string_view line;
    if (!s_.NextLine(line)) s_.FailAt(1, "empty file: not a legacy VTK file");
    const std::string_view magic = "# vtk DataFile Version ";
    if (line.size() < magic.size() || !EqualNoCase(line.substr(0, magic.size()), magic))
      s_.Fail("not a legacy VTK file: the first line must read '# vtk DataFile Version x.y'");
    const std::string_view v = Trim(line.substr(magic.size()));
    const double version = s_.Real(v, "the VTK file version");
    if (!(version >= 1.0 && version < 6.0))
      s_.Fail("VTK file version " + Printable(v) + " is not supported (2.0 to 5.1)");
    v5_ = version >= 5.0;
    if (!s_.NextLine(line)) s_.Fail("unexpected end of file after the first line (expected a title)");
    if (!s_.NextLine(line)) s_.Fail("unexpected end of file, expected ASCII or BINARY on line 3");
    const std::string_view format = Trim(line);
    if (EqualNoCase(format, "BINARY")) s_.Fail("binary VTK not supported, save as ASCII");
    if (!EqualNoCase(format, "ASCII")) s_.Fail("expected ASCII on line 3, got '" + Printable(format) + "'");
  }

  void NeedDataset(std::string_view key) {
    if (!have_dataset_) s_.Fail(std::string(key) + " before DATASET UNSTRUCTURED_GRID");
  }

  // POINT_DATA n / CELL_DATA n: the attributes that follow are per point /
  // cell, and n must be the number of `item`s read
  void StartAttributes(Attribute kind, const char* keyword, const std::string& item, size_t items) {
    attribute_count_ = s_.NextInteger(("the number of " + item + " data values").c_str(), 0, INT_MAX);
    if (attribute_count_ != static_cast<int64_t>(items))
      s_.Fail(std::string(keyword) + " " + std::to_string(attribute_count_) + " does not match the " +
              std::to_string(items) + " " + item + "s");
    attribute_ = kind;
  }

  void ReadPoints() {
    if (have_points_) s_.Fail("a second POINTS section");
    have_points_ = true;
    const int64_t n = s_.NextInteger("the number of points", 0, INT_MAX);
    s_.Token("the point data type");
    for (int64_t k = 0; k < n; ++k) {
      s_.SetEntity("point " + std::to_string(k));
      Point p;
      p.x.x() = s_.NextReal("x");
      p.line = s_.line();
      p.x.y() = s_.NextReal("y");
      p.x.z() = s_.NextReal("z");
      points_.push_back(p);
    }
    s_.SetEntity("");
  }

  void ReadCells() {
    if (have_cells_) s_.Fail("a second CELLS section");
    have_cells_ = true;
    const int64_t a = s_.NextInteger("the CELLS count", 0, INT_MAX);
    const int64_t b = s_.NextInteger("the CELLS size", 0, INT_MAX);
    if (v5_) {
      // CELLS nOffsets nConnectivity, then OFFSETS and CONNECTIVITY arrays
      if (a == 0) s_.Fail("CELLS needs at least one offset (cells + 1)");
      Expect("OFFSETS");
      s_.Token("the offsets data type");
      std::vector<int64_t> offsets;
      std::vector<int> lines;
      for (int64_t k = 0; k < a; ++k) {
        offsets.push_back(s_.NextInteger("an offset", 0, b));
        lines.push_back(s_.line());
        if (k == 0 && offsets[0] != 0) s_.Fail("the first offset must be 0");
        if (k > 0 && offsets[k] < offsets[k - 1]) s_.Fail("offsets must not decrease");
      }
      if (offsets.back() != b)
        s_.Fail("the last offset " + std::to_string(offsets.back()) + " differs from the connectivity size " +
                std::to_string(b));
      Expect("CONNECTIVITY");
      s_.Token("the connectivity data type");
      for (int64_t k = 0; k < b; ++k) conn_.push_back(s_.NextInteger("a point index", 0, INT_MAX));
      for (int64_t k = 0; k + 1 < a; ++k) {
        Cell c;
        c.first = offsets[k];
        c.count = static_cast<int>(std::min<int64_t>(offsets[k + 1] - offsets[k], INT_MAX));
        c.line = lines[k];
        cells_.push_back(c);
      }
    } else {
      // CELLS n size, then n lines 'count index...'; size counts every number
      int64_t used = 0;
      for (int64_t k = 0; k < a; ++k) {
        s_.SetEntity("cell " + std::to_string(k));
        Cell c;
        c.count = static_cast<int>(s_.NextInteger("a cell's point count", 0, INT_MAX));
        c.line = s_.line();
        used += 1 + c.count;
        if (used > b) s_.Fail("the cells hold more numbers than the CELLS size " + std::to_string(b));
        c.first = static_cast<int64_t>(conn_.size());
        for (int p = 0; p < c.count; ++p) conn_.push_back(s_.NextInteger("a point index", 0, INT_MAX));
        cells_.push_back(c);
      }
      s_.SetEntity("");
      if (used != b)
        s_.Fail("the cells hold " + std::to_string(used) + " numbers, the CELLS size says " + std::to_string(b));
    }
    s_.SetEntity("");
  }

  void Expect(const char* keyword) {
    const std::string_view t = s_.Token(keyword);
    if (!EqualNoCase(t, keyword)) s_.Fail(std::string("expected ") + keyword + ", got '" + Printable(t) + "'");
  }

  void ReadCellTypes() {
    if (have_types_) s_.Fail("a second CELL_TYPES section");
    if (!have_cells_) s_.Fail("CELL_TYPES before CELLS");
    have_types_ = true;
    const int64_t n = s_.NextInteger("the number of cell types", 0, INT_MAX);
    if (n != static_cast<int64_t>(cells_.size()))
      s_.Fail("CELL_TYPES " + std::to_string(n) + " does not match the " + std::to_string(cells_.size()) + " cells");
    for (int64_t k = 0; k < n; ++k) cells_[k].code = static_cast<int>(s_.NextInteger("a cell type", 0, INT_MAX));
  }

  // values of an id array (node_id, element_id), or nullptr to skip them
  std::vector<int>* IdTarget(std::string_view name) {
    if (attribute_ == kPointData && name == "node_id") return &node_ids_;
    if (attribute_ == kCellData && name == "element_id") return &element_ids_;
    return nullptr;
  }

  // reads `count` values; into `ids` (checked whole positive numbers) if given
  void Values(int64_t count, std::vector<int>* ids, const std::string& what) {
    if (ids != nullptr) {
      if (!ids->empty()) s_.Fail("a second '" + what + "' array");
      for (int64_t k = 0; k < count; ++k) {
        const double v = s_.NextReal(what.c_str());
        if (v != std::floor(v) || v < 1 || v > INT_MAX)
          s_.Fail("'" + what + "' value " + std::to_string(k) + " must be a whole number in [1, 2147483647]");
        ids->push_back(static_cast<int>(v));
      }
      return;
    }
    for (int64_t k = 0; k < count; ++k) s_.NextReal(what.c_str());
  }

  int64_t Product(int64_t a, int64_t b) {
    if (a < 0 || b < 0 || (b != 0 && a > INT64_MAX / 4 / b)) s_.Fail("array size out of range");
    return a * b;
  }

  void NotString(std::string_view type) {
    if (EqualNoCase(type, "string") || EqualNoCase(type, "utf8_string"))
      s_.Fail("string arrays are not supported");
  }

  // one attribute of POINT_DATA or CELL_DATA; false if `key` is none
  bool ReadAttribute(std::string_view key) {
    const int64_t n = attribute_count_;
    if (EqualNoCase(key, "SCALARS")) {
      const std::string name(s_.Token("the array name"));
      const std::string_view type = s_.Token("the data type");
      NotString(type);
      // optional component count, optional LOOKUP_TABLE name
      int64_t components = 1;
      TextScanner::Position p = s_.Tell();
      std::string_view t;
      if (s_.NextToken(t) && !EqualNoCase(t, "LOOKUP_TABLE") && s_.line() == LineOf(p)) {
        components = s_.Integer(t, "the number of components", 1, 4);
        p = s_.Tell();
      } else {
        s_.Seek(p);
      }
      if (s_.NextToken(t) && EqualNoCase(t, "LOOKUP_TABLE")) {
        s_.Token("the lookup table name");
      } else {
        s_.Seek(p);
      }
      std::vector<int>* ids = IdTarget(name);
      if (ids != nullptr && components != 1) s_.Fail("'" + name + "' must have one component");
      Values(Product(n, components), ids, name);
    } else if (EqualNoCase(key, "COLOR_SCALARS")) {
      s_.Token("the array name");
      const int64_t m = s_.NextInteger("the number of values", 1, 4);
      Values(Product(n, m), nullptr, "color scalar");
    } else if (EqualNoCase(key, "LOOKUP_TABLE")) {
      s_.Token("the table name");
      const int64_t size = s_.NextInteger("the table size", 0, INT_MAX);
      Values(Product(size, 4), nullptr, "lookup table entry");
    } else if (EqualNoCase(key, "VECTORS") || EqualNoCase(key, "NORMALS")) {
      s_.Token("the array name");
      NotString(s_.Token("the data type"));
      Values(Product(n, 3), nullptr, "vector component");
    } else if (EqualNoCase(key, "TEXTURE_COORDINATES")) {
      s_.Token("the array name");
      const int64_t dim = s_.NextInteger("the texture dimension", 1, 3);
      NotString(s_.Token("the data type"));
      Values(Product(n, dim), nullptr, "texture coordinate");
    } else if (EqualNoCase(key, "TENSORS") || EqualNoCase(key, "TENSORS6")) {
      s_.Token("the array name");
      NotString(s_.Token("the data type"));
      Values(Product(n, EqualNoCase(key, "TENSORS") ? 9 : 6), nullptr, "tensor component");
    } else {
      return false;
    }
    return true;
  }

  static int LineOf(const TextScanner::Position& p) { return p.pos_line; }

  // FIELD name numArrays, then per array 'name components tuples type' and its values
  void ReadField() {
    s_.Token("the field name");
    const int64_t arrays = s_.NextInteger("the number of field arrays", 0, INT_MAX);
    for (int64_t a = 0; a < arrays; ++a) {
      const std::string name(s_.Token("the field array name"));
      const int64_t components = s_.NextInteger("the number of components", 0, INT_MAX);
      const int64_t tuples = s_.NextInteger("the number of tuples", 0, INT_MAX);
      const std::string_view type = s_.Token("the data type");
      NotString(type);
      std::vector<int>* ids = attribute_ != kNone ? IdTarget(name) : nullptr;
      if (ids != nullptr && (components != 1 || tuples != attribute_count_))
        s_.Fail("'" + name + "' must have one component and " + std::to_string(attribute_count_) + " tuples");
      Values(Product(components, tuples), ids, name);
      // a METADATA block may follow an array
      const TextScanner::Position p = s_.Tell();
      std::string_view t;
      if (s_.NextToken(t) && EqualNoCase(t, "METADATA")) SkipMetadata();
      else s_.Seek(p);
    }
  }

  // METADATA blocks end with a blank line
  void SkipMetadata() {
    std::string_view line;
    s_.NextLine(line);  // rest of the METADATA line
    while (s_.NextLine(line))
      if (Trim(line).empty()) return;
  }

  fe::Mesh Build() {
    fe::Mesh mesh;
    const std::string& file = s_.file();
    mesh.source = file;
    if (!node_ids_.empty() && node_ids_.size() != points_.size())
      s_.FailAt(0, "'node_id' has " + std::to_string(node_ids_.size()) + " values for " +
                       std::to_string(points_.size()) + " points");
    std::unordered_map<int, int> seen;
    for (size_t k = 0; k < points_.size(); ++k) {
      fe::Node n;
      n.id = node_ids_.empty() ? static_cast<int>(k) + 1 : node_ids_[k];
      n.x = points_[k].x;
      n.origin = {file, points_[k].line};
      auto [it, fresh] = seen.emplace(n.id, static_cast<int>(k));
      if (!fresh)
        throw InputError("duplicate node id in 'node_id' (also point " + std::to_string(it->second) + ")",
                         {file, n.origin.line, "node " + std::to_string(n.id)});
      mesh.nodes.push_back(std::move(n));
    }
    seen.clear();
    const int np = static_cast<int>(points_.size());
    for (size_t k = 0; k < cells_.size(); ++k) {
      const Cell& c = cells_[k];
      const int id = element_ids_.empty() ? static_cast<int>(k) + 1 : element_ids_[k];
      const std::string entity = "cell " + std::to_string(k) + " (element " + std::to_string(id) + ")";
      for (int p = 0; p < c.count; ++p) {
        const int64_t q = conn_[c.first + p];
        if (q >= np)
          throw InputError("point index " + std::to_string(q) + " does not exist (" + std::to_string(np) +
                               " points)",
                           {file, c.line, entity});
      }
      if (c.code == kVertex) continue;
      const fe::ElementTraits* row = FromVtk(c.code);
      if (row == nullptr)
        throw InputError("VTK cell type " + std::to_string(c.code) + " is not supported (supported: " +
                             VtkSupported() + ")",
                         {file, c.line, entity});
      const ElementType type = row->type;
      if (c.count != fe::NodeCount(type))
        throw InputError("a VTK type " + std::to_string(c.code) + " cell has " +
                             std::to_string(fe::NodeCount(type)) + " points, got " + std::to_string(c.count),
                         {file, c.line, entity});
      auto [it, fresh] = seen.emplace(id, static_cast<int>(k));
      if (!fresh)
        throw InputError("duplicate element id in 'element_id' (also cell " + std::to_string(it->second) + ")",
                         {file, c.line, entity});
      fe::Element e;
      e.id = id;
      e.type = type;
      for (int p = 0; p < c.count; ++p)
        e.nodes.push_back(static_cast<int>(conn_[c.first + fe::FormatNode(row->vtk_order, p)]));
      e.origin = {file, c.line};
      mesh.elements.push_back(std::move(e));
    }
    mesh.IndexNodes();
    return mesh;
  }

  struct Point {
    fe::Vec3 x;
    int line = 0;
  };

  TextScanner s_;
  bool v5_ = false;
  bool have_dataset_ = false, have_points_ = false, have_cells_ = false, have_types_ = false;
  Attribute attribute_ = kNone;
  int64_t attribute_count_ = 0;
  std::vector<Point> points_;
  std::vector<int64_t> conn_;
  std::vector<Cell> cells_;
  std::vector<int> node_ids_, element_ids_;
};

}  // namespace

fe::Mesh ReadVtk(const std::string& path) { return VtkParser(path).Parse(); }

void WriteVtk(const fe::Mesh& mesh, const std::string& path) {
  const int nn = static_cast<int>(mesh.nodes.size());
  for (const fe::Node& n : mesh.nodes)
    if (n.id < 1) throw InputError("node ids must be positive to be written", {path, 0, "node " + std::to_string(n.id)});
  int64_t size = 0;
  for (const fe::Element& e : mesh.elements) {
    const std::string entity = "element " + std::to_string(e.id);
    if (e.id < 1) throw InputError("element ids must be positive to be written", {path, 0, entity});
    if (static_cast<int>(e.nodes.size()) != fe::NodeCount(e.type))
      throw InputError("has " + std::to_string(e.nodes.size()) + " nodes, a " + fe::TypeName(e.type) + " has " +
                           std::to_string(fe::NodeCount(e.type)),
                       {e.origin.file, e.origin.line, entity});
    for (int n : e.nodes)
      if (n < 0 || n >= nn)
        throw InputError("refers to node index " + std::to_string(n) + ", which does not exist",
                         {e.origin.file, e.origin.line, entity});
    size += 1 + static_cast<int64_t>(e.nodes.size());
  }
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw InputError("cannot open for writing: " + std::string(std::strerror(errno)), {path, 0, ""});
  std::fprintf(f, "# vtk DataFile Version 3.0\nflexmb FE mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n");
  std::fprintf(f, "POINTS %d double\n", nn);
  for (const fe::Node& n : mesh.nodes) std::fprintf(f, "%.17g %.17g %.17g\n", n.x.x(), n.x.y(), n.x.z());
  std::fprintf(f, "CELLS %zu %lld\n", mesh.elements.size(), static_cast<long long>(size));
  std::vector<int> cell;
  for (const fe::Element& e : mesh.elements) {
    const std::span<const int> order = fe::Traits(e.type).vtk_order;
    cell.assign(e.nodes.size(), 0);
    for (size_t k = 0; k < e.nodes.size(); ++k) cell[fe::FormatNode(order, static_cast<int>(k))] = e.nodes[k];
    std::fprintf(f, "%zu", cell.size());
    for (int n : cell) std::fprintf(f, " %d", n);
    std::fputc('\n', f);
  }
  std::fprintf(f, "CELL_TYPES %zu\n", mesh.elements.size());
  for (const fe::Element& e : mesh.elements) std::fprintf(f, "%d\n", fe::Traits(e.type).vtk_code);
  std::fprintf(f, "POINT_DATA %d\nSCALARS node_id int 1\nLOOKUP_TABLE default\n", nn);
  for (const fe::Node& n : mesh.nodes) std::fprintf(f, "%d\n", n.id);
  std::fprintf(f, "CELL_DATA %zu\nSCALARS element_id int 1\nLOOKUP_TABLE default\n", mesh.elements.size());
  for (const fe::Element& e : mesh.elements) std::fprintf(f, "%d\n", e.id);
  const bool failed = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || failed) throw InputError("writing failed: " + std::string(std::strerror(errno)), {path, 0, ""});
}

}  // namespace flexmb::io
