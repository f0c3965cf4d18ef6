// Reads a model-file body of type ancf_beam, ancf_cable, ancf_beam3d or ancf_hoist_rope (docs/model-file.md,
// "ANCF beams"): name, type, length, elements, section {area, inertia} |
// {diameter}, material {E, rho}, start [3], direction [3] (ancf_cable: or
// end [3]), normal [3], damping, curvature (ancf_beam), angular_velocity [3]
// (ancf_cable), load_per_length [3], axial_strain (engineering |
// green_lagrange), markers [{name, node | end, position, orientation}];
// ancf_beam3d: section {area, Iy, Iz, J} or a list of one per element, material {E, G | nu,
// rho}, radius instead of curvature
#include "flexmb/model_file/ancf_body_parser.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/ancf/ancf_beam3d_body.h"
#include "flexmb/ancf/ancf_cable3d_body.h"
#include "flexmb/ancf/ancf_hoist_rope_body.h"
#include "flexmb/common/error.h"
#include "flexmb/common/text.h"
#include "flexmb/forces/reeved_rope.h"
#include "flexmb/joints/winch_driver.h"
#include "flexmb/model/model.h"

namespace flexmb {
namespace {

// body name: non-empty, no '.', not ground
std::string BodyName(const YAML::Node& node, ParseContext& ctx) {
  const std::string name = ctx.String(node, "name");
  if (name.empty()) ctx.Fail(node["name"], "a body name must not be empty");
  if (name.find('.') != std::string::npos || name == "ground")
    ctx.Fail(node["name"], "invalid body name " + Quoted(name));
  return name;
}

// checks the entry's keys, reads the body name and names the body in errors
std::string BeginBody(const YAML::Node& node, ParseContext& ctx, std::initializer_list<const char*> keys) {
  ctx.CheckKeys(node, keys);
  const std::string name = BodyName(node, ctx);
  ctx.SetEntity("body '" + name + "'");
  return name;
}

// `axial_strain: engineering | green_lagrange` (default engineering)
ancf::AxialStrainMeasure ParseAxialStrainMeasure(const YAML::Node& node, ParseContext& ctx) {
  if (!node["axial_strain"]) return ancf::AxialStrainMeasure::kEngineering;
  const std::string measure = ctx.String(node, "axial_strain");
  if (measure == "engineering") return ancf::AxialStrainMeasure::kEngineering;
  if (measure == "green_lagrange") return ancf::AxialStrainMeasure::kGreenLagrange;
  ctx.Fail(node["axial_strain"],
           "unknown 'axial_strain' " + Quoted(measure) + " (allowed: engineering, green_lagrange)");
  return ancf::AxialStrainMeasure::kEngineering;
}

// element count, section, material, damping and axial strain measure
void ParseLine(const YAML::Node& node, ParseContext& ctx, int& elements, ancf::BeamSection& section) {
  if (!node["elements"]) ctx.Fail(node, "missing key 'elements' (number of ANCF elements)");
  elements = ctx.Integer(node, "elements", 0);
  if (elements <= 0)
    ctx.Fail(node["elements"], "'elements' must be a positive whole number, got " + std::to_string(elements));
  const YAML::Node sec = node["section"];
  if (!sec || !sec.IsMap()) ctx.Fail(sec ? sec : node, "expected 'section' as {area, inertia} or {diameter}");
  if (sec["diameter"]) {
    ctx.CheckKeys(sec, {"diameter"});
    const double D = ctx.Positive(sec, "diameter");
    section.A = std::numbers::pi * D * D / 4.0;
    section.I = std::numbers::pi * D * D * D * D / 64.0;
  } else {
    ctx.CheckKeys(sec, {"area", "inertia"});
    section.A = ctx.Positive(sec, "area");
    section.I = ctx.Positive(sec, "inertia");
  }
  const YAML::Node mat = node["material"];
  if (!mat || !mat.IsMap()) ctx.Fail(mat ? mat : node, "expected 'material' as {E, rho}");
  ctx.CheckKeys(mat, {"E", "rho"});
  section.E = ctx.Positive(mat, "E");
  section.rho = ctx.Positive(mat, "rho");
  section.damping = ctx.Double(node, "damping", 0.0);
  if (section.damping < 0.0) ctx.Fail(node["damping"], "'damping' must not be negative");
  section.axial_strain = ParseAxialStrainMeasure(node, ctx);
}

// markers on nodes 0..nodes-1: `node: k` or `end: start|end`
void ParseNodeMarkers(const YAML::Node& node, int body, int nodes, ParseContext& ctx,
                      std::map<std::string, int>& lines, bool offsets = true) {
  auto node_of = [&](const YAML::Node& m) {
    int k = 0;
    if (m["node"] && m["end"]) ctx.Fail(m, "give either 'node' or 'end', not both");
    if (m["node"]) {
      k = ctx.Integer(m, "node", -1);
      if (k < 0 || k >= nodes)
        ctx.Fail(m["node"], "node " + std::to_string(k) + " does not exist: the body has nodes 0.." +
                                std::to_string(nodes - 1));
    } else if (m["end"]) {
      const std::string end = ctx.String(m, "end");
      if (end == "start")
        k = 0;
      else if (end == "end")
        k = nodes - 1;
      else
        ctx.Fail(m["end"], "unknown 'end' " + Quoted(end) + " (allowed: start, end)");
    } else {
      ctx.Fail(m, "an ANCF marker needs 'node: k' or 'end: start|end'");
    }
    return k;
  };
  if (offsets)
    ctx.ParseMarkerList(node, body, {"name", "node", "end", "position", "orientation"}, node_of, lines);
  else  // points on the centre line
    ctx.ParseMarkerList(node, body, {"name", "node", "end"}, node_of, lines);
}

void ParseCable(const YAML::Node& node, ParseContext& ctx, std::map<std::string, int>& lines) {
  const std::string name =
      BeginBody(node, ctx,
                {"name", "type", "length", "elements", "section", "material", "start", "direction", "end", "normal",
                 "damping", "angular_velocity", "load_per_length", "axial_strain", "markers"});
  const std::string entity = "body '" + name + "'";
  ancf::AncfCable3dData d;
  d.start_W = ctx.Vector3(node, "start", Vec3::Zero());
  if (node["end"]) {
    // the cable runs straight from start to end: direction and length follow
    if (node["direction"] || node["length"])
      ctx.Fail(node["end"], "give either 'end' or 'length' and 'direction', not both");
    const Vec3 span = ctx.Vector3(node, "end") - d.start_W;
    if (!(span.norm() > 0.0)) ctx.Fail(node["end"], "'end' must differ from 'start' (zero cable length)");
    d.length = span.norm();
    d.direction_W = span;
  } else {
    d.length = ctx.Positive(node, "length");
    d.direction_W = ctx.Vector3(node, "direction", Vec3::UnitX());
    if (!(d.direction_W.norm() > 0.0)) ctx.Fail(node["direction"], "'direction' must not be zero");
  }
  ParseLine(node, ctx, d.elements, d.section);
  d.normal_W = ctx.Vector3(node, "normal", Vec3::Zero());
  d.angular_velocity_W = ctx.Vector3(node, "angular_velocity", Vec3::Zero());
  d.load_per_length_W = ctx.Vector3(node, "load_per_length", Vec3::Zero());
  auto body = ctx.Guard(node, [&] { return std::make_unique<ancf::AncfCable3dBody>(name, d); });
  const int nodes = body->nodes();
  const int b = ctx.Guard(node["name"], [&] { return ctx.model().AddBody(std::move(body)); });
  lines[entity] = ParseContext::Line(node);
  ParseNodeMarkers(node, b, nodes, ctx, lines);
}

// hoisting rope of changing length: the cable keys without length and end,
// plus free_length, stored_length, drum {position, radius, inertia}
// (optional: without it a rope force's 'span' feeds the body) and
// payout_speed; the payout marker "<name>.payout" is added
void ParseHoistRope(const YAML::Node& node, ParseContext& ctx, std::map<std::string, int>& lines) {
  const std::string name =
      BeginBody(node, ctx,
                {"name", "type", "free_length", "stored_length", "elements", "section", "material", "start",
                 "direction", "damping", "axial_strain", "drum", "payout_speed", "initial_length", "markers"});
  const std::string entity = "body '" + name + "'";
  ancf::HoistRopeData d;
  d.free_length = ctx.Positive(node, "free_length");
  d.stored_length = ctx.Double(node, "stored_length", 0.0);
  if (d.stored_length < 0.0) ctx.Fail(node["stored_length"], "'stored_length' must not be negative");
  ParseLine(node, ctx, d.elements, d.section);
  d.start_W = ctx.Vector3(node, "start", Vec3::Zero());
  d.direction_W = ctx.Vector3(node, "direction", -Vec3::UnitZ());
  if (!(d.direction_W.norm() > 0.0)) ctx.Fail(node["direction"], "'direction' must not be zero");
  // without 'drum' the span is fed over a sheave by a rope force element
  // with a 'span' (its lead span and drum) or paid out by a winch driver:
  // CheckHoistRopeFeeds, once the forces are read
  const YAML::Node drum = node["drum"];
  d.drum_in_body = static_cast<bool>(drum);
  if (drum) {
    if (!drum.IsMap()) ctx.Fail(drum, "expected 'drum' as {position, radius, inertia}");
    ctx.CheckKeys(drum, {"position", "radius", "inertia"});
    d.drum_W = ctx.Vector3(drum, "position");
    d.drum_radius = ctx.Positive(drum, "radius");
    d.drum_inertia = ctx.Double(drum, "inertia", 0.0);
    if (d.drum_inertia < 0.0) ctx.Fail(drum["inertia"], "the drum 'inertia' must not be negative");
  }
  d.payout_speed = ctx.Double(node, "payout_speed", 0.0);
  if (node["initial_length"]) d.initial_length = ctx.Positive(node, "initial_length");
  auto body = ctx.Guard(node, [&] { return std::make_unique<ancf::AncfHoistRopeBody>(name, d); });
  const int nodes = body->elements() + 1, payout = body->PayoutNode();
  const int b = ctx.Guard(node["name"], [&] { return ctx.model().AddBody(std::move(body)); });
  lines[entity] = ParseContext::Line(node);
  ctx.Guard(node["name"], [&] { return ctx.model().AddMarker(b, "payout", Vec3::Zero(), Mat3::Identity(), payout); });
  ParseNodeMarkers(node, b, nodes, ctx, lines, false);
}

// 3D beam with torsion: section {area, Iy, Iz, J}, material {E, G | nu, rho}
void ParseBeam3d(const YAML::Node& node, ParseContext& ctx, std::map<std::string, int>& lines) {
  const std::string name = BeginBody(node, ctx,
                                     {"name", "type", "length", "elements", "section", "material", "start", "direction",
                                      "normal", "radius", "damping", "load_per_length", "axial_strain", "markers"});
  const std::string entity = "body '" + name + "'";
  ancf::AncfBeam3dData d;
  d.length = ctx.Positive(node, "length");
  if (!node["elements"]) ctx.Fail(node, "missing key 'elements' (number of ANCF elements)");
  d.elements = ctx.Integer(node, "elements", 0);
  if (d.elements <= 0)
    ctx.Fail(node["elements"], "'elements' must be a positive whole number, got " + std::to_string(d.elements));
  // one section {area, Iy, Iz, J}, or a list of one per element (stepped or tapered)
  const YAML::Node sec = node["section"];
  if (!sec || !(sec.IsMap() || sec.IsSequence()))
    ctx.Fail(sec ? sec : node, "expected 'section' as {area, Iy, Iz, J} or a list of one per element");
  if (sec.IsSequence() && static_cast<int>(sec.size()) != d.elements)
    ctx.Fail(sec, "'section' lists " + std::to_string(sec.size()) + " sections for " + std::to_string(d.elements) +
                      " elements (give one per element, or one map for all)");
  std::vector<ancf::Beam3dSection> sections;
  for (std::size_t i = 0; i < (sec.IsSequence() ? sec.size() : 1); ++i) {
    const YAML::Node si = sec.IsSequence() ? sec[i] : sec;
    if (!si.IsMap()) ctx.Fail(si, "expected each section as {area, Iy, Iz, J}");
    ctx.CheckKeys(si, {"area", "Iy", "Iz", "J"});
    ancf::Beam3dSection& s = sections.emplace_back();
    s.A = ctx.Positive(si, "area");
    s.Iy = ctx.Positive(si, "Iy");
    s.Iz = ctx.Positive(si, "Iz");
    s.J = ctx.Positive(si, "J");
  }
  d.section = sections.front();
  const YAML::Node mat = node["material"];
  if (!mat || !mat.IsMap()) ctx.Fail(mat ? mat : node, "expected 'material' as {E, G or nu, rho}");
  ctx.CheckKeys(mat, {"E", "G", "nu", "rho"});
  d.section.E = ctx.Positive(mat, "E");
  d.section.rho = ctx.Positive(mat, "rho");
  if (mat["G"] && mat["nu"]) ctx.Fail(mat, "give either 'G' or 'nu', not both");
  if (mat["G"]) {
    d.section.G = ctx.Positive(mat, "G");
  } else if (mat["nu"]) {
    const double nu = ctx.Double(mat, "nu", 0.0);
    if (!(nu > -1.0 && nu < 0.5)) ctx.Fail(mat["nu"], "'nu' must lie in (-1, 0.5)");
    d.section.G = d.section.E / (2.0 * (1.0 + nu));
  } else {
    ctx.Fail(mat, "missing 'G' or 'nu' (shear modulus for the torsion stiffness)");
  }
  d.section.damping = ctx.Double(node, "damping", 0.0);
  if (d.section.damping < 0.0) ctx.Fail(node["damping"], "'damping' must not be negative");
  d.section.axial_strain = ParseAxialStrainMeasure(node, ctx);
  if (sec.IsSequence())
    for (ancf::Beam3dSection& s : sections) {
      const double A = s.A, Iy = s.Iy, Iz = s.Iz, J = s.J;
      s = d.section;  // material, damping and strain measure of the body
      s.A = A, s.Iy = Iy, s.Iz = Iz, s.J = J;
      d.element_sections.push_back(s);
    }
  d.radius = ctx.Double(node, "radius", 0.0);
  if (d.radius < 0.0) ctx.Fail(node["radius"], "'radius' must not be negative (0: straight)");
  d.start_W = ctx.Vector3(node, "start", Vec3::Zero());
  d.direction_W = ctx.Vector3(node, "direction", Vec3::UnitX());
  if (!(d.direction_W.norm() > 0.0)) ctx.Fail(node["direction"], "'direction' must not be zero");
  d.normal_W = ctx.Vector3(node, "normal", Vec3::Zero());
  d.load_per_length_W = ctx.Vector3(node, "load_per_length", Vec3::Zero());
  auto body = ctx.Guard(node, [&] { return std::make_unique<ancf::AncfBeam3dBody>(name, d); });
  const int nodes = body->nodes();
  const int b = ctx.Guard(node["name"], [&] { return ctx.model().AddBody(std::move(body)); });
  lines[entity] = ParseContext::Line(node);
  ParseNodeMarkers(node, b, nodes, ctx, lines);
}

}  // namespace

void ParseAncfBody(const YAML::Node& node, ParseContext& ctx, std::map<std::string, int>& lines) {
  if (node["type"].Scalar() == "ancf_cable") return ParseCable(node, ctx, lines);
  if (node["type"].Scalar() == "ancf_beam3d") return ParseBeam3d(node, ctx, lines);
  if (node["type"].Scalar() == "ancf_hoist_rope") return ParseHoistRope(node, ctx, lines);
  const std::string name = BeginBody(node, ctx,
                                     {"name", "type", "length", "elements", "section", "material", "start", "direction",
                                      "normal", "damping", "curvature", "load_per_length", "axial_strain", "markers"});
  const std::string entity = "body '" + name + "'";

  ancf::AncfBeam2dData d;
  d.length = ctx.Positive(node, "length");
  ParseLine(node, ctx, d.elements, d.section);
  d.curvature0 = ctx.Double(node, "curvature", 0.0);
  d.start_W = ctx.Vector3(node, "start", Vec3::Zero());
  d.direction_W = ctx.Vector3(node, "direction", Vec3::UnitX());
  d.normal_W = ctx.Vector3(node, "normal", Vec3::UnitZ());
  d.load_per_length_W = ctx.Vector3(node, "load_per_length", Vec3::Zero());

  auto body = ctx.Guard(node, [&] { return std::make_unique<ancf::AncfBeam2dBody>(name, d); });
  const int nodes = body->nodes();
  const int b = ctx.Guard(node["name"], [&] { return ctx.model().AddBody(std::move(body)); });
  lines[entity] = ParseContext::Line(node);
  ParseNodeMarkers(node, b, nodes, ctx, lines);
}


void CheckHoistRopeFeeds(ParseContext& ctx) {
  const Model& model = ctx.model();
  for (const auto& body : model.bodies) {
    const auto* rope = dynamic_cast<const ancf::AncfHoistRopeBody*>(body.get());
    if (!rope || rope->data().drum_in_body) continue;
    const int payout = model.FindMarker(rope->name() + ".payout");
    std::vector<std::string> feeds;
    for (const auto& f : model.forces) {
      const auto* r = dynamic_cast<const ReevedRope*>(f.get());
      if (r && r->span().present && r->MarkerAt(r->NumMarkers() - 1) == payout) feeds.push_back("rope '" + r->name() + "'");
    }
    for (const auto& j : model.joints)
      if (dynamic_cast<const WinchDriver*>(j.get()) && j->marker_i == payout)
        feeds.push_back("winch driver '" + j->name() + "'");
    if (feeds.size() == 1) continue;
    const std::string entity = "body '" + rope->name() + "'";
    const auto it = ctx.lines().find(entity);
    std::string list;
    for (const std::string& f : feeds) list += (list.empty() ? "" : " and ") + f;
    throw InputError(feeds.empty() ? "the hoist rope has no 'drum' and nothing pays it out: give it a 'drum', feed it "
                                     "from a rope with 'span: " + rope->name() + "', or drive it with a winch driver"
                                   : "the hoist rope is paid out by " + list + ": one of them must do it",
                     {ctx.file(), it == ctx.lines().end() ? 0 : it->second, entity});
  }
}

}  // namespace flexmb
