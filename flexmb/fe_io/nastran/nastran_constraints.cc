#include <set>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

void Builder::AddRbe2(const Entry& e) {
  fe::RigidLink link;
  link.id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, link.id, "element");
  link.independent = NodeIndex(e, 2, "GN");
  link.dofs = Components(e, 3, "CM");
  std::set<int> seen;
  bool any = false;
  for (const auto& [node, field] : GridList(e, 4, true, true)) {
    if (node == link.independent)
      e.Fail(field, "dependent node " + std::to_string(mesh_.nodes[node].id) + " is the independent node GN");
    if (!seen.insert(node).second)
      e.Fail(field, "dependent node " + std::to_string(mesh_.nodes[node].id) + " is listed twice");
    any = true;
    // components along the axes of a displacement system: linear constraints
    if (AddCdRigid(e, link.id, link.independent, node, link.dofs)) continue;
    link.dependent.push_back(node);
  }
  if (!any) e.Fail(4, "no dependent grid points GMi");
  link.origin = OriginOf(e);
  if (!link.dependent.empty()) mesh_.rigid_links.push_back(std::move(link));
}

void Builder::AddToSet(const std::string& name, int node) {
  if (set_members_[name].insert(node).second) mesh_.node_sets[name].push_back(node);
}

void Builder::AddSpc(const Entry& e) {
  // all SPC / SPC1 sets are merged, whatever their SID (no case control)
  e.Int(1, "SID");
  if (e.name() == "SPC1") {
    const int mask = Components(e, 2, "C");
    const std::vector<std::pair<int, int>> nodes = GridList(e, 3, false, false);
    if (nodes.empty() && e.Size() < 3) e.Fail(3, "no grid points");
    for (const auto& [node, field] : nodes) AddFixed(e, node, mask);
    return;
  }
  for (int f = 2; f <= e.Size(); f += 3) {
    if (e.Blank(f)) continue;
    const int node = NodeIndex(e, f, "G");
    const int mask = Components(e, f + 1, "C");
    if (e.Real(f + 2, "D", 0.0) != 0.0)
      Warn(e, "enforced displacement D is ignored: the DOF is constrained to zero", "SPC D");
    AddFixed(e, node, mask);
  }
}

void Builder::AddBoundarySet(const Entry& e) {
  const std::string set = e.name().substr(0, 4);  // ASET or BSET
  auto note_components = [&](int mask) {
    if (mask != 0b111111)
      Warn(e, set + " components other than 123456: the node set '" + set +
                  "' keeps whole nodes, not components", set + " components");
  };
  if (e.name().back() == '1') {
    note_components(Components(e, 1, "C"));
    for (const auto& [node, field] : GridList(e, 2, false, false)) AddToSet(set, node);
    return;
  }
  for (int f = 1; f <= e.Size(); f += 2) {
    if (e.Blank(f)) continue;
    const int node = NodeIndex(e, f, "ID");
    note_components(Components(e, f + 1, "C"));
    AddToSet(set, node);
  }
}

void Builder::AddSet1(const Entry& e) {
  const int sid = e.Id(1, "SID");
  const std::string name = "SET1_" + std::to_string(sid);
  if (mesh_.node_sets.count(name)) e.Fail(1, "duplicate SET1 id " + std::to_string(sid));
  for (int f = 2; f <= e.Size(); ++f) {
    if (e.Text(f) == "SKIN") {
      Warn(e, "SET1 with SKIN is not supported; the set is skipped", "SET1 SKIN");
      return;
    }
  }
  // a SET1 may list element or other ids: a set that is not all grids is skipped
  bool missing = false;
  const std::vector<std::pair<int, int>> nodes = GridList(e, 2, false, false, &missing);
  if (missing) {
    Warn(e, "SET1 lists ids that are not grid points; the set is skipped", "SET1 " + std::to_string(sid));
    return;
  }
  mesh_.node_sets[name];
  for (const auto& [node, field] : nodes) AddToSet(name, node);
}

}  // namespace flexmb::io::nastran

namespace flexmb::io::nastran {

// MPC SID G1 C1 A1 G2 C2 A2, continuations (field 2 blank) G C A G C A:
// sum_j A_j u_j = 0 with u_1 dependent, u_1 = -sum_j>1 (A_j / A_1) u_j. The
// components are in each grid's displacement system (CD); an independent
// term in a CD system is written on the basic components of its grid.
void Builder::AddMpc(const Entry& e) {
  // all MPC sets are merged, whatever their SID (no case control), as SPCs
  e.Int(1, "SID");
  struct Term {
    int node, component, field;
    double a;
  };
  std::vector<Term> terms;
  auto read = [&](int f) {
    if (e.Blank(f) && e.Blank(f + 1) && e.Blank(f + 2)) return;
    const int node = NodeIndex(e, f, "G");
    const int c = e.Int(f + 1, "C");
    if (c < 1 || c > 6)
      e.Fail(f + 1, "component C must be one of 1 to 6 (" + std::to_string(c) + "; scalar points are not supported)");
    terms.push_back({node, c - 1, f, e.Real(f + 2, "A")});
  };
  read(2);
  read(5);
  for (int base = 9; base <= e.Size(); base += 8) {
    if (!e.Blank(base)) e.Fail(base, "field 2 of an MPC continuation must be blank");
    read(base + 1);
    read(base + 4);
  }
  if (terms.size() < 2) e.Fail(2, "an MPC needs at least two terms (G1 C1 A1 and one more)");
  const Term& dep = terms.front();
  if (dep.a == 0.0) e.Fail(dep.field + 2, "A1, the coefficient of the dependent DOF, must not be 0");
  if (node_cd_[dep.node] != 0)
    e.Fail(dep.field, "the dependent grid " + std::to_string(mesh_.nodes[dep.node].id) +
                          " has a displacement coordinate system (CD); make it the independent one or use CD 0");
  fe::LinearConstraint row;
  row.id = e.Int(1, "SID");
  row.card = "MPC";
  row.node = dep.node;
  row.component = dep.component;
  row.origin = OriginOf(e);
  for (size_t k = 1; k < terms.size(); ++k) {
    const Term& t = terms[k];
    if (t.node == dep.node && t.component == dep.component)
      e.Fail(t.field, "the dependent DOF (G1, C1) appears again");
    if (t.a == 0.0) continue;
    const double g = -t.a / dep.a;
    if (node_cd_[t.node] == 0) {
      row.terms.push_back(fe::MpcTerm{t.node, t.component, g});
      continue;
    }
    // u_CD,c = axis_c . u_basic of its block
    const fe::Mat3 basis = CdBasis(t.node);
    const int block = t.component < 3 ? 0 : 3;
    for (int b = 0; b < 3; ++b) {
      const double w = basis(b, t.component - block);
      if (std::abs(w) > 1e-15) row.terms.push_back(fe::MpcTerm{t.node, block + b, g * w});
    }
  }
  mesh_.linear_constraints.push_back(std::move(row));
}

}  // namespace flexmb::io::nastran
