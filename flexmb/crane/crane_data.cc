#include "flexmb/crane/crane_data.h"

#include <cmath>

namespace flexmb::crane {
namespace {

// the map at node[key] (required), with its keys checked
YAML::Node Section(const YAML::Node& node, const char* key, std::initializer_list<const char*> keys,
                   YamlContext& ctx) {
  const YAML::Node s = node[key];
  if (!s) ctx.Fail(node, std::string("the crane needs '") + key + "'");
  ctx.SetEntity(std::string("crane.") + key);
  ctx.CheckKeys(s, keys);
  return s;
}

RigidPart ReadPart(const YAML::Node& node, YamlContext& ctx) {
  RigidPart p;
  p.mass = ctx.Positive(node, "mass");
  p.com = ctx.Vector3(node, "center_of_mass", Vec3::Zero());
  p.inertia = ctx.Vector3(node, "inertia");
  for (int k = 0; k < 3; ++k)
    if (!(p.inertia[k] > 0)) ctx.Fail(node["inertia"], "'inertia' must be three positive principal moments [kg m^2]");
  if (node["shape"]) p.shape = node["shape"];
  return p;
}

GroundContact ReadContact(const YAML::Node& node, YamlContext& ctx) {
  GroundContact c;
  c.stiffness = ctx.Positive(node, "stiffness");
  c.damping = ctx.Double(node, "damping", 0.0);
  c.friction = ctx.Double(node, "friction", 0.0);
  c.slip_velocity = ctx.Double(node, "slip_velocity", 0.01);
  if (c.damping < 0) ctx.Fail(node["damping"], "'damping' must not be negative");
  if (c.friction < 0) ctx.Fail(node["friction"], "'friction' must not be negative");
  if (!(c.slip_velocity > 0)) ctx.Fail(node["slip_velocity"], "'slip_velocity' must be positive");
  return c;
}

// a list of exactly two finite numbers at node[key]
std::pair<double, double> Pair(const YAML::Node& node, const char* key, const std::string& what, YamlContext& ctx) {
  const YAML::Node v = node[key];
  if (!v) ctx.Fail(node, std::string("missing '") + key + "' (" + what + ")");
  if (!v.IsSequence() || v.size() != 2) ctx.Fail(v, std::string("expected '") + key + "' as " + what);
  return {ctx.Number(v[0], std::string(key) + "[0]"), ctx.Number(v[1], std::string(key) + "[1]")};
}

void ReadCarrier(const YAML::Node& crane, CraneData& d, YamlContext& ctx) {
  if (!crane["carrier"]) return;
  const YAML::Node c = Section(crane, "carrier", {"mass", "center_of_mass", "inertia", "shape", "outriggers"}, ctx);
  d.has_carrier = true;
  d.carrier = ReadPart(c, ctx);
  if (!c["outriggers"]) ctx.Fail(c, "the carrier needs 'outriggers' (its pads on the ground)");
  const YAML::Node o = c["outriggers"];
  ctx.SetEntity("crane.carrier.outriggers");
  ctx.CheckKeys(o, {"pads", "stiffness", "damping", "friction", "slip_velocity"});
  const YAML::Node pads = o["pads"];
  if (!pads || !pads.IsMap() || pads.size() < 3)
    ctx.Fail(pads ? pads : o, "expected 'pads' as a map of at least three pads: name -> [x, y] on the ground [m]");
  for (const auto& kv : pads) {
    const auto [x, y] = Pair(pads, kv.first.Scalar().c_str(), "[x, y] of the pad on the ground [m]", ctx);
    d.pads.push_back({kv.first.Scalar(), x, y});
  }
  d.pad_contact = ReadContact(o, ctx);
}

void ReadBoom(const YAML::Node& crane, CraneData& d, YamlContext& ctx) {
  const YAML::Node b = Section(crane, "boom",
                               {"type", "file", "nodes", "mass", "center_of_mass", "inertia", "shape", "head", "eye",
                                "foot", "luffing_angle_deg", "damping_ratio", "deformation_stiffening",
                                "geometric_stiffening", "stresses"},
                               ctx);
  d.lines["boom"] = YamlContext::Line(b);
  d.boom_type = ctx.String(b, "type", "flexible");
  d.foot_W = ctx.Vector3(b, "foot");
  d.luffing_deg = ctx.Double(b, "luffing_angle_deg");
  if (!(d.luffing_deg > -90 && d.luffing_deg < 90))
    ctx.Fail(b["luffing_angle_deg"], "'luffing_angle_deg' must lie between -90 and 90 degrees");
  if (d.boom_type == "flexible") {
    for (const char* k : {"mass", "center_of_mass", "inertia", "shape", "head", "eye"})
      if (b[k]) ctx.Fail(b[k], std::string("'") + k + "' is for a rigid boom; a flexible boom has its body file");
    if (!b["file"]) ctx.Fail(b, "a flexible boom needs 'file' (a body file of flexmb reduce)");
    ctx.String(b, "file");
    d.boom_file = b["file"];
    const YAML::Node n = b["nodes"];
    if (!n) ctx.Fail(b, "a flexible boom needs 'nodes: {foot: ID, head: ID, eye: ID}' (interface nodes)");
    ctx.CheckKeys(n, {"foot", "head", "eye"});
    d.foot_node = ctx.Integer(n, "foot", 0);
    d.head_node = ctx.Integer(n, "head", 0);
    d.eye_node = ctx.Integer(n, "eye", 0);
    for (const char* k : {"foot", "head", "eye"})
      if (!n[k]) ctx.Fail(n, std::string("'nodes' needs '") + k + "' (an interface node id of the body file)");
    d.boom_damping_ratio = ctx.Double(b, "damping_ratio", -1.0);
    if (b["damping_ratio"] && !(d.boom_damping_ratio >= 0 && d.boom_damping_ratio < 1))
      ctx.Fail(b["damping_ratio"], "'damping_ratio' must lie in [0, 1)");
    d.boom_options = b;
  } else if (d.boom_type == "rigid") {
    for (const char* k : {"file", "nodes", "damping_ratio", "deformation_stiffening", "geometric_stiffening", "stresses"})
      if (b[k]) ctx.Fail(b[k], std::string("'") + k + "' is for a flexible boom");
    d.boom_rigid = ReadPart(b, ctx);
    d.head_B = ctx.Vector3(b, "head");
    d.eye_B = ctx.Vector3(b, "eye");
  } else {
    ctx.Fail(b["type"], "unknown boom type '" + d.boom_type + "' (allowed: flexible, rigid)");
  }
  if (const YAML::Node s = b["stresses"]) {
    if (!s.IsMap()) ctx.Fail(s, "expected 'stresses' as a map: sensor name -> element id of the body file");
    for (const auto& kv : s) d.stresses.push_back({kv.first.Scalar(), ctx.Integer(s, kv.first.Scalar().c_str(), 0)});
  }
}

void ReadCylinder(const YAML::Node& crane, CraneData& d, YamlContext& ctx) {
  const YAML::Node c = Section(crane, "luffing_cylinder", {"base", "stroke", "barrel", "rod"}, ctx);
  d.lines["luffing_cylinder"] = YamlContext::Line(c);
  d.cylinder_base_W = ctx.Vector3(c, "base");
  std::tie(d.stroke_min, d.stroke_max) = Pair(c, "stroke", "[shortest, longest] length between the pins [m]", ctx);
  if (!(d.stroke_min > 0 && d.stroke_max > d.stroke_min))
    ctx.Fail(c["stroke"], "'stroke' must be [shortest, longest] with 0 < shortest < longest [m]");
  auto tube = [&](const char* key, RigidPart& part, double& length, double& radius) {
    const YAML::Node t = c[key];
    if (!t) ctx.Fail(c, std::string("the luffing cylinder needs '") + key + "'");
    ctx.SetEntity(std::string("crane.luffing_cylinder.") + key);
    ctx.CheckKeys(t, {"mass", "inertia", "length", "radius"});
    part = ReadPart(t, ctx);
    length = ctx.Positive(t, "length");
    radius = ctx.Positive(t, "radius");
  };
  tube("barrel", d.barrel, d.barrel_length, d.barrel_radius);
  tube("rod", d.rod, d.rod_length, d.rod_radius);
}

void ReadWinchAndRope(const YAML::Node& crane, CraneData& d, YamlContext& ctx) {
  const YAML::Node w = Section(crane, "winch", {"axle", "drum_radius", "mass", "inertia", "width", "rope_on_drum"}, ctx);
  d.lines["winch"] = YamlContext::Line(w);
  d.winch_axle_W = ctx.Vector3(w, "axle");
  d.drum_radius = ctx.Double(w, "drum_radius");
  if (!(d.drum_radius > 0)) ctx.Fail(w["drum_radius"], "'drum_radius' must be positive (the winding radius [m])");
  d.drum_mass = ctx.Positive(w, "mass");
  const double j = ctx.Positive(w, "inertia");
  d.drum_inertia = Vec3(j, j, j);
  d.drum_width = ctx.Double(w, "width", 4 * d.drum_radius);
  d.rope_on_drum = ctx.Double(w, "rope_on_drum", -1.0);
  if (w["rope_on_drum"] && !(d.rope_on_drum > 0)) ctx.Fail(w["rope_on_drum"], "'rope_on_drum' must be positive [m]");

  const YAML::Node r = Section(crane, "rope",
                               {"axial_stiffness", "damping_time", "falls", "slack", "model", "elements",
                                "mass_per_length", "bending_stiffness"},
                               ctx);
  d.rope_ea = ctx.Positive(r, "axial_stiffness");
  d.rope_damping_time = ctx.Double(r, "damping_time", 0.0);
  if (d.rope_damping_time < 0) ctx.Fail(r["damping_time"], "'damping_time' must not be negative");
  d.falls = ctx.Integer(r, "falls", 1);
  if (d.falls < 1) ctx.Fail(r["falls"], "'falls' must be a whole number >= 1");
  d.rope_slack = ctx.Double(r, "slack", 0.0);
  if (d.rope_slack < 0) ctx.Fail(r["slack"], "'slack' must not be negative [m]");
  const std::string model = r["model"] ? r["model"].as<std::string>() : std::string("massless");
  if (model == "ancf") {
    d.rope_model = CraneData::RopeModel::kAncf;
    d.rope_elements = ctx.Integer(r, "elements", 10);
    if (d.rope_elements < 1) ctx.Fail(r["elements"], "'elements' must be a whole number >= 1");
    d.rope_mass_per_length = ctx.Positive(r, "mass_per_length");
    d.rope_bending_stiffness = ctx.Positive(r, "bending_stiffness");
  } else if (model == "massless") {
    for (const char* k : {"elements", "mass_per_length", "bending_stiffness"})
      if (r[k]) ctx.Fail(r[k], std::string("'") + k + "' is for the ANCF rope only (model: ancf); the massless rope has none");
  } else {
    ctx.Fail(r["model"], "unknown rope model '" + model + "' (massless or ancf)");
  }
}

void ReadPayload(const YAML::Node& crane, CraneData& d, YamlContext& ctx) {
  const YAML::Node p =
      Section(crane, "payload", {"mass", "size", "hook_height", "clearance", "release_mass", "ground"}, ctx);
  d.lines["payload"] = YamlContext::Line(p);
  d.payload_mass = ctx.Positive(p, "mass");
  d.payload_size = ctx.Vector3(p, "size");
  for (int k = 0; k < 3; ++k)
    if (!(d.payload_size[k] > 0)) ctx.Fail(p["size"], "'size' must be three positive lengths [m]");
  d.hook_height = ctx.Positive(p, "hook_height");
  if (d.hook_height <= d.payload_size.z() / 2)
    ctx.Fail(p["hook_height"], "'hook_height' (above the payload's centre) must clear its top");
  d.clearance = ctx.Double(p, "clearance", 0.0);
  if (d.clearance < 0) ctx.Fail(p["clearance"], "'clearance' must not be negative (0: on the ground)");
  d.release_mass = ctx.Double(p, "release_mass", 0.0);
  if (!(d.release_mass >= 0 && d.release_mass < d.payload_mass))
    ctx.Fail(p["release_mass"], "'release_mass' must lie in [0, mass)");
  if (!p["ground"]) ctx.Fail(p, "the payload needs 'ground' (its contact with the ground)");
  ctx.SetEntity("crane.payload.ground");
  ctx.CheckKeys(p["ground"], {"stiffness", "damping", "friction", "slip_velocity"});
  d.payload_contact = ReadContact(p["ground"], ctx);
}

}  // namespace

CraneData ReadCraneData(const YAML::Node& crane, YamlContext& ctx) {
  ctx.SetEntity("crane");
  ctx.CheckKeys(crane, {"slewing_ring", "carrier", "superstructure", "boom", "luffing_cylinder", "winch", "rope",
                        "payload"});
  CraneData d;
  const YAML::Node ring = Section(crane, "slewing_ring", {"height"}, ctx);
  d.ring_height = ctx.Positive(ring, "height");
  ReadCarrier(crane, d, ctx);
  const YAML::Node s = Section(crane, "superstructure", {"mass", "center_of_mass", "inertia", "shape"}, ctx);
  d.superstructure = ReadPart(s, ctx);
  ReadBoom(crane, d, ctx);
  ReadCylinder(crane, d, ctx);
  ReadWinchAndRope(crane, d, ctx);
  ReadPayload(crane, d, ctx);
  if (d.rope_model == CraneData::RopeModel::kAncf && !(d.clearance > 0)) {
    ctx.SetEntity("crane.rope");
    ctx.Fail(crane["rope"]["model"],
             "the ANCF rope needs the load hanging (payload 'clearance' > 0): its span carries compression, so it "
             "cannot start slack on a grounded load (docs/crane-file.md, \"The ANCF rope\"); lift-off of a "
             "grounded load is the massless rope's case");
  }
  ctx.SetEntity("crane");
  return d;
}

}  // namespace flexmb::crane
