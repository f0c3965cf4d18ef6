// Reads one entry of the model file's `forces:` list (reference:
// docs/model-file-forces.md). Keys per type:
//   spring_damper:            i, j, stiffness | force_deflection, damping | force_velocity,
//                             free_length (default: initial distance), preload
//   rotational_spring_damper: i, j, stiffness | torque_angle, damping, angle0, preload
//   bushing:                  i, j, translational_/rotational_ stiffness/damping [3],
//                             preload_force [3], preload_torque [3]
//   point_force:              marker, force [3 numbers or functions of t], frame
//   point_torque:             marker, torque [3 numbers or functions of t], frame
//   joint_motor:              joint, coordinate, function, target, kp, kd
//   plane_contact:            marker, point [3], normal [3], stiffness, damping, friction,
//                             slip_velocity
//   rope:                     i, j | path [markers], drum {joint, radius}, axial_stiffness,
//                             falls, damping_time, free_length (number or function of t),
//                             hoist_speed

#include <array>
#include <string>
#include <vector>

#include "flexmb/ancf/ancf_hoist_rope_body.h"
#include "flexmb/common/error.h"
#include "flexmb/forces/bushing.h"
#include "flexmb/forces/joint_motor.h"
#include "flexmb/forces/plane_contact.h"
#include "flexmb/forces/point_force.h"
#include "flexmb/forces/point_torque.h"
#include "flexmb/forces/rotational_spring_damper.h"
#include "flexmb/forces/reeved_rope.h"
#include "flexmb/forces/rope.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/math/input_function.h"
#include "flexmb/model_file/element_registry.h"
#include "flexmb/model_file/parse_context.h"
#include "flexmb/model/model.h"

namespace flexmb {
namespace {

using Components = std::array<std::shared_ptr<const ScalarFunction>, 3>;

/// State of marker `m` from its body's initial coordinates (the model is not
/// finalized yet, so the body's coordinates are evaluated on their own).
MarkerState InitialMarker(const Model& model, int m) {
  const Marker& marker = model.markers[m];
  const Body& body = *model.bodies[marker.body];
  std::vector<double> q(body.nq() + 1, 0.0), v(body.nv() + 1, 0.0);
  body.InitialCoordinates(q.data(), v.data());
  MarkerState s;
  body.EvaluateMarker(q.data(), v.data(), marker, s);
  return s;
}

/// Optional number at node[key] that must not be negative.
double NonNegative(const YAML::Node& node, const char* key, ParseContext& ctx) {
  const double x = ctx.Double(node, key, 0.0);
  if (x < 0.0) ctx.Fail(node[key], std::string("'") + key + "' must not be negative");
  return x;
}

/// Optional 3-vector at node[key] whose entries must not be negative.
Vec3 NonNegative3(const YAML::Node& node, const char* key, ParseContext& ctx) {
  const Vec3 x = ctx.Vector3(node, key, Vec3::Zero());
  if (x.minCoeff() < 0.0) ctx.Fail(node[key], std::string("'") + key + "' entries must not be negative");
  return x;
}

/// Fails if both alternative keys are given.
void EitherOr(const YAML::Node& node, const char* a, const char* b, ParseContext& ctx) {
  if (node[a] && node[b])
    ctx.Fail(node[b], std::string("give either '") + a + "' or '" + b + "', not both");
}

/// The two markers i and j; they must differ.
std::pair<int, int> MarkerPair(const YAML::Node& node, ParseContext& ctx) {
  const int i = ctx.Marker(node, "i"), j = ctx.Marker(node, "j");
  if (i == j) ctx.Fail(node["j"], "'i' and 'j' name the same marker");
  return {i, j};
}

/// Three components at node[key], each a number or a function of t.
Components ComponentFunctions(const YAML::Node& node, const char* key, ParseContext& ctx) {
  const YAML::Node v = node[key];
  if (!v) ctx.Fail(node, std::string("missing required key '") + key + "'");
  if (!v.IsSequence() || v.size() != 3)
    ctx.Fail(v, std::string("expected '") + key +
                    "' as a list of 3 components [x, y, z], each a number or a function of t");
  Components out;
  for (int k = 0; k < 3; ++k) {
    // a one-entry map so that messages name the component, e.g. 'force[2]'
    const std::string label = std::string(key) + "[" + std::to_string(k) + "]";
    YAML::Node holder(YAML::NodeType::Map);
    holder[label] = v[k];
    out[k] = ctx.Function(holder, label.c_str(), "t");
  }
  return out;
}

LoadFrame Frame(const YAML::Node& node, ParseContext& ctx) {
  const std::string f = ctx.String(node, "frame", "world");
  if (f == "world") return LoadFrame::kWorld;
  if (f == "marker") return LoadFrame::kMarker;
  ctx.Fail(node["frame"], "unknown frame '" + f + "' (allowed: world, marker)");
}

/// Coordinate of `joint` named or numbered at node["coordinate"]; 0 if absent.
int ForceCoordinateIndex(const YAML::Node& node, const Joint& joint, ParseContext& ctx) {
  if (!node["coordinate"]) return 0;
  const std::string text = ctx.String(node, "coordinate");
  std::string known;
  for (int k = 0; k < joint.NumCoordinates(); ++k) {
    if (text == joint.CoordinateName(k) || text == std::to_string(k)) return k;
    known += (k ? ", " : "") + std::string(joint.CoordinateName(k));
  }
  ctx.Fail(node["coordinate"], "joint '" + joint.name() + "' has no coordinate '" + text +
                                   "' (it has: " + known + ")");
}

void AddSpringDamper(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "i", "j", "stiffness", "force_deflection", "damping",
                       "force_velocity", "free_length", "preload"});
  EitherOr(node, "stiffness", "force_deflection", ctx);
  EitherOr(node, "damping", "force_velocity", ctx);
  const auto [i0, j0] = MarkerPair(node, ctx);
  const int i = i0, j = j0;  // named copies: clang 14 cannot capture structured bindings
  SpringDamperLaw law;
  law.stiffness = NonNegative(node, "stiffness", ctx);
  law.damping = NonNegative(node, "damping", ctx);
  if (node["force_deflection"]) law.force_deflection = ctx.Function(node, "force_deflection", "x");
  if (node["force_velocity"]) law.force_velocity = ctx.Function(node, "force_velocity", "x");
  law.preload = ctx.Double(node, "preload", 0.0);
  if (node["free_length"]) {
    law.free_length = NonNegative(node, "free_length", ctx);
  } else {
    const Model& model = ctx.model();
    law.free_length = (InitialMarker(model, j).p_WM - InitialMarker(model, i).p_WM).norm();
    if (!(law.free_length > 1e-12))
      ctx.Fail(node, "the origins of markers 'i' and 'j' coincide initially: a spring-damper acts "
                     "along the line between them (use a bushing, or give 'free_length' and "
                     "separate the markers)");
  }
  ctx.Guard(node, [&] { ctx.model().AddForce(std::make_unique<SpringDamper>(name, law), i, j); });
}

void AddRotationalSpringDamper(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "i", "j", "stiffness", "torque_angle", "damping", "angle0",
                       "preload"});
  EitherOr(node, "stiffness", "torque_angle", ctx);
  const auto [i0, j0] = MarkerPair(node, ctx);
  const int i = i0, j = j0;  // named copies: clang 14 cannot capture structured bindings
  RotationalSpringDamperLaw law;
  law.stiffness = NonNegative(node, "stiffness", ctx);
  law.damping = NonNegative(node, "damping", ctx);
  if (node["torque_angle"]) law.torque_angle = ctx.Function(node, "torque_angle", "x");
  law.angle0 = ctx.Double(node, "angle0", 0.0);
  law.preload = ctx.Double(node, "preload", 0.0);
  ctx.Guard(node, [&] {
    ctx.model().AddForce(std::make_unique<RotationalSpringDamper>(name, law), i, j);
  });
}

void AddBushing(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "i", "j", "translational_stiffness", "rotational_stiffness",
                       "translational_damping", "rotational_damping", "preload_force",
                       "preload_torque"});
  const auto [i0, j0] = MarkerPair(node, ctx);
  const int i = i0, j = j0;  // named copies: clang 14 cannot capture structured bindings
  BushingData d;
  d.translational_stiffness = NonNegative3(node, "translational_stiffness", ctx);
  d.rotational_stiffness = NonNegative3(node, "rotational_stiffness", ctx);
  d.translational_damping = NonNegative3(node, "translational_damping", ctx);
  d.rotational_damping = NonNegative3(node, "rotational_damping", ctx);
  d.preload_force = ctx.Vector3(node, "preload_force", Vec3::Zero());
  d.preload_torque = ctx.Vector3(node, "preload_torque", Vec3::Zero());
  ctx.Guard(node, [&] { ctx.model().AddForce(std::make_unique<Bushing>(name, d), i, j); });
}

void AddPointLoad(const YAML::Node& node, const std::string& name, bool torque, ParseContext& ctx) {
  const char* key = torque ? "torque" : "force";
  ctx.CheckKeys(node, {"name", "type", "marker", key, "frame"});
  const int m = ctx.Marker(node, "marker");
  const Components f = ComponentFunctions(node, key, ctx);
  const LoadFrame frame = Frame(node, ctx);
  ctx.Guard(node, [&] {
    if (torque)
      ctx.model().AddForce(std::make_unique<PointTorque>(name, f, frame), m, -1);
    else
      ctx.model().AddForce(std::make_unique<PointForce>(name, f, frame), m, -1);
  });
}

void AddJointMotor(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "joint", "coordinate", "function", "target", "kp", "kd"});
  const Joint& joint = *ctx.model().joints[ctx.Joint(node, "joint")];
  if (joint.NumCoordinates() == 0)
    ctx.Fail(node["joint"], "joint '" + joint.name() + "' (" + joint.type() +
                                ") has no joint coordinate for a motor to act on");
  const int k = ForceCoordinateIndex(node, joint, ctx);
  std::shared_ptr<const ScalarFunction> f;
  if (node["function"]) f = ctx.Function(node, "function", "t");
  JointMotorPd pd;
  if (node["target"]) {
    pd.target = ctx.Function(node, "target", "t");
    pd.kp = NonNegative(node, "kp", ctx);
    pd.kd = NonNegative(node, "kd", ctx);
    if (pd.kp == 0.0 && pd.kd == 0.0) ctx.Fail(node["target"], "'target' needs a positive 'kp' or 'kd'");
  } else {
    if (node["kp"]) ctx.Fail(node["kp"], "'kp' needs a 'target' motion");
    if (node["kd"]) ctx.Fail(node["kd"], "'kd' needs a 'target' motion");
    if (!f) ctx.Fail(node, "a joint_motor needs 'function' (torque or force of t), 'target' with "
                           "'kp'/'kd', or both");
  }
  ctx.Guard(node, [&] {
    ctx.model().AddForce(std::make_unique<JointMotor>(name, &joint, k, f, pd), joint.marker_i,
                         joint.marker_j);
  });
}

// the path of a reeved rope: `path` (a list of marker names) or i, j
std::vector<int> RopePath(const YAML::Node& node, ParseContext& ctx) {
  const YAML::Node path = node["path"];
  if (!path) {
    const auto [i, j] = MarkerPair(node, ctx);
    return {i, j};
  }
  if (node["i"] || node["j"]) ctx.Fail(path, "give the rope's markers as 'path' or as 'i' and 'j', not both");
  if (!path.IsSequence() || path.size() < 2)
    ctx.Fail(path, "'path' must list at least two markers: where the rope leaves the winch, the sheaves, "
                   "the hook block");
  std::vector<int> markers;
  for (size_t k = 0; k < path.size(); ++k) {
    YAML::Node entry;
    entry["path"] = path[k];
    markers.push_back(ctx.Marker(entry, "path"));
    if (k > 0 && markers[k] == markers[k - 1])
      ctx.Fail(path[k], "'path' lists marker '" + path[k].Scalar() + "' twice in a row: a span needs two markers");
  }
  return markers;
}

void AddRope(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "i", "j", "path", "drum", "span", "axial_stiffness", "falls", "damping_time",
                       "free_length", "hoist_speed"});
  std::vector<int> markers = RopePath(node, ctx);
  const int path_markers = static_cast<int>(markers.size());
  RopeLaw law;
  law.axial_stiffness = ctx.Double(node, "axial_stiffness");
  law.falls = ctx.Integer(node, "falls", 1);
  law.damping_time = ctx.Double(node, "damping_time", 0.0);
  RopeDrum drum;
  if (const YAML::Node d = node["drum"]) {
    ctx.CheckKeys(d, {"joint", "radius"});
    const int jd = ctx.Joint(d, "joint");
    drum.joint = ctx.model().joints[jd].get();
    drum.radius = ctx.Double(d, "radius");
    if (node["hoist_speed"])
      ctx.Fail(node["hoist_speed"], "with a 'drum' the drum pays the rope out: no 'hoist_speed' (drive the "
                                    "drum's joint with a joint_motor or a motion driver)");
    markers.push_back(drum.joint->marker_i);
    markers.push_back(drum.joint->marker_j);
  }
  // the hanging span as an ANCF hoisting rope fed by this rope
  RopeSpan span;
  if (node["span"]) {
    const int b = ctx.Body(node, "span");
    const auto* body = dynamic_cast<const ancf::AncfHoistRopeBody*>(ctx.model().bodies[b].get());
    if (!body)
      ctx.Fail(node["span"], "body '" + ctx.model().bodies[b]->name() + "' is not an ancf_hoist_rope: a rope's "
                             "'span' is the hanging span of changing length that the rope feeds");
    if (body->data().drum_in_body)
      ctx.Fail(node["span"], "the span '" + body->name() + "' has a 'drum' of its own: leave it out, the rope '" +
                                 name + "' feeds the span (its drum is the rope's 'drum')");
    if (node["hoist_speed"] || (node["free_length"] && !node["free_length"].IsScalar()))
      ctx.Fail(node["span"], "with a 'span' the rope is paid out by its 'drum' (or not at all): give neither "
                             "'hoist_speed' nor 'free_length' as a function");
    span.present = true;
    span.free_length = body->data().free_length;
    markers.push_back(ctx.model().FindMarker(body->name() + ".payout"));
  }
  if (node["hoist_speed"]) {
    law.hoist_speed = ctx.Function(node, "hoist_speed", "t");
    if (dynamic_cast<const InputFunction*>(law.hoist_speed.get()))
      ctx.Fail(node["hoist_speed"], "a hoisting speed set by a script cannot be integrated in time: "
                                    "give 'free_length' as {input: ...} instead");
  }
  const YAML::Node l0 = node["free_length"];
  if (l0 && !l0.IsScalar()) {
    if (law.hoist_speed)
      ctx.Fail(l0, "with 'hoist_speed', 'free_length' is the initial free length: a number");
    if (drum.joint) ctx.Fail(l0, "with a 'drum', 'free_length' is the free length at drum angle 0: a number");
    law.free_length_function = ctx.Function(node, "free_length", "t");
  } else if (l0) {
    law.free_length = ctx.Double(node, "free_length");
  } else {
    // unstretched at the start: the path, the last segment on all falls
    const Model& model = ctx.model();
    for (int s = 0; s + 1 < path_markers; ++s)
      law.free_length += (s + 2 == path_markers && !span.present ? law.falls : 1) *
                         (InitialMarker(model, markers[s + 1]).p_WM - InitialMarker(model, markers[s]).p_WM).norm();
  }
  ctx.Guard(node, [&] {
    if (path_markers == 2 && !drum.joint && !span.present)
      ctx.model().AddForce(std::make_unique<Rope>(name, law), markers[0], markers[1]);
    else
      ctx.model().AddForce(std::make_unique<ReevedRope>(name, law, path_markers, drum, span), markers);
  });
}

void AddPointForce(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  AddPointLoad(node, name, false, ctx);
}

void AddPointTorque(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  AddPointLoad(node, name, true, ctx);
}

void AddPlaneContact(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "marker", "point", "normal", "stiffness", "damping", "friction",
                       "slip_velocity"});
  const int m = ctx.Marker(node, "marker");
  PlaneContactLaw law;
  law.point_W = ctx.Vector3(node, "point", Vec3::Zero());
  law.normal_W = ctx.Vector3(node, "normal", Vec3::UnitZ());
  if (!(law.normal_W.norm() > 0.0)) ctx.Fail(node["normal"], "'normal' must not be the zero vector");
  if (!node["stiffness"]) ctx.Fail(node, "missing required key 'stiffness'");
  law.stiffness = ctx.Double(node, "stiffness", 0.0);
  if (!(law.stiffness > 0.0)) ctx.Fail(node["stiffness"], "'stiffness' must be > 0");
  law.damping = NonNegative(node, "damping", ctx);
  law.friction = NonNegative(node, "friction", ctx);
  law.slip_velocity = ctx.Double(node, "slip_velocity", law.slip_velocity);
  if (!(law.slip_velocity > 0.0)) ctx.Fail(node["slip_velocity"], "'slip_velocity' must be > 0");
  ctx.Guard(node, [&] { ctx.model().AddForce(std::make_unique<PlaneContact>(name, law), m, -1); });
}

}  // namespace

void RegisterForceTypes(ElementRegistry& r) {
  r.Add(ElementKind::kForce, "spring_damper", AddSpringDamper);
  r.Add(ElementKind::kForce, "rotational_spring_damper", AddRotationalSpringDamper);
  r.Add(ElementKind::kForce, "bushing", AddBushing);
  r.Add(ElementKind::kForce, "point_force", AddPointForce);
  r.Add(ElementKind::kForce, "point_torque", AddPointTorque);
  r.Add(ElementKind::kForce, "joint_motor", AddJointMotor);
  r.Add(ElementKind::kForce, "plane_contact", AddPlaneContact);
  r.Add(ElementKind::kForce, "rope", AddRope);
}

}  // namespace flexmb
