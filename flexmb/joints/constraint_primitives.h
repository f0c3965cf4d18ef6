#pragma once
/// \file constraint_primitives.h
/// The basic constraint equations joints are built of, each with its analytic
/// first derivative (a row of D) and its geometric stiffness
/// lambda * d(D^T)/dx, in the marker variations x = (dp_i, dth_i, dp_j, dth_j).
/// a = R_i e_a is an axis of marker i, b = R_j e_b an axis of marker j,
/// d = p_j - p_i.

#include "flexmb/joints/joint.h"

namespace flexmb::primitives {

/// Phi = a . b (perpendicular axes). Geometric stiffness added to H.
void Perpendicular(const Vec3& a, const Vec3& b, JointEval& e, int row);
void PerpendicularStiffness(const Vec3& a, const Vec3& b, double lambda, Mat12& H);

/// Phi = a . d (point j in the plane through p_i normal to a).
void PointInPlane(const Vec3& a, const Vec3& d, JointEval& e, int row);
void PointInPlaneStiffness(const Vec3& a, const Vec3& d, double lambda, Mat12& H);

/// Phi = |d| - L. Throws NumericalError if |d| is ~0.
void Distance(const Vec3& d, double length, JointEval& e, int row);
void DistanceStiffness(const Vec3& d, double lambda, Mat12& H);

/// Relative angle of marker j about z_i: atan2(y_i . x_j, x_i . x_j) and its
/// derivative (12); valid when z_i and z_j are parallel.
double RelativeAngle(const MarkerState& mi, const MarkerState& mj, Vec12* dq);

/// Translation of marker j along z_i: d . z_i and its derivative (12).
double AxialTranslation(const MarkerState& mi, const MarkerState& mj, Vec12* dq);

}  // namespace flexmb::primitives
