#pragma once
/// \file residual_share.h
/// Which model element is at fault when a step fails: the shares of the
/// bodies, joints and force elements in the scaled Newton residual of the
/// last iterate. The residual r = M vdot - Q + B^T lambda is split row by
/// row into its contributions: each force element's generalized force
/// -J^T wrench, each joint's reaction B^T lambda, and each body's own part
/// (inertia and its own forces: the rest). A row is scaled by the Newton
/// coefficient and the row's mass, r_i / (beta' M_ii), so that every row is
/// a position correction [m or rad]; its magnitude is shared among the
/// row's contributors in proportion to their magnitudes. A constraint row
/// |Phi_r| [m or rad] belongs to its joint. Shares are fractions of the sum.

#include <string>
#include <vector>

#include "flexmb/model/model.h"
#include "flexmb/model/state.h"
#include "flexmb/model/workspace.h"

namespace flexmb {

/// One element's share of the scaled Newton residual.
struct ResidualShare {
  std::string kind;    ///< "body", "joint" or "force element"
  std::string name;    ///< the element's name
  double share = 0.0;  ///< fraction of the scaled residual, in [0, 1] (1 for a non-finite part)
  bool non_finite = false;  ///< the element's contribution is not finite

  /// "force element 'spring'".
  std::string Entity() const { return kind + " '" + name + "'"; }
};

/// The elements with the largest shares, largest first (at most `count`,
/// none below 1 %; only those with a non-finite contribution if there are
/// any), of the residual `res` = M vdot - Q + B^T lambda (nv)
/// evaluated in `ws` at the multipliers `lambda` (all equations, nc), with
/// `bp` = d vdot / d dx of the integrator (1 / (beta h^2) scale). Allocates:
/// for failed steps only.
std::vector<ResidualShare> LargestResidualShares(const Model& model, const Workspace& ws, const VecX& res,
                                                 const VecX& lambda, double bp, int count);

/// "largest share of the scaled Newton residual: force element 'k' (62 %),
/// then body 'b' (30 %)"; empty for no shares.
std::string DescribeResidualShares(const std::vector<ResidualShare>& shares);

}  // namespace flexmb
