#include "flexmb/vehicle/truck.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <tuple>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/forces/bushing.h"
#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/forces/joint_motor.h"
#include "flexmb/forces/rotational_spring_damper.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/yaml/yaml_context.h"
#include "flexmb/joints/distance.h"
#include "flexmb/joints/gear.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/vehicle/command_signal.h"
#include "flexmb/vehicle/contact_patch_joint.h"
#include "flexmb/vehicle/tir_file.h"
#include "flexmb/vehicle/truck_frame.h"
#include "flexmb/vehicle/wheel_brake.h"

namespace flexmb::vehicle {
namespace {

// marker orientations: z axis along world y (wheel spin, arm pivot) and x (axle roll)
Mat3 AxisY() {
  Mat3 R;
  R << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  return R;
}
Mat3 AxisX() {
  Mat3 R;
  R << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  return R;
}

// mass of the contact-patch body of a relaxed tire set (0 without relaxation)
double TruckPatchMass(const TireData& t) { return t.relaxation_length > 0 ? t.count * t.patch_mass : 0.0; }

// mass of the parts moving with an axle (axle, wheels, knuckles, contact patches)
double UnsprungMass(const TruckData& d, bool front) {
  const double hub = (front ? d.front : d.rear).extra_arm_height > 0 ? kAxleHubMass : 0.0;
  return hub + (front ? d.front_axle.mass + 2 * (d.front_wheel.mass + d.knuckle.mass + TruckPatchMass(d.front_tire))
                      : d.rear_axle.mass + 2 * (d.rear_wheel.mass + TruckPatchMass(d.rear_tire)));
}

int AddPart(Model& m, const std::string& name, const PartData& p, const Vec3& cg, double speed, const Vec3& w) {
  RigidBodyData b;
  b.mass = p.mass;
  b.inertia_C = p.inertia.asDiagonal();
  b.inertia_C(0, 1) = b.inertia_C(1, 0) = p.products.x();
  b.inertia_C(0, 2) = b.inertia_C(2, 0) = p.products.y();
  b.inertia_C(1, 2) = b.inertia_C(2, 1) = p.products.z();
  b.c_B = cg;
  // the body frame is the vehicle frame: its origin's velocity gives the
  // centre of mass the forward speed
  b.v_WB = Vec3(speed, 0, 0) - w.cross(cg);
  b.w_WB = w;
  return m.AddBody(std::make_unique<RigidBody>(name, b));
}

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
  SubsystemMap m;
  m.ctx = &ctx;
  m.node = n[key];
  if (!m.node || !m.node.IsScalar()) return m;
  const std::string path = (std::filesystem::path(dir) / m.node.Scalar()).string();
  if (!std::filesystem::is_regular_file(path))
    ctx.Fail(m.node, std::string("'") + key + "': no " + kind + " file '" + path + "'");
  m.file_ctx = std::make_unique<YamlContext>(path);
  m.ctx = m.file_ctx.get();
  m.node = LoadDataFileMap(path, kind, kind, std::string(kind) + " '" + key + "'", *m.file_ctx);
  return m;
}

void ReadPart(const YAML::Node& truck, YamlContext& truck_ctx, const char* key, const std::string& dir, PartData& p,
              MountData* mounts = nullptr) {
  const SubsystemMap sub = Subsystem(truck, truck_ctx, key, "part", dir);
  const YAML::Node& node = sub.node;
  YamlContext& ctx = *sub.ctx;
  ctx.SetEntity(std::string("truck part '") + key + "'");
  if (!node) ctx.Fail(truck, std::string("missing part '") + key + "'");
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
                    SuspensionData& s) {
  const SubsystemMap sub = Subsystem(truck, truck_ctx, key, "suspension", dir);
  const YAML::Node& node = sub.node;
  YamlContext& ctx = *sub.ctx;
  ctx.SetEntity(std::string("suspension '") + key + "'");
  if (!node) ctx.Fail(truck, std::string("missing suspension '") + key + "'");
  ctx.CheckKeys(node, {"spring_stiffness", "spring_damping", "spring_half_spacing", "spring_length", "arm_length",
                       "stabilizer_stiffness", "stabilizer_damping", "extra_arm_height"});
  s.spring_stiffness = ctx.Positive(node, "spring_stiffness");
  s.spring_damping = ctx.Double(node, "spring_damping", s.spring_damping);
  s.spring_half_spacing = ctx.Positive(node, "spring_half_spacing");
  s.spring_length = ctx.Positive(node, "spring_length");
  s.arm_length = ctx.Positive(node, "arm_length");
  s.stabilizer_stiffness = ctx.Double(node, "stabilizer_stiffness", 0.0);
  s.stabilizer_damping = ctx.Double(node, "stabilizer_damping", 0.0);
  s.extra_arm_height = ctx.Double(node, "extra_arm_height", 0.0);
  if (!(s.extra_arm_height >= 0)) ctx.Fail(node, "extra_arm_height must be >= 0");
}

// the steering of the truck map `n` (inline or a steering file: Subsystem)
void ReadSteering(const YAML::Node& n, YamlContext& truck_ctx, const std::string& dir, TruckData& d) {
  const SubsystemMap sub = Subsystem(n, truck_ctx, "steering", "steering", dir);
  const YAML::Node& st = sub.node;
  YamlContext& ctx = *sub.ctx;
  ctx.SetEntity("steering");
  if (!st) ctx.Fail(n, "missing 'steering'");
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

// the brakes of the truck map `n`, optional (inline or a brakes file: Subsystem)
void ReadBrakes(const YAML::Node& n, YamlContext& truck_ctx, const std::string& dir, TruckData& d) {
  const SubsystemMap sub = Subsystem(n, truck_ctx, "brakes", "brakes", dir);
  if (const YAML::Node& br = sub.node) {
    YamlContext& ctx = *sub.ctx;
    ctx.SetEntity("brakes");
    ctx.CheckKeys(br, {"front_share", "smoothing_spin", "note"});
    d.brake_front_share = ctx.Double(br, "front_share", d.brake_front_share);
    d.brake_smoothing_spin = ctx.Double(br, "smoothing_spin", d.brake_smoothing_spin);
    if (!(d.brake_front_share >= 0 && d.brake_front_share <= 1) || !(d.brake_smoothing_spin > 0))
      ctx.Fail(br, "front_share must lie in [0, 1] and smoothing_spin be positive");
  }
}

// static wheel-centre heights front, rear [m] from the tire deflections
std::array<double, 2> WheelCentreHeights(const TruckData& d, double g) {
  const std::array<double, 2> loads = StaticAxleLoads(d, g);
  return {d.front_tire.unloaded_radius - 0.5 * loads[0] / (d.front_tire.count * d.front_tire.vertical_stiffness),
          d.rear_tire.unloaded_radius - 0.5 * loads[1] / (d.rear_tire.count * d.rear_tire.vertical_stiffness)};
}

// left kingpin on the axle at wheel-centre height zf
Vec3 LeftKingpin(const TruckData& d, double zf) { return Vec3(0, 0.5 * d.front_track - d.kingpin_offset, zf); }

// ball of the left knuckle's inboard steering arm (drag link's rear end)
Vec3 SteeringArmBall(const TruckData& d, double zf) {
  return LeftKingpin(d, zf) + Vec3(0, -d.pitman_arm_length, d.steering_arm_height);
}

// pitman ball (drag link's front end): the drag link is horizontal
Vec3 PitmanBall(const TruckData& d, double zf) { return SteeringArmBall(d, zf) + Vec3(d.drag_link_length, 0, 0); }

// pitman arm pivot (the steering gear's output shaft) on the frame, the
// pitman arm hanging down from it to the ball; see BuildTruck
Vec3 SteeringGearPivot(const TruckData& d, double zf) { return PitmanBall(d, zf) + Vec3(0, 0, d.pitman_arm_length); }

// the steering gear box's mount on the left rail's outer web, mid-height,
// ahead of the pitman pivot by twice the spider radius: clear of the front
// arm pivot's bracket (the spring hanger at x = arm_length, where the pitman
// sits); the elastic frame's interface point of the gear, whose node carries
// the pitman and column markers offset to the pivot
Vec3 SteeringGearMount(const TruckData& d, double zf) {
  return Vec3(SteeringGearPivot(d, zf).x() + 2 * d.ladder.spider_radius, d.ladder.half_spacing,
              d.ladder.bottom_z + 0.5 * d.ladder.web_height);
}

// mount points of a part: per station left then right, at the rails' top corners
std::vector<Vec3> MountPoints(const TruckData& d, const MountData& mounts) {
  std::vector<Vec3> p;
  const double top = d.ladder.bottom_z + d.ladder.web_height;
  for (double x : mounts.x)
    for (double side : {1.0, -1.0}) p.emplace_back(x, side * d.ladder.half_spacing, top);
  return p;
}

}  // namespace

void SetFrameMesh(TruckData& d) {
  auto mesh = std::make_shared<fe::Mesh>(GenerateLadderFrame(d.ladder, {}).mesh);
  const MassProperties3 mp = ShellMassProperties(*mesh);
  d.frame.mass = mp.mass;
  d.frame.cg = mp.cg;
  d.frame.inertia = mp.inertia.diagonal();
  d.frame.products = Vec3(mp.inertia(0, 1), mp.inertia(0, 2), mp.inertia(1, 2));
  d.frame_mesh = std::move(mesh);
}

std::vector<FrameAttachment> FrameAttachments(const TruckData& d, double g) {
  const std::array<double, 2> zw = WheelCentreHeights(d, g);
  const double xr = -d.wheelbase;
  std::vector<FrameAttachment> a;
  for (int axle = 0; axle < 2; ++axle) {
    const SuspensionData& s = axle == 0 ? d.front : d.rear;
    const double x = axle == 0 ? 0.0 : xr;
    const std::string side = axle == 0 ? "front" : "rear";
    a.push_back({"spring_seat_" + side + "_left", Vec3(x, s.spring_half_spacing, zw[axle] + s.spring_length)});
    a.push_back({"spring_seat_" + side + "_right", Vec3(x, -s.spring_half_spacing, zw[axle] + s.spring_length)});
    a.push_back({"arm_pivot_" + side, Vec3(x + s.arm_length, 0, zw[axle])});
  }
  a.push_back({"steering_gear", SteeringGearMount(d, zw[0])});
  for (const auto& [name, mounts] : {std::pair<std::string, const MountData*>{"cab", &d.cab_mounts},
                                     {"powertrain", &d.powertrain_mounts},
                                     {"cargo", &d.cargo_mounts}}) {
    const std::vector<Vec3> p = MountPoints(d, *mounts);
    for (size_t k = 0; k < p.size(); ++k)
      a.push_back({name + "_mount_" + std::to_string(k / 2 + 1) + (k % 2 == 0 ? "_left" : "_right"), p[k]});
  }
  a.push_back({"tow_hitch", Vec3(d.ladder.front_x - d.ladder.length, 0, d.ladder.bottom_z + 0.5 * d.ladder.web_height)});
  return a;
}

std::array<double, 2> StaticAxleLoads(const TruckData& d, double g) {
  const double L = d.wheelbase;
  double w = 0, moment = 0;  // total weight and its moment about the rear axle
  auto add = [&](double mass, double x) {
    w += mass * g;
    moment += mass * g * (x + L);
  };
  for (const PartData* p : {&d.frame, &d.cab, &d.powertrain, &d.cargo}) add(p->mass, p->cg.x());
  add(UnsprungMass(d, true), 0.0);
  add(UnsprungMass(d, false), -L);
  add(d.arm.mass, 0.5 * d.front.arm_length);
  add(d.arm.mass, -L + 0.5 * d.rear.arm_length);
  if (d.steering_linkage) add(d.pitman_arm_mass, d.drag_link_length);
  if (d.steering_linkage && d.steering_column)
    add(d.column_mass, d.drag_link_length - 0.5 * d.column_length * std::sin(d.column_inclination));
  const double front = moment / L;
  return {front, w - front};
}

TruckHandles BuildTruck(const TruckData& d, double speed, double mu, std::shared_ptr<const double> steering_wheel,
                        std::shared_ptr<const double> drive_torque, Model& m,
                        std::shared_ptr<const double> brake_torque) {
  TruckInputs in;
  in.steering_wheel = std::make_shared<CommandSignal>(std::move(steering_wheel), 1.0);
  in.drive_torque = std::make_shared<CommandSignal>(std::move(drive_torque), 1.0);
  if (brake_torque) in.brake_torque = std::make_shared<CommandSignal>(std::move(brake_torque), 1.0);
  return BuildTruck(d, speed, mu, in, m);
}

TruckHandles BuildTruck(const TruckData& d, double speed, double mu, const TruckInputs& inputs, Model& m) {
  if (!inputs.steering_wheel || !inputs.drive_torque)
    throw InputError("the truck needs a steering-wheel angle and a drive torque", {"", 0, "truck"});
  const auto& steering_wheel = inputs.steering_wheel;
  const auto& drive_torque = inputs.drive_torque;
  const auto& brake_torque = inputs.brake_torque;
  if (!(d.brake_front_share >= 0 && d.brake_front_share <= 1) || !(d.brake_smoothing_spin > 0))
    throw InputError("brake front_share must lie in [0, 1] and smoothing_spin be positive", {"", 0, "truck brakes"});
  const double g = -m.gravity_W.z();
  const std::array<double, 2> loads = StaticAxleLoads(d, g);
  TruckHandles h;
  // static wheel-centre heights from the tire deflections
  const std::array<double, 2> zw = WheelCentreHeights(d, g);
  const double zf = zw[0], zr = zw[1];
  h.wheel_centre_z = {zf, zr};
  const double xr = -d.wheelbase;
  const Vec3 zero = Vec3::Zero();
  const Mat3 I = Mat3::Identity();

  // the frame: rigid with the generated frame's mass properties, or elastic
  int frame = -1;
  if (d.elastic_frame) {
    FlexibleBodyData fd;
    fd.reduced = d.elastic_frame;
    fd.v_WB = Vec3(speed, 0, 0);
    frame = m.AddBody(std::make_unique<FlexibleBody>("frame", fd));
    h.elastic = true;
  } else {
    frame = AddPart(m, "frame", d.frame, d.frame.cg, speed, zero);
  }
  h.frame_body = frame;
  // a frame marker at an attachment point: on the elastic frame carried by
  // the attachment's interface node (FrameMountNode), offset to the point
  // (`anchor`: the attachment whose node carries a marker offset from it)
  auto frame_marker = [&](const std::string& name, const Vec3& p, const Mat3& R,
                          const FrameAttachment* anchor = nullptr) {
    if (!d.elastic_frame) return m.AddMarker(frame, name, p, R);
    const int node = anchor ? FrameMountNode(d, *d.elastic_frame, anchor->name, anchor->point)
                            : FrameMountNode(d, *d.elastic_frame, name, p);
    return m.AddMarker(frame, name, p - d.elastic_frame->mesh.nodes[static_cast<size_t>(node)].x, R, node);
  };
  h.frame_ref = m.AddMarker(frame, "ref", d.frame.cg, I);
  h.front_axle_ref = m.AddMarker(frame, "front_axle_ref", Vec3(0, 0, 0), I);
  h.rear_axle_ref = m.AddMarker(frame, "rear_axle_ref", Vec3(xr, 0, 0), I);
  const double hb = 0.5 * d.gauge_width;
  h.gauge = {m.AddMarker(frame, "gauge_fl", Vec3(0, hb, zf), I), m.AddMarker(frame, "gauge_fr", Vec3(0, -hb, zf), I),
             m.AddMarker(frame, "gauge_rl", Vec3(xr, hb, zr), I), m.AddMarker(frame, "gauge_rr", Vec3(xr, -hb, zr), I)};
  // cab, powertrain, cargo on bushings at the mount points, preloaded by
  // their weight shared by the lever rule along x
  for (const auto& [name, part, mounts] :
       {std::tuple<const char*, const PartData*, const MountData*>{"cab", &d.cab, &d.cab_mounts},
        {"powertrain", &d.powertrain, &d.powertrain_mounts},
        {"cargo", &d.cargo, &d.cargo_mounts}}) {
    const int b = AddPart(m, name, *part, part->cg, speed, zero);
    const std::vector<Vec3> pts = MountPoints(d, *mounts);
    const double n = static_cast<double>(pts.size());
    double xm = 0, sxx = 0;
    for (const Vec3& p : pts) xm += p.x() / n;
    for (const Vec3& p : pts) sxx += (p.x() - xm) * (p.x() - xm);
    for (size_t k = 0; k < pts.size(); ++k) {
      const std::string mname = std::string(name) + "_mount_" + std::to_string(k / 2 + 1) + (k % 2 == 0 ? "_left" : "_right");
      const double share = 1.0 / n + (sxx > 0 ? (part->cg.x() - xm) * (pts[k].x() - xm) / sxx : 0.0);
      BushingData bd;
      bd.translational_stiffness = mounts->stiffness;
      bd.translational_damping = mounts->damping;
      bd.preload_force = Vec3(0, 0, share * part->mass * g);
      m.AddForce(std::make_unique<Bushing>(mname, bd), frame_marker(mname, pts[k], I),
                 m.AddMarker(b, "mount_" + std::to_string(k + 1), pts[k], I));
    }
  }
  // the rear tow hitch: an attachment point without a load in this model
  frame_marker("tow_hitch", Vec3(d.ladder.front_x - d.ladder.length, 0, d.ladder.bottom_z + 0.5 * d.ladder.web_height), I);

  // one axle: arm, axle, suspension springs, stabilizer; returns the axle body
  auto axle = [&](bool front) {
    const std::string side = front ? "front" : "rear";
    const SuspensionData& s = front ? d.front : d.rear;
    const double x = front ? 0.0 : xr, z = front ? zf : zr;
    const PartData& ap = front ? d.front_axle : d.rear_axle;
    const int arm = AddPart(m, side + "_arm", d.arm, Vec3(x + 0.5 * s.arm_length, 0, z), speed, zero);
    const int ax = AddPart(m, side + "_axle", ap, Vec3(x, 0, z), speed, zero);
    const Vec3 pivot(x + s.arm_length, 0, z), centre(x, 0, z);
    m.AddJoint(std::make_unique<RevoluteJoint>(side + "_arm_pivot"), frame_marker("arm_pivot_" + side, pivot, AxisY()),
               m.AddMarker(arm, "pivot", pivot, AxisY()));
    // the axle rolls on the arm, or with the additional arm (seed Fig. 3) on
    // a hub pitching on the arm and held parallel by the additional arm, a
    // rod of the arm's length above it (a parallelogram in side view)
    int roll_carrier = arm;
    if (s.extra_arm_height > 0) {
      PartData hp;
      hp.mass = kAxleHubMass;
      hp.inertia = Vec3::Constant(0.01);
      roll_carrier = AddPart(m, side + "_axle_hub", hp, centre, speed, zero);
      m.AddJoint(std::make_unique<RevoluteJoint>(side + "_axle_pitch"), m.AddMarker(arm, "hub", centre, AxisY()),
                 m.AddMarker(roll_carrier, "pitch", centre, AxisY()));
      const Vec3 up(0, 0, s.extra_arm_height);
      const FrameAttachment pivot_attachment{"arm_pivot_" + side, pivot};
      m.AddJoint(std::make_unique<DistanceJoint>(side + "_extra_arm", s.arm_length),
                 frame_marker("extra_arm_pivot_" + side, pivot + up, I, &pivot_attachment),
                 m.AddMarker(roll_carrier, "extra_arm", centre + up, I));
    }
    const int ri = m.AddMarker(roll_carrier, "roll", centre, AxisX()), rj = m.AddMarker(ax, "roll", centre, AxisX());
    m.AddJoint(std::make_unique<RevoluteJoint>(side + "_axle_roll"), ri, rj);
    RotationalSpringDamperLaw stab;
    stab.stiffness = s.stabilizer_stiffness;
    stab.damping = s.stabilizer_damping;
    m.AddForce(std::make_unique<RotationalSpringDamper>(side + "_stabilizer", stab), ri, rj);
    const double unsprung = UnsprungMass(d, front);
    const double spring_load = 0.5 * (loads[front ? 0 : 1] - (unsprung + 0.5 * d.arm.mass) * g);
    for (int k = 0; k < 2; ++k) {
      const double y = k == 0 ? s.spring_half_spacing : -s.spring_half_spacing;
      const std::string lr = k == 0 ? "left" : "right";
      SpringDamperLaw law;
      law.free_length = s.spring_length;
      law.stiffness = s.spring_stiffness;
      law.damping = s.spring_damping;
      law.preload = -spring_load;
      m.AddForce(std::make_unique<SpringDamper>(side + "_spring_" + lr, law),
                 frame_marker("spring_seat_" + side + "_" + lr, Vec3(x, y, z + s.spring_length), I),
                 m.AddMarker(ax, "spring_" + lr, Vec3(x, y, z), I));
    }
    return ax;
  };

  // wheel with its tire on carrier body `carrier`; returns the wheel joint
  auto wheel = [&](const std::string& name, int carrier, const PartData& wp, const TireData& td, const Vec3& c, int k) {
    const double re = td.unloaded_radius - td.rolling_radius_factor * (td.unloaded_radius - c.z());
    const int wb = AddPart(m, name, wp, c, speed, Vec3(0, speed / re, 0));
    const int jm = m.AddJoint(std::make_unique<RevoluteJoint>(name + "_bearing"),
                              m.AddMarker(carrier, name + "_bearing", c, AxisY()), m.AddMarker(wb, "bearing", c, AxisY()));
    if (brake_torque) {
      const double share = 0.5 * (k < 2 ? d.brake_front_share : 1.0 - d.brake_front_share);
      m.AddForce(std::make_unique<WheelBrake>(name + "_brake", std::make_shared<ScaledSignal>(brake_torque, share),
                                              d.brake_smoothing_spin),
                 m.joints[jm]->marker_i, m.joints[jm]->marker_j);
    }
    const int wm = m.AddMarker(wb, "centre", c, AxisY());
    h.wheel_marker[k] = wm;
    int patch_marker = -1;
    if (td.relaxation_length > 0) {
      // contact-patch body sliding along the spin axis on the carrier, and
      // forward too when the tire relaxes longitudinally
      PartData pp;
      pp.mass = TruckPatchMass(td);
      pp.inertia = Vec3::Constant(0.01 * pp.mass);
      const int pb = AddPart(m, name + "_patch", pp, c, speed, zero);
      patch_marker = m.AddMarker(pb, "centre", c, AxisY());
      const int cm = m.AddMarker(carrier, name + "_carcass", c, AxisY());
      if (td.longitudinal_relaxation_length > 0)
        m.AddJoint(std::make_unique<ContactPatchJoint>(name + "_carcass"), cm, patch_marker);
      else
        m.AddJoint(std::make_unique<PrismaticJoint>(name + "_carcass"), cm, patch_marker);
    }
    h.tire_force[k] = m.AddForce(std::make_unique<Tire>(name + "_tire", td, mu), wm, patch_marker);
    return jm;
  };

  const int fa = axle(true);
  const int ra = axle(false);
  // steered knuckles on kingpin revolutes
  std::array<int, 2> knuckle{};
  std::array<Vec3, 2> kingpin{};
  for (int k = 0; k < 2; ++k) {
    const double sgn = k == 0 ? 1.0 : -1.0;
    const std::string name = k == 0 ? "knuckle_left" : "knuckle_right";
    kingpin[k] = Vec3(1, sgn, 1).cwiseProduct(LeftKingpin(d, zf));
    const Vec3 wc(0, sgn * 0.5 * d.front_track, zf);
    knuckle[k] = AddPart(m, name, d.knuckle, Vec3(0, sgn * (0.5 * d.front_track - 0.5 * d.kingpin_offset), zf),
                         speed, zero);
    h.kingpin_joint[k] = m.AddJoint(std::make_unique<RevoluteJoint>(name + "_kingpin"),
                                    m.AddMarker(fa, name + "_kingpin", kingpin[k], I),
                                    m.AddMarker(knuckle[k], "kingpin", kingpin[k], I));
    wheel(k == 0 ? "wheel_fl" : "wheel_fr", knuckle[k], d.front_wheel, d.front_tire, wc, k);
  }
  auto servo = [&](const std::string& name, int joint, double gain) {
    auto target = std::make_shared<ScaledSignal>(steering_wheel, gain);
    m.AddForce(std::make_unique<JointMotor>(name, m.joints[joint].get(), 0, nullptr,
                                            JointMotorPd{target, d.steering_stiffness, d.steering_damping}),
               m.joints[joint]->marker_i, m.joints[joint]->marker_j);
  };
  if (!d.steering_linkage) {
    for (int k = 0; k < 2; ++k)
      servo(k == 0 ? "knuckle_left_servo" : "knuckle_right_servo", h.kingpin_joint[k], 1.0 / d.steering_ratio);
  } else {
    // pitman arm on the frame (axis y) hanging down, ahead of the left kingpin;
    // its ball and the end of the left knuckle's inboard steering arm are
    // joined by the drag link; a pitman rotation theta turns the knuckle by
    // -theta (equal lever lengths). With the ball at the arm pivot's height
    // (steering_arm_height 0) axle heave, brake wind-up and roll move the
    // steering arm's ball across the link and do not steer (roll: to first
    // order).
    const Vec3 arm_end = SteeringArmBall(d, zf);
    const Vec3 ball = PitmanBall(d, zf);
    const Vec3 pivot = SteeringGearPivot(d, zf);
    const FrameAttachment mount{"steering_gear", SteeringGearMount(d, zf)};
    PartData pitman;
    pitman.mass = d.pitman_arm_mass;
    pitman.inertia = Vec3(0.03, 0.03, 0.01);
    const int pb = AddPart(m, "pitman_arm", pitman, 0.5 * (ball + pivot), speed, zero);
    const int pj = m.AddJoint(std::make_unique<RevoluteJoint>("steering_gear"),
                              frame_marker("steering_gear", pivot, AxisY(), &mount), m.AddMarker(pb, "gear", pivot, AxisY()));
    m.AddJoint(std::make_unique<DistanceJoint>("drag_link", (ball - arm_end).norm()), m.AddMarker(pb, "ball", ball, I),
               m.AddMarker(knuckle[0], "steering_arm", arm_end, I));
    // one-piece tie rod between trapezoid arms aimed at the rear-axle centre
    std::array<Vec3, 2> tr{};
    for (int k = 0; k < 2; ++k) {
      const Vec3 dir = (Vec3(xr, 0, zf) - kingpin[k]).normalized();
      tr[k] = kingpin[k] + d.tie_rod_arm_length * dir;
    }
    m.AddJoint(std::make_unique<DistanceJoint>("tie_rod", (tr[0] - tr[1]).norm()),
               m.AddMarker(knuckle[0], "tie_rod_arm", tr[0], I), m.AddMarker(knuckle[1], "tie_rod_arm", tr[1], I));
    if (!d.steering_column) {
      // the servo (column and gear) turns the pitman arm to -road-wheel angle
      servo("steering_servo", pj, -1.0 / d.steering_ratio);
    } else {
      // steering column on the frame at the gear, axis ac leaning rearwards;
      // the gear turns the pitman arm by -1/ratio of the column's angle
      const Vec3 ac(-std::sin(d.column_inclination), 0, std::cos(d.column_inclination));
      const Vec3 ap(0, 1, 0);
      Mat3 Rc, Rg, Rp;  // column revolute, gear marker on the column (x along ap), on the pitman (x along ac)
      Rc.col(0) = ap;
      Rc.col(1) = ac.cross(ap);
      Rc.col(2) = ac;
      Rg = Rc;
      Rp.col(0) = ac;
      Rp.col(1) = ap.cross(ac);
      Rp.col(2) = ap;
      PartData column;
      column.mass = d.column_mass;
      const Vec3 cg = pivot + 0.5 * d.column_length * ac;
      // principal inertias: column_inertia about the axis, a slender rod across it
      const double across = d.column_mass * d.column_length * d.column_length / 12.0 + 0.5 * d.column_inertia;
      const Mat3 Ic = Rc * Vec3(across, across, d.column_inertia).asDiagonal() * Rc.transpose();
      column.inertia = Ic.diagonal();
      column.products = Vec3(Ic(0, 1), Ic(0, 2), Ic(1, 2));
      const int cb = AddPart(m, "steering_column", column, cg, speed, zero);
      const int cj = m.AddJoint(std::make_unique<RevoluteJoint>("steering_column"),
                                frame_marker("steering_column", pivot, Rc, &mount), m.AddMarker(cb, "column", pivot, Rc));
      m.AddJoint(std::make_unique<GearJoint>("steering_gear_ratio", -d.steering_ratio),
                 m.AddMarker(cb, "gear", pivot, Rg), m.AddMarker(pb, "gear_coupling", pivot, Rp));
      const double r2 = d.steering_ratio * d.steering_ratio;
      m.AddForce(std::make_unique<JointMotor>(
                     "steering_servo", m.joints[cj].get(), 0, nullptr,
                     JointMotorPd{std::make_shared<ScaledSignal>(steering_wheel, 1.0), d.steering_stiffness / r2,
                                  d.steering_damping / r2}),
                 m.joints[cj]->marker_i, m.joints[cj]->marker_j);
    }
  }
  // rear wheels with the drive torque, half to each side
  auto drive = std::make_shared<ScaledSignal>(drive_torque, 0.5);
  for (int k = 0; k < 2; ++k) {
    const double sgn = k == 0 ? 1.0 : -1.0;
    const std::string name = k == 0 ? "wheel_rl" : "wheel_rr";
    const int jm = wheel(name, ra, d.rear_wheel, d.rear_tire, Vec3(xr, sgn * 0.5 * d.rear_track, zr), 2 + k);
    m.AddForce(std::make_unique<JointMotor>(name + "_drive", m.joints[jm].get(), 0, drive),
               m.joints[jm]->marker_i, m.joints[jm]->marker_j);
  }
  return h;
}

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
  ctx.CheckKeys(n, {"wheelbase", "front_track", "rear_track", "kingpin_offset", "frame", "cab", "powertrain", "cargo",
                    "front_axle", "rear_axle", "knuckle", "front_wheel", "rear_wheel", "arm", "front_suspension",
                    "rear_suspension", "steering", "tires", "gauge_width", "brakes"});
  d.wheelbase = ctx.Positive(n, "wheelbase");
  d.front_track = ctx.Positive(n, "front_track");
  d.rear_track = ctx.Positive(n, "rear_track");
  d.kingpin_offset = ctx.Double(n, "kingpin_offset", d.kingpin_offset);
  d.gauge_width = ctx.Positive(n, "gauge_width");
  ReadPart(n, ctx, "cab", dir, d.cab, &d.cab_mounts);
  ReadPart(n, ctx, "powertrain", dir, d.powertrain, &d.powertrain_mounts);
  ReadPart(n, ctx, "cargo", dir, d.cargo, &d.cargo_mounts);
  ReadPart(n, ctx, "front_axle", dir, d.front_axle);
  ReadPart(n, ctx, "rear_axle", dir, d.rear_axle);
  ReadPart(n, ctx, "knuckle", dir, d.knuckle);
  ReadPart(n, ctx, "front_wheel", dir, d.front_wheel);
  ReadPart(n, ctx, "rear_wheel", dir, d.rear_wheel);
  ReadPart(n, ctx, "arm", dir, d.arm);
  ReadSuspension(n, ctx, "front_suspension", dir, d.front);
  ReadSuspension(n, ctx, "rear_suspension", dir, d.rear);
  ReadSteering(n, ctx, dir, d);
  ReadBrakes(n, ctx, dir, d);
  ctx.SetEntity("tires");
  const YAML::Node tires = n["tires"];
  if (!tires) ctx.Fail(n, "missing 'tires'");
  ctx.CheckKeys(tires, {"front", "rear"});
  const std::filesystem::path base(dir);
  d.front_tire = LoadTireFile((base / ctx.String(tires, "front")).string());
  d.rear_tire = LoadTireFile((base / ctx.String(tires, "rear")).string());
  ReadTruckFrame(n, ctx, dir, d);
  return d;
}

}  // namespace flexmb::vehicle
