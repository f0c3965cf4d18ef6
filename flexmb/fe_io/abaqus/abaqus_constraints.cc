#include <map>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/abaqus/abaqus_builder.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io::abaqus {

using fe::Origin;

namespace {

// fields i (first) and i + 1 (last, blank for the first) as a component mask
int DofRange(const DataLine& d, size_t i, const std::string& entity) {
  const int first = Integer(d, i, entity, "first degree of freedom", 1, 6);
  const int last = d.fields.size() > i + 1 && !d.fields[i + 1].empty()
                       ? Integer(d, i + 1, entity, "last degree of freedom", 1, 6)
                       : first;
  if (last < first) Fail(d.origin, entity, "last degree of freedom before the first");
  int mask = 0;
  for (int k = first; k <= last; ++k) mask |= 1 << (k - 1);
  return mask;
}

}  // namespace

void Builder::Boundary(const Card& c) {
  static const std::map<std::string, int> kTypes = {
      {"ENCASTRE", 0b111111}, {"PINNED", 0b000111}, {"XSYMM", 0b110001}, {"YSYMM", 0b101010},
      {"ZSYMM", 0b011100},    {"XASYMM", 0b001110}, {"YASYMM", 0b010101}, {"ZASYMM", 0b100011}};
  for (const char* unsupported : {"USER", "TYPE"}) {
    const Param* p = c.Find(unsupported);
    if (p && !(std::string(unsupported) == "TYPE" && Upper(p->value) == "DISPLACEMENT"))
      Fail(c.origin, c.name, std::string(unsupported) + (p->has_value ? "=" + p->value : "") + " is not supported");
  }
  for (const DataLine& d : c.data) {
    const std::string entity = c.name;
    if (d.fields.size() < 2) Fail(d.origin, entity, "needs a node or node set and a degree of freedom");
    MaxFields(d, 4, entity);
    int mask = 0;
    const std::string second = Upper(d.fields[1]);
    if (kTypes.count(second)) {
      MaxFields(d, 2, entity);
      mask = kTypes.at(second);
    } else {
      mask = DofRange(d, 1, entity);
      const double value = RealOr(d, 3, entity, "prescribed value", 0.0);
      if (value != 0.0)
        Fail(d.origin, entity, "prescribed value " + d.fields[3] +
                                   ": only zero (fixed) boundary conditions are supported");
    }
    for (int n : NodesOf(d.fields[0], d.origin, entity)) {
      auto [it, fresh] = constraint_of_node_.emplace(n, static_cast<int>(mesh_.constraints.size()));
      if (fresh) {
        fe::Constraint k;
        k.node = n;
        k.dofs = 0;
        k.origin = d.origin;
        mesh_.constraints.push_back(k);
      }
      mesh_.constraints[it->second].dofs |= mask;
    }
  }
}

int Builder::RefNode(const Card& c, const std::string& entity) {
  const Param* p = c.Find("REFNODE");
  if (p == nullptr || p->value.empty()) Fail(c.origin, entity, "needs REF NODE=");
  int64_t id = 0;
  if (!ParseInt(p->value, id)) {
    // a node set with one node
    const NamedSet& s = NodeSetRef(p->value, c.origin, entity);
    if (s.items.size() != 1) Fail(c.origin, entity, "REF NODE set '" + p->value + "' must hold exactly one node");
    return s.items[0];
  }
  const int n = NodeOfId(id);
  if (n < 0) Fail(c.origin, entity, "reference node " + p->value + " does not exist");
  return n;
}

void Builder::AddLink(int ref, const std::vector<int>& nodes, int mask, const Origin& o, const std::string& entity) {
  fe::RigidLink l;
  l.id = ++link_count_;
  l.independent = ref;
  l.dofs = mask;
  l.origin = o;
  for (int n : nodes)
    if (n != ref) l.dependent.push_back(n);
  if (l.dependent.empty()) Fail(o, entity, "no dependent nodes besides the reference node");
  mesh_.rigid_links.push_back(std::move(l));
}

void Builder::RigidBody(const Card& c) {
  const std::string entity = c.name;
  const int ref = RefNode(c, entity);
  NamedSet tie, pin;
  for (const char* key : {"NSET", "TIENSET"})
    if (const Param* p = c.Find(key))
      for (int n : NodeSetRef(p->value, c.origin, entity).items) tie.Add(n);
  if (const Param* p = c.Find("ELSET")) AddElementNodes(ElementSetRef(p->value, c.origin, entity), tie);
  if (const Param* p = c.Find("PINNSET"))
    for (int n : NodeSetRef(p->value, c.origin, entity).items) pin.Add(n);
  if (tie.items.empty() && pin.items.empty()) Fail(c.origin, entity, "needs NSET=, TIE NSET=, PIN NSET= or ELSET=");
  if (!tie.items.empty()) AddLink(ref, tie.items, 0b111111, c.origin, entity);
  if (!pin.items.empty()) AddLink(ref, pin.items, 0b000111, c.origin, entity);
}

void Builder::Coupling(const std::vector<Card>& cards, const std::vector<int>& order, int i) {
  const Card& c = cards[i];
  const std::string entity = c.name;
  const int ref = RefNode(c, entity);
  const Param* sp = c.Find("SURFACE");
  if (sp == nullptr || sp->value.empty()) Fail(c.origin, entity, "needs SURFACE=");
  auto it = surfaces_.find(Upper(sp->value));
  if (it == surfaces_.end()) Fail(c.origin, entity, "unknown surface '" + Printable(sp->value) + "'");
  int mask = -1;
  for (int j : order) {
    const Card& k = cards[j];
    if (k.parent != i) continue;
    if (k.key == "DISTRIBUTING")
      Fail(k.origin, entity, "*DISTRIBUTING coupling is not supported (only *KINEMATIC)");
    mask = k.data.empty() ? 0b111111 : 0;
    for (const DataLine& d : k.data) {
      MaxFields(d, 2, entity);
      mask |= DofRange(d, 0, entity);
    }
  }
  if (mask < 0) Fail(c.origin, entity, "needs a *KINEMATIC sub-option");
  AddLink(ref, it->second, mask, c.origin, entity);
}

}  // namespace flexmb::io::abaqus
