#include <array>
#include <cmath>
#include <string>

#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

// PELAS: up to two properties (PID K GE S) on one card
void Builder::AddPelas(const Entry& e) {
  for (int first : {1, 5}) {
    if (first == 5 && e.Blank(5) && e.Blank(6) && e.Blank(7) && e.Blank(8)) break;
    const int pid = e.Id(first, "PID");
    CheckNewId(property_origin_, e, pid, "property");
    const double k = e.Real(first + 1, "K");
    if (!std::isfinite(k) || k < 0.0) e.Fail(first + 1, "spring stiffness K must not be negative, got " + Str(k));
    const double ge = e.Real(first + 2, "GE", 0.0);
    if (ge != 0.0)
      Warn(e, "structural damping GE of PELAS is ignored (flexmb's FE model has no damping matrix)", "PELAS GE");
    e.Real(first + 3, "S", 0.0);
    properties_[pid] = PropertyRef{"PELAS", static_cast<int>(pelas_k_.size())};
    pelas_k_.push_back(k);
  }
  if (e.Size() > 8) e.Fail(9, "unexpected field");
}

// CELAS1 (EID PID G1 C1 G2 C2) and CELAS2 (EID K G1 C1 G2 C2 GE S): a
// spring between two grid components, or to ground when one grid is blank
void Builder::AddCelas(const Entry& e) {
  fe::ScalarSpring s;
  s.id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, s.id, "element");
  if (e.name() == "CELAS1") {
    s.k = pelas_k_[PropertyIndex(e, 2, e.Int(2, "PID", s.id), {"PELAS"})];
    if (e.Size() > 6) e.Fail(7, "unexpected field");
  } else {
    s.k = e.Real(2, "K");
    if (!std::isfinite(s.k) || s.k < 0.0) e.Fail(2, "spring stiffness K must not be negative, got " + Str(s.k));
    if (e.Real(7, "GE", 0.0) != 0.0)
      Warn(e, "structural damping GE of CELAS2 is ignored (flexmb's FE model has no damping matrix)", "CELAS2 GE");
    e.Real(8, "S", 0.0);
    if (e.Size() > 8) e.Fail(9, "unexpected field");
  }
  // one end: grid (field g) and component (field g + 1); false if blank or 0 (ground)
  auto end = [&](int g, int& node, int& component) {
    if (e.Blank(g) || e.Text(g) == "0") {
      if (!e.Blank(g + 1) && e.Text(g + 1) != "0") e.Fail(g + 1, "a component is given without a grid");
      return false;
    }
    node = NodeIndex(e, g, g == 3 ? "G1" : "G2");
    const std::string& c = e.Text(g + 1);
    if (c.size() != 1 || c[0] < '1' || c[0] > '6')
      e.Fail(g + 1, std::string(g == 3 ? "C1" : "C2") + ": component '" + c +
                        "' is not a single digit 1 to 6 (scalar points are not supported)");
    component = c[0] - '1';
    return true;
  };
  int node_b = -1, component_b = 0;
  const bool has_a = end(3, s.node_a, s.component_a);
  const bool has_b = end(5, node_b, component_b);
  if (!has_a && !has_b) e.Fail(3, "both grids are blank: the spring connects nothing");
  if (has_a) {
    s.node_b = has_b ? node_b : -1;
    s.component_b = has_b ? component_b : 0;
  } else {
    s.node_a = node_b;
    s.component_a = component_b;
  }
  if (s.node_a == s.node_b && s.component_a == s.component_b)
    e.Fail(5, "the spring connects component " + std::to_string(s.component_a + 1) + " of node " +
                  std::to_string(mesh_.nodes[s.node_a].id) + " to itself");
  // a component of a node with a displacement system acts along that
  // system's axis at the node: a directional spring in basic components
  if (node_cd_[s.node_a] != 0 || (s.node_b >= 0 && node_cd_[s.node_b] != 0)) {
    auto coefficients = [&](int node, int component, std::array<double, 6>& coef) {
      const fe::Vec3 axis = CdBasis(node).col(component % 3);
      for (int j = 0; j < 3; ++j) coef[3 * (component / 3) + j] = axis[j];
    };
    s.directional = true;
    coefficients(s.node_a, s.component_a, s.coef_a);
    if (s.node_b >= 0) coefficients(s.node_b, s.component_b, s.coef_b);
  }
  s.origin = OriginOf(e);
  mesh_.springs.push_back(s);
}

}  // namespace flexmb::io::nastran
