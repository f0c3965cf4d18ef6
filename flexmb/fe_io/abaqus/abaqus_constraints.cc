#include <map>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/linear_constraint.h"
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
  bool distributing = false;
  for (int j : order) {
    const Card& k = cards[j];
    if (k.parent != i) continue;
    distributing = k.key == "DISTRIBUTING";
    if (distributing && k.Find("WEIGHTINGMETHOD") && Upper(k.Find("WEIGHTINGMETHOD")->value) != "UNIFORM")
      Fail(k.origin, entity, "WEIGHTING METHOD=" + k.Find("WEIGHTINGMETHOD")->value + " is not supported (UNIFORM)");
    mask = k.data.empty() ? 0b111111 : 0;
    for (const DataLine& d : k.data) {
      MaxFields(d, 2, entity);
      mask |= DofRange(d, 0, entity);
    }
  }
  if (mask < 0) Fail(c.origin, entity, "needs a *KINEMATIC or *DISTRIBUTING sub-option");
  if (!distributing) return AddLink(ref, it->second, mask, c.origin, entity);
  // an RBE3 over the surface's translations, weighted as CalculiX does:
  // by area for a facial surface, by the entries' weights for a node-based one
  const std::vector<double>& w = surface_weights_[Upper(sp->value)];
  if (w.size() != it->second.size())
    Fail(c.origin, entity, "*DISTRIBUTING on a surface of faces with mid-side nodes is not supported (no area weights)");
  fe::Rbe3Spec spec;
  spec.id = ++link_count_;
  spec.card = "*COUPLING";
  spec.ref_node = ref;
  spec.ref_components = mask;
  spec.origin = c.origin;
  for (size_t k = 0; k < w.size(); ++k)
    if (it->second[k] != ref) spec.groups.push_back({w[k], 0b111, {it->second[k]}});
  for (fe::LinearConstraint& row : fe::Rbe3Constraints(mesh_, spec)) mesh_.linear_constraints.push_back(std::move(row));
}

// *EQUATION: a line with the number of terms N, then N terms (node, DOF,
// coefficient), at most four on a line; the first term's DOF is dependent:
// u_1 = -sum_k>1 (a_k / a_1) u_k
void Builder::Equation(const Card& c) {
  size_t line = 0;
  while (line < c.data.size()) {
    const DataLine& head = c.data[line++];
    MaxFields(head, 1, c.name);
    const int count = Integer(head, 0, c.name, "number of terms", 2, 100000);
    std::vector<fe::MpcTerm> terms;
    fe::Origin origin = head.origin;
    while (static_cast<int>(terms.size()) < count) {
      if (line >= c.data.size()) Fail(head.origin, c.name, "fewer terms than the " + std::to_string(count) + " announced");
      const DataLine& d = c.data[line++];
      MaxFields(d, 12, c.name);
      for (size_t f = 0; f < d.fields.size(); f += 3) {
        if (d.fields[f].empty()) break;
        if (static_cast<int>(terms.size()) == count) Fail(d.origin, c.name, "more terms than the " + std::to_string(count) + " announced");
        const std::vector<int> nodes = NodesOf(d.fields[f], d.origin, c.name);
        if (nodes.size() != 1) Fail(d.origin, c.name, "node set '" + d.fields[f] + "' must hold exactly one node");
        const int dof = Integer(d, f + 1, c.name, "degree of freedom", 1, 6);
        const double a = RealReq(d, f + 2, c.name, "coefficient");
        terms.push_back(fe::MpcTerm{nodes[0], dof - 1, a});
      }
    }
    const fe::MpcTerm first = terms.front();
    if (first.coef == 0.0) Fail(origin, c.name, "the first (dependent) term has coefficient 0");
    fe::LinearConstraint row;
    row.id = ++link_count_;
    row.card = "*EQUATION";
    row.node = first.node;
    row.component = first.component;
    row.origin = origin;
    for (size_t k = 1; k < terms.size(); ++k) {
      if (terms[k].node == first.node && terms[k].component == first.component)
        Fail(origin, c.name, "the dependent DOF appears twice");
      if (terms[k].coef != 0.0) row.terms.push_back({terms[k].node, terms[k].component, -terms[k].coef / first.coef});
    }
    mesh_.linear_constraints.push_back(std::move(row));
  }
}

}  // namespace flexmb::io::abaqus
