#pragma once
/// \file state.h
/// The state of a simulation: only what evolves in time.

#include <Eigen/Core>

namespace flexmb {

/// t [s], coordinates q, velocities v and constraint multipliers lambda
/// (global vectors; bodies and joints address slices of them).
struct State {
  double t = 0.0;
  Eigen::VectorXd q;       ///< position coordinates (nq)
  Eigen::VectorXd v;       ///< velocity coordinates (nv)
  Eigen::VectorXd lambda;  ///< constraint multipliers (nc); reactions are -B^T lambda
};

}  // namespace flexmb
