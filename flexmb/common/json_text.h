#pragma once
/// \file json_text.h
/// Small pieces of JSON text for the command line's machine-readable output
/// (summary.json, `--json`): strings escaped, numbers at full precision so
/// that they read back to the same double, vectors and 3 x 3 matrices as
/// nested arrays. Non-finite numbers become null.

#include <Eigen/Core>
#include <string>

namespace flexmb::io {

/// s as a JSON string literal (quotes, backslashes and control characters escaped).
std::string JsonString(const std::string& s);

/// x with 17 significant digits, or null if x is not finite.
std::string JsonNumber(double x);

/// [x, y, z].
std::string JsonVector(const Eigen::Vector3d& v);

/// [[row 0], [row 1], [row 2]].
std::string JsonMatrix(const Eigen::Matrix3d& m);

/// [v_0, v_1, ...] for any length.
std::string JsonArray(const Eigen::VectorXd& v);

}  // namespace flexmb::io
