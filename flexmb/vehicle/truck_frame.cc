#include "flexmb/vehicle/truck_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "flexmb/body_file/body_file.h"
#include "flexmb/body_file/unit_system.h"
#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/common/text.h"
#include "flexmb/yaml/yaml_context.h"

namespace flexmb::vehicle {
namespace {

std::string Point(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", p.x(), p.y(), p.z());
  return buf;
}

// keys that shape the generated frame: not with a body file
const std::vector<const char*> kGeneratorKeys = {"mass",      "flange_width",           "thickness",    "cross_members",
                                                 "cross_member_thickness", "element_size", "E", "nu", "rho"};

// reads the frame's `platform` map into f.platform; with a body file only
// the keys that place the cargo's mounts
void ReadPlatform(const YAML::Node& frame, YamlContext& ctx, bool body, LadderFrameData& f) {
  const YAML::Node node = frame["platform"];
  if (!node) return;
  ctx.SetEntity("truck frame platform");
  if (!node.IsMap()) ctx.Fail(node, "expected 'platform' as a map");
  PlatformData& p = f.platform;
  p.present = true;
  if (body) {
    ctx.CheckKeys(node, {"spacer", "sill_height", "note"});
  } else {
    ctx.CheckKeys(node, {"front_x", "length", "width", "spacer", "sill_height", "sill_flange_width", "sill_thickness",
                         "bearer_spacing", "bearer_thickness", "side_rail_thickness", "brackets", "bracket_length",
                         "bracket_thickness", "bearer_flange_width", "side_rail_flange_width", "mass", "note"});
    p.front_x = ctx.Double(node, "front_x");
    p.length = ctx.Positive(node, "length");
    p.width = ctx.Positive(node, "width");
    p.mass = ctx.Positive(node, "mass");
    p.sill_flange_width = ctx.Double(node, "sill_flange_width", p.sill_flange_width);
    p.sill_thickness = ctx.Double(node, "sill_thickness", p.sill_thickness);
    p.bearer_spacing = ctx.Double(node, "bearer_spacing", p.bearer_spacing);
    p.bearer_thickness = ctx.Double(node, "bearer_thickness", p.bearer_thickness);
    p.side_rail_thickness = ctx.Double(node, "side_rail_thickness", p.side_rail_thickness);
    p.bracket_length = ctx.Double(node, "bracket_length", p.bracket_length);
    p.bracket_thickness = ctx.Double(node, "bracket_thickness", p.bracket_thickness);
    p.bearer_flange_width = ctx.Double(node, "bearer_flange_width", p.bearer_flange_width);
    p.side_rail_flange_width = ctx.Double(node, "side_rail_flange_width", p.side_rail_flange_width);
    const YAML::Node b = node["brackets"];
    if (!b || !b.IsSequence() || b.size() < 2)
      ctx.Fail(b ? b : node,
               "expected 'brackets' as a list of at least two x [m] (the platform's brackets on the rails)");
    for (const YAML::Node& v : b) p.brackets.push_back(ctx.Number(v, "bracket x"));
  }
  // the keys that place the cargo's mounts (the platform's top), also with a body file
  for (auto [key, value] : {std::pair<const char*, double*>{"spacer", &p.spacer}, {"sill_height", &p.sill_height}}) {
    *value = ctx.Double(node, key, *value);
    if (!(*value > 0) || !std::isfinite(*value))
      ctx.Fail(node[key] ? node[key] : node, std::string("'") + key + "' must be positive [m]");
  }
  ctx.SetEntity("truck frame");
}

// reads the user's frame: body file, mounts, tolerance; checks every mount
void ReadFrameBody(const YAML::Node& node, YamlContext& ctx, const std::string& dir, TruckData& d) {
  for (const char* key : kGeneratorKeys)
    if (node[key])
      ctx.Fail(node[key], std::string("'") + key +
                              "' shapes the generated ladder frame; with 'body' the frame's mesh, material and mass "
                              "come from the body file");
  std::filesystem::path path(ctx.String(node, "body"));
  if (path.is_relative()) path = std::filesystem::path(dir) / path;
  auto body = std::make_shared<reduction::ReducedBody>();
  try {
    *body = io::ReadBody(path.string());
  } catch (const InputError& e) {
    ctx.Fail(node["body"], "cannot use body file " + Quoted(path.string()) + ": " + e.what());
  }
  std::vector<std::string> warnings;
  try {
    warnings = io::CheckBodyUnits(*body, path.string());
  } catch (const InputError& e) {
    ctx.Fail(node["body"], e.what());
  }
  for (const std::string& w : warnings)
    LogWarning(ctx.file() + ":" + std::to_string(YamlContext::Line(node["body"])) + ": truck frame: " + w);
  d.frame_body_file = path.string();
  d.mount_tolerance = ctx.Double(node, "mount_tolerance", d.mount_tolerance);
  if (!(d.mount_tolerance > 0)) ctx.Fail(node["mount_tolerance"], "mount_tolerance must be positive [m]");
  SetFrameBody(d, body);

  const YAML::Node mounts = node["mounts"];
  if (!mounts || !mounts.IsMap())
    ctx.Fail(mounts ? mounts : node, "a frame from a body file needs 'mounts': {attachment name: node id}");
  std::set<std::string> names;
  std::string list;
  for (const FrameAttachment& a : FrameAttachments(d)) {
    names.insert(a.name);
    list += (list.empty() ? "" : ", ") + a.name;
  }
  for (const auto& kv : mounts) {
    const std::string name = kv.first.as<std::string>();
    if (!names.count(name)) ctx.Fail(kv.first, "unknown mount " + Quoted(name) + "; this truck's mounts are: " + list);
    const double id = ctx.Number(kv.second, "node id of mount " + Quoted(name));
    if (!(id >= 1) || id != std::floor(id) || id > 2147483647.0)
      ctx.Fail(kv.second, "the node id of mount " + Quoted(name) + " must be a positive integer");
    d.frame_mounts[name] = static_cast<int>(id);
  }
  for (const FrameAttachment& a : FrameAttachments(d)) {
    if (!d.frame_mounts.count(a.name))
      ctx.Fail(mounts, "mount " + Quoted(a.name) + " at " + Point(a.point) +
                           " m has no node: give the id of the interface node that carries it");
    ctx.Guard(mounts[a.name], [&] { return FrameMountNode(d, *body, a.name, a.point); });
  }
}

}  // namespace

void ReadTruckFrame(const YAML::Node& n, YamlContext& ctx, const std::string& dir, TruckData& d) {
  const YAML::Node& node = n["frame"];
  ctx.SetEntity("truck frame");
  if (!node) ctx.Fail(n, "missing 'frame'");
  ctx.CheckKeys(node, {"body", "mounts", "mount_tolerance", "mass", "front_x", "length", "half_spacing", "web_height",
                       "flange_width", "thickness", "bottom_z", "cross_members", "cross_member_thickness",
                       "element_size", "E", "nu", "rho", "spider_radius", "platform", "note"});
  LadderFrameData& f = d.ladder;
  // the rail geometry: the generated frame's, and where the mounts sit
  f.front_x = ctx.Double(node, "front_x", f.front_x);
  f.length = ctx.Double(node, "length", f.length);
  f.half_spacing = ctx.Double(node, "half_spacing", f.half_spacing);
  f.web_height = ctx.Double(node, "web_height", f.web_height);
  f.bottom_z = ctx.Double(node, "bottom_z", f.bottom_z);
  f.spider_radius = ctx.Double(node, "spider_radius", f.spider_radius);
  ReadPlatform(node, ctx, static_cast<bool>(node["body"]), f);
  if (node["body"]) return ReadFrameBody(node, ctx, dir, d);
  for (const char* key : {"mounts", "mount_tolerance"})
    if (node[key]) ctx.Fail(node[key], std::string("'") + key + "' needs 'body' (the frame's body file)");
  f.total_mass = ctx.Positive(node, "mass");
  f.flange_width = ctx.Double(node, "flange_width", f.flange_width);
  f.thickness = ctx.Double(node, "thickness", f.thickness);
  f.cross_member_thickness = ctx.Double(node, "cross_member_thickness", f.cross_member_thickness);
  f.element_size = ctx.Double(node, "element_size", f.element_size);
  f.E = ctx.Double(node, "E", f.E);
  f.nu = ctx.Double(node, "nu", f.nu);
  f.rho = ctx.Double(node, "rho", f.rho);
  if (const YAML::Node c = node["cross_members"]) {
    if (!c.IsSequence() || c.size() < 2) ctx.Fail(c, "expected 'cross_members' as a list of at least two x [m]");
    f.cross_members.clear();
    for (const YAML::Node& v : c) f.cross_members.push_back(ctx.Number(v, "cross member x"));
  }
  if (f.platform.present) {
    // the cargo rests on the platform's sills: its mount stations must lie on it
    const double rear = f.platform.front_x - f.platform.length;
    for (double x : d.cargo_mounts.x)
      if (x < rear - 1e-9 || x > f.platform.front_x + 1e-9) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "the cargo's mount station x = %g m is off the platform (x = %g to %g m)", x,
                      rear, f.platform.front_x);
        ctx.Fail(node["platform"], buf);
      }
  }
  try {
    SetFrameMesh(d);
  } catch (const InputError& e) {
    // a platform's error at the platform's line
    const bool platform = std::string(e.what()).find("platform: ") != std::string::npos;
    ctx.Rethrow(platform ? node["platform"] : node, e);
  }
}

MassProperties3 BodyMassProperties(const reduction::ReducedBody& body) {
  const reduction::InertiaInvariants& v = body.invariants;
  MassProperties3 mp;
  mp.mass = v.mvv(0, 0);
  const Mat3 s = -v.mvo0 / mp.mass;  // skew(c)
  mp.cg = Vec3(s(2, 1), s(0, 2), s(1, 0));
  const Vec3& c = mp.cg;
  mp.inertia = v.moo0 - mp.mass * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  return mp;
}

void SetFrameBody(TruckData& d, std::shared_ptr<const reduction::ReducedBody> body) {
  const MassProperties3 mp = BodyMassProperties(*body);
  d.frame.mass = mp.mass;
  d.frame.cg = mp.cg;
  d.frame.inertia = mp.inertia.diagonal();
  d.frame.products = Vec3(mp.inertia(0, 1), mp.inertia(0, 2), mp.inertia(1, 2));
  d.frame_mesh = std::make_shared<fe::Mesh>(body->mesh);
  d.frame_body = std::move(body);
}

GeneratedFrameModel BuildGeneratedFrameModel(const TruckData& d, double g) {
  if (!d.frame_mesh || d.frame_body)
    throw InputError("the truck has no generated frame (its frame is a body file)", {d.frame_body_file, 0, "truck frame"});
  GeneratedFrameModel out;
  out.mesh = *d.frame_mesh;
  const LadderFrameData& lf = d.ladder;
  for (const FrameAttachment& a : FrameAttachments(d, g)) {
    const int node = NearestNode(out.mesh, a.point);
    out.mounts.emplace_back(a.name, node);
    if (std::find(out.interface_nodes.begin(), out.interface_nodes.end(), node) != out.interface_nodes.end()) continue;
    out.interface_nodes.push_back(node);
    // the axle arms' pivots reach both rails (the leaf springs' eyes)
    if (a.name.rfind("arm_pivot", 0) == 0) {
      const double x = out.mesh.nodes[static_cast<size_t>(node)].x.x();
      AddBracket(out.mesh, node, {Vec3(x, lf.half_spacing, lf.bottom_z), Vec3(x, -lf.half_spacing, lf.bottom_z)},
                 lf.spider_radius);
    }
  }
  // a spider on the rails must not reach the platform above them, nor one on the platform the rails
  const std::vector<int> part = FramePartOfNodes(out.mesh);
  AddSpiders(out.mesh, out.interface_nodes, lf.spider_radius, &part);
  return out;
}

int FrameMountNode(const TruckData& d, const reduction::ReducedBody& frame, const std::string& name,
                   const Vec3& point) {
  // no file: a truck file's reader adds its own and the line of the mount
  const ErrorContext where{"", 0, "frame mount " + Quoted(name)};
  const std::string of = d.frame_body ? " of " + Quoted(d.frame_body_file) : "";
  int node = -1;
  if (d.frame_body) {
    const auto it = d.frame_mounts.find(name);
    if (it == d.frame_mounts.end()) throw InputError("no node is given for this mount (frame.mounts)", where);
    node = frame.mesh.NodeIndex(it->second);
    if (node < 0) throw InputError("node " + std::to_string(it->second) + " does not exist in body file " + Quoted(d.frame_body_file), where);
  } else {
    node = NearestNode(frame.mesh, point);
  }
  const fe::Node& fn = frame.mesh.nodes[static_cast<size_t>(node)];
  const auto& in = frame.interface_nodes;
  if (std::find(in.begin(), in.end(), node) == in.end())
    throw InputError("node " + std::to_string(fn.id) + of +
                         " is not an interface node of the elastic frame (reduce the frame with it in --interface)",
                     where);
  const double distance = (fn.x - point).norm();
  if (d.frame_body && distance > d.mount_tolerance) {
    char buf[160];
    std::snprintf(buf, sizeof buf, " is %.3f m from the mount point %s m, more than mount_tolerance %.3g m", distance,
                  Point(point).c_str(), d.mount_tolerance);
    throw InputError("node " + std::to_string(fn.id) + of + " at " + Point(fn.x) + buf +
                         ": the FE frame and the truck data disagree (the FE model's basic frame must be the vehicle "
                         "frame: x forward from the front-axle centre, y left, z up from the road)",
                     where);
  }
  return node;
}

}  // namespace flexmb::vehicle
