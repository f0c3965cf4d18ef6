// Reads a model-file body of type ancf_beam (docs/model-file.md, "ANCF beams"):
//   name, type, length, elements, section {area, inertia} | {diameter},
//   material {E, rho}, start [3], direction [3], normal [3], damping,
//   curvature, load_per_length [3], markers [{name, node | end, position, orientation}]
#include "flexmb/io/ancf_body_parser.h"

#include <cmath>
#include <memory>
#include <numbers>

#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/common/error.h"
#include "flexmb/model/model.h"

namespace flexmb {
namespace {

std::string Quote(const std::string& s) { return "'" + s + "'"; }

}  // namespace

bool IsAncfBodyType(const std::string& type) { return type == "ancf_beam"; }

void ParseAncfBody(const YAML::Node& node, ParseContext& ctx, std::map<std::string, int>& lines) {
  ctx.CheckKeys(node, {"name", "type", "length", "elements", "section", "material", "start", "direction",
                       "normal", "damping", "curvature", "load_per_length", "markers"});
  const std::string name = ctx.String(node, "name");
  if (name.empty()) ctx.Fail(node["name"], "a body name must not be empty");
  if (name.find('.') != std::string::npos || name == "ground")
    ctx.Fail(node["name"], "invalid body name " + Quote(name));
  const std::string entity = "body '" + name + "'";
  ctx.SetEntity(entity);

  ancf::AncfBeam2dData d;
  d.length = ctx.Positive(node, "length");
  if (!node["elements"]) ctx.Fail(node, "missing key 'elements' (number of ANCF elements)");
  d.elements = ctx.Integer(node, "elements", 0);
  if (d.elements <= 0)
    ctx.Fail(node["elements"], "'elements' must be a positive whole number, got " +
                                   std::to_string(d.elements));

  const YAML::Node sec = node["section"];
  if (!sec || !sec.IsMap()) ctx.Fail(sec ? sec : node, "expected 'section' as {area, inertia} or {diameter}");
  if (sec["diameter"]) {
    ctx.CheckKeys(sec, {"diameter"});
    const double D = ctx.Positive(sec, "diameter");
    d.section.A = std::numbers::pi * D * D / 4.0;
    d.section.I = std::numbers::pi * D * D * D * D / 64.0;
  } else {
    ctx.CheckKeys(sec, {"area", "inertia"});
    d.section.A = ctx.Positive(sec, "area");
    d.section.I = ctx.Positive(sec, "inertia");
  }
  const YAML::Node mat = node["material"];
  if (!mat || !mat.IsMap()) ctx.Fail(mat ? mat : node, "expected 'material' as {E, rho}");
  ctx.CheckKeys(mat, {"E", "rho"});
  d.section.E = ctx.Positive(mat, "E");
  d.section.rho = ctx.Positive(mat, "rho");
  d.section.damping = ctx.Double(node, "damping", 0.0);
  if (d.section.damping < 0.0) ctx.Fail(node["damping"], "'damping' must not be negative");
  d.curvature0 = ctx.Double(node, "curvature", 0.0);
  d.start_W = ctx.Vector3(node, "start", Vec3::Zero());
  d.direction_W = ctx.Vector3(node, "direction", Vec3::UnitX());
  d.normal_W = ctx.Vector3(node, "normal", Vec3::UnitZ());
  d.load_per_length_W = ctx.Vector3(node, "load_per_length", Vec3::Zero());

  auto body = ctx.Guard(node, [&] { return std::make_unique<ancf::AncfBeam2dBody>(name, d); });
  const int nodes = body->nodes();
  const int b = ctx.Guard(node["name"], [&] { return ctx.model().AddBody(std::move(body)); });
  lines[entity] = ParseContext::Line(node);

  const YAML::Node list = node["markers"];
  if (!list) return;
  if (!list.IsSequence()) ctx.Fail(list, "expected 'markers' as a list of entries ('- ...')");
  for (const YAML::Node& m : list) {
    ctx.SetEntity(entity);
    ctx.CheckKeys(m, {"name", "node", "end", "position", "orientation"});
    const std::string mname = ctx.String(m, "name");
    if (mname.empty() || mname.find('.') != std::string::npos)
      ctx.Fail(m["name"], "invalid marker name " + Quote(mname));
    const std::string mentity = "marker '" + name + "." + mname + "'";
    ctx.SetEntity(mentity);
    int k = 0;
    if (m["node"] && m["end"]) ctx.Fail(m, "give either 'node' or 'end', not both");
    if (m["node"]) {
      k = ctx.Integer(m, "node", -1);
      if (k < 0 || k >= nodes)
        ctx.Fail(m["node"], "node " + std::to_string(k) + " does not exist: the beam has nodes 0.." +
                                std::to_string(nodes - 1));
    } else if (m["end"]) {
      const std::string end = ctx.String(m, "end");
      if (end == "start")
        k = 0;
      else if (end == "end")
        k = nodes - 1;
      else
        ctx.Fail(m["end"], "unknown 'end' " + Quote(end) + " (allowed: start, end)");
    } else {
      ctx.Fail(m, "an ANCF beam marker needs 'node: k' or 'end: start|end'");
    }
    const Vec3 p = ctx.Vector3(m, "position", Vec3::Zero());
    const Mat3 R = ctx.Orientation(m, "orientation");
    ctx.Guard(m, [&] { return ctx.model().AddMarker(b, mname, p, R, k); });
    lines[mentity] = ParseContext::Line(m);
  }
}

}  // namespace flexmb
