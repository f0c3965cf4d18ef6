#pragma once
/// \file rotation.h
/// Rotations on SO(3): unit quaternions as the state, the exponential and
/// logarithm maps (singularity-free at any angle), skew matrices and the
/// tangent operator. Conventions: a rotation R_AB maps vectors expressed in
/// frame B to frame A; rotation vectors are in radians.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace flexmb {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// Skew-symmetric matrix with skew(a) * b = a x b.
Mat3 Skew(const Vec3& a);

/// The orientation quaternion of a body's position coordinates q = (p, quat
/// wxyz) (rigid and flexible bodies alike): Quat(q[3], q[4], q[5], q[6]).
inline Quat BodyQuat(const double* q) { return Quat(q[3], q[4], q[5], q[6]); }

/// Exponential map: unit quaternion of the rotation vector `phi` [rad].
/// Exact for all angles; uses a Taylor series below 1e-4 rad.
Quat ExpQuat(const Vec3& phi);

/// Logarithm map: rotation vector [rad] of the unit quaternion `q`, with angle
/// in [0, pi]. `q` and -q give the same result.
Vec3 LogQuat(const Quat& q);

/// Exponential map to a rotation matrix (Rodrigues), exact at all angles.
Mat3 ExpSO3(const Vec3& phi);

/// Logarithm of a rotation matrix: rotation vector with angle in [0, pi].
/// Robust near 0 and near pi (goes through the quaternion).
Vec3 LogSO3(const Mat3& R);

/// Tangent operator T(phi) of the exponential map, such that
/// d/dt exp(phi) = exp(phi) * skew(T(phi) * phidot) (right trivialization).
Mat3 TangentSO3(const Vec3& phi);

/// Cardan angles (roll about x, pitch about y, yaw about z; R = Rz(yaw) Ry(pitch)
/// Rx(roll)), the vehicle convention [rad]. Pitch in [-pi/2, pi/2].
Vec3 RollPitchYaw(const Mat3& R);

/// Rotation matrix from roll, pitch, yaw [rad] (same convention as RollPitchYaw).
Mat3 FromRollPitchYaw(const Vec3& rpy);

}  // namespace flexmb
