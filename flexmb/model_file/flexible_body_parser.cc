// Reads a model-file body of type flexible (docs/model-file.md, "Flexible
// bodies"): name, type, file, position, orientation, velocity,
// angular_velocity, modal_coordinates, modal_velocities, damping
// {rayleigh: [alpha, beta]} | {ratios: [..]}, geometric_stiffening and
// deformation_stiffening
// (true | false; default: used if the body file has it), markers [{name,
// node, position, orientation}].
#include "flexmb/model_file/flexible_body_parser.h"

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/common/text.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/body_file/unit_system.h"
#include "flexmb/model/model.h"

namespace flexmb {
namespace {

// a list of exactly n numbers at node[key], or empty if absent
VecX NumberList(const YAML::Node& node, const char* key, int n, const ParseContext& ctx) {
  const YAML::Node v = node[key];
  if (!v) return VecX();
  if (!v.IsSequence() || static_cast<int>(v.size()) != n)
    ctx.Fail(v, std::string("expected '") + key + "' as a list of " + std::to_string(n) +
                    " numbers (one per modal coordinate of the body file)");
  VecX out(n);
  for (int k = 0; k < n; ++k) out(k) = ctx.Number(v[k], std::string("'") + key + "' entry " + std::to_string(k + 1));
  return out;
}

// damping override: Rayleigh D = alpha M + beta K, or per-mode ratios
// D = diag(2 zeta_j sqrt(k_jj m_jj)) (the last ratio repeats)
MatX ParseDamping(const YAML::Node& d, const reduction::ReducedBody& body, const ParseContext& ctx) {
  const int n = body.invariants.n;
  ctx.CheckKeys(d, {"rayleigh", "ratios"});
  if (d["rayleigh"] && d["ratios"]) ctx.Fail(d, "give either 'rayleigh' or 'ratios', not both");
  if (d["rayleigh"]) {
    const YAML::Node r = d["rayleigh"];
    if (!r.IsSequence() || r.size() != 2) ctx.Fail(r, "expected 'rayleigh' as [alpha, beta] (D = alpha M + beta K)");
    const double alpha = ctx.Number(r[0], "Rayleigh alpha"), beta = ctx.Number(r[1], "Rayleigh beta");
    if (alpha < 0.0 || beta < 0.0) ctx.Fail(r, "Rayleigh coefficients must not be negative");
    return alpha * body.mass + beta * body.stiffness;
  }
  if (d["ratios"]) {
    const YAML::Node r = d["ratios"];
    if (!r.IsSequence() || r.size() == 0) ctx.Fail(r, "expected 'ratios' as a list of damping ratios");
    MatX D = MatX::Zero(n, n);
    double zeta = 0.0;
    for (int j = 0; j < n; ++j) {
      if (j < static_cast<int>(r.size())) zeta = ctx.Number(r[j], "damping ratio " + std::to_string(j + 1));
      if (zeta < 0.0) ctx.Fail(r, "damping ratios must not be negative");
      D(j, j) = 2.0 * zeta * std::sqrt(std::max(0.0, body.stiffness(j, j) * body.mass(j, j)));
    }
    return D;
  }
  ctx.Fail(d, "expected 'damping' as {rayleigh: [alpha, beta]} or {ratios: [..]}");
}

}  // namespace

void ParseFlexibleBody(const YAML::Node& node, ParseContext& ctx, std::map<std::string, int>& lines) {
  ctx.CheckKeys(node, {"name", "type", "file", "position", "orientation", "velocity", "angular_velocity",
                       "modal_coordinates", "modal_velocities", "damping", "geometric_stiffening", "deformation_stiffening", "markers"});
  const std::string name = ctx.String(node, "name");
  if (name.empty()) ctx.Fail(node["name"], "a body name must not be empty");
  if (name.find('.') != std::string::npos || name == "ground")
    ctx.Fail(node["name"], "invalid body name " + Quoted(name));
  const std::string entity = "body '" + name + "'";
  ctx.SetEntity(entity);

  // the body file, relative to the model file's folder
  const std::string file = ctx.String(node, "file");
  std::filesystem::path path(file);
  if (path.is_relative()) path = std::filesystem::path(ctx.file()).parent_path() / path;
  auto reduced = std::make_shared<reduction::ReducedBody>();
  try {
    *reduced = io::ReadBody(path.string());
  } catch (const InputError& e) {
    ctx.Fail(node["file"], "cannot use body file " + Quoted(path.string()) + ": " + e.what());
  }
  // units: another system is an error, an unknown or implausible one a warning
  std::vector<std::string> unit_warnings;
  try {
    unit_warnings = io::CheckBodyUnits(*reduced, path.string());
  } catch (const InputError& e) {
    ctx.Fail(node["file"], e.what());
  }
  for (const std::string& w : unit_warnings)
    LogWarning(ctx.file() + ":" + std::to_string(ParseContext::Line(node["file"])) + ": " + entity + ": " + w);
  const int n = reduced->invariants.n;

  FlexibleBodyData d;
  d.p_WB = ctx.Vector3(node, "position", Vec3::Zero());
  d.R_WB = ctx.Orientation(node, "orientation");
  d.v_WB = ctx.Vector3(node, "velocity", Vec3::Zero());
  d.w_WB = ctx.Vector3(node, "angular_velocity", Vec3::Zero());
  d.w0 = NumberList(node, "modal_coordinates", n, ctx);
  d.wd0 = NumberList(node, "modal_velocities", n, ctx);
  if (node["damping"]) d.damping = ParseDamping(node["damping"], *reduced, ctx);
  // a stiffening switch: absent = auto; true needs the body file's matrices
  auto stiffening = [&](const char* key, bool present, const char* what, const char* option,
                        GeometricStiffening& out) {
    if (!node[key]) return;
    const bool on = ctx.Bool(node, key, false);
    if (on && !present)
      ctx.Fail(node[key], "body file " + Quoted(path.string()) + " has no " + what + ": reduce it with " + option);
    out = on ? GeometricStiffening::kOn : GeometricStiffening::kOff;
  };
  stiffening("geometric_stiffening", !reduced->geometric_stiffness.empty(), "geometric stiffness",
             "--geometric-stiffening", d.geometric_stiffening);
  stiffening("deformation_stiffening", !reduced->deformation_stiffness.empty(), "deformation stiffness",
             "--deformation-stiffening", d.deformation_stiffening);
  d.reduced = reduced;

  auto body = ctx.Guard(node, [&] { return std::make_unique<FlexibleBody>(name, d); });
  const FlexibleBody* flex = body.get();
  if (flex->HasGeometricStiffening() && flex->HasDeformationStiffening())
    LogWarning(ctx.file() + ":" + std::to_string(ParseContext::Line(node)) + ": " + entity +
               ": both the centrifugal and the deformation stiffening are on; where the modes represent the "
               "centrifugal stretch both count the same stress (set one of geometric_stiffening, "
               "deformation_stiffening to false; docs/model-file.md)");
  const int b = ctx.Guard(node["name"], [&] { return ctx.model().AddBody(std::move(body)); });
  lines[entity] = ParseContext::Line(node);

  // a marker on a node of the body file (by its id), or on the floating frame
  auto node_of = [&](const YAML::Node& m) {
    if (!m["node"]) return -1;
    const int id = ctx.Integer(m, "node", -1);
    const int k = reduced->mesh.NodeIndex(id);
    if (k < 0)
      ctx.Fail(m["node"], "node " + std::to_string(id) + " does not exist in body file " +
                              Quoted(path.string()) + " of body " + Quoted(name));
    if (!flex->IsInterfaceNode(k))
      LogWarning(ctx.file() + ":" + std::to_string(ParseContext::Line(m["node"])) + ": " + ctx.entity() +
                 ": node " + std::to_string(id) + " is not an interface node of the reduction; its motion "
                 "is only as exact as the kept modes make it");
    return k;
  };
  ctx.ParseMarkerList(node, b, {"name", "node", "position", "orientation"}, node_of, lines);
}

}  // namespace flexmb
