// Body entries of the model file (reference: docs/model-file.md, "bodies"):
// rigid bodies here; flexible and ANCF bodies in their own parsers.

#include <memory>
#include <string>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/model/model.h"
#include "flexmb/model_file/ancf_body_parser.h"
#include "flexmb/model_file/body_entry.h"
#include "flexmb/model_file/element_registry.h"
#include "flexmb/model_file/flexible_body_parser.h"
#include "flexmb/model_file/parse_context.h"

namespace flexmb {
namespace {

std::string BodyQuote(const std::string& s) { return "'" + s + "'"; }

void ParseRigidMarkers(const YAML::Node& node, int body, ParseContext& ctx) {
  ctx.ParseMarkerList(node, body, {"name", "position", "orientation"}, nullptr, ctx.lines());
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

void ParseRigidBody(const YAML::Node& node, const std::string&, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "mass", "center_of_mass", "inertia", "inertia_frame", "position",
                       "orientation", "velocity", "angular_velocity", "markers", "shape"});
  const std::string name = BodyEntryName(node, "body", ctx);
  if (name == "ground")
    ctx.Fail(node["name"], "the name 'ground' is reserved for the fixed world frame; put markers on "
                           "it in the top-level 'ground' section");
  const std::string entity = "body '" + name + "'";
  ctx.SetEntity(entity);
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
        ctx.Fail(frame, "unknown 'inertia_frame' " + BodyQuote(f) +
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
  if (node["shape"]) ParseBodyShape(node["shape"], body->shape, ctx);
  const int b = ctx.Guard(node["name"], [&] { return ctx.model().AddBody(std::move(body)); });
  ctx.lines()[entity] = ParseContext::Line(node);
  ParseRigidMarkers(node, b, ctx);
}

void ParseFlexibleEntry(const YAML::Node& node, const std::string&, ParseContext& ctx) {
  ParseFlexibleBody(node, ctx, ctx.lines());
}

void ParseAncfEntry(const YAML::Node& node, const std::string&, ParseContext& ctx) {
  ParseAncfBody(node, ctx, ctx.lines());
}

}  // namespace

std::string BodyEntryName(const YAML::Node& node, const char* kind, const ParseContext& ctx) {
  const std::string name = ctx.String(node, "name");
  const YAML::Node v = node["name"];
  if (name.empty()) ctx.Fail(v, std::string("a ") + kind + " name must not be empty");
  if (name.find('.') != std::string::npos)
    ctx.Fail(v, std::string("a ") + kind + " name must not contain '.' (it separates body and marker in "
                "'body.marker'), got " + BodyQuote(name));
  return name;
}

void ParseBodyMarkers(const YAML::Node& node, int body, ParseContext& ctx) { ParseRigidMarkers(node, body, ctx); }

void ParseBodyShape(const YAML::Node& s, Shape& shape, const ParseContext& ctx) {
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
    ctx.Fail(s["type"], "unknown shape type " + BodyQuote(type) + " (allowed: box, cylinder, sphere)");
  }
  shape.p_BS = ctx.Vector3(s, "position", Vec3::Zero());
  shape.R_BS = ctx.Orientation(s, "orientation");
}


void RegisterBodyTypes(ElementRegistry& r) {
  r.Add(ElementKind::kBody, "rigid", ParseRigidBody);
  r.Add(ElementKind::kBody, "flexible", ParseFlexibleEntry);
  r.Add(ElementKind::kBody, "ancf_beam", ParseAncfEntry);
  r.Add(ElementKind::kBody, "ancf_beam3d", ParseAncfEntry);
  r.Add(ElementKind::kBody, "ancf_cable", ParseAncfEntry);
  r.Add(ElementKind::kBody, "ancf_hoist_rope", ParseAncfEntry);
}

}  // namespace flexmb
