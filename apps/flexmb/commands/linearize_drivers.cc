#include "apps/flexmb/commands/linearize_drivers.h"

#include <Eigen/QR>
#include <algorithm>
#include <string>

#include "flexmb/common/error.h"

namespace flexmb::cli {

bool IsLinearizeDriver(const Model& m, const std::string& name) {
  const int j = m.FindJoint(name);
  return j >= 0 && std::string(m.joints[static_cast<size_t>(j)]->type()) == "motion";
}

LinearizeDriverSet LinearizeDriverInputs(const Model& m, const Workspace& ws, const LinearizedSystem& L,
                                         const std::vector<int>& independent, const std::vector<std::string>& names) {
  LinearizeDriverSet set;
  set.names = names;
  const int nv = m.nv, rows = static_cast<int>(L.B.rows()), k = static_cast<int>(names.size());
  set.P = MatX::Zero(nv, k);
  if (k == 0) return set;
  // the dependent coordinates: those not independent
  std::vector<int> dependent;
  for (int c = 0; c < nv; ++c)
    if (!std::binary_search(independent.begin(), independent.end(), c)) dependent.push_back(c);
  MatX Bd(rows, static_cast<int>(dependent.size()));
  for (size_t c = 0; c < dependent.size(); ++c) Bd.col(static_cast<Eigen::Index>(c)) = L.B.col(dependent[c]);
  const Eigen::ColPivHouseholderQR<MatX> qr(Bd);
  for (int d = 0; d < k; ++d) {
    const int j = m.FindJoint(names[static_cast<size_t>(d)]);
    if (j < 0 || !IsLinearizeDriver(m, names[static_cast<size_t>(d)]))
      throw InputError("--inputs: no motion driver named '" + names[static_cast<size_t>(d)] + "'");
    const int row = ws.row_of_eq[static_cast<size_t>(m.joints[static_cast<size_t>(j)]->lambda_offset)];
    if (row < 0)
      throw InputError("--inputs: the equation of driver '" + names[static_cast<size_t>(d)] +
                       "' was removed as redundant; it cannot be an input");
    VecX e = VecX::Zero(rows);
    e(row) = 1.0;
    const VecX pd = qr.solve(e);
    if (!pd.allFinite() || (Bd * pd - e).lpNorm<Eigen::Infinity>() > 1e-8)
      throw NumericalError("--inputs: driver '" + names[static_cast<size_t>(d)] +
                           "' cannot be moved with the other constraints held (its coordinate is fixed by them)");
    for (size_t c = 0; c < dependent.size(); ++c) set.P(dependent[c], d) = pd(static_cast<Eigen::Index>(c));
  }
  return set;
}

}  // namespace flexmb::cli
