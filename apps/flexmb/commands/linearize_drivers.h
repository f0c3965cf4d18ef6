#pragma once
/// \file linearize_drivers.h
/// Motion drivers as inputs of `flexmb linearize` (docs/cli.md, "Drivers as
/// inputs"). A driver's equation c(q) - f(t) = 0, linearized, is the row
/// b_d dx = df of the constraint Jacobian B: the driver's value df is
/// prescribed, not found. The input is the driver's acceleration u = df''
/// and df, df' are appended to the state, so that the model stays proper
/// (no derivative of an input) and exact for the linearized equations:
/// with dx = N z + P df (P(independent, :) = 0 and B P = E_d, the unit
/// columns of the drivers' rows; the independent coordinates z keep their
/// meaning),
///   Mr z'' + Cr z' + Kr z = N^T (Qu u_f - K P df - C P df' - M P u_d).

#include <string>
#include <vector>

#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/linearization.h"

namespace flexmb::cli {

/// The drivers chosen as inputs and their particular solutions.
struct LinearizeDriverSet {
  std::vector<std::string> names;  ///< the drivers' names, in input order
  /// nv x k: the coordinate increments of a unit increment of each driver's
  /// value with the independent coordinates held (rows of the independent
  /// coordinates 0; B P = E_d over the active constraint rows).
  MatX P;
};

/// True when `name` is a motion driver of `m` (a joint of type "motion").
bool IsLinearizeDriver(const Model& m, const std::string& name);

/// P for the drivers `names` of `m` linearized in `L` with the independent
/// coordinates `independent` (PartitionedNullSpace). `ws` holds the active
/// rows of the state (row_of_eq). Throws InputError naming the driver when
/// its equation was removed as redundant, NumericalError when the dependent
/// columns of B cannot carry it.
LinearizeDriverSet LinearizeDriverInputs(const Model& m, const Workspace& ws, const LinearizedSystem& L,
                                         const std::vector<int>& independent, const std::vector<std::string>& names);

}  // namespace flexmb::cli
