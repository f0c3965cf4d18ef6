// Joint and driver entries of the model file (reference: docs/model-file.md,
// "joints" and "drivers"): every joint connects markers i and j on two
// different bodies; a driver prescribes a coordinate of a joint.

#include <memory>
#include <string>

#include "flexmb/ancf/ancf_hoist_rope_body.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/joints/cylindrical.h"
#include "flexmb/joints/distance.h"
#include "flexmb/joints/fixed.h"
#include "flexmb/joints/gear.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/joints/planar.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/joints/universal.h"
#include "flexmb/joints/winch_driver.h"
#include "flexmb/math/input_function.h"
#include "flexmb/model/model.h"
#include "flexmb/model_file/element_registry.h"
#include "flexmb/model_file/joint_entry.h"
#include "flexmb/model_file/parse_context.h"

namespace flexmb {
namespace {

// initial world position of a marker's origin, from its body's initial coordinates
Vec3 JointMarkerInitialPosition(const Model& model, int marker) {
  const Marker& m = model.markers[marker];
  const Body& b = *model.bodies[m.body];
  VecX q = VecX::Zero(b.nq()), v = VecX::Zero(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  MarkerState s;
  b.EvaluateMarker(q.data(), v.data(), m, s);
  return s.p_WM;
}

// a joint type without parameters
template <class J>
void ParsePlainJoint(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  AddJointEntry(node, name, ctx, {}, [&](int, int) { return std::make_unique<J>(name); });
}

void ParseDistanceJoint(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  AddJointEntry(node, name, ctx, {"length"}, [&](int mi, int mj) {
    if (node["length"]) return std::make_unique<DistanceJoint>(name, ctx.Positive(node, "length"));
    const double L = (JointMarkerInitialPosition(ctx.model(), mj) -
                      JointMarkerInitialPosition(ctx.model(), mi)).norm();
    if (!(L > 1e-9))
      ctx.Fail(node, "the markers coincide initially, so the default length (their initial "
                     "distance) is zero; a distance joint needs a positive 'length'");
    return std::make_unique<DistanceJoint>(name, L);
  });
}

void ParseGearJoint(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  AddJointEntry(node, name, ctx, {"ratio"},
                [&](int, int) { return std::make_unique<GearJoint>(name, ctx.Double(node, "ratio")); });
}

void ParseCoordinateDriver(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "joint", "coordinate", "function"});
  const Joint& target = *ctx.model().joints[ctx.Joint(node, "joint")];
  if (target.NumCoordinates() == 0)
    ctx.Fail(node["joint"], "joint '" + target.name() + "' is a " + target.type() +
                                " joint, which has no joint coordinate to drive");
  int coordinate = 0;
  if (node["coordinate"]) {
    const std::string c = ctx.String(node, "coordinate");
    std::string list;
    coordinate = -1;
    for (int i = 0; i < target.NumCoordinates(); ++i) {
      if (c == target.CoordinateName(i)) coordinate = i;
      list += (list.empty() ? "" : ", ") + std::string(target.CoordinateName(i));
    }
    if (coordinate < 0)
      ctx.Fail(node["coordinate"], "joint '" + target.name() + "' has no coordinate '" + c +
                                       "' (it has: " + list + ")");
  }
  auto f = ctx.Function(node, "function");
  auto driver = std::make_unique<MotionDriver>(name, &target, coordinate, std::move(f));
  ctx.Guard(node, [&] {
    return ctx.model().AddJoint(std::move(driver), target.marker_i, target.marker_j);
  });
  ctx.lines()["joint '" + name + "'"] = ParseContext::Line(node);
}

// winch of a hoisting rope: rope (an ancf_hoist_rope body), free_length
// (a number, or L(t) as a function) and hoist_speed (a function); acts on
// the rope's payout marker and a ground marker of its own, driver_<name>
void ParseWinchDriver(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "rope", "free_length", "hoist_speed"});
  const int b = ctx.Body(node, "rope");
  const auto* rope = dynamic_cast<const ancf::AncfHoistRopeBody*>(ctx.model().bodies[b].get());
  if (!rope)
    ctx.Fail(node["rope"], "body '" + ctx.model().bodies[b]->name() + "' is not an ancf_hoist_rope: a winch "
                           "driver pays out a hoisting rope of changing length");
  WinchLaw law;
  law.free_length = rope->data().free_length;
  if (node["hoist_speed"]) {
    law.hoist_speed = ctx.Function(node, "hoist_speed", "t");
    if (dynamic_cast<const InputFunction*>(law.hoist_speed.get()))
      ctx.Fail(node["hoist_speed"], "a hoisting speed set by a script cannot be integrated in time: "
                                    "give 'free_length' as {input: ...} instead");
  }
  if (const YAML::Node l0 = node["free_length"]) {
    if (law.hoist_speed) ctx.Fail(l0, "give 'free_length' or 'hoist_speed', not both (the rope's 'free_length' is L(0))");
    if (l0.IsScalar())
      law.free_length = ctx.Positive(node, "free_length");
    else
      law.free_length_function = ctx.Function(node, "free_length", "t");
  }
  const int mi = ctx.model().FindMarker(rope->name() + ".payout");
  const int mj = ctx.Guard(node, [&] {
    return ctx.model().AddMarker(0, "driver_" + name, Vec3::Zero(), Mat3::Identity());
  });
  auto driver = ctx.Guard(node, [&] { return std::make_unique<WinchDriver>(name, law); });
  ctx.Guard(node, [&] { return ctx.model().AddJoint(std::move(driver), mi, mj); });
  ctx.lines()["driver '" + name + "'"] = ParseContext::Line(node);
  ctx.lines()["joint '" + name + "'"] = ParseContext::Line(node);
}

// A joint on a flexible body must sit on an interface node of its body file:
// elsewhere the reduction has no static mode for the joint's load, so the
// attachment would be stiffer than the FE model says (a different model)
void CheckJointNodeIsInterface(const YAML::Node& node, const char* key, int marker, ParseContext& ctx) {
  const Model& model = ctx.model();
  const Marker& m = model.markers[marker];
  const auto* flex = dynamic_cast<const FlexibleBody*>(model.bodies[m.body].get());
  if (!flex || m.node < 0 || flex->IsInterfaceNode(m.node)) return;
  ctx.Fail(node[key], "marker '" + m.name + "' sits on node " + std::to_string(flex->reduced().mesh.nodes[m.node].id) +
                          " of flexible body '" + flex->name() +
                          "', which is not an interface node of its body file: a joint there would be only as "
                          "stiff as the kept modes make it, not as the FE model; reduce the part with the node in "
                          "--interface");
}

}  // namespace

void AddJointEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx,
                   std::initializer_list<const char*> parameters,
                   const std::function<std::unique_ptr<Joint>(int mi, int mj)>& make) {
  std::vector<const char*> keys = {"name", "type", "i", "j", "release_time", "limits"};
  keys.insert(keys.end(), parameters.begin(), parameters.end());
  ctx.CheckKeys(node, keys);
  const int mi = ctx.Marker(node, "i");
  const int mj = ctx.Marker(node, "j");
  CheckJointNodeIsInterface(node, "i", mi, ctx);
  CheckJointNodeIsInterface(node, "j", mj, ctx);
  const Model& model = ctx.model();
  if (model.markers[mi].body == model.markers[mj].body)
    ctx.Fail(node, "markers '" + model.markers[mi].name + "' and '" + model.markers[mj].name +
                       "' are both on body '" + model.bodies[model.markers[mi].body]->name() +
                       "': a joint must connect two different bodies");
  auto joint = ctx.Guard(node, [&] { return make(mi, mj); });
  if (node["release_time"]) joint->release_time = ctx.Positive(node, "release_time");
  if (const YAML::Node lim = node["limits"]) {
    if (joint->NumCoordinates() == 0)
      ctx.Fail(lim, std::string("a ") + joint->type() + " joint has no coordinate to limit");
    if (!lim.IsSequence() || lim.size() != 2)
      ctx.Fail(lim, std::string("expected 'limits' as [lower, upper] of the joint's ") + joint->CoordinateName(0));
    const double lo = ctx.Number(lim[0], "the lower limit"), hi = ctx.Number(lim[1], "the upper limit");
    if (!(lo < hi)) ctx.Fail(lim, "'limits' needs lower < upper");
    joint->coordinate_min = lo;
    joint->coordinate_max = hi;
  }
  ctx.Guard(node, [&] { return ctx.model().AddJoint(std::move(joint), mi, mj); });
}

void RegisterJointTypes(ElementRegistry& r) {
  r.Add(ElementKind::kJoint, "cylindrical", ParsePlainJoint<CylindricalJoint>);
  r.Add(ElementKind::kJoint, "distance", ParseDistanceJoint);
  r.Add(ElementKind::kJoint, "fixed", ParsePlainJoint<FixedJoint>);
  r.Add(ElementKind::kJoint, "gear", ParseGearJoint);
  r.Add(ElementKind::kJoint, "planar", ParsePlainJoint<PlanarJoint>);
  r.Add(ElementKind::kJoint, "prismatic", ParsePlainJoint<PrismaticJoint>);
  r.Add(ElementKind::kJoint, "revolute", ParsePlainJoint<RevoluteJoint>);
  r.Add(ElementKind::kJoint, "spherical", ParsePlainJoint<SphericalJoint>);
  r.Add(ElementKind::kJoint, "universal", ParsePlainJoint<UniversalJoint>);
  r.Add(ElementKind::kDriver, "coordinate", ParseCoordinateDriver);
  r.Add(ElementKind::kDriver, "winch", ParseWinchDriver);
}

}  // namespace flexmb
