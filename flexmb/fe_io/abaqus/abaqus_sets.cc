#include <climits>
#include <map>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/abaqus/abaqus_builder.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io::abaqus {
namespace {

using fe::ElementType;
using fe::Origin;

// element faces (1-based node positions) for element-based surfaces
const fe::AbaqusFace* Face(ElementType t, const std::string& label) {
  for (const fe::AbaqusFace& f : fe::Traits(t).abaqus_faces)
    if (label == f.label) return &f;
  return nullptr;
}

}  // namespace

NamedSet& Builder::NewSet(std::map<std::string, NamedSet>& sets, const std::string& name, const Origin& o,
                 const std::string& entity) {
  if (name.empty()) Fail(o, entity, "empty set name");
  NamedSet& s = sets[Upper(name)];
  if (s.name.empty()) s.name = name;
  return s;
}

// an existing set, also under an instance-qualified name "Part-1-1.name"
NamedSet* Builder::FindSet(std::map<std::string, NamedSet>& sets, const std::string& name) {
  auto it = sets.find(Upper(name));
  if (it == sets.end()) {
    const size_t dot = name.rfind('.');
    if (dot != std::string::npos) it = sets.find(Upper(name.substr(dot + 1)));
  }
  return it == sets.end() ? nullptr : &it->second;
}

NamedSet& Builder::NodeSetRef(const std::string& name, const Origin& o, const std::string& entity) {
  NamedSet* s = FindSet(nsets_, name);
  if (s == nullptr) Fail(o, entity, "unknown node set '" + Printable(name) + "'");
  return *s;
}

NamedSet& Builder::ElementSetRef(const std::string& name, const Origin& o, const std::string& entity) {
  NamedSet* s = FindSet(elsets_, name);
  if (s == nullptr) Fail(o, entity, "unknown element set '" + Printable(name) + "'");
  return *s;
}

// node indices of the elements of an element set
void Builder::AddElementNodes(const NamedSet& es, NamedSet& out) {
  for (int id : es.items) {
    const ElementRecord& r = elements_.at(id);
    if (r.kind == Kind::kStructural) {
      for (int n : mesh_.elements[r.index].nodes) out.Add(n);
    } else {
      out.Add(masses_[r.index].node);
      if (masses_[r.index].node_b >= 0) out.Add(masses_[r.index].node_b);
    }
  }
}

// the items of a set card: ids (checked by `exists`, added by `add`) or
// names of sets (added by `copy_set`)
template <class Exists, class Add, class Copy>
void Builder::SetItems(const Card& c, const std::string& entity, const char* what, Exists&& exists, Add&& add,
              Copy&& copy_set) {
  const bool generate = c.Find("GENERATE") != nullptr;
  for (const DataLine& d : c.data) {
    if (generate) {
      MaxFields(d, 3, entity);
      const int first = Integer(d, 0, entity, "first id", 1, INT_MAX);
      const int last = Integer(d, 1, entity, "last id", 1, INT_MAX);
      const int inc = d.fields.size() > 2 && !d.fields[2].empty() ? Integer(d, 2, entity, "increment", 1, INT_MAX) : 1;
      if (last < first) Fail(d.origin, entity, "GENERATE range ends before it starts");
      for (int64_t id = first; id <= last; id += inc) {
        if (!exists(static_cast<int>(id)))
          Fail(d.origin, entity, std::string(what) + " " + std::to_string(id) + " does not exist");
        add(static_cast<int>(id));
      }
      continue;
    }
    for (size_t k = 0; k < d.fields.size(); ++k) {
      const std::string& f = d.fields[k];
      if (f.empty()) Fail(d.origin, entity, "empty entry");
      int64_t id = 0;
      if (ParseInt(f, id)) {
        if (id < 1 || id > INT_MAX || !exists(static_cast<int>(id)))
          Fail(d.origin, entity, std::string(what) + " " + f + " does not exist");
        add(static_cast<int>(id));
      } else {
        copy_set(f, d.origin, entity);
      }
    }
  }
}

// a node id or the name of a node set, as node indices
std::vector<int> Builder::NodesOf(const std::string& f, const Origin& o, const std::string& entity) {
  int64_t id = 0;
  if (!ParseInt(f, id)) return NodeSetRef(f, o, entity).items;
  const int n = NodeOfId(id);
  if (n < 0) Fail(o, entity, "node " + f + " does not exist");
  return {n};
}

void Builder::NodeSet(const Card& c) {
  const Param* p = c.Find("NSET");
  if (p == nullptr) Fail(c.origin, c.name, "needs NSET=");
  NamedSet& set = NewSet(nsets_, p->value, c.origin, c.name);
  const std::string entity = c.name + " " + set.name;
  if (const Param* e = c.Find("ELSET")) AddElementNodes(ElementSetRef(e->value, c.origin, entity), set);
  SetItems(
      c, entity, "node", [&](int id) { return mesh_.NodeIndex(id) >= 0; },
      [&](int id) { set.Add(mesh_.NodeIndex(id)); },
      [&](const std::string& name, const Origin& o, const std::string& ent) {
        const NamedSet& other = NodeSetRef(name, o, ent);
        for (int n : std::vector<int>(other.items)) set.Add(n);
      });
}

void Builder::ElementSet(const Card& c) {
  const Param* p = c.Find("ELSET");
  if (p == nullptr) Fail(c.origin, c.name, "needs ELSET=");
  NamedSet& set = NewSet(elsets_, p->value, c.origin, c.name);
  const std::string entity = c.name + " " + set.name;
  SetItems(
      c, entity, "element", [&](int id) { return elements_.count(id) > 0; }, [&](int id) { set.Add(id); },
      [&](const std::string& name, const Origin& o, const std::string& ent) {
        const NamedSet& other = ElementSetRef(name, o, ent);
        for (int id : std::vector<int>(other.items)) set.Add(id);
      });
}

void Builder::Surface(const Card& c) {
  const Param* p = c.Find("NAME");
  if (p == nullptr || p->value.empty()) Fail(c.origin, c.name, "needs NAME=");
  const std::string entity = c.name + " " + p->value;
  const Param* tp = c.Find("TYPE");
  const std::string type = tp ? Upper(tp->value) : "ELEMENT";
  NamedSet nodes;
  // weight of each node for a distributing coupling: a face's area shared
  // equally by its nodes (linear faces), or the node-based entry's weight
  std::map<int, double> weight;
  bool weights_ok = true;
  std::vector<SurfaceFace> faces;
  for (const DataLine& d : c.data) {
    if (d.fields.empty() || d.fields[0].empty()) Fail(d.origin, entity, "empty entry");
    const std::string& f = d.fields[0];
    if (type == "NODE") {
      MaxFields(d, 2, entity);
      const double w = RealOr(d, 1, entity, "node weight", 1.0);
      for (int n : NodesOf(f, d.origin, entity)) {
        nodes.Add(n);
        weight[n] += w;
      }
    } else if (type == "ELEMENT") {
      MaxFields(d, 2, entity);
      const std::string face = d.fields.size() > 1 ? Upper(d.fields[1]) : "";
      std::vector<int> ids;
      int64_t id = 0;
      if (ParseInt(f, id)) {
        if (id < 1 || id > INT_MAX || !elements_.count(static_cast<int>(id)))
          Fail(d.origin, entity, "element " + f + " does not exist");
        ids.push_back(static_cast<int>(id));
      } else {
        ids = ElementSetRef(f, d.origin, entity).items;
      }
      for (int eid : ids) {
        const ElementRecord& r = elements_.at(eid);
        if (r.kind != Kind::kStructural) Fail(d.origin, entity, ElementName(eid) + " has no faces");
        const fe::Element& e = mesh_.elements[r.index];
        const fe::AbaqusFace* nodes_of_face = Face(e.type, face);
        if (nodes_of_face == nullptr)
          Fail(d.origin, entity, "face '" + Printable(face) + "' does not exist on " + ElementName(eid));
        const int nf = nodes_of_face->count;
        auto corner = [&](int k) { return mesh_.nodes[e.nodes[nodes_of_face->nodes[k] - 1]].x; };
        double area = 0.0;
        if (nf == 3) area = 0.5 * (corner(1) - corner(0)).cross(corner(2) - corner(0)).norm();
        if (nf == 4) area = 0.5 * (corner(2) - corner(0)).cross(corner(3) - corner(1)).norm();
        weights_ok = weights_ok && (nf == 3 || nf == 4);
        SurfaceFace sf{eid, {}};
        for (int k = 0; k < nf; ++k) sf.nodes.push_back(e.nodes[nodes_of_face->nodes[k] - 1]);
        faces.push_back(std::move(sf));
        for (int k = 0; k < nf; ++k) {
          nodes.Add(e.nodes[nodes_of_face->nodes[k] - 1]);
          weight[e.nodes[nodes_of_face->nodes[k] - 1]] += area / nf;
        }
      }
    } else {
      Fail(c.origin, entity, "TYPE=" + tp->value + " is not supported (NODE or ELEMENT)");
    }
  }
  surfaces_[Upper(p->value)] = nodes.items;
  surface_faces_[Upper(p->value)] = std::move(faces);
  std::vector<double>& w = surface_weights_[Upper(p->value)];
  w.clear();
  if (weights_ok)
    for (int n : nodes.items) w.push_back(weight[n]);
}

}  // namespace flexmb::io::abaqus
