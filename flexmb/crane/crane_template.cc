#include "flexmb/crane/crane_template.h"

#include <filesystem>
#include <map>

#include "flexmb/crane/crane_data.h"
#include "flexmb/crane/crane_geometry.h"
#include "flexmb/crane/crane_manoeuvre.h"
#include "flexmb/crane/crane_motion.h"

namespace flexmb::crane {
namespace {

YAML::Node Seq(std::initializer_list<double> xs) {
  YAML::Node n(YAML::NodeType::Sequence);
  n.SetStyle(YAML::EmitterStyle::Flow);
  for (double x : xs) n.push_back(Num(x));
  return n;
}
YAML::Node V(const Vec3& v) { return Seq({v.x(), v.y(), v.z()}); }

YAML::Node Map(std::initializer_list<std::pair<const char*, YAML::Node>> kv) {
  YAML::Node n(YAML::NodeType::Map);
  for (const auto& [k, v] : kv) n[k] = v;
  return n;
}
YAML::Node S(const std::string& s) { return YAML::Node(s); }
YAML::Node D(double x) { return YAML::Node(Num(x)); }

// orientations: the pins' axis (y) as the marker's z axis; a pitch about y
YAML::Node PinAxis() { return Map({{"z_axis", Seq({0, 1, 0})}}); }
YAML::Node Pitch(double deg) { return Map({{"roll_pitch_yaw_deg", Seq({0, deg, 0})}}); }

YAML::Node Marker(const char* name, const Vec3& p, YAML::Node orientation = YAML::Node(YAML::NodeType::Undefined)) {
  YAML::Node m = Map({{"name", S(name)}, {"position", V(p)}});
  if (orientation) m["orientation"] = orientation;
  return m;
}

// a rigid body entry from a part's mass properties
YAML::Node RigidBody(const char* name, const RigidPart& p, const Vec3& position, YAML::Node orientation = YAML::Node(YAML::NodeType::Undefined)) {
  YAML::Node b = Map({{"name", S(name)}, {"mass", D(p.mass)}, {"center_of_mass", V(p.com)}, {"inertia", V(p.inertia)}});
  if (position != Vec3::Zero()) b["position"] = V(position);
  if (orientation) b["orientation"] = orientation;
  if (p.shape) b["shape"] = p.shape;
  return b;
}

YAML::Node Contact(const std::string& name, const std::string& marker, const GroundContact& c) {
  return Map({{"name", S(name)}, {"type", S("plane_contact")}, {"marker", S(marker)}, {"stiffness", D(c.stiffness)},
              {"damping", D(c.damping)}, {"friction", D(c.friction)}, {"slip_velocity", D(c.slip_velocity)}});
}

YAML::Node Joint(const char* name, const char* type, const std::string& i, const std::string& j) {
  return Map({{"name", S(name)}, {"type", S(type)}, {"i", S(i)}, {"j", S(j)}});
}

YAML::Node Sensor(const std::string& name, const char* type, const char* key, const std::string& value) {
  return Map({{"name", S(name)}, {"type", S(type)}, {key, S(value)}});
}

// the box of a payload body: mass, centre, inertia of a uniform block
YAML::Node Block(const char* name, double mass, const Vec3& size, const Vec3& position) {
  const double a = size.x(), b = size.y(), h = size.z();
  const Vec3 J(mass / 12 * (b * b + h * h), mass / 12 * (a * a + h * h), mass / 12 * (a * a + b * b));
  YAML::Node n = RigidBody(name, {mass, Vec3::Zero(), J, YAML::Node(YAML::NodeType::Undefined)}, position);
  n["shape"] = Map({{"type", S("box")}, {"size", V(size)}});
  return n;
}

struct Entries {
  YAML::Node bodies{YAML::NodeType::Sequence}, joints{YAML::NodeType::Sequence},
      drivers{YAML::NodeType::Sequence}, forces{YAML::NodeType::Sequence}, sensors{YAML::NodeType::Sequence},
      ground_markers{YAML::NodeType::Sequence};
  YAML::Node rope;  ///< the hoisting rope, first of the forces
};

void AddCarrierAndPlatform(const CraneData& d, const CraneGeometry& c, Entries& e) {
  const Vec3 ring(0, 0, d.ring_height);
  if (d.has_carrier) {
    YAML::Node carrier = RigidBody("carrier", d.carrier, Vec3::Zero());
    YAML::Node markers(YAML::NodeType::Sequence);
    markers.push_back(Marker("slew", ring));
    for (const Pad& p : d.pads) {
      markers.push_back(Marker(("pad_" + p.name).c_str(), Vec3(p.x, p.y, -c.pad_penetration)));
      e.forces.push_back(Contact("pad_" + p.name, "carrier.pad_" + p.name, d.pad_contact));
    }
    carrier["markers"] = markers;
    e.bodies.push_back(carrier);
    e.joints.push_back(Joint("slewing_ring", "revolute", "carrier.slew", "platform.slew"));
  } else {
    e.ground_markers.push_back(Marker("slew", ring));
    e.joints.push_back(Joint("slewing_ring", "revolute", "ground.slew", "platform.slew"));
  }
  YAML::Node platform = RigidBody("platform", d.superstructure, Vec3::Zero());
  YAML::Node markers(YAML::NodeType::Sequence);
  markers.push_back(Marker("slew", ring));
  markers.push_back(Map({{"name", S("frame")}}));
  markers.push_back(Marker("foot", d.foot_W, PinAxis()));
  markers.push_back(Marker("cylinder", d.cylinder_base_W, PinAxis()));
  markers.push_back(Marker("winch_axle", d.winch_axle_W, PinAxis()));
  markers.push_back(Marker("winch_exit", c.winch_exit_W));
  platform["markers"] = markers;
  e.bodies.push_back(platform);
}

void AddWinchCylinderBoom(const CraneData& d, const CraneGeometry& c, Entries& e) {
  YAML::Node drum = RigidBody("drum", {d.drum_mass, Vec3::Zero(), d.drum_inertia, YAML::Node(YAML::NodeType::Undefined)}, d.winch_axle_W);
  drum["shape"] = Map({{"type", S("cylinder")}, {"radius", D(d.drum_radius)}, {"length", D(d.drum_width)},
                       {"orientation", PinAxis()}});
  drum["markers"] = YAML::Node(YAML::NodeType::Sequence);
  drum["markers"].push_back(Marker("axle", Vec3::Zero(), PinAxis()));
  e.bodies.push_back(drum);

  auto tube = [&](const char* name, const RigidPart& p, const Vec3& at, double length, double radius,
                  const char* pin, double pin_x) {
    YAML::Node b = RigidBody(name, p, at, Pitch(c.cylinder_pitch_deg));
    b["shape"] = Map({{"type", S("cylinder")}, {"radius", D(radius)}, {"length", D(length)},
                      {"orientation", Map({{"z_axis", Seq({1, 0, 0})}})}});
    b["markers"] = YAML::Node(YAML::NodeType::Sequence);
    b["markers"].push_back(Marker(pin, Vec3(pin_x, 0, 0), std::string(pin) == "base" ? PinAxis() : YAML::Node(YAML::NodeType::Undefined)));
    b["markers"].push_back(Marker("axis", Vec3(pin_x, 0, 0), Map({{"z_axis", Seq({1, 0, 0})}})));
    e.bodies.push_back(b);
  };
  tube("barrel", d.barrel, c.barrel_W, d.barrel_length, d.barrel_radius, "base", -0.5 * d.barrel_length);
  tube("rod", d.rod, c.rod_W, d.rod_length, d.rod_radius, "eye", 0.5 * d.rod_length);

  YAML::Node boom(YAML::NodeType::Map);
  boom["name"] = "boom";
  boom["position"] = V(c.p_WB);
  boom["orientation"] = Pitch(-d.luffing_deg);
  YAML::Node markers(YAML::NodeType::Sequence);
  if (d.boom_type == "flexible") {
    boom["type"] = "flexible";
    boom["file"] = d.boom_file;
    if (d.boom_damping_ratio >= 0) boom["damping"] = Map({{"ratios", Seq({d.boom_damping_ratio})}});
    for (const char* k : {"deformation_stiffening", "geometric_stiffening"})
      if (d.boom_options[k]) boom[k] = d.boom_options[k];
    const YAML::Node nodes = d.boom_options["nodes"];
    markers.push_back(Map({{"name", S("foot")}, {"node", nodes["foot"]}, {"orientation", PinAxis()}}));
    markers.push_back(Map({{"name", S("head")}, {"node", nodes["head"]}}));
    markers.push_back(Map({{"name", S("eye")}, {"node", nodes["eye"]}}));
  } else {
    boom = RigidBody("boom", d.boom_rigid, c.p_WB, Pitch(-d.luffing_deg));
    markers.push_back(Marker("foot", Vec3::Zero(), PinAxis()));
    markers.push_back(Marker("head", d.head_B));
    markers.push_back(Marker("eye", d.eye_B));
  }
  boom["markers"] = markers;
  e.bodies.push_back(boom);

  e.joints.push_back(Joint("foot_pin", "revolute", "platform.foot", "boom.foot"));
  e.joints.push_back(Joint("winch", "revolute", "platform.winch_axle", "drum.axle"));
  e.joints.push_back(Joint("cylinder_base", "revolute", "platform.cylinder", "barrel.base"));
  YAML::Node stroke = Joint("cylinder_stroke", "prismatic", "barrel.axis", "rod.axis");
  stroke["limits"] = Seq({d.stroke_min, d.stroke_max});
  e.joints.push_back(stroke);
  e.joints.push_back(Joint("cylinder_eye", "spherical", "rod.eye", "boom.eye"));
}

// the hanging span as an ANCF hoisting rope of changing length: the n falls
// as one span of n times one fall's section (they hang side by side, stretch
// and swing together), fed over the head sheave by `rope` (now the lead
// span from the drum to the head) and hung on the head and the hook by
// spherical joints; free lengths from the geometry, the span's nodes on the
// stretched line from the head to the hook (initial_length)
void AddAncfSpan(const CraneData& d, const CraneGeometry& c, YAML::Node& rope, Entries& e) {
  const double n = d.falls;
  rope["free_length"] = D(c.lead_free_length);
  rope["span"] = "hoist_span";
  const Vec3 head = c.head_W, hook = c.head_W - Vec3(0, 0, c.hook_drop);
  YAML::Node body = Map({{"name", S("hoist_span")}, {"type", S("ancf_hoist_rope")},
                         {"free_length", D(c.span_free_length)},
                         {"stored_length", D(d.rope_on_drum > 0 ? d.rope_on_drum / n : 1e6)},
                         {"elements", YAML::Node(d.rope_elements)}});
  // the section of n falls with a unit area: E A = n EA, rho A = n m', E I = n EI
  body["section"] = Map({{"area", D(1.0)}, {"inertia", D(d.rope_bending_stiffness / d.rope_ea)}});
  body["material"] = Map({{"E", D(n * d.rope_ea)}, {"rho", D(n * d.rope_mass_per_length)}});
  body["damping"] = D(d.rope_damping_time);
  body["initial_length"] = D(c.hook_drop);  // stretched to the hook
  body["start"] = V(head);
  body["direction"] = V(hook - head);
  body["markers"] = YAML::Node(YAML::NodeType::Sequence);
  body["markers"].push_back(Map({{"name", S("top")}, {"end", S("start")}}));
  body["markers"].push_back(Map({{"name", S("hook")}, {"end", S("end")}}));
  e.bodies.push_back(body);
  e.joints.push_back(Joint("sheave", "spherical", "boom.head", "hoist_span.top"));
  e.joints.push_back(Joint("hook", "spherical", "hoist_span.hook", "load.hook"));
  e.sensors.push_back(Sensor("span_length", "marker_position", "marker", "hoist_span.payout"));  // x: L
  YAML::Node sensor = Sensor("hook_force", "joint_reaction", "joint", "hook");
  sensor["frame"] = "world";
  e.sensors.push_back(sensor);
}

void AddPayloadAndRope(const CraneData& d, const CraneGeometry& c, Entries& e) {
  const Vec3& size = d.payload_size;
  const bool split = d.release_mass > 0;
  const double m_upper = d.payload_mass - d.release_mass;
  YAML::Node load = Block("load", m_upper, Vec3(size.x(), size.y(), split ? c.upper_height : size.z()), c.load_W);
  load["markers"] = YAML::Node(YAML::NodeType::Sequence);
  load["markers"].push_back(Marker("hook", c.hook_L));
  const char* lower = split ? "part" : "load";
  const double h_low = split ? c.lower_height : size.z();
  YAML::Node part;
  if (split) {
    load["markers"].push_back(Marker("grab", Vec3(0, 0, -0.5 * c.upper_height)));
    part = Block("part", d.release_mass, Vec3(size.x(), size.y(), c.lower_height), c.part_W);
    part["markers"] = YAML::Node(YAML::NodeType::Sequence);
    part["markers"].push_back(Marker("grab", Vec3(0, 0, 0.5 * c.lower_height)));
  }
  YAML::Node& corners_on = split ? part : load;
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int k = 0; k < 4; ++k) {
    const std::string name = "c" + std::to_string(k + 1);
    corners_on["markers"].push_back(
        Marker(name.c_str(), Vec3(0.5 * sx[k] * size.x(), 0.5 * sy[k] * size.y(), -0.5 * h_low)));
    e.forces.push_back(Contact("ground_" + name, std::string(lower) + "." + name, d.payload_contact));
  }
  e.bodies.push_back(load);
  if (split) {
    e.bodies.push_back(part);
    e.joints.push_back(Joint("grab", "fixed", "load.grab", "part.grab"));
  }

  YAML::Node rope = Map({{"name", S("hoist_rope")}, {"type", S("rope")}});
  YAML::Node path(YAML::NodeType::Sequence);
  path.SetStyle(YAML::EmitterStyle::Flow);
  path.push_back("platform.winch_exit");
  path.push_back("boom.head");
  const bool ancf = d.rope_model == CraneData::RopeModel::kAncf;
  if (!ancf) path.push_back("load.hook");
  rope["path"] = path;
  rope["falls"] = d.falls;
  rope["axial_stiffness"] = D(d.rope_ea);
  rope["damping_time"] = D(d.rope_damping_time);
  rope["drum"] = Map({{"joint", S("winch")}, {"radius", D(d.drum_radius)}});
  rope["free_length"] = D(c.free_length);
  if (ancf) AddAncfSpan(d, c, rope, e);
  e.rope = rope;
}

void AddSensors(const CraneData& d, Entries& e) {
  e.sensors.push_back(Sensor("rope", "force_element", "force", "hoist_rope"));
  e.sensors.push_back(Sensor("winch_exit", "marker_position", "marker", "platform.winch_exit"));
  e.sensors.push_back(Sensor("head", "marker_position", "marker", "boom.head"));
  YAML::Node on_platform = Sensor("head_on_platform", "marker_position", "marker", "boom.head");
  on_platform["relative_to"] = "platform.frame";
  e.sensors.push_back(on_platform);
  e.sensors.push_back(Sensor("hook", "marker_position", "marker", "load.hook"));
  e.sensors.push_back(Sensor("slew", "joint_coordinate", "joint", "slewing_ring"));
  for (const Pad& p : d.pads) e.sensors.push_back(Sensor("pad_" + p.name, "force_element", "force", "pad_" + p.name));
  if (d.has_carrier) e.sensors.push_back(Sensor("carrier", "marker_orientation", "marker", "carrier.slew"));
  auto world = [](YAML::Node s) {
    s["frame"] = "world";
    return s;
  };
  e.sensors.push_back(world(Sensor("slew_torque", "joint_reaction", "joint", "slew_drive")));
  e.sensors.push_back(Sensor("foot_pin", "joint_reaction", "joint", "foot_pin"));
  e.sensors.push_back(world(Sensor("cylinder", "joint_reaction", "joint", "luffing")));
  e.sensors.push_back(Sensor("cylinder_length", "joint_coordinate", "joint", "cylinder_stroke"));
  e.sensors.push_back(Sensor("winch_torque", "joint_reaction", "joint", "hoist_drive"));
  if (d.release_mass > 0) {
    e.sensors.push_back(world(Sensor("grab", "joint_reaction", "joint", "grab")));
    e.sensors.push_back(Sensor("part", "marker_position", "marker", "part.grab"));
  }
  for (const auto& [name, element] : d.stresses) {
    YAML::Node s = Sensor(name, "element_stress", "body", "boom");
    s["element"] = element;
    e.sensors.push_back(s);
  }
}

// appends `list` to root[key] (created if absent)
void Append(YAML::Node& root, const char* key, const YAML::Node& list, YamlContext& ctx) {
  if (list.size() == 0) return;
  if (!root[key]) root[key] = YAML::Node(YAML::NodeType::Sequence);
  YAML::Node target = root[key];
  if (!target.IsSequence()) ctx.Fail(target, std::string("expected '") + key + "' as a list of entries ('- ...')");
  for (const YAML::Node& n : list) target.push_back(n);
}

}  // namespace

bool IsCraneFile(const YAML::Node& root) { return root.IsMap() && root["crane"]; }

void ExpandCraneFile(YAML::Node& root, const std::string& requested, YamlContext& ctx) {
  if (!IsCraneFile(root)) return;
  const std::string owner = ctx.entity();
  const std::filesystem::path folder = std::filesystem::path(ctx.file()).parent_path();
  const double g = ctx.Vector3(root, "gravity", Vec3(0, 0, -9.81)).norm();
  CraneSetup setup = SelectCraneManoeuvre(root, requested, folder.string(), g, ctx);
  const CraneData& d = setup.data;
  const CraneGeometry& c = setup.geometry;

  Entries e;
  AddCarrierAndPlatform(d, c, e);
  AddWinchCylinderBoom(d, c, e);
  AddPayloadAndRope(d, c, e);
  // the drives: the cylinder's length, the drum's angle, the slew angle
  auto driver = [&](const char* name, const char* joint, const std::string& expr) {
    e.drivers.push_back(Map({{"name", S(name)}, {"joint", S(joint)}, {"function", Map({{"expression", S(expr)}})}}));
  };
  driver("luffing", "cylinder_stroke", setup.luffing);
  driver("hoist_drive", "winch", setup.hoist);
  driver("slew_drive", "slewing_ring", setup.slew);
  AddSensors(d, e);

  if (e.ground_markers.size() > 0) {
    if (!root["ground"]) root["ground"] = YAML::Node(YAML::NodeType::Map);
    YAML::Node ground = root["ground"];
    Append(ground, "markers", e.ground_markers, ctx);
  }
  Append(root, "bodies", e.bodies, ctx);
  Append(root, "joints", e.joints, ctx);
  Append(root, "drivers", e.drivers, ctx);
  YAML::Node forces(YAML::NodeType::Sequence);
  forces.push_back(e.rope);
  for (const YAML::Node& f : e.forces) forces.push_back(f);
  Append(root, "forces", forces, ctx);
  Append(root, "sensors", e.sensors, ctx);
  root.remove("crane");
  ctx.SetEntity(owner);
}

}  // namespace flexmb::crane

namespace flexmb::crane {

std::string ExpandedCraneFile(const std::string& path, const std::string& manoeuvre) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw InputError("cannot open the crane file", {path, 0, ""});
  } catch (const YAML::Exception& e) {
    throw InputError("YAML syntax error: " + e.msg, {path, e.mark.is_null() ? 0 : e.mark.line + 1, ""});
  }
  YamlContext ctx(path);
  if (!IsCraneFile(root)) throw InputError("not a crane file: it has no top-level 'crane' map", {path, 0, ""});
  try {
    ExpandCraneFile(root, manoeuvre, ctx);
  } catch (const YAML::Exception& e) {
    throw InputError(e.msg, {path, e.mark.is_null() ? 0 : e.mark.line + 1, ctx.entity()});
  }
  // only the selected manoeuvre: the entries were made for it
  std::string name = manoeuvre;
  if (name.empty() && root["manoeuvre"]) name = root["manoeuvre"].as<std::string>();
  if (!name.empty() && !(root["manoeuvres"] && root["manoeuvres"].IsMap() && root["manoeuvres"][name])) {
    std::string names;
    if (root["manoeuvres"] && root["manoeuvres"].IsMap())
      for (const auto& kv : root["manoeuvres"]) names += (names.empty() ? "" : ", ") + kv.first.Scalar();
    throw InputError((manoeuvre.empty() ? "manoeuvre " : "--manoeuvre ") + name + ": no manoeuvre named '" + name +
                         "' in the file (" + (names.empty() ? std::string("it defines none") : "defined: " + names) +
                         ")",
                     {path, 0, "manoeuvres"});
  }
  if (root["manoeuvres"]) {
    YAML::Node kept(YAML::NodeType::Map);
    if (!name.empty() && root["manoeuvres"][name]) kept[name] = root["manoeuvres"][name];
    root["manoeuvres"] = kept;
    if (!name.empty()) root["manoeuvre"] = name;
  }
  YAML::Emitter out;
  out << root;
  return std::string("# written by flexmb crane expand from ") + path + "\n" + out.c_str() + "\n";
}

}  // namespace flexmb::crane
