#include "flexmb/crane/crane_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexmb/body_file/body_file.h"
#include "flexmb/common/text.h"
#include "flexmb/crane/crane_motion.h"

namespace flexmb::crane {
namespace {

// boom axes in world for a luffing angle: x along the boom, y the pins' axis
Mat3 BoomAxes(double luffing_deg) { return FromRollPitchYaw(Vec3(0, -luffing_deg * kRadPerDeg, 0)); }

// fails at the crane file's line of `part` ("boom" ...)
[[noreturn]] void FailAt(const CraneData& d, const char* part, const std::string& msg, YamlContext& ctx) {
  const auto it = d.lines.find(part);
  throw InputError(msg, {ctx.file(), it == d.lines.end() ? 0 : it->second, std::string("crane.") + part});
}

}  // namespace

BoomPoints ReadBoomPoints(const CraneData& d, const std::string& body_path, YamlContext& ctx) {
  BoomPoints b;
  if (d.boom_type == "rigid") {
    b.head_B = d.head_B;
    b.eye_B = d.eye_B;
    b.mass = d.boom_rigid.mass;
    return b;
  }
  reduction::ReducedBody body;
  try {
    body = io::ReadBody(body_path);
  } catch (const InputError& e) {
    ctx.SetEntity("crane.boom");
    ctx.Fail(d.boom_file, "cannot use body file " + Quoted(body_path) + ": " + e.what());
  }
  auto point = [&](int id, const char* what) {
    const int k = body.mesh.NodeIndex(id);
    if (k < 0) FailAt(d, "boom", fmt::format("{} node {} does not exist in body file {}", what, id, Quoted(body_path)), ctx);
    if (std::find(body.interface_nodes.begin(), body.interface_nodes.end(), k) == body.interface_nodes.end())
      FailAt(d, "boom",
             fmt::format("{} node {} is not an interface node of body file {}: reduce the boom with it in "
                         "--interface (the crane's pins and the sheave act there)",
                         what, id, Quoted(body_path)),
             ctx);
    return body.mesh.nodes[k].x;
  };
  b.foot_B = point(d.foot_node, "the foot");
  b.head_B = point(d.head_node, "the head");
  b.eye_B = point(d.eye_node, "the eye");
  b.mass = body.invariants.mvv(0, 0);
  return b;
}

double CylinderLength(const CraneData& d, const BoomPoints& b, double luffing_deg) {
  const Vec3 eye_W = d.foot_W + BoomAxes(luffing_deg) * (b.eye_B - b.foot_B);
  return (eye_W - d.cylinder_base_W).norm();
}

CraneGeometry PlaceCrane(const CraneData& d, const BoomPoints& b, double g, YamlContext& ctx) {
  CraneGeometry c;
  // the boom turned up by its luffing angle about its foot pin
  c.R_WB = BoomAxes(d.luffing_deg);
  c.p_WB = d.foot_W - c.R_WB * b.foot_B;
  c.head_W = c.p_WB + c.R_WB * b.head_B;
  c.eye_W = c.p_WB + c.R_WB * b.eye_B;

  // the cylinder from its base pin to the boom's eye
  const Vec3 axis = c.eye_W - d.cylinder_base_W;
  c.cylinder_length = axis.norm();
  if (std::abs(axis.y()) > 1e-6)
    FailAt(d, "luffing_cylinder",
           fmt::format("the cylinder's base pin and the boom's eye must lie in one x-z plane (y differs by {} m)",
                       Num(axis.y())),
           ctx);
  if (c.cylinder_length < d.stroke_min || c.cylinder_length > d.stroke_max)
    FailAt(d, "luffing_cylinder",
           fmt::format("the boom at {} deg needs the luffing cylinder at {:.4f} m between its pins, outside its "
                       "stroke [{}, {}] m",
                       Num(d.luffing_deg), c.cylinder_length, Num(d.stroke_min), Num(d.stroke_max)),
           ctx);
  const Vec3 u = axis / c.cylinder_length;
  c.cylinder_pitch_deg = -std::atan2(u.z(), u.x()) / kRadPerDeg;
  c.barrel_W = d.cylinder_base_W + 0.5 * d.barrel_length * u;
  c.rod_W = c.eye_W - 0.5 * d.rod_length * u;
  c.winch_exit_W = d.winch_axle_W + Vec3(0, 0, d.drum_radius);

  // the masses standing on the pads
  c.crane_mass = d.superstructure.mass + d.drum_mass + d.barrel.mass + d.rod.mass + b.mass +
                 (d.has_carrier ? d.carrier.mass : 0.0);
  if (d.has_carrier) c.pad_penetration = c.crane_mass * g / (d.pads.size() * d.pad_contact.stiffness);

  // the payload under the head: on the ground (pressed in by its weight) or hanging
  const double H = d.payload_size.z(), m = d.payload_mass;
  c.lower_height = d.release_mass > 0 ? H * d.release_mass / m : H;
  c.upper_height = H - c.lower_height;
  c.bottom_z = d.clearance > 0 ? d.clearance : -m * g / (4 * d.payload_contact.stiffness);
  const double hook_z = c.bottom_z + 0.5 * H + d.hook_height;
  if (d.release_mass > 0) {
    c.load_W = Vec3(c.head_W.x(), c.head_W.y(), c.bottom_z + c.lower_height + 0.5 * c.upper_height);
    c.part_W = Vec3(c.head_W.x(), c.head_W.y(), c.bottom_z + 0.5 * c.lower_height);
  } else {
    c.load_W = Vec3(c.head_W.x(), c.head_W.y(), c.bottom_z + 0.5 * H);
  }
  c.hook_L = Vec3(0, 0, hook_z - c.load_W.z());
  c.hook_drop = c.head_W.z() - hook_z;
  if (!(c.hook_drop > 0))
    FailAt(d, "payload", fmt::format("the hook at {:.3f} m is not below the boom head ({:.3f} m)", hook_z,
                                     c.head_W.z()), ctx);

  // the rope: slack on a grounded load, stretched by the load's weight on a hanging one
  const double path = (c.head_W - c.winch_exit_W).norm() + d.falls * c.hook_drop;
  c.free_length = d.clearance > 0 ? path / (1.0 + m * g / (d.falls * d.rope_ea)) : path + d.rope_slack;
  if (d.rope_model == CraneData::RopeModel::kAncf) {
    // the (hanging) load and the falls' own weight on n falls
    const double n = d.falls, W_span = n * d.rope_mass_per_length * c.hook_drop * g;
    c.lead_free_length = (c.head_W - c.winch_exit_W).norm() / (1.0 + (m * g + W_span) / (n * d.rope_ea));
    c.span_free_length = c.hook_drop / (1.0 + (m * g + 0.5 * W_span) / (n * d.rope_ea));
  }
  return c;
}

}  // namespace flexmb::crane
