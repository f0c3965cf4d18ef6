#include "flexmb/fe_io/node_selection.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace flexmb::io {

std::vector<int> SelectNodes(const fe::Mesh& mesh, const std::string& mesh_name, const YAML::Node& v,
                             const YamlContext& ctx) {
  if (v.size() != 1 || !(v["cylinder"] || v["box"])) {
    std::string keys;
    for (auto it = v.begin(); it != v.end(); ++it)
      keys += (keys.empty() ? "" : ", ") + std::string("'") + (it->first.IsScalar() ? it->first.Scalar() : "?") + "'";
    ctx.Fail(v, "a node selection is {cylinder: {from, to, radius, tolerance}} or {box: {min, max, tolerance}}" +
                    (keys.empty() ? std::string() : ", got " + keys));
  }
  // a tolerance >= 0
  const auto tolerance = [&](const YAML::Node& n, double fallback) {
    if (!n["tolerance"]) return fallback;
    const double t = ctx.Number(n["tolerance"], "'tolerance'");
    if (!(t >= 0.0)) ctx.Fail(n["tolerance"], "'tolerance' must not be negative");
    return t;
  };
  std::vector<int> out;
  const int nn = static_cast<int>(mesh.nodes.size());
  double nearest = std::numeric_limits<double>::infinity();
  int nearest_node = -1;
  auto consider = [&](int n, double miss) {
    if (miss <= 0.0) out.push_back(n);
    if (miss < nearest) nearest = miss, nearest_node = n;
  };
  std::string what;
  if (v["cylinder"]) {
    const YAML::Node c = v["cylinder"];
    ctx.CheckKeys(c, {"from", "to", "radius", "tolerance"});
    const fe::Vec3 p = ctx.Vector3(c, "from"), q = ctx.Vector3(c, "to");
    const double r = ctx.Positive(c, "radius");
    const double tol = tolerance(c, 1e-3 * r);
    const double length = (q - p).norm();
    if (!(length > 0.0)) ctx.Fail(c, "the cylinder's 'from' and 'to' must differ");
    const fe::Vec3 axis = (q - p) / length;
    for (int n = 0; n < nn; ++n) {
      const fe::Vec3 d = mesh.nodes[n].x - p;
      const double a = d.dot(axis);
      const double radial = std::abs((d - a * axis).norm() - r);
      consider(n, std::max({radial - tol, -a - tol, a - length - tol}));
    }
    what = "the cylinder";
  } else {
    const YAML::Node b = v["box"];
    ctx.CheckKeys(b, {"min", "max", "tolerance"});
    const fe::Vec3 lo = ctx.Vector3(b, "min"), hi = ctx.Vector3(b, "max");
    if (!(lo.array() <= hi.array()).all()) ctx.Fail(b, "the box's 'min' must not exceed its 'max' in any axis");
    const double tol = tolerance(b, 0.0);
    for (int n = 0; n < nn; ++n) {
      const fe::Vec3& x = mesh.nodes[n].x;
      consider(n, std::max((lo - x).maxCoeff(), (x - hi).maxCoeff()) - tol);
    }
    what = "the box";
  }
  if (out.empty())
    ctx.Fail(v, "the selection picks no node of " + mesh_name +
                     (nearest_node < 0 ? std::string(" (it has no nodes)")
                                       : ": the nearest is node " + std::to_string(mesh.nodes[nearest_node].id) +
                                             " at " + fmt::format("({:.6g}, {:.6g}, {:.6g})",
                                                                  mesh.nodes[nearest_node].x.x(),
                                                                  mesh.nodes[nearest_node].x.y(),
                                                                  mesh.nodes[nearest_node].x.z()) +
                                             ", which misses " + what + " by " + fmt::format("{:.4g}", nearest) +
                                             " (beyond the tolerance)"));
  return out;
}

}  // namespace flexmb::io
