#include "flexmb/yaml/yaml_context.h"

#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include "flexmb/math/input_function.h"

namespace flexmb {
namespace {

// short text of a node for messages: the scalar itself, or its kind
std::string Describe(const YAML::Node& node) {
  if (!node.IsDefined()) return "nothing";
  switch (node.Type()) {
    case YAML::NodeType::Null: return "an empty value";
    case YAML::NodeType::Scalar: return "'" + node.Scalar() + "'";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a map";
    default: return "nothing";
  }
}

std::string FormatNumber(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

}  // namespace

int YamlContext::Line(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

void YamlContext::Fail(const YAML::Node& node, const std::string& message) const {
  throw InputError(message, {file_, Line(node), entity_});
}

void YamlContext::Rethrow(const YAML::Node& node, const InputError& e) const {
  if (!e.context().file.empty()) throw e;
  const std::string& entity = e.context().entity.empty() ? entity_ : e.context().entity;
  throw InputError(e.message(), {file_, Line(node), entity});
}

void YamlContext::CheckKeys(const YAML::Node& node,
                             std::initializer_list<const char*> allowed) const {
  CheckKeys(node, std::vector<const char*>(allowed));
}

void YamlContext::CheckKeys(const YAML::Node& node, const std::vector<const char*>& allowed) const {
  if (!node.IsMap()) Fail(node, "expected a map of 'key: value' entries, got " + Describe(node));
  std::set<std::string> seen;
  for (auto it = node.begin(); it != node.end(); ++it) {
    const YAML::Node key = it->first;
    if (!key.IsScalar()) Fail(key, "a key must be a plain name, got " + Describe(key));
    const std::string& k = key.Scalar();
    bool ok = false;
    for (const char* a : allowed) ok = ok || k == a;
    if (!ok) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      Fail(key, "unknown key '" + k + "' (allowed: " + list + ")");
    }
    if (!seen.insert(k).second) Fail(key, "duplicate key '" + k + "'");
  }
}

namespace {

// node[key] of a map, or an undefined node; throws through ctx if node is no map
YAML::Node Child(const YamlContext& ctx, const YAML::Node& node, const char* key) {
  if (!node.IsMap()) ctx.Fail(node, std::string("expected a map with key '") + key + "', got " + Describe(node));
  return node[key];
}

YAML::Node Required(const YamlContext& ctx, const YAML::Node& node, const char* key) {
  YAML::Node v = Child(ctx, node, key);
  if (!v.IsDefined()) ctx.Fail(node, std::string("missing required key '") + key + "'");
  if (v.IsNull()) ctx.Fail(v, std::string("key '") + key + "' has no value");
  return v;
}

std::string Quoted(const char* key) { return std::string("'") + key + "'"; }

// a list of exactly n finite numbers
template <int N>
Eigen::Matrix<double, N, 1> Numbers(const YamlContext& ctx, const YAML::Node& v, const char* key,
                                    const char* form) {
  if (!v.IsSequence() || static_cast<int>(v.size()) != N)
    ctx.Fail(v, "expected " + std::to_string(N) + " numbers " + form + " for " + Quoted(key) +
                    ", got " +
                    (v.IsSequence() ? "a list of " + std::to_string(v.size()) : Describe(v)));
  Eigen::Matrix<double, N, 1> out;
  for (int k = 0; k < N; ++k)
    out(k) = ctx.Number(v[k], Quoted(key) + " entry " + std::to_string(k + 1));
  return out;
}

}  // namespace

double YamlContext::Number(const YAML::Node& v, const std::string& what) const {
  // quoted scalars carry the tag "!": they are strings even if they look numeric
  if (!v.IsScalar() || v.Tag() == "!") Fail(v, "expected a number for " + what + ", got " + Describe(v));
  double x = 0.0;
  try {
    x = v.as<double>();
  } catch (const YAML::Exception&) {
    Fail(v, "expected a number for " + what + ", got " + Describe(v));
  }
  if (!std::isfinite(x)) Fail(v, what + " must be a finite number, got " + Describe(v));
  return x;
}

double YamlContext::Double(const YAML::Node& node, const char* key) const {
  return Number(Required(*this, node, key), Quoted(key));
}

double YamlContext::Double(const YAML::Node& node, const char* key, double fallback) const {
  const YAML::Node v = Child(*this, node, key);
  if (!v.IsDefined()) return fallback;
  return Number(v, Quoted(key));
}

double YamlContext::Positive(const YAML::Node& node, const char* key) const {
  const YAML::Node v = Required(*this, node, key);
  const double x = Number(v, Quoted(key));
  if (!(x > 0.0)) Fail(v, Quoted(key) + " must be positive, got " + FormatNumber(x));
  return x;
}

int YamlContext::Integer(const YAML::Node& node, const char* key, int fallback) const {
  const YAML::Node v = Child(*this, node, key);
  if (!v.IsDefined()) return fallback;
  const double x = Number(v, Quoted(key));
  if (x != std::floor(x) || std::abs(x) > 1e9)
    Fail(v, Quoted(key) + " must be a whole number, got " + Describe(v));
  return static_cast<int>(x);
}

std::string YamlContext::String(const YAML::Node& node, const char* key) const {
  const YAML::Node v = Required(*this, node, key);
  if (!v.IsScalar()) Fail(v, "expected a text for " + Quoted(key) + ", got " + Describe(v));
  return v.Scalar();
}

std::string YamlContext::String(const YAML::Node& node, const char* key,
                                 const std::string& fallback) const {
  const YAML::Node v = Child(*this, node, key);
  if (!v.IsDefined()) return fallback;
  if (!v.IsScalar()) Fail(v, "expected a text for " + Quoted(key) + ", got " + Describe(v));
  return v.Scalar();
}

bool YamlContext::Bool(const YAML::Node& node, const char* key, bool fallback) const {
  const YAML::Node v = Child(*this, node, key);
  if (!v.IsDefined()) return fallback;
  if (!v.IsScalar() || v.Tag() == "!")
    Fail(v, "expected true or false for " + Quoted(key) + ", got " + Describe(v));
  bool b = false;
  try {
    b = v.as<bool>();
  } catch (const YAML::Exception&) {
    Fail(v, "expected true or false for " + Quoted(key) + ", got " + Describe(v));
  }
  return b;
}

Vec3 YamlContext::Vector3(const YAML::Node& node, const char* key) const {
  return Numbers<3>(*this, Required(*this, node, key), key, "[x, y, z]");
}

Vec3 YamlContext::Vector3(const YAML::Node& node, const char* key, const Vec3& fallback) const {
  const YAML::Node v = Child(*this, node, key);
  if (!v.IsDefined()) return fallback;
  return Numbers<3>(*this, v, key, "[x, y, z]");
}

Mat3 YamlContext::Orientation(const YAML::Node& node, const char* key) const {
  const YAML::Node o = Child(*this, node, key);
  if (!o.IsDefined()) return Mat3::Identity();
  CheckKeys(o, {"quaternion", "rotation_vector", "roll_pitch_yaw", "roll_pitch_yaw_deg", "z_axis",
                "x_axis", "matrix"});
  if (o["x_axis"] && !o["z_axis"]) Fail(o, "'x_axis' needs 'z_axis' (x_axis alone does not fix a frame)");
  const int forms = (o["quaternion"] ? 1 : 0) + (o["rotation_vector"] ? 1 : 0) +
                    (o["roll_pitch_yaw"] ? 1 : 0) + (o["roll_pitch_yaw_deg"] ? 1 : 0) +
                    (o["z_axis"] ? 1 : 0) + (o["matrix"] ? 1 : 0);
  if (forms != 1)
    Fail(o, "an orientation needs exactly one of quaternion, rotation_vector, roll_pitch_yaw, "
            "roll_pitch_yaw_deg, z_axis (with optional x_axis), matrix; got " +
                std::to_string(forms));
  if (o["quaternion"]) {
    const Eigen::Vector4d w = Numbers<4>(*this, o["quaternion"], "quaternion", "[w, x, y, z]");
    if (!(w.norm() > 1e-12)) Fail(o["quaternion"], "'quaternion' must not be zero");
    return Quat(w(0), w(1), w(2), w(3)).normalized().toRotationMatrix();
  }
  if (o["rotation_vector"]) return ExpSO3(Numbers<3>(*this, o["rotation_vector"], "rotation_vector", "[x, y, z] in rad"));
  if (o["roll_pitch_yaw"])
    return FromRollPitchYaw(Numbers<3>(*this, o["roll_pitch_yaw"], "roll_pitch_yaw", "[roll, pitch, yaw] in rad"));
  if (o["roll_pitch_yaw_deg"])
    return FromRollPitchYaw(M_PI / 180.0 *
                            Numbers<3>(*this, o["roll_pitch_yaw_deg"], "roll_pitch_yaw_deg",
                                       "[roll, pitch, yaw] in degrees"));
  if (o["z_axis"]) {
    const Vec3 z0 = Numbers<3>(*this, o["z_axis"], "z_axis", "[x, y, z]");
    if (!(z0.norm() > 1e-12)) Fail(o["z_axis"], "'z_axis' must not be the zero vector");
    const Vec3 z = z0.normalized();
    Vec3 x;
    if (o["x_axis"]) {
      const Vec3 x0 = Numbers<3>(*this, o["x_axis"], "x_axis", "[x, y, z]");
      if (!(x0.norm() > 1e-12)) Fail(o["x_axis"], "'x_axis' must not be the zero vector");
      x = x0 - x0.dot(z) * z;
      if (!(x.norm() > 1e-9 * x0.norm())) Fail(o["x_axis"], "'x_axis' is parallel to 'z_axis'");
    } else {
      // the world axis least aligned with z, made perpendicular (z = e_z gives x = e_x)
      int k = 0;
      for (int i = 1; i < 3; ++i)
        if (std::abs(z(i)) < std::abs(z(k)) - 1e-12) k = i;
      x = Vec3::Unit(k) - z(k) * z;
    }
    x.normalize();
    Mat3 R;
    R.col(0) = x;
    R.col(1) = z.cross(x);
    R.col(2) = z;
    return R;
  }
  const YAML::Node m = o["matrix"];
  if (!m.IsSequence() || m.size() != 3)
    Fail(m, "expected 'matrix' as 3 rows of 3 numbers [[..], [..], [..]], got " + Describe(m));
  Mat3 R;
  for (int r = 0; r < 3; ++r) R.row(r) = Numbers<3>(*this, m[r], "matrix", "(one row)").transpose();
  const double err = (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff();
  if (err > 1e-6)
    Fail(m, "'matrix' is not orthonormal (max |R^T R - I| = " + FormatNumber(err) +
                " > 1e-6)");
  if (R.determinant() < 0) Fail(m, "'matrix' is a reflection (determinant -1), not a rotation");
  return Quat(R).normalized().toRotationMatrix();
}

std::shared_ptr<const ScalarFunction> YamlContext::Function(const YAML::Node& node, const char* key,
                                                             const char* variable) const {
  const YAML::Node f = Required(*this, node, key);
  if (f.IsScalar()) return std::make_shared<ConstantFunction>(Number(f, Quoted(key)));
  if (!f.IsMap())
    Fail(f, "expected a number, {expression: ...}, {table: ...} or {input: ...} for " + Quoted(key) +
                ", got " + Describe(f));
  if (f["input"]) {
    // a value set by a script between steps (math/input_function.h)
    CheckKeys(f, {"input", "initial"});
    const std::string name = String(f, "input");
    if (name.empty()) Fail(f["input"], "'input' needs a name");
    return std::make_shared<InputFunction>(RegisterInput(name, Double(f, "initial", 0.0)));
  }
  CheckKeys(f, {"expression", "table", "interpolation", "extrapolate", "input"});
  if (f["expression"] && f["table"]) Fail(f, "give either 'expression' or 'table', not both");
  if (f["expression"]) {
    if (f["interpolation"] || f["extrapolate"])
      Fail(f, "'interpolation' and 'extrapolate' apply to a table, not to an expression");
    const std::string text = String(f, "expression");
    return Guard(f["expression"], [&] { return std::make_shared<ExpressionFunction>(text, variable); });
  }
  if (!f["table"]) Fail(f, "a function needs 'expression' or 'table'");
  const YAML::Node t = f["table"];
  if (!t.IsSequence()) Fail(t, "expected 'table' as a list of [x, y] rows, got " + Describe(t));
  std::vector<double> xs, ys;
  for (size_t r = 0; r < t.size(); ++r) {
    const Eigen::Vector2d row = Numbers<2>(*this, t[r], "table", "[x, y] (one row)");
    if (r > 0 && !(row(0) > xs.back()))
      Fail(t[r], "table x values must increase strictly: row " + std::to_string(r + 1) + " has x = " +
                     FormatNumber(row(0)) + " after " + FormatNumber(xs.back()));
    xs.push_back(row(0));
    ys.push_back(row(1));
  }
  const std::string interp = String(f, "interpolation", "linear");
  TableFunction::Interpolation mode;
  if (interp == "linear")
    mode = TableFunction::Interpolation::kLinear;
  else if (interp == "spline")
    mode = TableFunction::Interpolation::kCubicSpline;
  else
    Fail(f["interpolation"], "unknown interpolation '" + interp + "' (allowed: linear, spline)");
  const bool extrapolate = Bool(f, "extrapolate", false);
  return Guard(t, [&] {
    return std::make_shared<TableFunction>(std::move(xs), std::move(ys), mode, extrapolate);
  });
}

YAML::Node YamlContext::MapChild(const YAML::Node& node, const char* key) const {
  return Child(*this, node, key);
}

}  // namespace flexmb
