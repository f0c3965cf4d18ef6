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
