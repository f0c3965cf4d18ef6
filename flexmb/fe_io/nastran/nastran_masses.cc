#include <array>
#include <cmath>
#include <string>

#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

// PMASS: up to four properties (PID M) on one card
void Builder::AddPmass(const Entry& e) {
  for (int first : {1, 3, 5, 7}) {
    if (first > 1 && e.Blank(first) && e.Blank(first + 1)) continue;
    const int pid = e.Id(first, "PID");
    CheckNewId(property_origin_, e, pid, "property");
    const double m = e.Real(first + 1, "M");
    if (!std::isfinite(m) || m < 0.0) e.Fail(first + 1, "scalar mass M must not be negative, got " + Str(m));
    properties_[pid] = PropertyRef{"PMASS", static_cast<int>(pmass_m_.size())};
    pmass_m_.push_back(m);
  }
  if (e.Size() > 8) e.Fail(9, "unexpected field");
}

// CMASS1 (EID PID G1 C1 G2 C2) and CMASS2 (EID M G1 C1 G2 C2): a scalar mass
// on one grid component (to ground), or between two components of one
// grid, written as that node's 6 x 6 mass matrix m a a^T with a = the
// component's axis (of the grid's displacement system CD) minus the other's
void Builder::AddCmass(const Entry& e) {
  fe::PointMass pm;
  pm.id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, pm.id, "element");
  double m = 0.0;
  if (e.name() == "CMASS1") {
    m = pmass_m_[PropertyIndex(e, 2, e.Int(2, "PID", pm.id), {"PMASS"})];
  } else {
    m = e.Real(2, "M");
    if (!std::isfinite(m) || m < 0.0) e.Fail(2, "scalar mass M must not be negative, got " + Str(m));
  }
  if (e.Size() > 6) e.Fail(7, "unexpected field");
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
  int node_a = -1, component_a = 0, node_b = -1, component_b = 0;
  const bool has_a = end(3, node_a, component_a);
  const bool has_b = end(5, node_b, component_b);
  if (!has_a && !has_b) e.Fail(3, "both grids are blank: the scalar mass connects nothing");
  if (has_a && has_b && node_a != node_b)
    e.Fail(5, "a scalar mass between two different grids (" + std::to_string(mesh_.nodes[node_a].id) + " and " +
                  std::to_string(mesh_.nodes[node_b].id) +
                  ") is not supported: its mass matrix couples the two nodes; give one grid, or use CONM2");
  if (has_a && has_b && component_a == component_b)
    e.Fail(5, "the scalar mass connects component " + std::to_string(component_a + 1) + " of grid " +
                  std::to_string(mesh_.nodes[node_a].id) + " to itself");
  pm.node = has_a ? node_a : node_b;
  // a = axis of the first component minus that of the second, basic frame
  Eigen::Matrix<double, 6, 1> a = Eigen::Matrix<double, 6, 1>::Zero();
  const fe::Mat3 basis = CdBasis(pm.node);
  auto add_axis = [&](int component, double sign) {
    a.segment<3>(3 * (component / 3)) += sign * basis.col(component % 3);
  };
  if (has_a) add_axis(component_a, 1.0);
  if (has_b) add_axis(component_b, -1.0);
  pm.general = true;
  pm.matrix = m * a * a.transpose();
  pm.origin = OriginOf(e);
  mesh_.point_masses.push_back(pm);
}
}  // namespace flexmb::io::nastran
