#include "flexmb/model_file/solver_section.h"

#include <string>
#include <vector>

namespace flexmb {

void ReadSolverSection(const YAML::Node& node, YamlContext& ctx, SolverSettings& s,
                       std::initializer_list<const char*> extra) {
  std::vector<const char*> keys = {"t_end", "dt", "dt_min", "dt_max", "rho_inf", "adaptive", "rtol", "atol",
                                   "newton_tol", "max_newton", "geometric_stiffness", "assembly_tol",
                                   "redundancy_tol", "jacobian_reuse", "jacobian_reuse_rate", "analysis",
                                   "statics_hold", "statics_residual_tol"};
  keys.insert(keys.end(), extra.begin(), extra.end());
  ctx.CheckKeys(node, keys);
  s.t_end = ctx.Double(node, "t_end", s.t_end);
  s.dt = ctx.Double(node, "dt", s.dt);
  s.dt_min = ctx.Double(node, "dt_min", s.dt_min);
  s.dt_max = ctx.Double(node, "dt_max", s.dt_max);
  s.rho_inf = ctx.Double(node, "rho_inf", s.rho_inf);
  s.adaptive = ctx.Bool(node, "adaptive", s.adaptive);
  s.rtol = ctx.Double(node, "rtol", s.rtol);
  s.atol = ctx.Double(node, "atol", s.atol);
  s.newton_tol = ctx.Double(node, "newton_tol", s.newton_tol);
  s.max_newton = ctx.Integer(node, "max_newton", s.max_newton);
  s.geometric_stiffness = ctx.Bool(node, "geometric_stiffness", s.geometric_stiffness);
  s.jacobian_reuse = ctx.Bool(node, "jacobian_reuse", s.jacobian_reuse);
  s.jacobian_reuse_rate = ctx.Double(node, "jacobian_reuse_rate", s.jacobian_reuse_rate);
  s.assembly_tol = ctx.Double(node, "assembly_tol", s.assembly_tol);
  s.redundancy_tol = ctx.Double(node, "redundancy_tol", s.redundancy_tol);
  if (node["statics_hold"]) {
    const std::string h = ctx.String(node, "statics_hold");
    if (h != "singular" && h != "always")
      ctx.Fail(node["statics_hold"], "'statics_hold' must be singular (the default) or always, got " + h);
    s.statics_hold_always = h == "always";
  }
  s.statics_residual_tol = ctx.Double(node, "statics_residual_tol", s.statics_residual_tol);
  if (!(s.statics_residual_tol > 0) || !(s.statics_residual_tol < 1))
    ctx.Fail(node["statics_residual_tol"], "'statics_residual_tol' must lie in (0, 1)");
  if (node["analysis"]) {
    const std::string a = ctx.String(node, "analysis");
    if (a == "dynamics") s.analysis = Analysis::kDynamics;
    else if (a == "statics") s.analysis = Analysis::kStatics;
    else if (a == "statics_then_dynamics") s.analysis = Analysis::kStaticsThenDynamics;
    else ctx.Fail(node["analysis"], "'analysis' must be dynamics, statics or statics_then_dynamics, got " + a);
  }
  // the rules every writer of the settings obeys (model/settings.h), at the line of the key
  if (const auto p = FindSolverSettingsProblem(s)) ctx.Fail(node[p->key] ? node[p->key] : node, p->message);
}

}  // namespace flexmb
