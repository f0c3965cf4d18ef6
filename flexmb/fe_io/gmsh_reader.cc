#include "flexmb/fe_io/gmsh_reader.h"

#include <algorithm>
#include <span>
#include <climits>
#include <map>
#include <set>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io {
namespace {

using fe::ElementType;

// what flexmb makes of a gmsh element type
struct GmshType {
  int nodes = 0;            // node count
  int dim = 0;              // topological dimension (2.2: dimension of the physical group)
  bool point = false;       // type 15: no element, nodes still join their groups' node sets
  bool supported = false;   // else read, and accepted only as a boundary of supported elements
  // second-order lines and surfaces (3-node line, 6-node triangle, 8-node
  // quadrangle): a boundary of supported elements of higher dimension when
  // all their nodes belong to such elements (the physical groups of a
  // second-order solid mesh), an element otherwise
  bool boundary_if_covered = false;
  ElementType type = ElementType::kQuad4;
  std::span<const int> order;  // node order of the type (fe/element_traits.h)
};

// the gmsh element types known here: code, node count, dimension, name
struct GmshCatalogueEntry {
  int code, nodes, dim;
  const char* name;
};
constexpr GmshCatalogueEntry kGmshCatalogue[] = {
    {1, 2, 1, "line"},          {2, 3, 2, "triangle"},          {3, 4, 2, "quadrangle"},
    {4, 4, 3, "tetrahedron"},   {5, 8, 3, "hexahedron"},        {6, 6, 3, "6-node prism"},
    {7, 5, 3, "5-node pyramid"}, {8, 3, 1, "3-node line"},      {9, 6, 2, "6-node triangle"},
    {10, 9, 2, "9-node quadrangle"}, {11, 10, 3, "10-node tetrahedron"}, {12, 27, 3, "27-node hexahedron"},
    {13, 18, 3, "18-node prism"}, {14, 14, 3, "14-node pyramid"}, {15, 1, 0, "point"},
    {16, 8, 2, "8-node quadrangle"}, {17, 20, 3, "20-node hexahedron"}, {18, 15, 3, "15-node prism"},
    {19, 13, 3, "13-node pyramid"}, {20, 9, 2, "9-node triangle"}, {21, 10, 2, "10-node triangle"},
    {26, 4, 1, "4-node line"}};
constexpr int kGmshPoint = 15;

const GmshCatalogueEntry* GmshEntry(int code) {
  for (const GmshCatalogueEntry& c : kGmshCatalogue)
    if (c.code == code) return &c;
  return nullptr;
}

// the row of fe/element_traits.h read from gmsh type `code`, or null
const fe::ElementTraits* GmshRow(int code) {
  for (const fe::ElementTraits& t : fe::AllElementTraits())
    if (t.gmsh_code == code) return &t;
  return nullptr;
}

bool LookUpType(int code, GmshType& t) {
  const GmshCatalogueEntry* c = GmshEntry(code);
  if (c == nullptr) return false;
  t = {c->nodes, c->dim, code == kGmshPoint, code == kGmshPoint, code == 8 || code == 9 || code == 16,
       ElementType::kQuad4, {}};
  if (const fe::ElementTraits* row = GmshRow(code)) {
    t.supported = true;
    t.type = row->type;
    t.order = row->gmsh_order;
  }
  return true;
}

std::string UnsupportedType(int code) {
  const GmshCatalogueEntry* c = GmshEntry(code);
  std::string supported;
  for (const GmshCatalogueEntry& k : kGmshCatalogue)
    if (k.code == kGmshPoint || GmshRow(k.code)) {
      if (!supported.empty()) supported += ", ";
      supported += std::to_string(k.code) + " " + k.name;
    }
  return "gmsh element type " + std::to_string(code) + (c ? std::string(" (") + c->name + ")" : std::string()) +
         " is not supported (supported: " + supported + ")";
}

// a physical group: (dimension, tag)
using GroupKey = std::pair<int, int>;

struct RawNode {
  int id = 0;
  fe::Vec3 x;
  int line = 0;
};

struct RawElement {
  int id = 0;
  int code = 0;
  GmshType type;
  std::vector<int> node_ids;
  std::vector<GroupKey> groups;
  int entity_dim = 0;  // 4.1: dimension of the entity (block header)
  int entity = 0;      // elementary entity tag (2.2: 0 if not given)
  int line = 0;
};

class GmshParser {
 public:
  explicit GmshParser(const std::string& path) : s_(path) {}

  fe::Mesh Parse() {
    std::string_view line;
    bool have_format = false;
    while (s_.NextNonBlankLine(line)) {
      SplitTokens(line, tok_);
      const std::string_view name = tok_[0];
      s_.SetEntity("");
      if (!have_format && name != "$MeshFormat")
        s_.Fail("not a gmsh .msh file of version 2.2 or 4.1: it must start with $MeshFormat (got '" +
                Printable(line) + "')");
      if (name.empty() || name[0] != '$')
        s_.Fail("expected a section header such as $Nodes, got '" + Printable(line) + "'");
      const std::string section(name.substr(1));
      if (tok_.size() != 1) s_.Fail("unexpected text after $" + Printable(section));
      if (section == "MeshFormat") {
        if (have_format) s_.Fail("a second $MeshFormat section");
        ReadFormat();
        have_format = true;
      } else if (section == "PhysicalNames") {
        ReadPhysicalNames();
      } else if (section == "Entities") {
        if (v41_) ReadEntities();
        else SkipSection(section);
      } else if (section == "Nodes") {
        if (seen_nodes_) s_.Fail("a second $Nodes section (not supported)");
        seen_nodes_ = true;
        if (v41_) ReadNodes41();
        else ReadNodes22();
      } else if (section == "Elements") {
        if (seen_elements_) s_.Fail("a second $Elements section (not supported)");
        seen_elements_ = true;
        if (v41_) ReadElements41();
        else ReadElements22();
      } else {
        SkipSection(section);
        continue;
      }
      ExpectEnd(section);
    }
    s_.SetEntity("");
    if (!have_format) s_.FailAt(0, "empty file: not a gmsh .msh file (no $MeshFormat)");
    if (!seen_nodes_) s_.FailAt(0, "no $Nodes section");
    return Build();
  }

 private:
  // next non-blank line split into tok_; `what` names what is expected
  void Line(const char* what) {
    std::string_view line;
    if (!s_.NextNonBlankLine(line)) s_.Fail(std::string("unexpected end of file, expected ") + what);
    SplitTokens(line, tok_);
    if (!tok_.empty() && !tok_[0].empty() && tok_[0][0] == '$')
      s_.Fail(std::string("unexpected '") + Printable(tok_[0]) + "', expected " + what);
  }

  void ExpectTokens(size_t n, const char* what) {
    if (tok_.size() != n)
      s_.Fail(std::string("expected ") + std::to_string(n) + " values (" + what + "), got " +
              std::to_string(tok_.size()));
  }

  // a line holding one count, "the number of `what`"
  int64_t Count(const std::string& what) {
    const std::string name = "number of " + what;
    Line(("the " + name).c_str());
    ExpectTokens(1, name.c_str());
    return Int(0, name.c_str(), 0, INT_MAX);
  }

  // the next line of a version 2.2 list, of the form `form` ("'id x y z'")
  // with at least `min_tokens` tokens
  void Record(const char* form, size_t min_tokens) {
    Line(form);
    if (tok_.size() < min_tokens) s_.Fail(std::string("expected ") + form);
  }

  void ExpectEnd(const std::string& section) {
    std::string_view line;
    s_.SetEntity("");
    if (!s_.NextNonBlankLine(line)) s_.Fail("unexpected end of file, expected $End" + section);
    SplitTokens(line, tok_);
    if (tok_.size() != 1 || tok_[0] != "$End" + section)
      s_.Fail("expected $End" + section + ", got '" + Printable(line) + "' (more entries than announced?)");
  }

  void SkipSection(const std::string& section) {
    const int start = s_.line();
    std::string_view line;
    while (s_.NextLine(line)) {
      SplitTokens(line, tok_);
      if (!tok_.empty() && tok_[0] == "$End" + section) return;
    }
    s_.FailAt(start, "section $" + Printable(section) + " is not closed ($End" + Printable(section) + " missing)");
  }

  int64_t Int(size_t k, const char* what, int64_t lo, int64_t hi) { return s_.Integer(tok_[k], what, lo, hi); }
  double Real(size_t k, const char* what) { return s_.Real(tok_[k], what); }

  void ReadFormat() {
    Line("'version file-type data-size'");
    if (tok_.size() < 3) s_.Fail("expected 'version file-type data-size' after $MeshFormat");
    const std::string_view v = tok_[0];
    if (v == "4.1") {
      v41_ = true;
    } else if (v == "2.2" || v == "2.1" || v == "2.0" || v == "2") {
      v41_ = false;
    } else {
      s_.Fail("gmsh format version " + Printable(v) + " is not supported (save as version 4.1 or 2.2)");
    }
    const int64_t type = Int(1, "file-type", 0, 1);
    if (type == 1) s_.Fail("binary .msh not supported, save as ASCII");
    Int(2, "data-size", 1, 16);
  }

  void ReadPhysicalNames() {
    const int64_t n = Count("physical names");
    std::string_view line;
    for (int64_t k = 0; k < n; ++k) {
      if (!s_.NextNonBlankLine(line)) s_.Fail("unexpected end of file in $PhysicalNames");
      SplitTokens(line, tok_);
      if (tok_.size() < 3 || tok_[0][0] == '$')
        s_.Fail("expected 'dimension tag \"name\"' in $PhysicalNames, got '" + Printable(line) + "'");
      const int dim = static_cast<int>(Int(0, "physical group dimension", 0, 3));
      const int tag = static_cast<int>(Int(1, "physical group tag", INT_MIN + 1, INT_MAX));
      // the name is the rest of the line, in quotes
      const size_t rest = static_cast<size_t>(tok_[2].data() - line.data());
      std::string_view name = line.substr(rest);
      while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.remove_suffix(1);
      if (name.size() >= 2 && name.front() == '"' && name.back() == '"') {
        name = name.substr(1, name.size() - 2);
      } else if (tok_.size() != 3 || name.find('"') != std::string_view::npos) {
        s_.Fail("physical name must be in double quotes, got '" + Printable(line.substr(rest)) + "'");
      }
      if (name.empty()) s_.Fail("physical group " + std::to_string(tag) + " has an empty name");
      if (!names_.emplace(GroupKey{dim, tag}, std::string(name)).second)
        s_.Fail("physical group " + std::to_string(tag) + " of dimension " + std::to_string(dim) +
                " is named twice");
    }
  }

  void ReadEntities() {
    Line("'numPoints numCurves numSurfaces numVolumes'");
    ExpectTokens(4, "numPoints numCurves numSurfaces numVolumes");
    int64_t count[4];
    for (int d = 0; d < 4; ++d) count[d] = Int(d, "entity count", 0, INT_MAX);
    for (int d = 0; d < 4; ++d) {
      for (int64_t k = 0; k < count[d]; ++k) {
        Line("an entity");
        // points: tag x y z nphys phys...; others: tag box(6) nphys phys... nbound bound...
        const size_t head = d == 0 ? 5 : 8;
        if (tok_.size() < head) s_.Fail("entity line too short");
        const int tag = static_cast<int>(Int(0, "entity tag", INT_MIN + 1, INT_MAX));
        s_.SetEntity("entity " + std::to_string(d) + "-" + std::to_string(tag));
        for (size_t c = 1; c < head - 1; ++c) Real(c, "entity coordinate");
        const int64_t nphys = Int(head - 1, "number of physical tags", 0, static_cast<int64_t>(tok_.size()));
        if (tok_.size() < head + nphys) s_.Fail("fewer physical tags than announced");
        std::vector<int> phys;
        for (int64_t p = 0; p < nphys; ++p)
          phys.push_back(static_cast<int>(Int(head + p, "physical tag", INT_MIN + 1, INT_MAX)));
        size_t used = head + nphys;
        if (d > 0) {
          if (tok_.size() < used + 1) s_.Fail("missing the number of bounding entities");
          const int64_t nb = Int(used, "number of bounding entities", 0, static_cast<int64_t>(tok_.size()));
          used += 1;
          for (int64_t b = 0; b < nb; ++b) {
            if (used >= tok_.size()) s_.Fail("fewer bounding entities than announced");
            Int(used++, "bounding entity tag", INT_MIN + 1, INT_MAX);
          }
        }
        if (used != tok_.size()) s_.Fail("unexpected values at the end of the entity line");
        if (!entity_groups_.emplace(GroupKey{d, tag}, std::move(phys)).second)
          s_.Fail("entity defined twice");
        s_.SetEntity("");
      }
    }
  }

  void AddNode(int64_t id, const fe::Vec3& x, int line) {
    RawNode n;
    n.id = static_cast<int>(id);
    n.x = x;
    n.line = line;
    nodes_.push_back(n);
  }

  // the counts on the first line of a version 4.1 $Nodes or $Elements section
  struct BlockCounts {
    int line;        // of the header
    int64_t blocks;  // entity blocks
    int64_t total;   // nodes or elements in all blocks
  };

  // reads that line, of the form `form`; `item` is "node" or "element"
  BlockCounts BlockHeader(const char* form, const std::string& item) {
    Line((std::string("'") + form + "'").c_str());
    ExpectTokens(4, form);
    const int line = s_.line();
    const int64_t blocks = Int(0, ("number of " + item + " blocks").c_str(), 0, INT_MAX);
    const int64_t total = Int(1, ("number of " + item + "s").c_str(), 0, INT_MAX);
    return {line, blocks, total};
  }

  // the blocks held `read` items: the header's total
  void CheckBlockTotal(const BlockCounts& h, int64_t read, const std::string& item) {
    if (read != h.total)
      s_.FailAt(h.line, "the " + item + " blocks hold " + std::to_string(read) + " " + item +
                            "s, the header announced " + std::to_string(h.total));
  }

  void ReadNodes41() {
    const BlockCounts h = BlockHeader("numEntityBlocks numNodes minNodeTag maxNodeTag", "node");
    const int64_t total = h.total;
    std::vector<int64_t> tags;
    for (int64_t b = 0; b < h.blocks; ++b) {
      Line("a node block header 'entityDim entityTag parametric numNodesInBlock'");
      ExpectTokens(4, "entityDim entityTag parametric numNodesInBlock");
      const int dim = static_cast<int>(Int(0, "entity dimension", 0, 3));
      Int(1, "entity tag", INT_MIN + 1, INT_MAX);
      const bool parametric = Int(2, "parametric flag", 0, 1) == 1;
      const int64_t n = Int(3, "number of nodes in the block", 0, INT_MAX);
      if (static_cast<int64_t>(nodes_.size()) + n > total)
        s_.Fail("more nodes in the blocks than the " + std::to_string(total) + " announced");
      tags.clear();
      for (int64_t k = 0; k < n; ++k) {
        Line("a node tag");
        ExpectTokens(1, "node tag");
        tags.push_back(Int(0, "node tag", 1, INT_MAX));
      }
      const size_t values = 3 + (parametric ? static_cast<size_t>(dim) : 0);
      for (int64_t k = 0; k < n; ++k) {
        Line("node coordinates");
        s_.SetEntity("node " + std::to_string(tags[k]));
        if (tok_.size() != values)
          s_.Fail("expected " + std::to_string(values) + " coordinates, got " + std::to_string(tok_.size()));
        const fe::Vec3 x(Real(0, "x"), Real(1, "y"), Real(2, "z"));
        for (size_t c = 3; c < values; ++c) Real(c, "parametric coordinate");
        AddNode(tags[k], x, s_.line());
      }
      s_.SetEntity("");
    }
    CheckBlockTotal(h, static_cast<int64_t>(nodes_.size()), "node");
  }

  void ReadNodes22() {
    const int64_t n = Count("nodes");
    for (int64_t k = 0; k < n; ++k) {
      Record("'id x y z'", 1);
      const int64_t id = Int(0, "node id", 1, INT_MAX);
      s_.SetEntity("node " + std::to_string(id));
      ExpectTokens(4, "id x y z");
      AddNode(id, fe::Vec3(Real(1, "x"), Real(2, "y"), Real(3, "z")), s_.line());
      s_.SetEntity("");
    }
  }

  // node tags tok_[first ...] of an element of type t
  void ElementNodes(RawElement& e, size_t first) {
    if (tok_.size() != first + static_cast<size_t>(e.type.nodes))
      s_.Fail("a gmsh type " + std::to_string(e.code) + " element has " + std::to_string(e.type.nodes) +
              " nodes, got " + std::to_string(static_cast<int64_t>(tok_.size()) - static_cast<int64_t>(first)));
    for (int k = 0; k < e.type.nodes; ++k)
      e.node_ids.push_back(static_cast<int>(Int(first + k, "node tag", 1, INT_MAX)));
  }

  void ReadElements41() {
    const BlockCounts h = BlockHeader("numEntityBlocks numElements minElementTag maxElementTag", "element");
    const int64_t total = h.total;
    int64_t read = 0;
    for (int64_t b = 0; b < h.blocks; ++b) {
      Line("an element block header 'entityDim entityTag elementType numElementsInBlock'");
      ExpectTokens(4, "entityDim entityTag elementType numElementsInBlock");
      const int dim = static_cast<int>(Int(0, "entity dimension", 0, 3));
      const int tag = static_cast<int>(Int(1, "entity tag", INT_MIN + 1, INT_MAX));
      const int code = static_cast<int>(Int(2, "element type", 1, INT_MAX));
      const int64_t n = Int(3, "number of elements in the block", 0, INT_MAX);
      GmshType type;
      if (!LookUpType(code, type)) s_.Fail(UnsupportedType(code));
      if (read + n > total) s_.Fail("more elements in the blocks than the " + std::to_string(total) + " announced");
      for (int64_t k = 0; k < n; ++k) {
        Line("'elementTag nodeTag ...'");
        RawElement e;
        e.id = static_cast<int>(Int(0, "element tag", 1, INT_MAX));
        s_.SetEntity("element " + std::to_string(e.id));
        e.code = code;
        e.type = type;
        e.entity_dim = dim;
        e.entity = tag;
        e.line = s_.line();
        ElementNodes(e, 1);
        elements_.push_back(std::move(e));
        s_.SetEntity("");
      }
      read += n;
    }
    CheckBlockTotal(h, read, "element");
  }

  void ReadElements22() {
    const int64_t n = Count("elements");
    for (int64_t k = 0; k < n; ++k) {
      Record("'id type ntags tags... nodes...'", 3);
      RawElement e;
      e.id = static_cast<int>(Int(0, "element id", 1, INT_MAX));
      s_.SetEntity("element " + std::to_string(e.id));
      e.code = static_cast<int>(Int(1, "element type", 1, INT_MAX));
      if (!LookUpType(e.code, e.type)) s_.Fail(UnsupportedType(e.code));
      const int64_t ntags = Int(2, "number of tags", 0, static_cast<int64_t>(tok_.size()) - 3);
      // first tag: physical group (0 = none); the others are not used
      for (int64_t t = 0; t < ntags; ++t) {
        const int64_t tag = Int(3 + t, "element tag value", INT_MIN + 1, INT_MAX);
        if (t == 0 && tag != 0) e.groups.emplace_back(e.type.dim, static_cast<int>(tag));
        if (t == 1) e.entity = static_cast<int>(tag);
      }
      e.line = s_.line();
      ElementNodes(e, 3 + static_cast<size_t>(ntags));
      elements_.push_back(std::move(e));
      s_.SetEntity("");
    }
  }

  std::string GroupName(const GroupKey& g) const {
    auto it = names_.find(g);
    return it != names_.end() ? it->second : "group" + std::to_string(g.second);
  }

  fe::Mesh Build() {
    fe::Mesh mesh;
    mesh.source = s_.file();
    const std::string& file = s_.file();
    std::unordered_map<int, int> node_index;
    node_index.reserve(nodes_.size());
    mesh.nodes.reserve(nodes_.size());
    for (const RawNode& r : nodes_) {
      auto [it, fresh] = node_index.emplace(r.id, static_cast<int>(mesh.nodes.size()));
      if (!fresh)
        throw InputError("duplicate node id (first defined at line " +
                             std::to_string(mesh.nodes[it->second].origin.line) + ")",
                         {file, r.line, "node " + std::to_string(r.id)});
      fe::Node n;
      n.id = r.id;
      n.x = r.x;
      n.origin = {file, r.line};
      mesh.nodes.push_back(std::move(n));
    }
    nodes_.clear();
    nodes_.shrink_to_fit();

    // elements. gmsh 2.2 writes an element that is in several physical
    // groups once per group, under new ids: such copies (same type,
    // elementary entity and nodes, another group) are merged into the first.
    std::unordered_map<int, size_t> first;               // element id -> raw index
    std::map<std::vector<int>, size_t> copies;           // 2.2: (type, entity, nodes) -> raw index
    std::vector<int> element_of(elements_.size(), -1);   // raw -> mesh element index
    std::map<std::string, std::set<int>> element_sets, node_sets;
    std::vector<int> idx, key;
    // 4.1: the physical groups of an element are those of its entity
    if (v41_) {
      for (RawElement& e : elements_) {
        auto it = entity_groups_.find({e.entity_dim, e.entity});
        if (it != entity_groups_.end())
          for (int p : it->second) e.groups.emplace_back(e.entity_dim, p);
      }
    }
    // highest dimension of the supported elements at each node
    std::vector<int8_t> max_dim(mesh.nodes.size(), -1);
    for (const RawElement& e : elements_) {
      if (!e.type.supported || e.type.point) continue;
      for (int id : e.node_ids) {
        auto it = node_index.find(id);
        if (it != node_index.end()) max_dim[it->second] = std::max<int8_t>(max_dim[it->second], e.type.dim);
      }
    }
    for (size_t r = 0; r < elements_.size(); ++r) {
      RawElement& e = elements_[r];
      const std::string entity = "element " + std::to_string(e.id);
      idx.clear();
      for (int id : e.node_ids) {
        auto it = node_index.find(id);
        if (it == node_index.end())
          throw InputError("node " + std::to_string(id) + " does not exist", {file, e.line, entity});
        idx.push_back(it->second);
      }
      auto [f, fresh] = first.emplace(e.id, r);
      if (!fresh)
        throw InputError("duplicate element id (first defined at line " + std::to_string(elements_[f->second].line) +
                             ")",
                         {file, e.line, entity});
      int index = -1;
      bool merged = false;
      if (!v41_ && e.groups.size() == 1) {
        key.assign({e.code, e.entity});
        key.insert(key.end(), e.node_ids.begin(), e.node_ids.end());
        auto [c, novel] = copies.emplace(key, r);
        if (!novel) {
          RawElement& o = elements_[c->second];
          if (std::find(o.groups.begin(), o.groups.end(), e.groups[0]) == o.groups.end()) {
            o.groups.push_back(e.groups[0]);
            index = element_of[c->second];
            merged = true;
          }
        }
      }
      bool covered = e.type.boundary_if_covered;
      for (int n : idx) covered = covered && max_dim[n] > e.type.dim;
      if (!e.type.supported || covered) {
        // a face or edge of supported elements (e.g. the 6-node triangles of a
        // physical surface on a 10-node tetrahedral mesh) only marks nodes
        for (int n : idx)
          if (max_dim[n] <= e.type.dim)
            throw InputError(UnsupportedType(e.code) +
                                 "; an element of another type is accepted only as a boundary of supported "
                                 "elements of higher dimension (its nodes then join the node sets of its groups)",
                             {file, e.line, entity});
        merged = true;
      }
      if (!merged && !e.type.point) {
        fe::Element el;
        el.id = e.id;
        el.type = e.type.type;
        el.nodes = idx;
        for (size_t k = 0; k < idx.size(); ++k) el.nodes[k] = idx[fe::FormatNode(e.type.order, static_cast<int>(k))];
        el.origin = {file, e.line};
        index = static_cast<int>(mesh.elements.size());
        mesh.elements.push_back(std::move(el));
      }
      element_of[r] = index;
      for (const GroupKey& g : e.groups) {
        const std::string name = GroupName(g);
        node_sets[name].insert(idx.begin(), idx.end());
        if (index >= 0) element_sets[name].insert(index);
      }
    }
    for (auto& [name, set] : node_sets) mesh.node_sets[name].assign(set.begin(), set.end());
    for (auto& [name, set] : element_sets) mesh.element_sets[name].assign(set.begin(), set.end());
    mesh.IndexNodes();
    return mesh;
  }

  TextScanner s_;
  std::vector<std::string_view> tok_;
  bool v41_ = false;
  bool seen_nodes_ = false, seen_elements_ = false;
  std::map<GroupKey, std::string> names_;
  std::map<GroupKey, std::vector<int>> entity_groups_;
  std::vector<RawNode> nodes_;
  std::vector<RawElement> elements_;
};

}  // namespace

fe::Mesh ReadGmsh(const std::string& path) { return GmshParser(path).Parse(); }

}  // namespace flexmb::io
