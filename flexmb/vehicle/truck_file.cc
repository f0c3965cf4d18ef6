#include "flexmb/vehicle/truck.h"

#include <cmath>
#include <filesystem>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/vehicle/tir_file.h"
#include "flexmb/vehicle/truck_frame.h"
#include "flexmb/yaml/yaml_context.h"

namespace flexmb::vehicle {
namespace {

// The map under the one top-level key `kind` of the vehicle data file
// `path` (a tire, a suspension, a part, ...); errors through `ctx` (made for
// `path`) name the file and line; `what` names the file's kind in read
// errors, `entity` the map in the others.
YAML::Node LoadDataFileMap(const std::string& path, const char* kind, const std::string& what, const std::string& entity,
                           YamlContext& ctx) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw InputError("cannot open the " + what + " file", {path, 0, ""});
  } catch (const YAML::Exception& e) {
    throw InputError("cannot read the " + what + " file: " + e.what(), {path, e.mark.line >= 0 ? e.mark.line + 1 : 0, ""});
  }
  ctx.SetEntity(entity);
  const std::string expected = std::string("expected a top-level '") + kind + "' map";
  if (!root.IsMap()) ctx.Fail(root, expected);
  const YAML::Node t = ctx.MapChild(root, kind);
  if (!t) ctx.Fail(root, expected);
  ctx.CheckKeys(root, {kind, "note"});
  return t;
}

// A subsystem of the truck map: its map and the context its errors go
// through (the truck file's, or that of the data file it was read from).
struct SubsystemMap {
  YAML::Node node;                         ///< undefined when the key is absent
  YamlContext* ctx = nullptr;              ///< the truck file's or file_ctx
  std::unique_ptr<YamlContext> file_ctx;   ///< the data file's, when read from one
};

// The subsystem of the truck map `n` under `key`: written inline, or the
// name of a data file (relative to the truck file's folder `dir`) whose
// top-level `kind` map holds it, so that several trucks share one cab,
// suspension or steering file.
SubsystemMap Subsystem(const YAML::Node& n, YamlContext& ctx, const char* key, const char* kind,
                       const std::string& dir) {
  // copy-constructed: a missing key is yaml-cpp's invalid node, which
  // assigning (operator=) would throw on
  SubsystemMap m{ctx.MapChild(n, key), &ctx, nullptr};
  if (!m.node || !m.node.IsScalar()) return m;
  const std::string path = (std::filesystem::path(dir) / m.node.Scalar()).string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    ctx.Fail(m.node, std::string("'") + key + "': no " + kind + " file '" + path + "'");
  m.file_ctx = std::make_unique<YamlContext>(path);
  m.ctx = m.file_ctx.get();
  m.node = LoadDataFileMap(path, kind, kind, std::string(kind) + " '" + key + "'", *m.file_ctx);
  return m;
}

// Subsystem, required: its errors name `entity`; without it, an error
// `missing` at the map `n`
SubsystemMap RequiredSubsystem(const YAML::Node& n, YamlContext& ctx, const char* key, const char* kind,
                               const std::string& dir, const std::string& entity, const std::string& missing) {
  SubsystemMap m = Subsystem(n, ctx, key, kind, dir);
  m.ctx->SetEntity(entity);
  if (!m.node) m.ctx->Fail(n, missing);
  return m;
}

// the part under `key` of map `truck` (a truck or an axle map); `label`
// names it in errors (default: the key)
void ReadPart(const YAML::Node& truck, YamlContext& truck_ctx, const char* key, const std::string& dir, PartData& p,
              MountData* mounts = nullptr, const std::string& label = "") {
  const std::string name = label.empty() ? key : label;
  const SubsystemMap sub =
      RequiredSubsystem(truck, truck_ctx, key, "part", dir, "truck part '" + name + "'", "missing part '" + name + "'");
  const YAML::Node& node = sub.node;
  YamlContext& ctx = *sub.ctx;
  if (mounts) {
    ctx.CheckKeys(node, {"mass", "cg", "inertia", "note", "mount_x", "mount_stiffness", "mount_damping"});
    const YAML::Node mx = node["mount_x"];
    if (!mx || !mx.IsSequence() || mx.size() == 0) ctx.Fail(node, "expected 'mount_x' as a list of x stations [m]");
    mounts->x.clear();
    for (const YAML::Node& v : mx) mounts->x.push_back(ctx.Number(v, "mount station"));
    mounts->stiffness = ctx.Vector3(node, "mount_stiffness", mounts->stiffness);
    mounts->damping = ctx.Vector3(node, "mount_damping", mounts->damping);
    if (mounts->stiffness.minCoeff() <= 0 || mounts->damping.minCoeff() < 0)
      ctx.Fail(node, "mount stiffness must be positive and damping not negative");
  } else {
    ctx.CheckKeys(node, {"mass", "cg", "inertia", "note"});
  }
  p.mass = ctx.Positive(node, "mass");
  p.cg = ctx.Vector3(node, "cg", Vec3::Zero());
  p.inertia = ctx.Vector3(node, "inertia");
  if (p.inertia.minCoeff() <= 0) ctx.Fail(node["inertia"], "principal inertias must be positive");
}

void ReadSuspension(const YAML::Node& truck, YamlContext& truck_ctx, const char* key, const std::string& dir,
                    SuspensionData& s, const std::string& label = "") {
  const std::string name = label.empty() ? key : label;
  const SubsystemMap sub = RequiredSubsystem(truck, truck_ctx, key, "suspension", dir, "suspension '" + name + "'",
                                             "missing suspension '" + name + "'");
  const YAML::Node& node = sub.node;
  YamlContext& ctx = *sub.ctx;
  ctx.CheckKeys(node, {"spring_stiffness", "spring_damping", "spring_half_spacing", "spring_length", "arm_length",
                       "stabilizer_stiffness", "stabilizer_damping", "extra_arm_height", "friction_force",
                       "friction_velocity", "note"});
  s.spring_stiffness = ctx.Positive(node, "spring_stiffness");
  s.spring_damping = ctx.Double(node, "spring_damping", s.spring_damping);
  s.spring_half_spacing = ctx.Positive(node, "spring_half_spacing");
  s.spring_length = ctx.Positive(node, "spring_length");
  s.arm_length = ctx.Positive(node, "arm_length");
  s.stabilizer_stiffness = ctx.Double(node, "stabilizer_stiffness", 0.0);
  s.stabilizer_damping = ctx.Double(node, "stabilizer_damping", 0.0);
  s.extra_arm_height = ctx.Double(node, "extra_arm_height", 0.0);
  if (!(s.extra_arm_height >= 0)) ctx.Fail(node, "extra_arm_height must be >= 0");
  s.friction_force = ctx.Double(node, "friction_force", 0.0);
  s.friction_velocity = ctx.Double(node, "friction_velocity", s.friction_velocity);
  if (!(s.friction_force >= 0) || !(s.friction_velocity > 0))
    ctx.Fail(node, "friction_force must be >= 0 [N] and friction_velocity positive [m/s]");
}

// the steering of the truck map `n` (inline or a steering file: Subsystem)
void ReadSteering(const YAML::Node& n, YamlContext& truck_ctx, const std::string& dir, TruckData& d) {
  const SubsystemMap sub = RequiredSubsystem(n, truck_ctx, "steering", "steering", dir, "steering", "missing 'steering'");
  const YAML::Node& st = sub.node;
  YamlContext& ctx = *sub.ctx;
  ctx.CheckKeys(st, {"ratio", "stiffness", "damping", "linkage", "pitman_arm_length", "tie_rod_arm_length", "column",
                     "column_mass", "column_inertia", "column_length", "column_inclination_deg", "pitman_x",
                     "steering_arm_height"});
  d.steering_ratio = ctx.Positive(st, "ratio");
  d.steering_stiffness = ctx.Positive(st, "stiffness");
  d.steering_damping = ctx.Double(st, "damping", d.steering_damping);
  d.steering_linkage = ctx.Bool(st, "linkage", d.steering_linkage);
  d.pitman_arm_length = ctx.Double(st, "pitman_arm_length", d.pitman_arm_length);
  d.tie_rod_arm_length = ctx.Double(st, "tie_rod_arm_length", d.tie_rod_arm_length);
  d.steering_column = ctx.Bool(st, "column", d.steering_column);
  d.column_mass = ctx.Double(st, "column_mass", d.column_mass);
  d.column_inertia = ctx.Double(st, "column_inertia", d.column_inertia);
  d.column_length = ctx.Double(st, "column_length", d.column_length);
  d.column_inclination = ctx.Double(st, "column_inclination_deg", d.column_inclination * 180.0 / M_PI) * M_PI / 180.0;
  if (!(d.column_mass > 0) || !(d.column_inertia > 0) || !(d.column_length > 0) ||
      !(std::abs(d.column_inclination) < 0.5 * M_PI))
    ctx.Fail(st, "column_mass, column_inertia, column_length must be positive, |column_inclination_deg| < 90");
  d.drag_link_length = ctx.Double(st, "pitman_x", d.drag_link_length);
  d.steering_arm_height = ctx.Double(st, "steering_arm_height", d.steering_arm_height);
  if (!(d.pitman_arm_length > 0) || !(d.tie_rod_arm_length > 0))
    ctx.Fail(st, "pitman_arm_length and tie_rod_arm_length must be positive");
  if (!(d.drag_link_length > 0) || !std::isfinite(d.steering_arm_height))
    ctx.Fail(st, "pitman_x must be positive and steering_arm_height finite");
}

// the brakes of the truck map `n`, optional (inline or a brakes file:
// Subsystem); returns the front axle's share (front_share, 0.4 by default)
// of a two-axle truck file, which `axles` replaces by each axle's brake_share
double ReadBrakes(const YAML::Node& n, YamlContext& truck_ctx, const std::string& dir, TruckData& d) {
  const SubsystemMap sub = Subsystem(n, truck_ctx, "brakes", "brakes", dir);
  double front_share = 0.4;
  if (const YAML::Node& br = sub.node) {
    YamlContext& ctx = *sub.ctx;
    ctx.SetEntity("brakes");
    ctx.CheckKeys(br, {"front_share", "smoothing_spin", "note"});
    if (br["front_share"] && n["axles"])
      ctx.Fail(br["front_share"], "with 'axles' each axle gives its 'brake_share'");
    front_share = ctx.Double(br, "front_share", front_share);
    d.brake_smoothing_spin = ctx.Double(br, "smoothing_spin", d.brake_smoothing_spin);
    if (!(front_share >= 0 && front_share <= 1) || !(d.brake_smoothing_spin > 0))
      ctx.Fail(br, "front_share must lie in [0, 1] and smoothing_spin be positive");
  }
  return front_share;
}

// the bogies of the truck map `n` (optional list)
void ReadBogies(const YAML::Node& n, YamlContext& ctx, const std::string& dir, TruckData& d) {
  const YAML::Node list = n["bogies"];
  if (!list) return;
  ctx.SetEntity("truck bogies");
  if (!list.IsSequence()) ctx.Fail(list, "expected 'bogies' as a list of {name, x, beam}");
  for (const YAML::Node& b : list) {
    BogieData bg;
    ctx.SetEntity("truck bogie");
    if (!b.IsMap()) ctx.Fail(b, "expected a bogie as a map {name, x, beam}");
    ctx.CheckKeys(b, {"name", "x", "beam", "note"});
    bg.name = ctx.String(b, "name");
    ctx.SetEntity("bogie '" + bg.name + "'");
    bg.x = ctx.Double(b, "x");
    ReadPart(b, ctx, "beam", dir, bg.beam, nullptr, "bogie " + bg.name + " beam");
    if (b["beam"].IsMap() && b["beam"]["cg"])
      ctx.Fail(b["beam"]["cg"], "a bogie's beam has its centre of mass on the trunnion axis: no 'cg'");
    for (const BogieData& other : d.bogies)
      if (other.name == bg.name) ctx.Fail(b["name"], "two bogies are named '" + bg.name + "'");
    d.bogies.push_back(bg);
  }
}

// the axles of the truck map `n`: a list from front to rear, each with its
// parts, suspension (inline or a file), tire file and roles
void ReadAxles(const YAML::Node& n, YamlContext& ctx, const std::string& dir, TruckData& d) {
  ReadBogies(n, ctx, dir, d);
  const YAML::Node list = n["axles"];
  ctx.SetEntity("truck axles");
  if (!list.IsSequence() || list.size() < 2) ctx.Fail(list, "expected 'axles' as a list of at least two axles");
  for (const YAML::Node& a : list) {
    AxleData ax;
    ctx.SetEntity("truck axle");
    if (!a.IsMap()) ctx.Fail(a, "expected an axle as a map");
    ctx.CheckKeys(a, {"name", "x", "track", "steered", "driven", "brake_share", "axle", "wheel", "suspension", "tire",
                      "bogie", "note"});
    ax.name = ctx.String(a, "name");
    const std::string entity = "axle '" + ax.name + "'";
    ctx.SetEntity(entity);
    ax.x = ctx.Double(a, "x");
    ax.track = ctx.Positive(a, "track");
    ax.steered = ctx.Bool(a, "steered", false);
    ax.driven = ctx.Bool(a, "driven", false);
    ax.brake_share = ctx.Double(a, "brake_share");
    ReadPart(a, ctx, "axle", dir, ax.axle, nullptr, ax.name + " axle");
    ReadPart(a, ctx, "wheel", dir, ax.wheel, nullptr, ax.name + " wheel");
    ReadSuspension(a, ctx, "suspension", dir, ax.suspension, ax.name);
    ctx.SetEntity(entity);
    ax.tire = LoadTireFile((std::filesystem::path(dir) / ctx.String(a, "tire")).string());
    if (const YAML::Node b = a["bogie"]) {
      const std::string name = ctx.String(a, "bogie");
      for (size_t k = 0; k < d.bogies.size(); ++k)
        if (d.bogies[k].name == name) ax.bogie = static_cast<int>(k);
      if (ax.bogie < 0) ctx.Fail(b, "no bogie '" + name + "' in 'bogies'");
    }
    d.axles.push_back(ax);
  }
  // the rules over all axles: order, steering, shares, bogies
  ctx.SetEntity("truck axles");
  ctx.Guard(list, [&] { CheckAxles(d); });
}

}  // namespace

TireData ReadTireData(const YAML::Node& t, YamlContext& ctx) {
  ctx.CheckKeys(t, {"name", "note", "count", "unloaded_radius", "vertical_stiffness", "vertical_damping",
                    "rolling_radius_factor", "nominal_load", "pcx1", "pdx1", "pdx2", "pex1", "pkx1", "pcy1", "pdy1",
                    "pdy2", "pey1", "pky1", "pky2", "rbx1", "rby1", "trail", "trail_decay", "rolling_resistance",
                    "low_speed", "relaxation_length", "patch_mass", "longitudinal_relaxation_length"});
  TireData d;
  d.count = ctx.Integer(t, "count", d.count);
  d.unloaded_radius = ctx.Positive(t, "unloaded_radius");
  d.vertical_stiffness = ctx.Positive(t, "vertical_stiffness");
  d.vertical_damping = ctx.Double(t, "vertical_damping", d.vertical_damping);
  d.rolling_radius_factor = ctx.Double(t, "rolling_radius_factor", d.rolling_radius_factor);
  d.nominal_load = ctx.Positive(t, "nominal_load");
  d.pcx1 = ctx.Double(t, "pcx1", d.pcx1);
  d.pdx1 = ctx.Double(t, "pdx1", d.pdx1);
  d.pdx2 = ctx.Double(t, "pdx2", d.pdx2);
  d.pex1 = ctx.Double(t, "pex1", d.pex1);
  d.pkx1 = ctx.Double(t, "pkx1", d.pkx1);
  d.pcy1 = ctx.Double(t, "pcy1", d.pcy1);
  d.pdy1 = ctx.Double(t, "pdy1", d.pdy1);
  d.pdy2 = ctx.Double(t, "pdy2", d.pdy2);
  d.pey1 = ctx.Double(t, "pey1", d.pey1);
  d.pky1 = ctx.Double(t, "pky1", d.pky1);
  d.pky2 = ctx.Double(t, "pky2", d.pky2);
  d.rbx1 = ctx.Double(t, "rbx1", d.rbx1);
  d.rby1 = ctx.Double(t, "rby1", d.rby1);
  d.trail = ctx.Double(t, "trail", d.trail);
  d.trail_decay = ctx.Double(t, "trail_decay", d.trail_decay);
  d.rolling_resistance = ctx.Double(t, "rolling_resistance", d.rolling_resistance);
  d.low_speed = ctx.Double(t, "low_speed", d.low_speed);
  d.relaxation_length = ctx.Double(t, "relaxation_length", d.relaxation_length);
  d.patch_mass = ctx.Double(t, "patch_mass", d.patch_mass);
  d.longitudinal_relaxation_length = ctx.Double(t, "longitudinal_relaxation_length", d.longitudinal_relaxation_length);
  // validate now, naming the file
  ctx.Guard(t, [&] { Tire("check", d, 1.0); });
  return d;
}

TireData LoadTireFile(const std::string& path) {
  if (IsTirPath(path)) {
    // a Magic Formula property file (tir_file.h); warn of what the simplified model leaves out
    TirFile tir = ReadTirFile(path);
    if (!tir.ignored.empty()) {
      std::string list;
      for (const std::string& k : tir.ignored) list += (list.empty() ? "" : ", ") + k;
      LogWarning(path + ": ignored by the simplified tire model (not used, values not neutral): " + list);
    }
    return tir.data;
  }
  YamlContext ctx(path);
  const YAML::Node t = LoadDataFileMap(path, "tire", "tire", "tire data", ctx);
  try {
    return ReadTireData(t, ctx);
  } catch (const YAML::Exception& e) {
    // a value of the wrong YAML kind that the checks above did not catch
    throw InputError(std::string("cannot read the tire file: ") + e.what(), {path, YamlContext::Line(t), "tire data"});
  }
}

TruckData ParseTruck(const YAML::Node& n, YamlContext& ctx, const std::string& dir) {
  TruckData d;
  ctx.SetEntity("truck");
  if (!n.IsMap()) ctx.Fail(n, "expected 'truck' as a map");
  if (n["axles"]) {
    ctx.CheckKeys(n, {"axles", "bogies", "kingpin_offset", "frame", "cab", "powertrain", "cargo", "knuckle", "arm",
                      "steering", "gauge_width", "brakes", "note"});
  } else {
    ctx.CheckKeys(n, {"wheelbase", "front_track", "rear_track", "kingpin_offset", "frame", "cab", "powertrain", "cargo",
                      "front_axle", "rear_axle", "knuckle", "front_wheel", "rear_wheel", "arm", "front_suspension",
                      "rear_suspension", "steering", "tires", "gauge_width", "brakes", "note"});
  }
  d.kingpin_offset = ctx.Double(n, "kingpin_offset", d.kingpin_offset);
  d.gauge_width = ctx.Positive(n, "gauge_width");
  ReadPart(n, ctx, "cab", dir, d.cab, &d.cab_mounts);
  ReadPart(n, ctx, "powertrain", dir, d.powertrain, &d.powertrain_mounts);
  ReadPart(n, ctx, "cargo", dir, d.cargo, &d.cargo_mounts);
  if (n["axles"]) {
    ReadAxles(n, ctx, dir, d);
    ReadPart(n, ctx, "knuckle", dir, d.knuckle);
    ReadPart(n, ctx, "arm", dir, d.arm);
    ReadSteering(n, ctx, dir, d);
    ReadBrakes(n, ctx, dir, d);
  } else {
    // the two-axle form: axles "front" (steered) and "rear" (driven)
    d.axles.resize(2);
    AxleData& f = d.axles[0];
    AxleData& r = d.axles[1];
    f.name = "front";
    r.name = "rear";
    f.steered = true;
    r.driven = true;
    r.x = -ctx.Positive(n, "wheelbase");
    f.track = ctx.Positive(n, "front_track");
    r.track = ctx.Positive(n, "rear_track");
    ReadPart(n, ctx, "front_axle", dir, f.axle);
    ReadPart(n, ctx, "rear_axle", dir, r.axle);
    ReadPart(n, ctx, "knuckle", dir, d.knuckle);
    ReadPart(n, ctx, "front_wheel", dir, f.wheel);
    ReadPart(n, ctx, "rear_wheel", dir, r.wheel);
    ReadPart(n, ctx, "arm", dir, d.arm);
    ReadSuspension(n, ctx, "front_suspension", dir, f.suspension);
    ReadSuspension(n, ctx, "rear_suspension", dir, r.suspension);
    ReadSteering(n, ctx, dir, d);
    f.brake_share = ReadBrakes(n, ctx, dir, d);
    r.brake_share = 1.0 - f.brake_share;
    ctx.SetEntity("tires");
    const YAML::Node tires = n["tires"];
    if (!tires) ctx.Fail(n, "missing 'tires'");
    ctx.CheckKeys(tires, {"front", "rear"});
    const std::filesystem::path base(dir);
    f.tire = LoadTireFile((base / ctx.String(tires, "front")).string());
    r.tire = LoadTireFile((base / ctx.String(tires, "rear")).string());
  }
  ReadTruckFrame(n, ctx, dir, d);
  return d;
}

}  // namespace flexmb::vehicle
