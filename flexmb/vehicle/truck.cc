#include "flexmb/vehicle/truck.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
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
double UnsprungMass(const TruckData& d, const AxleData& a) {
  const double hub = a.suspension.extra_arm_height > 0 ? kAxleHubMass : 0.0;
  const double knuckle = a.steered ? d.knuckle.mass : 0.0;
  return hub + a.axle.mass + 2 * (a.wheel.mass + knuckle + TruckPatchMass(a.tire));
}

// vertical stiffness of an axle's support: its two springs in series with its tires [N/m]
double AxleSupportStiffness(const AxleData& a) {
  const double springs = 2 * a.suspension.spring_stiffness, tires = 2 * a.tire.count * a.tire.vertical_stiffness;
  return springs * tires / (springs + tires);
}

// the two axles of bogie `b` (front, rear)
std::array<int, 2> BogieAxles(const TruckData& d, int b) {
  std::array<int, 2> ab{-1, -1};
  int n = 0;
  for (size_t a = 0; a < d.axles.size(); ++a)
    if (d.axles[a].bogie == b && n < 2) ab[n++] = static_cast<int>(a);
  return ab;
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

// static wheel-centre height of each axle [m] from its tire deflection
std::vector<double> WheelCentreHeights(const TruckData& d, double g) {
  const std::vector<double> loads = StaticAxleLoads(d, g);
  std::vector<double> z(d.axles.size());
  for (size_t i = 0; i < z.size(); ++i) {
    const TireData& t = d.axles[i].tire;
    z[i] = t.unloaded_radius - 0.5 * loads[i] / (t.count * t.vertical_stiffness);
  }
  return z;
}

// height of the spring seats of axle `a` (at wheel-centre height z) [m]
double SpringSeatZ(const AxleData& a, double z) { return z + a.suspension.spring_length; }

// trunnion height of bogie `b`: the mean of its axles' spring seats [m]
double TrunnionZ(const TruckData& d, int b, const std::vector<double>& zw) {
  const std::array<int, 2> ab = BogieAxles(d, b);
  return 0.5 * (SpringSeatZ(d.axles[ab[0]], zw[ab[0]]) + SpringSeatZ(d.axles[ab[1]], zw[ab[1]]));
}

// left kingpin of steered axle i at wheel-centre height z
Vec3 LeftKingpin(const TruckData& d, size_t i, double z) {
  const AxleData& a = d.axles[i];
  return Vec3(a.x, 0.5 * a.track - d.kingpin_offset, z);
}

// ball of the left knuckle's inboard steering arm (drag link's rear end)
Vec3 SteeringArmBall(const TruckData& d, size_t i, double z) {
  return LeftKingpin(d, i, z) + Vec3(0, -d.pitman_arm_length, d.steering_arm_height);
}

// ball of the pitman arm (axle 0) or of the relay arm (axle 1), the drag
// link's front end: the drag link is horizontal
Vec3 PitmanBall(const TruckData& d, size_t i, double z) {
  return SteeringArmBall(d, i, z) + Vec3(d.drag_link_length, 0, 0);
}

// pivot on the frame of the pitman arm (the steering gear's output shaft,
// axle 0) or of the relay arm (axle 1), the arm hanging down from it to the
// ball; see BuildTruck
Vec3 SteeringGearPivot(const TruckData& d, size_t i, double z) {
  return PitmanBall(d, i, z) + Vec3(0, 0, d.pitman_arm_length);
}

// the steering gear box's mount (axle 0; axle 1: the relay arm's bracket) on
// the left rail's outer web, mid-height, ahead of the arm's pivot by twice
// the spider radius: clear of the arm pivot's bracket (the spring hanger at
// x = arm_length, where the pitman sits); the elastic frame's interface
// point of the gear, whose node carries the pitman and column markers offset
// to the pivot
Vec3 SteeringGearMount(const TruckData& d, size_t i, double z) {
  return Vec3(SteeringGearPivot(d, i, z).x() + 2 * d.ladder.spider_radius, d.ladder.half_spacing,
              d.ladder.bottom_z + 0.5 * d.ladder.web_height);
}

// the steering relay of a second steered axle: the relay arm on the frame
// turned by a rod from a lever on the pitman arm (linkage only)
bool HasSteeringRelay(const TruckData& d) { return d.steering_linkage && d.axles.size() > 1 && d.axles[1].steered; }

// mount points of a part: per station left then right, at the rails' top corners
std::vector<Vec3> MountPoints(const TruckData& d, const MountData& mounts) {
  std::vector<Vec3> p;
  // the cargo rests on the platform where there is one, the rest on the rails
  const double top = &mounts == &d.cargo_mounts && d.ladder.platform.present ? PlatformTopZ(d.ladder)
                                                                            : d.ladder.bottom_z + d.ladder.web_height;
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

std::string WheelName(const AxleData& a, int side) {
  const char* lr = side == 0 ? "l" : "r";
  if (a.name == "front") return std::string("wheel_f") + lr;
  if (a.name == "rear") return std::string("wheel_r") + lr;
  return "wheel_" + a.name + "_" + lr;
}

double SteerRatio(const TruckData& d, size_t i) {
  if (!d.axles[i].steered) return 0.0;
  if (i == 0) return 1.0;
  const double x_ref = d.axles[0].x - Wheelbase(d);
  return (d.axles[i].x - x_ref) / (d.axles[0].x - x_ref);
}

double Wheelbase(const TruckData& d) {
  if (d.axles.empty()) return 0.0;
  const AxleData& last = d.axles.back();
  const double x_rear = last.bogie >= 0 ? d.bogies[static_cast<size_t>(last.bogie)].x : last.x;
  return d.axles.front().x - x_rear;
}

std::vector<FrameAttachment> FrameAttachments(const TruckData& d, double g) {
  const std::vector<double> zw = WheelCentreHeights(d, g);
  std::vector<FrameAttachment> a;
  for (size_t i = 0; i < d.axles.size(); ++i) {
    const AxleData& ax = d.axles[i];
    const SuspensionData& s = ax.suspension;
    if (ax.bogie < 0) {
      a.push_back({"spring_seat_" + ax.name + "_left", Vec3(ax.x, s.spring_half_spacing, SpringSeatZ(ax, zw[i]))});
      a.push_back({"spring_seat_" + ax.name + "_right", Vec3(ax.x, -s.spring_half_spacing, SpringSeatZ(ax, zw[i]))});
    }
    a.push_back({"arm_pivot_" + ax.name, Vec3(ax.x + s.arm_length, 0, zw[i])});
  }
  for (size_t b = 0; b < d.bogies.size(); ++b) {
    const double y = d.axles[BogieAxles(d, static_cast<int>(b))[0]].suspension.spring_half_spacing;
    const double z = TrunnionZ(d, static_cast<int>(b), zw);
    a.push_back({"trunnion_" + d.bogies[b].name + "_left", Vec3(d.bogies[b].x, y, z)});
    a.push_back({"trunnion_" + d.bogies[b].name + "_right", Vec3(d.bogies[b].x, -y, z)});
  }
  a.push_back({"steering_gear", SteeringGearMount(d, 0, zw[0])});
  if (HasSteeringRelay(d)) a.push_back({"steering_relay", SteeringGearMount(d, 1, zw[1])});
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

std::vector<double> StaticAxleLoads(const TruckData& d, double g) {
  CheckAxles(d);
  const size_t n = d.axles.size();
  // the supports: an axle on its own springs, or a bogie's trunnions
  struct Support {
    double x, k;
    int axle, bogie;
  };
  std::vector<Support> sup;
  for (size_t i = 0; i < n; ++i)
    if (d.axles[i].bogie < 0) sup.push_back({d.axles[i].x, AxleSupportStiffness(d.axles[i]), static_cast<int>(i), -1});
  for (size_t b = 0; b < d.bogies.size(); ++b) {
    // the trunnion's stiffness through the beam's levers a (ahead) and c:
    // a load F gives the axles F c / (a + c) and F a / (a + c), and the
    // trunnion sinks by their deflections weighted the same way
    const std::array<int, 2> ab = BogieAxles(d, static_cast<int>(b));
    const double a = d.axles[ab[0]].x - d.bogies[b].x, c = d.bogies[b].x - d.axles[ab[1]].x;
    const double k = (a + c) * (a + c) /
                     (c * c / AxleSupportStiffness(d.axles[ab[0]]) + a * a / AxleSupportStiffness(d.axles[ab[1]]));
    sup.push_back({d.bogies[b].x, k, -1, static_cast<int>(b)});
  }
  // two supports: statically determinate, the lever rule about the rear
  // one; an axle on its own springs then takes its unsprung weight through
  // it (the weight stands on the support). Otherwise each axle carries its
  // unsprung weight and half its arm's directly.
  const bool lever = sup.size() == 2;
  const double x_ref = lever ? sup[1].x : 0.0;
  double w = 0, moment = 0;  // weights on the supports, their moment about x_ref
  auto add = [&](double mass, double x) {
    w += mass * g;
    moment += mass * g * (x - x_ref);
  };
  std::vector<double> load(n, 0.0);
  for (const PartData* p : {&d.frame, &d.cab, &d.powertrain, &d.cargo}) add(p->mass, p->cg.x());
  if (lever) {
    for (const AxleData& a : d.axles)
      if (a.bogie < 0) add(UnsprungMass(d, a), a.x);
    for (const AxleData& a : d.axles)
      if (a.bogie < 0) add(d.arm.mass, a.x + 0.5 * a.suspension.arm_length);
  }
  if (d.steering_linkage) add(d.pitman_arm_mass, d.drag_link_length);
  if (d.steering_linkage && d.steering_column)
    add(d.column_mass, d.drag_link_length - 0.5 * d.column_length * std::sin(d.column_inclination));
  if (HasSteeringRelay(d)) add(d.pitman_arm_mass, d.axles[1].x + d.drag_link_length);
  for (const BogieData& b : d.bogies) add(2 * b.beam.mass, b.x);
  for (size_t i = 0; i < n; ++i) {
    const AxleData& a = d.axles[i];
    if (lever && a.bogie < 0) continue;
    load[i] = (UnsprungMass(d, a) + 0.5 * d.arm.mass) * g;
    add(0.5 * d.arm.mass, a.x + a.suspension.arm_length);  // the arm's other half at its pivot
  }
  std::vector<double> f(sup.size());
  if (lever) {
    f[0] = moment / (sup[0].x - sup[1].x);
    f[1] = w - f[0];
  } else {
    // a rigid frame on the supports' springs: heave z and pitch t with
    // sum k (z + t x) = w and sum k x (z + t x) = moment
    double k0 = 0, k1 = 0, k2 = 0;
    for (const Support& s : sup) {
      k0 += s.k;
      k1 += s.k * s.x;
      k2 += s.k * s.x * s.x;
    }
    const double det = k0 * k2 - k1 * k1;
    const double z = (w * k2 - moment * k1) / det, t = (k0 * moment - k1 * w) / det;
    for (size_t j = 0; j < sup.size(); ++j) f[j] = sup[j].k * (z + t * sup[j].x);
  }
  for (size_t j = 0; j < sup.size(); ++j) {
    if (sup[j].axle >= 0) {
      load[static_cast<size_t>(sup[j].axle)] += f[j];
      continue;
    }
    // a bogie: its trunnion load shared by the lever rule
    const std::array<int, 2> ab = BogieAxles(d, sup[j].bogie);
    const double x1 = d.axles[ab[0]].x, x2 = d.axles[ab[1]].x;
    const double first = f[j] * (sup[j].x - x2) / (x1 - x2);
    load[static_cast<size_t>(ab[0])] += first;
    load[static_cast<size_t>(ab[1])] += f[j] - first;
  }
  return load;
}

void CheckAxles(const TruckData& d) {
  auto fail = [](const std::string& what, const std::string& entity) {
    throw InputError(what, {"", 0, entity});
  };
  const size_t n = d.axles.size();
  if (n < 2) fail("a truck needs at least two axles", "truck axles");
  std::set<std::string> names;
  double shares = 0;
  bool driven = false;
  for (size_t i = 0; i < n; ++i) {
    const AxleData& a = d.axles[i];
    const std::string entity = "axle '" + a.name + "'";
    if (a.name.empty() || a.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
      fail("an axle's name must be lower-case letters, digits and '_'", entity);
    for (const char* taken : {"pitman", "relay", "steering", "knuckle", "wheel", "bogie", "frame"})
      if (a.name == taken) fail("the axle name '" + a.name + "' is taken by the truck's other parts", entity);
    if (!names.insert(a.name).second) fail("two axles are named '" + a.name + "'", entity);
    if (i == 0 && a.x != 0.0) fail("the first axle must be at x = 0 (the vehicle frame's origin)", entity);
    if (i > 0 && !(a.x < d.axles[i - 1].x)) fail("axles must be listed from front to rear (x decreasing)", entity);
    if (i == 0 && !a.steered) fail("the first axle must be steered", entity);
    if (i > 1 && a.steered) fail("only the first two axles can be steered", entity);
    if (i == 1 && a.steered && (n < 3 || a.bogie >= 0))
      fail("a second steered axle needs an unsteered axle behind it and its own springs", entity);
    if (!(a.track > 0)) fail("track must be positive", entity);
    if (!(a.brake_share >= 0 && a.brake_share <= 1)) fail("brake_share must lie in [0, 1]", entity);
    if (a.bogie >= static_cast<int>(d.bogies.size())) fail("unknown bogie", entity);
    shares += a.brake_share;
    driven = driven || a.driven;
  }
  if (std::abs(shares - 1.0) > 1e-9) fail("the axles' brake_share must sum to 1", "truck axles");
  if (!driven) fail("no axle is driven", "truck axles");
  std::set<std::string> bogie_names;
  for (size_t b = 0; b < d.bogies.size(); ++b) {
    const BogieData& bg = d.bogies[b];
    const std::string entity = "bogie '" + bg.name + "'";
    if (bg.name.empty() || bg.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos)
      fail("a bogie's name must be lower-case letters, digits and '_'", entity);
    if (!bogie_names.insert(bg.name).second) fail("two bogies are named '" + bg.name + "'", entity);
    int count = 0;
    for (const AxleData& a : d.axles) count += a.bogie == static_cast<int>(b);
    if (count != 2) fail("a bogie carries exactly two axles, this one " + std::to_string(count), entity);
    const std::array<int, 2> ab = BogieAxles(d, static_cast<int>(b));
    if (ab[1] != ab[0] + 1) fail("a bogie's two axles must be neighbours", entity);
    if (!(bg.x < d.axles[ab[0]].x && bg.x > d.axles[ab[1]].x))
      fail("the trunnion must lie between the bogie's axles", entity);
    if (d.axles[ab[0]].suspension.spring_half_spacing != d.axles[ab[1]].suspension.spring_half_spacing)
      fail("the bogie's axles must have the same spring_half_spacing (the beams' lateral positions)", entity);
    if (!(bg.beam.mass > 0) || !(bg.beam.inertia.minCoeff() > 0)) fail("the beam's mass and inertia must be positive", entity);
  }
  size_t supports = d.bogies.size();
  for (const AxleData& a : d.axles) supports += a.bogie < 0;
  if (supports < 2) fail("the frame needs at least two supports (axles on their own springs or bogies)", "truck axles");
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
  if (!(d.brake_smoothing_spin > 0))
    throw InputError("brake smoothing_spin must be positive", {"", 0, "truck brakes"});
  CheckAxles(d);
  const double g = -m.gravity_W.z();
  const std::vector<double> loads = StaticAxleLoads(d, g);
  TruckHandles h;
  const size_t n_axles = d.axles.size();
  // static wheel-centre heights from the tire deflections
  const std::vector<double> zw = WheelCentreHeights(d, g);
  const double zf = zw[0], zr = zw.back();
  h.wheel_centre_z = zw;
  h.tire_force.assign(2 * n_axles, -1);
  h.wheel_marker.assign(2 * n_axles, -1);
  const double x_ref = -Wheelbase(d), x_last = d.axles.back().x;
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
  h.rear_axle_ref = m.AddMarker(frame, "rear_axle_ref", Vec3(x_ref, 0, 0), I);
  const double hb = 0.5 * d.gauge_width;
  h.gauge = {m.AddMarker(frame, "gauge_fl", Vec3(0, hb, zf), I), m.AddMarker(frame, "gauge_fr", Vec3(0, -hb, zf), I),
             m.AddMarker(frame, "gauge_rl", Vec3(x_last, hb, zr), I),
             m.AddMarker(frame, "gauge_rr", Vec3(x_last, -hb, zr), I)};
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

  // balancer bogies: a beam on a trunnion revolute (axis y) on each side
  std::vector<std::array<int, 2>> bogie_beam(d.bogies.size());
  for (size_t b = 0; b < d.bogies.size(); ++b) {
    const BogieData& bg = d.bogies[b];
    const double y = d.axles[BogieAxles(d, static_cast<int>(b))[0]].suspension.spring_half_spacing;
    const double z = TrunnionZ(d, static_cast<int>(b), zw);
    for (int k = 0; k < 2; ++k) {
      const std::string lr = k == 0 ? "left" : "right";
      const Vec3 pivot(bg.x, k == 0 ? y : -y, z);
      bogie_beam[b][k] = AddPart(m, "bogie_" + bg.name + "_" + lr, bg.beam, pivot, speed, zero);
      m.AddJoint(std::make_unique<RevoluteJoint>("bogie_" + bg.name + "_" + lr + "_trunnion"),
                 frame_marker("trunnion_" + bg.name + "_" + lr, pivot, AxisY()),
                 m.AddMarker(bogie_beam[b][k], "trunnion", pivot, AxisY()));
    }
  }

  // one axle: arm, axle, suspension springs (to the frame or the bogie's
  // beams), stabilizer; returns the axle body
  auto axle = [&](size_t i) {
    const AxleData& a = d.axles[i];
    const std::string& side = a.name;
    const SuspensionData& s = a.suspension;
    const double x = a.x, z = zw[i];
    const int arm = AddPart(m, side + "_arm", d.arm, Vec3(x + 0.5 * s.arm_length, 0, z), speed, zero);
    const int ax = AddPart(m, side + "_axle", a.axle, Vec3(x, 0, z), speed, zero);
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
    const double unsprung = UnsprungMass(d, a);
    const double spring_load = 0.5 * (loads[i] - (unsprung + 0.5 * d.arm.mass) * g);
    for (int k = 0; k < 2; ++k) {
      const double y = k == 0 ? s.spring_half_spacing : -s.spring_half_spacing;
      const std::string lr = k == 0 ? "left" : "right";
      SpringDamperLaw law;
      law.free_length = s.spring_length;
      law.stiffness = s.spring_stiffness;
      law.damping = s.spring_damping;
      law.preload = -spring_load;
      if (s.friction_force > 0)
        law.force_velocity =
            std::make_shared<ViscousCoulombFunction>(s.spring_damping, s.friction_force, s.friction_velocity);
      const Vec3 seat(x, y, z + s.spring_length);
      const int upper = a.bogie < 0 ? frame_marker("spring_seat_" + side + "_" + lr, seat, I)
                                    : m.AddMarker(bogie_beam[static_cast<size_t>(a.bogie)][k], side + "_spring", seat, I);
      m.AddForce(std::make_unique<SpringDamper>(side + "_spring_" + lr, law), upper,
                 m.AddMarker(ax, "spring_" + lr, Vec3(x, y, z), I));
    }
    return ax;
  };

  // wheel `k` (axle i, side k % 2) with its tire on carrier body `carrier`; returns the wheel joint
  auto wheel = [&](const AxleData& a, int carrier, const Vec3& c, int k) {
    const std::string name = WheelName(a, k % 2);
    const TireData& td = a.tire;
    const double re = td.unloaded_radius - td.rolling_radius_factor * (td.unloaded_radius - c.z());
    const int wb = AddPart(m, name, a.wheel, c, speed, Vec3(0, speed / re, 0));
    const int jm = m.AddJoint(std::make_unique<RevoluteJoint>(name + "_bearing"),
                              m.AddMarker(carrier, name + "_bearing", c, AxisY()), m.AddMarker(wb, "bearing", c, AxisY()));
    if (brake_torque) {
      const double share = 0.5 * a.brake_share;
      m.AddForce(std::make_unique<WheelBrake>(name + "_brake", std::make_shared<ScaledSignal>(brake_torque, share),
                                              d.brake_smoothing_spin),
                 m.joints[jm]->marker_i, m.joints[jm]->marker_j);
    }
    const int wm = m.AddMarker(wb, "centre", c, AxisY());
    h.wheel_marker[static_cast<size_t>(k)] = wm;
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
    h.tire_force[static_cast<size_t>(k)] = m.AddForce(std::make_unique<Tire>(name + "_tire", td, mu), wm, patch_marker);
    return jm;
  };
  // the drive torque, shared equally by the driven axles' wheels
  int n_driven = 0;
  for (const AxleData& a : d.axles) n_driven += a.driven;
  auto drive = std::make_shared<ScaledSignal>(drive_torque, 0.5 / n_driven);
  auto add_drive = [&](const std::string& name, int jm) {
    m.AddForce(std::make_unique<JointMotor>(name + "_drive", m.joints[jm].get(), 0, drive), m.joints[jm]->marker_i,
               m.joints[jm]->marker_j);
  };

  std::vector<int> axle_body(n_axles);
  for (size_t i = 0; i < n_axles; ++i) axle_body[i] = axle(i);
  // a steered axle i: knuckles on kingpin revolutes, with its wheels; `tag`
  // in the names ("" for the first axle: knuckle_left, ...; "_<axle>" for
  // the second: knuckle_<axle>_left, ...)
  struct SteeredAxle {
    std::array<int, 2> knuckle{}, kingpin_joint{};
    std::array<Vec3, 2> kingpin{};
    std::string tag;
  };
  auto steered_axle = [&](size_t i) {
    const AxleData& a = d.axles[i];
    SteeredAxle sa;
    sa.tag = i == 0 ? "" : "_" + a.name;
    for (int k = 0; k < 2; ++k) {
      const double sgn = k == 0 ? 1.0 : -1.0;
      const std::string name = "knuckle" + sa.tag + (k == 0 ? "_left" : "_right");
      sa.kingpin[k] = Vec3(1, sgn, 1).cwiseProduct(LeftKingpin(d, i, zw[i]));
      const Vec3 wc(a.x, sgn * 0.5 * a.track, zw[i]);
      sa.knuckle[k] = AddPart(m, name, d.knuckle, Vec3(a.x, sgn * (0.5 * a.track - 0.5 * d.kingpin_offset), zw[i]),
                              speed, zero);
      sa.kingpin_joint[k] = m.AddJoint(std::make_unique<RevoluteJoint>(name + "_kingpin"),
                                       m.AddMarker(axle_body[i], name + "_kingpin", sa.kingpin[k], I),
                                       m.AddMarker(sa.knuckle[k], "kingpin", sa.kingpin[k], I));
      const int jm = wheel(a, sa.knuckle[k], wc, static_cast<int>(2 * i) + k);
      if (a.driven) add_drive(WheelName(a, k), jm);
    }
    return sa;
  };
  // one-piece tie rod of a steered axle between trapezoid arms aimed at the
  // rear axle group's centre
  auto tie_rod = [&](size_t i, const SteeredAxle& sa) {
    std::array<Vec3, 2> tr{};
    for (int k = 0; k < 2; ++k) {
      const Vec3 dir = (Vec3(x_ref, 0, zw[i]) - sa.kingpin[k]).normalized();
      tr[k] = sa.kingpin[k] + d.tie_rod_arm_length * dir;
    }
    m.AddJoint(std::make_unique<DistanceJoint>("tie_rod" + sa.tag, (tr[0] - tr[1]).norm()),
               m.AddMarker(sa.knuckle[0], "tie_rod_arm", tr[0], I), m.AddMarker(sa.knuckle[1], "tie_rod_arm", tr[1], I));
  };
  const SteeredAxle first = steered_axle(0);
  const std::array<int, 2>& knuckle = first.knuckle;
  h.kingpin_joint = first.kingpin_joint;
  // a second steered axle (8x4) turns by SteerRatio of the first's angle
  const bool second_steered = n_axles > 1 && d.axles[1].steered;
  SteeredAxle second;
  if (second_steered) second = steered_axle(1);
  h.steered_axles = second_steered ? 2 : 1;
  auto servo = [&](const std::string& name, int joint, double gain) {
    auto target = std::make_shared<ScaledSignal>(steering_wheel, gain);
    m.AddForce(std::make_unique<JointMotor>(name, m.joints[joint].get(), 0, nullptr,
                                            JointMotorPd{target, d.steering_stiffness, d.steering_damping}),
               m.joints[joint]->marker_i, m.joints[joint]->marker_j);
  };
  if (!d.steering_linkage) {
    for (int k = 0; k < 2; ++k)
      servo(k == 0 ? "knuckle_left_servo" : "knuckle_right_servo", h.kingpin_joint[k], 1.0 / d.steering_ratio);
    for (int k = 0; second_steered && k < 2; ++k)
      servo("knuckle" + second.tag + (k == 0 ? "_left_servo" : "_right_servo"), second.kingpin_joint[k],
            SteerRatio(d, 1) / d.steering_ratio);
  } else {
    // pitman arm on the frame (axis y) hanging down, ahead of the left kingpin;
    // its ball and the end of the left knuckle's inboard steering arm are
    // joined by the drag link; a pitman rotation theta turns the knuckle by
    // -theta (equal lever lengths). With the ball at the arm pivot's height
    // (steering_arm_height 0) axle heave, brake wind-up and roll move the
    // steering arm's ball across the link and do not steer (roll: to first
    // order).
    const Vec3 arm_end = SteeringArmBall(d, 0, zf);
    const Vec3 ball = PitmanBall(d, 0, zf);
    const Vec3 pivot = SteeringGearPivot(d, 0, zf);
    const FrameAttachment mount{"steering_gear", SteeringGearMount(d, 0, zf)};
    PartData pitman;
    pitman.mass = d.pitman_arm_mass;
    pitman.inertia = Vec3(0.03, 0.03, 0.01);
    const int pb = AddPart(m, "pitman_arm", pitman, 0.5 * (ball + pivot), speed, zero);
    const int pj = m.AddJoint(std::make_unique<RevoluteJoint>("steering_gear"),
                              frame_marker("steering_gear", pivot, AxisY(), &mount), m.AddMarker(pb, "gear", pivot, AxisY()));
    m.AddJoint(std::make_unique<DistanceJoint>("drag_link", (ball - arm_end).norm()), m.AddMarker(pb, "ball", ball, I),
               m.AddMarker(knuckle[0], "steering_arm", arm_end, I));
    tie_rod(0, first);
    if (second_steered) {
      // the relay arm of the second steered axle, on the frame ahead of it
      // like the pitman arm, drives that axle's drag link; a relay rod joins
      // levers above the two arms' pivots, b on the pitman arm and b / r on
      // the relay arm: whatever the rod's slope, both lever ends move along
      // x, so the relay arm turns by r times the pitman arm's angle
      const Vec3 end2 = SteeringArmBall(d, 1, zw[1]), ball2 = PitmanBall(d, 1, zw[1]);
      const Vec3 pivot2 = SteeringGearPivot(d, 1, zw[1]);
      const FrameAttachment mount2{"steering_relay", SteeringGearMount(d, 1, zw[1])};
      const int rb = AddPart(m, "relay_arm", pitman, 0.5 * (ball2 + pivot2), speed, zero);
      m.AddJoint(std::make_unique<RevoluteJoint>("steering_relay"),
                 frame_marker("steering_relay", pivot2, AxisY(), &mount2), m.AddMarker(rb, "pivot", pivot2, AxisY()));
      m.AddJoint(std::make_unique<DistanceJoint>("drag_link" + second.tag, (ball2 - end2).norm()),
                 m.AddMarker(rb, "ball", ball2, I), m.AddMarker(second.knuckle[0], "steering_arm", end2, I));
      const double b = d.pitman_arm_length;
      const Vec3 lever1 = pivot + Vec3(0, 0, b), lever2 = pivot2 + Vec3(0, 0, b / SteerRatio(d, 1));
      m.AddJoint(std::make_unique<DistanceJoint>("relay_rod", (lever1 - lever2).norm()),
                 m.AddMarker(pb, "relay_lever", lever1, I), m.AddMarker(rb, "relay_lever", lever2, I));
      tie_rod(1, second);
    }
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
  // the other axles' wheels
  for (size_t i = 1; i < n_axles; ++i) {
    const AxleData& a = d.axles[i];
    if (a.steered) continue;  // with its knuckles above
    for (int k = 0; k < 2; ++k) {
      const double sgn = k == 0 ? 1.0 : -1.0;
      const int wk = static_cast<int>(2 * i) + k;
      const int jm = wheel(a, axle_body[i], Vec3(a.x, sgn * 0.5 * a.track, zw[i]), wk);
      if (a.driven) add_drive(WheelName(a, k), jm);
    }
  }
  // the unsprung parts of each axle, by their names
  h.body_axle.assign(m.bodies.size(), -1);
  for (size_t i = 0; i < n_axles; ++i) {
    const AxleData& a = d.axles[i];
    std::vector<std::string> names = {a.name + "_arm", a.name + "_axle", a.name + "_axle_hub"};
    for (int k = 0; k < 2; ++k) {
      const std::string lr = k == 0 ? "_left" : "_right";
      names.push_back(WheelName(a, k));
      names.push_back(WheelName(a, k) + "_patch");
      if (a.steered) names.push_back("knuckle" + (i == 0 ? std::string() : "_" + a.name) + lr);
      if (a.bogie >= 0 && i + 1 < n_axles && d.axles[i + 1].bogie == a.bogie)  // the beams count with the rear axle
        continue;
      if (a.bogie >= 0) names.push_back("bogie_" + d.bogies[static_cast<size_t>(a.bogie)].name + lr);
    }
    for (const std::string& name : names)
      if (const int b = m.FindBody(name); b >= 0) h.body_axle[static_cast<size_t>(b)] = static_cast<int>(i);
  }
  return h;
}

}  // namespace flexmb::vehicle
