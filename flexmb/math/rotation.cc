#include "flexmb/math/rotation.h"

#include <cmath>

namespace flexmb {

Mat3 Skew(const Vec3& a) {
  Mat3 s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

Quat ExpQuat(const Vec3& phi) {
  const double theta = phi.norm();
  double w, s;  // q = (w, s * phi)
  if (theta < 1e-4) {
    const double t2 = theta * theta;
    w = 1.0 - t2 / 8.0 + t2 * t2 / 384.0;
    s = 0.5 - t2 / 48.0 + t2 * t2 / 3840.0;
  } else {
    w = std::cos(0.5 * theta);
    s = std::sin(0.5 * theta) / theta;
  }
  Quat q(w, s * phi.x(), s * phi.y(), s * phi.z());
  q.normalize();
  return q;
}

Vec3 LogQuat(const Quat& q_in) {
  Quat q = q_in;
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // shortest rotation
  const Vec3 v = q.vec();
  const double vn = v.norm();
  const double w = q.w();
  if (vn < 1e-8) {
    // theta = 2 atan(vn / w) ~ 2 vn / w (1 - vn^2 / (3 w^2))
    return (2.0 / w) * (1.0 - vn * vn / (3.0 * w * w)) * v;
  }
  const double theta = 2.0 * std::atan2(vn, w);
  return (theta / vn) * v;
}

Mat3 ExpSO3(const Vec3& phi) { return ExpQuat(phi).toRotationMatrix(); }

Vec3 LogSO3(const Mat3& R) { return LogQuat(Quat(R)); }

Mat3 TangentSO3(const Vec3& phi) {
  const double t = phi.norm();
  const Mat3 S = Skew(phi);
  double a, b;  // T = I - a S + b S^2
  if (t < 1e-4) {
    const double t2 = t * t;
    a = 0.5 - t2 / 24.0;
    b = 1.0 / 6.0 - t2 / 120.0;
  } else {
    a = (1.0 - std::cos(t)) / (t * t);
    b = (t - std::sin(t)) / (t * t * t);
  }
  return Mat3::Identity() - a * S + b * S * S;
}

Vec3 RollPitchYaw(const Mat3& R) {
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  double roll, yaw;
  if (std::abs(R(2, 0)) < 1.0 - 1e-12) {
    roll = std::atan2(R(2, 1), R(2, 2));
    yaw = std::atan2(R(1, 0), R(0, 0));
  } else {  // gimbal lock: put everything into yaw
    roll = 0.0;
    yaw = std::atan2(-R(0, 1), R(1, 1));
  }
  return {roll, pitch, yaw};
}

Mat3 FromRollPitchYaw(const Vec3& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Vec3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Vec3::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Vec3::UnitX()))
      .toRotationMatrix();
}

}  // namespace flexmb
