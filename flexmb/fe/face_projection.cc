#include "flexmb/fe/face_projection.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace flexmb::fe {
namespace {

bool IsTriangle(int count) { return count == 3 || count == 6; }

// the face coordinates moved into the face: the triangle xi, eta >= 0,
// xi + eta <= 1 (the excess over the hypotenuse taken off both equally);
// the square [-1, 1]^2
void Clamp(int count, double& xi, double& eta) {
  if (!IsTriangle(count)) {
    xi = std::clamp(xi, -1.0, 1.0);
    eta = std::clamp(eta, -1.0, 1.0);
    return;
  }
  const double excess = xi + eta - 1.0;
  if (excess > 0.0) {
    xi -= 0.5 * excess;
    eta -= 0.5 * excess;
  }
  xi = std::clamp(xi, 0.0, 1.0);
  eta = std::clamp(eta, 0.0, 1.0);
  if (xi + eta > 1.0) {  // one of them was clamped at 0 after the shift
    const double s = xi + eta;
    xi /= s;
    eta /= s;
  }
}

// position and tangents of the face at (xi, eta)
void Evaluate(std::span<const Vec3> x, double xi, double eta, Vec3& at, Vec3& t1, Vec3& t2,
              std::array<double, 8>& n) {
  std::array<std::array<double, 2>, 8> dn{};
  FaceShapeFunctions(static_cast<int>(x.size()), xi, eta, n, dn);
  at.setZero();
  t1.setZero();
  t2.setZero();
  for (size_t k = 0; k < x.size(); ++k) {
    at += n[k] * x[k];
    t1 += dn[k][0] * x[k];
    t2 += dn[k][1] * x[k];
  }
}

}  // namespace

void FaceShapeFunctions(int count, double xi, double eta, std::array<double, 8>& n,
                        std::array<std::array<double, 2>, 8>& dn) {
  n.fill(0.0);
  for (auto& d : dn) d = {0.0, 0.0};
  if (count == 3 || count == 6) {
    const double l[3] = {1.0 - xi - eta, xi, eta};
    // dL/dxi, dL/deta of the area coordinates
    const double dl[3][2] = {{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}};
    if (count == 3) {
      for (int k = 0; k < 3; ++k) {
        n[k] = l[k];
        dn[k] = {dl[k][0], dl[k][1]};
      }
      return;
    }
    for (int k = 0; k < 3; ++k) {
      n[k] = l[k] * (2.0 * l[k] - 1.0);
      for (int j = 0; j < 2; ++j) dn[k][j] = (4.0 * l[k] - 1.0) * dl[k][j];
    }
    for (int k = 0; k < 3; ++k) {  // mid-side node between corners k and k + 1
      const int a = k, b = (k + 1) % 3;
      n[3 + k] = 4.0 * l[a] * l[b];
      for (int j = 0; j < 2; ++j) dn[3 + k][j] = 4.0 * (dl[a][j] * l[b] + l[a] * dl[b][j]);
    }
    return;
  }
  if (count != 4 && count != 8) throw std::invalid_argument("face with " + std::to_string(count) + " nodes");
  static constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0}, kEta[4] = {-1.0, -1.0, 1.0, 1.0};
  if (count == 4) {
    for (int k = 0; k < 4; ++k) {
      n[k] = 0.25 * (1.0 + kXi[k] * xi) * (1.0 + kEta[k] * eta);
      dn[k] = {0.25 * kXi[k] * (1.0 + kEta[k] * eta), 0.25 * kEta[k] * (1.0 + kXi[k] * xi)};
    }
    return;
  }
  for (int k = 0; k < 4; ++k) {
    const double a = 1.0 + kXi[k] * xi, b = 1.0 + kEta[k] * eta, c = kXi[k] * xi + kEta[k] * eta - 1.0;
    n[k] = 0.25 * a * b * c;
    dn[k] = {0.25 * kXi[k] * b * (c + a), 0.25 * kEta[k] * a * (c + b)};
  }
  // mid-side nodes: edges eta = -1, xi = 1, eta = 1, xi = -1
  n[4] = 0.5 * (1.0 - xi * xi) * (1.0 - eta);
  dn[4] = {-xi * (1.0 - eta), -0.5 * (1.0 - xi * xi)};
  n[5] = 0.5 * (1.0 + xi) * (1.0 - eta * eta);
  dn[5] = {0.5 * (1.0 - eta * eta), -eta * (1.0 + xi)};
  n[6] = 0.5 * (1.0 - xi * xi) * (1.0 + eta);
  dn[6] = {-xi * (1.0 + eta), 0.5 * (1.0 - xi * xi)};
  n[7] = 0.5 * (1.0 - xi) * (1.0 - eta * eta);
  dn[7] = {-0.5 * (1.0 - eta * eta), -eta * (1.0 - xi)};
}

FaceProjection ProjectOntoFace(std::span<const Vec3> x, const Vec3& p) {
  const int count = static_cast<int>(x.size());
  FaceProjection out;
  double xi = IsTriangle(count) ? 1.0 / 3.0 : 0.0, eta = xi;
  Vec3 at, t1, t2;
  std::array<double, 8> n{};
  for (int it = 0; it < 50; ++it) {
    Evaluate(x, xi, eta, at, t1, t2, n);
    const Vec3 r = at - p;
    const double h11 = t1.dot(t1), h12 = t1.dot(t2), h22 = t2.dot(t2);
    const double det = h11 * h22 - h12 * h12;
    if (!(det > 1e-24 * h11 * h22)) return out;  // degenerate face
    const double g1 = t1.dot(r), g2 = t2.dot(r);
    double d1 = -(h22 * g1 - h12 * g2) / det, d2 = -(h11 * g2 - h12 * g1) / det;
    // far outside a curved face the model is poor: limit the step
    const double len = std::hypot(d1, d2);
    if (len > 1.0) {
      d1 /= len;
      d2 /= len;
    }
    xi += d1;
    eta += d2;
    if (std::hypot(d1, d2) < 1e-13) {
      out.converged = true;
      break;
    }
  }
  if (!out.converged) return out;
  Evaluate(x, xi, eta, at, t1, t2, n);
  const Vec3 normal = t1.cross(t2).normalized();
  out.normal_distance = std::abs((p - at).dot(normal));
  const Vec3 foot = at;
  Clamp(count, xi, eta);
  Evaluate(x, xi, eta, at, t1, t2, n);
  out.xi = xi;
  out.eta = eta;
  out.point = at;
  out.weights = n;
  out.outside = (foot - at).norm();
  return out;
}

}  // namespace flexmb::fe
