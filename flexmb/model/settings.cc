#include "flexmb/model/settings.h"

#include <cmath>

#include <fmt/format.h>

#include "flexmb/common/error.h"

namespace flexmb {
namespace {

std::optional<SettingsProblem> NotPositive(const char* key, double x) {
  if (x > 0.0 && std::isfinite(x)) return std::nullopt;
  return SettingsProblem{key, fmt::format("'{}' must be positive, got {:g}", key, x)};
}

}  // namespace

std::optional<SettingsProblem> FindSolverSettingsProblem(const SolverSettings& s) {
  const std::pair<const char*, double> positive[] = {
      {"t_end", s.t_end}, {"dt", s.dt}, {"dt_min", s.dt_min}, {"rtol", s.rtol}, {"atol", s.atol},
      {"newton_tol", s.newton_tol}, {"assembly_tol", s.assembly_tol}, {"redundancy_tol", s.redundancy_tol}};
  for (const auto& [key, x] : positive)
    if (auto p = NotPositive(key, x)) return p;
  if (s.dt_min > s.dt) return SettingsProblem{"dt_min", "'dt_min' must not exceed 'dt'"};
  if (!std::isfinite(s.dt_max) || s.dt_max < 0.0 || (s.dt_max > 0.0 && s.dt_max < s.dt))
    return SettingsProblem{"dt_max", "'dt_max' must be 0 (= 100 dt) or at least 'dt'"};
  if (!(s.rho_inf >= 0.0 && s.rho_inf <= 1.0))
    return SettingsProblem{"rho_inf", fmt::format("'rho_inf' must lie in [0, 1], got {:g}", s.rho_inf)};
  if (s.max_newton < 1) return SettingsProblem{"max_newton", "'max_newton' must be at least 1"};
  if (!(s.jacobian_reuse_rate > 0.0 && s.jacobian_reuse_rate < 1.0))
    return SettingsProblem{"jacobian_reuse_rate", "'jacobian_reuse_rate' must lie in (0, 1)"};
  if (s.redundancy_tol >= 1.0) return SettingsProblem{"redundancy_tol", "'redundancy_tol' must be below 1"};
  return std::nullopt;
}

void ApplySolverOverrides(const SolverOverrides& o, SolverSettings& s) {
  std::string given;
  if (o.t_end) {
    s.t_end = *o.t_end;
    given = fmt::format("--t-end {:g}", *o.t_end);
  }
  if (o.dt) {
    s.dt = *o.dt;
    given += fmt::format("{}--dt {:g}", given.empty() ? "" : ", ", *o.dt);
  }
  if (auto p = FindSolverSettingsProblem(s)) throw InputError(given + ": " + p->message, {"", 0, "solver"});
}

}  // namespace flexmb
