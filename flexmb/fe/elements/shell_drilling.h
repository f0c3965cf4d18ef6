#pragma once
/// \file shell_drilling.h
/// The drilling rotary inertia of the 3- and 4-node shells, chosen so that
/// the modes of the drilling penalty lie well above the element's highest
/// physical frequency instead of in the range a user reduces.
/// Formulation notes: docs/design.md, "FE: shell elements" (drilling).

#include <Eigen/Core>

#include "flexmb/fe/elements/shell_common.h"

namespace flexmb::fe::shell {

/// The drilling modes (rz patterns that the one-point tie does not reach,
/// held only by the kDrillingStabilization penalty) get at least this many
/// times the element's highest physical circular frequency.
inline constexpr double kDrillingFrequencyRatio = 3.0;

/// Largest generalized eigenvalue [rad^2/s^2] of the element's physical
/// part, before any drilling term is added: the membrane (local u, v) and
/// the plate (local w, rx, ry) blocks of the local 6N x 6N stiffness `k`
/// and mass `m` of an element with N nodes, node by node u v w rx ry rz.
/// Both mass blocks must be positive definite.
template <int N>
double MaxPhysicalEigenvalue(const Eigen::Matrix<double, 6 * N, 6 * N>& k,
                             const Eigen::Matrix<double, 6 * N, 6 * N>& m);

/// Smallest generalized eigenvalue of (nn, diag(share)): how far a lumped
/// rz mass lowers the drilling modes against the consistent one (1/9 for a
/// rectangle, 1/4 for a triangle); `nn` = int N N^T dA, `share` = int N dA.
double LumpedDrillingRatio(const Eigen::MatrixXd& nn, const Eigen::VectorXd& share);

/// Drilling inertia [kg] per area of a drilling strain energy with the
/// stiffness `k` [N/m] per area (the stabilization beta G t on the full
/// rule, or the tie alpha G t at the centroid), the consistent mass on the
/// same strain (rz - omega), or lumped on rz with the area shares:
/// min(m2, mu k / (kDrillingFrequencyRatio^2 lambda_max)), m2 = rho t^3 / 12,
/// mu = 1 (consistent) or LumpedDrillingRatio (lumped), lambda_max =
/// MaxPhysicalEigenvalue, so that the drilling modes of that term sit
/// kDrillingFrequencyRatio times above the element's highest physical
/// frequency. m2 when lambda_max is not positive and finite; 0 when m2 = 0.
double DrillingInertia(const SectionConstants& sc, double k, double lambda_max, double mu);

}  // namespace flexmb::fe::shell
