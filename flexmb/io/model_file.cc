#include "flexmb/io/model_file.h"

#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <type_traits>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/io/ancf_body_parser.h"
#include "flexmb/io/flexible_body_parser.h"
#include "flexmb/io/parse_context.h"
#include "flexmb/joints/cylindrical.h"
#include "flexmb/joints/distance.h"
#include "flexmb/joints/fixed.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/joints/planar.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/joints/universal.h"

namespace flexmb {
namespace {

// line of each named entity ("joint 'j1'"), for errors raised by Model::Finalize
using Lines = std::map<std::string, int>;

std::string Quote(const std::string& s) { return "'" + s + "'"; }

// a name of a body or marker: non-empty, no '.' (it separates body and marker)
std::string Name(const YAML::Node& node, const char* kind, const ParseContext& ctx) {
  const std::string name = ctx.String(node, "name");
  const YAML::Node v = node["name"];
  if (name.empty()) ctx.Fail(v, std::string("a ") + kind + " name must not be empty");
  if (name.find('.') != std::string::npos)
    ctx.Fail(v, std::string("a ") + kind + " name must not contain '.' (it separates body and marker in "
                "'body.marker'), got " + Quote(name));
  return name;
}

// the list at root[key], or an undefined node if absent
YAML::Node List(const YAML::Node& node, const char* key, const ParseContext& ctx) {
  const YAML::Node v = node[key];
  if (v && !v.IsSequence())
    ctx.Fail(v, std::string("expected '") + key + "' as a list of entries ('- ...')");
  return v;
}

// initial world position of a marker's origin, from its body's initial coordinates
Vec3 InitialMarkerPosition(const Model& model, int marker) {
  const Marker& m = model.markers[marker];
  const Body& b = *model.bodies[m.body];
  VecX q = VecX::Zero(b.nq()), v = VecX::Zero(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  MarkerState s;
  b.EvaluateMarker(q.data(), v.data(), m, s);
  return s.p_WM;
}

void ParseMarkers(const YAML::Node& node, int body, ParseContext& ctx, Lines& lines) {
  ctx.ParseMarkerList(node, body, {"name", "position", "orientation"}, nullptr, lines);
}

void ParseShape(const YAML::Node& s, Shape& shape, const ParseContext& ctx) {
  const std::string type = ctx.String(s, "type");
  if (type == "box") {
    ctx.CheckKeys(s, {"type", "size", "position", "orientation"});
    shape.type = Shape::Type::kBox;
    shape.size = ctx.Vector3(s, "size");
    if (!(shape.size.minCoeff() > 0.0)) ctx.Fail(s["size"], "all entries of 'size' must be positive");
  } else if (type == "cylinder") {
    ctx.CheckKeys(s, {"type", "radius", "length", "position", "orientation"});
    shape.type = Shape::Type::kCylinder;
    shape.size = Vec3(ctx.Positive(s, "radius"), ctx.Positive(s, "length"), 0.0);
  } else if (type == "sphere") {
    ctx.CheckKeys(s, {"type", "radius", "position", "orientation"});
    shape.type = Shape::Type::kSphere;
    shape.size = Vec3(ctx.Positive(s, "radius"), 0.0, 0.0);
  } else {
    ctx.Fail(s["type"], "unknown shape type " + Quote(type) + " (allowed: box, cylinder, sphere)");
  }
  shape.p_BS = ctx.Vector3(s, "position", Vec3::Zero());
  shape.R_BS = ctx.Orientation(s, "orientation");
}

// inertia as given: [ixx, iyy, izz], [ixx, iyy, izz, ixy, ixz, iyz] or a 3x3 matrix
Mat3 ParseInertia(const YAML::Node& body, const ParseContext& ctx) {
  const YAML::Node v = body["inertia"];
  if (!v) ctx.Fail(body, "missing required key 'inertia'");
  const char* forms =
      "expected 'inertia' as [ixx, iyy, izz], [ixx, iyy, izz, ixy, ixz, iyz] or a 3x3 matrix "
      "[[..], [..], [..]] in kg m^2";
  if (!v.IsSequence()) ctx.Fail(v, forms);
  Mat3 I = Mat3::Zero();
  if (v.size() == 3 && v[0].IsSequence()) {
    for (int r = 0; r < 3; ++r) {
      const YAML::Node row = v[r];
      if (!row.IsSequence() || row.size() != 3) ctx.Fail(row, forms);
      for (int c = 0; c < 3; ++c)
        I(r, c) = ctx.Number(row[c], "'inertia' row " + std::to_string(r + 1) + " entry " +
                                         std::to_string(c + 1));
    }
    if ((I - I.transpose()).cwiseAbs().maxCoeff() > 1e-9 * I.cwiseAbs().maxCoeff())
      ctx.Fail(v, "the 'inertia' matrix is not symmetric");
    return 0.5 * (I + I.transpose());
  }
  if (v.size() != 3 && v.size() != 6) ctx.Fail(v, std::string(forms) + ", got a list of " + std::to_string(v.size()));
  Eigen::Matrix<double, 6, 1> e = Eigen::Matrix<double, 6, 1>::Zero();
  for (size_t k = 0; k < v.size(); ++k) {
    if (!v[k].IsScalar()) ctx.Fail(v[k], forms);
    e(static_cast<int>(k)) = ctx.Number(v[k], "'inertia' entry " + std::to_string(k + 1));
  }
  I << e(0), e(3), e(4), e(3), e(1), e(5), e(4), e(5), e(2);
  return I;
}

void ParseBody(const YAML::Node& node, int k, ParseContext& ctx, Lines& lines) {
  ctx.SetEntity("body #" + std::to_string(k + 1));
  if (node.IsMap() && node["type"] && node["type"].IsScalar() && IsAncfBodyType(node["type"].Scalar()))
    return ParseAncfBody(node, ctx, lines);
  if (node.IsMap() && node["type"] && node["type"].IsScalar() && IsFlexibleBodyType(node["type"].Scalar()))
    return ParseFlexibleBody(node, ctx, lines);
  ctx.CheckKeys(node, {"name", "type", "mass", "center_of_mass", "inertia", "inertia_frame", "position",
                       "orientation", "velocity", "angular_velocity", "markers", "shape"});
  const std::string name = Name(node, "body", ctx);
  if (name == "ground")
    ctx.Fail(node["name"], "the name 'ground' is reserved for the fixed world frame; put markers on "
                           "it in the top-level 'ground' section");
  const std::string entity = "body '" + name + "'";
  ctx.SetEntity(entity);
  const std::string type = ctx.String(node, "type", "rigid");
  if (type != "rigid")
    ctx.Fail(node["type"], "body type " + Quote(type) + " is not supported yet (supported: rigid, flexible, ancf_beam, ancf_cable)");

  RigidBodyData d;
  d.mass = ctx.Positive(node, "mass");
  d.c_B = ctx.Vector3(node, "center_of_mass", Vec3::Zero());
  const Mat3 I = ParseInertia(node, ctx);
  const YAML::Node frame = node["inertia_frame"];
  d.inertia_C = I;
  if (frame) {
    Vec3 p_BF = Vec3::Zero();
    Mat3 R_BF = Mat3::Identity();
    bool about_com = false;
    if (frame.IsScalar()) {
      const std::string f = frame.Scalar();
      if (f == "com")
        about_com = true;
      else if (f != "body")
        ctx.Fail(frame, "unknown 'inertia_frame' " + Quote(f) +
                            " (allowed: com, body, or {position: [..], orientation: {..}})");
    } else if (frame.IsMap()) {
      ctx.CheckKeys(frame, {"position", "orientation"});
      p_BF = ctx.Vector3(frame, "position", Vec3::Zero());
      R_BF = ctx.Orientation(frame, "orientation");
    } else {
      ctx.Fail(frame, "expected 'inertia_frame' as com, body, or {position: [..], orientation: {..}}");
    }
    if (!about_com) {
      const Mat3 Ic = InertiaAboutCom(d.mass, I, p_BF, R_BF, d.c_B);
      d.inertia_C = 0.5 * (Ic + Ic.transpose());
    }
  }
  d.p_WB = ctx.Vector3(node, "position", Vec3::Zero());
  d.R_WB = ctx.Orientation(node, "orientation");
  d.v_WB = ctx.Vector3(node, "velocity", Vec3::Zero());
  d.w_WB = ctx.Vector3(node, "angular_velocity", Vec3::Zero());

  auto body = ctx.Guard(node["inertia"], [&] { return std::make_unique<RigidBody>(name, d); });
  if (node["shape"]) ParseShape(node["shape"], body->shape, ctx);
  const int b = ctx.Guard(node["name"], [&] { return ctx.model().AddBody(std::move(body)); });
  lines[entity] = ParseContext::Line(node);
  ParseMarkers(node, b, ctx, lines);
}

void ParseGround(const YAML::Node& node, ParseContext& ctx, Lines& lines) {
  ctx.SetEntity("ground");
  ctx.CheckKeys(node, {"markers", "shape"});
  if (node["shape"]) ParseShape(node["shape"], ctx.model().bodies[0]->shape, ctx);
  ParseMarkers(node, 0, ctx, lines);
}

using JointFactory = std::function<std::unique_ptr<Joint>(const std::string&, const YAML::Node&,
                                                         int, int, ParseContext&)>;

// joint types by their model-file name
const std::map<std::string, JointFactory>& JointTypes() {
  static const std::map<std::string, JointFactory> types = [] {
    std::map<std::string, JointFactory> t;
    auto plain = [](auto tag) {
      return [](const std::string& n, const YAML::Node&, int, int, ParseContext&) -> std::unique_ptr<Joint> {
        return std::make_unique<typename decltype(tag)::type>(n);
      };
    };
    t["fixed"] = plain(std::type_identity<FixedJoint>{});
    t["revolute"] = plain(std::type_identity<RevoluteJoint>{});
    t["prismatic"] = plain(std::type_identity<PrismaticJoint>{});
    t["cylindrical"] = plain(std::type_identity<CylindricalJoint>{});
    t["spherical"] = plain(std::type_identity<SphericalJoint>{});
    t["universal"] = plain(std::type_identity<UniversalJoint>{});
    t["planar"] = plain(std::type_identity<PlanarJoint>{});
    t["distance"] = [](const std::string& n, const YAML::Node& node, int mi, int mj,
                       ParseContext& ctx) -> std::unique_ptr<Joint> {
      if (node["length"]) return std::make_unique<DistanceJoint>(n, ctx.Positive(node, "length"));
      const double L = (InitialMarkerPosition(ctx.model(), mj) -
                        InitialMarkerPosition(ctx.model(), mi)).norm();
      if (!(L > 1e-9))
        ctx.Fail(node, "the markers coincide initially, so the default length (their initial "
                       "distance) is zero; a distance joint needs a positive 'length'");
      return std::make_unique<DistanceJoint>(n, L);
    };
    return t;
  }();
  return types;
}

void ParseJoint(const YAML::Node& node, int k, ParseContext& ctx, Lines& lines) {
  ctx.SetEntity("joint #" + std::to_string(k + 1));
  if (!node.IsMap()) ctx.CheckKeys(node, {});
  const std::string name = ctx.String(node, "name");
  const std::string entity = "joint '" + name + "'";
  ctx.SetEntity(entity);
  const std::string type = ctx.String(node, "type");
  const auto& types = JointTypes();
  const auto it = types.find(type);
  if (it == types.end()) {
    std::string list;
    for (const auto& t : types) list += (list.empty() ? "" : ", ") + t.first;
    ctx.Fail(node["type"], "unknown joint type " + Quote(type) + " (allowed: " + list + ")");
  }
  if (type == "distance")
    ctx.CheckKeys(node, {"name", "type", "i", "j", "length"});
  else
    ctx.CheckKeys(node, {"name", "type", "i", "j"});
  const int mi = ctx.Marker(node, "i");
  const int mj = ctx.Marker(node, "j");
  const Model& model = ctx.model();
  if (model.markers[mi].body == model.markers[mj].body)
    ctx.Fail(node, "markers '" + model.markers[mi].name + "' and '" + model.markers[mj].name +
                       "' are both on body '" + model.bodies[model.markers[mi].body]->name() +
                       "': a joint must connect two different bodies");
  auto joint = ctx.Guard(node, [&] { return it->second(name, node, mi, mj, ctx); });
  ctx.Guard(node, [&] { return ctx.model().AddJoint(std::move(joint), mi, mj); });
  lines[entity] = ParseContext::Line(node);
}

void ParseDriver(const YAML::Node& node, int k, ParseContext& ctx, Lines& lines) {
  ctx.SetEntity("driver #" + std::to_string(k + 1));
  ctx.CheckKeys(node, {"name", "joint", "coordinate", "function"});
  const std::string name = ctx.String(node, "name");
  const std::string entity = "driver '" + name + "'";
  ctx.SetEntity(entity);
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
      ctx.Fail(node["coordinate"], "joint '" + target.name() + "' has no coordinate " + Quote(c) +
                                       " (it has: " + list + ")");
  }
  auto f = ctx.Function(node, "function");
  auto driver = std::make_unique<MotionDriver>(name, &target, coordinate, std::move(f));
  ctx.Guard(node, [&] {
    return ctx.model().AddJoint(std::move(driver), target.marker_i, target.marker_j);
  });
  lines["joint '" + name + "'"] = ParseContext::Line(node);
}

// the name of a force or sensor node, if it has one, for the line table
std::string NameOf(const YAML::Node& node) {
  if (node.IsMap() && node["name"] && node["name"].IsScalar()) return node["name"].Scalar();
  return "";
}

void ParseSolver(const YAML::Node& node, ParseContext& ctx) {
  ctx.SetEntity("solver");
  ctx.CheckKeys(node, {"t_end", "dt", "dt_min", "dt_max", "rho_inf", "adaptive", "rtol", "atol",
                       "newton_tol", "max_newton", "geometric_stiffness", "assembly_tol",
                       "redundancy_tol", "jacobian_reuse", "jacobian_reuse_rate", "analysis"});
  SolverSettings& s = ctx.model().solver;
  auto positive = [&](const char* key, double fallback) {
    const double x = ctx.Double(node, key, fallback);
    if (!(x > 0.0)) ctx.Fail(node[key], std::string("'") + key + "' must be positive, got " + node[key].Scalar());
    return x;
  };
  s.t_end = positive("t_end", s.t_end);
  s.dt = positive("dt", s.dt);
  s.dt_min = positive("dt_min", s.dt_min);
  if (s.dt_min > s.dt)
    ctx.Fail(node["dt_min"] ? node["dt_min"] : node["dt"], "'dt_min' must not exceed 'dt'");
  s.dt_max = ctx.Double(node, "dt_max", s.dt_max);
  if (s.dt_max < 0.0 || (s.dt_max > 0.0 && s.dt_max < s.dt))
    ctx.Fail(node["dt_max"], "'dt_max' must be 0 (= 100 dt) or at least 'dt'");
  s.rho_inf = ctx.Double(node, "rho_inf", s.rho_inf);
  if (s.rho_inf < 0.0 || s.rho_inf > 1.0)
    ctx.Fail(node["rho_inf"], "'rho_inf' must lie in [0, 1], got " + node["rho_inf"].Scalar());
  s.adaptive = ctx.Bool(node, "adaptive", s.adaptive);
  s.rtol = positive("rtol", s.rtol);
  s.atol = positive("atol", s.atol);
  s.newton_tol = positive("newton_tol", s.newton_tol);
  s.max_newton = ctx.Integer(node, "max_newton", s.max_newton);
  if (s.max_newton < 1) ctx.Fail(node["max_newton"], "'max_newton' must be at least 1");
  s.geometric_stiffness = ctx.Bool(node, "geometric_stiffness", s.geometric_stiffness);
  s.jacobian_reuse = ctx.Bool(node, "jacobian_reuse", s.jacobian_reuse);
  s.jacobian_reuse_rate = ctx.Double(node, "jacobian_reuse_rate", s.jacobian_reuse_rate);
  if (!(s.jacobian_reuse_rate > 0.0 && s.jacobian_reuse_rate < 1.0))
    ctx.Fail(node["jacobian_reuse_rate"], "'jacobian_reuse_rate' must lie in (0, 1)");
  s.assembly_tol = positive("assembly_tol", s.assembly_tol);
  s.redundancy_tol = positive("redundancy_tol", s.redundancy_tol);
  if (s.redundancy_tol >= 1.0) ctx.Fail(node["redundancy_tol"], "'redundancy_tol' must be below 1");
  if (node["analysis"]) {
    const std::string a = ctx.String(node, "analysis", "dynamics");
    if (a == "dynamics") s.analysis = Analysis::kDynamics;
    else if (a == "statics") s.analysis = Analysis::kStatics;
    else if (a == "statics_then_dynamics") s.analysis = Analysis::kStaticsThenDynamics;
    else ctx.Fail(node["analysis"], "'analysis' must be dynamics, statics or statics_then_dynamics, got " + a);
  }
}

void ParseOutput(const YAML::Node& node, ParseContext& ctx) {
  ctx.SetEntity("output");
  ctx.CheckKeys(node, {"interval", "animation", "animation_interval", "deformation_scale"});
  OutputSettings& o = ctx.model().output;
  o.interval = ctx.Double(node, "interval", o.interval);
  if (o.interval < 0.0) ctx.Fail(node["interval"], "'interval' must not be negative (0 = every step)");
  o.animation = ctx.Bool(node, "animation", o.animation);
  o.animation_interval = ctx.Double(node, "animation_interval", o.animation_interval);
  if (!(o.animation_interval > 0.0))
    ctx.Fail(node["animation_interval"], "'animation_interval' must be positive");
  o.deformation_scale = ctx.Double(node, "deformation_scale", o.deformation_scale);
  if (!(o.deformation_scale >= 0.0) || !std::isfinite(o.deformation_scale))
    ctx.Fail(node["deformation_scale"], "'deformation_scale' must be a finite number >= 0");
}

void BuildModel(const YAML::Node& root, ParseContext& ctx) {
  Lines lines;
  if (!root || root.IsNull()) ctx.Fail(root, "the model file is empty");
  ctx.CheckKeys(root, {"name", "gravity", "ground", "bodies", "joints", "drivers", "forces", "sensors",
                       "solver", "output"});
  Model& model = ctx.model();
  model.name = ctx.String(root, "name", model.name);
  model.gravity_W = ctx.Vector3(root, "gravity", model.gravity_W);
  if (root["ground"]) ParseGround(root["ground"], ctx, lines);
  int k = 0;
  if (const YAML::Node list = List(root, "bodies", ctx))
    for (const YAML::Node& b : list) ParseBody(b, k++, ctx, lines);
  k = 0;
  if (const YAML::Node list = List(root, "joints", ctx))
    for (const YAML::Node& j : list) ParseJoint(j, k++, ctx, lines);
  k = 0;
  if (const YAML::Node list = List(root, "drivers", ctx))
    for (const YAML::Node& d : list) ParseDriver(d, k++, ctx, lines);
  k = 0;
  if (const YAML::Node list = List(root, "forces", ctx)) {
    for (const YAML::Node& f : list) {
      ctx.SetEntity("force #" + std::to_string(++k));
      ctx.Guard(f, [&] { ParseForce(f, ctx); });
      lines["force '" + NameOf(f) + "'"] = ParseContext::Line(f);
    }
  }
  k = 0;
  if (const YAML::Node list = List(root, "sensors", ctx)) {
    for (const YAML::Node& s : list) {
      ctx.SetEntity("sensor #" + std::to_string(++k));
      ctx.Guard(s, [&] { ParseSensor(s, ctx); });
      lines["sensor '" + NameOf(s) + "'"] = ParseContext::Line(s);
    }
  }
  if (root["solver"]) ParseSolver(root["solver"], ctx);
  if (root["output"]) ParseOutput(root["output"], ctx);
  ctx.SetEntity("");
  try {
    model.Finalize();
  } catch (const InputError& e) {
    const auto it = lines.find(e.context().entity);
    throw InputError(e.message(), {ctx.file(), it == lines.end() ? 0 : it->second, e.context().entity});
  }
}

}  // namespace

std::unique_ptr<Model> LoadModelString(const std::string& yaml, const std::string& name_for_messages) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw InputError("YAML syntax error: " + e.msg,
                     {name_for_messages, e.mark.is_null() ? 0 : e.mark.line + 1, ""});
  }
  auto model = std::make_unique<Model>();
  ParseContext ctx(name_for_messages, *model);
  try {
    BuildModel(root, ctx);
  } catch (const YAML::Exception& e) {
    throw InputError(e.msg, {name_for_messages, e.mark.is_null() ? 0 : e.mark.line + 1, ctx.entity()});
  }
  return model;
}

std::unique_ptr<Model> LoadModelFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("cannot open the model file: it is a directory", {path, 0, ""});
  std::ifstream in(path);
  if (!in)
    throw InputError("cannot open the model file: " + std::string(std::strerror(errno)), {path, 0, ""});
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("cannot read the model file", {path, 0, ""});
  return LoadModelString(text.str(), path);
}

}  // namespace flexmb
