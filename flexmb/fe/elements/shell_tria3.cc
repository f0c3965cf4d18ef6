#include "flexmb/fe/elements/shell_tria3.h"

#include <Eigen/Dense>
#include <cmath>

#include "flexmb/fe/elements/shell_common.h"

namespace flexmb::fe {
namespace {

using Mat18 = Eigen::Matrix<double, 18, 18>;

// plane frame and local coordinates (node 1 at the origin, e1 along edge 1-2)
shell::LocalFrame<3> Frame(const ElementInput& in, const shell::ShellData& s, double& area) {
  const ErrorContext ctx = shell::Context(*in.element);
  const Vec3* x = in.x;
  double max_edge = 0.0, min_edge = INFINITY;
  for (int i = 0; i < 3; ++i) {
    const double len = (x[(i + 1) % 3] - x[i]).norm();
    max_edge = std::max(max_edge, len);
    min_edge = std::min(min_edge, len);
  }
  if (!(min_edge > 1e-8 * max_edge)) throw InputError("coincident nodes", ctx);
  const Vec3 n_raw = (x[1] - x[0]).cross(x[2] - x[0]);
  area = 0.5 * n_raw.norm();
  if (!(area > 1e-10 * max_edge * max_edge)) throw InputError("zero area", ctx);
  const Vec3 e3 = n_raw.normalized();
  const Vec3 e1 = (x[1] - x[0]).normalized();
  const Vec3 e2 = e3.cross(e1);
  shell::LocalFrame<3> f;
  f.R.col(0) = e1;
  f.R.col(1) = e2;
  f.R.col(2) = e3;
  for (int i = 0; i < 3; ++i) {
    f.xy(i, 0) = e1.dot(x[i] - x[0]);
    f.xy(i, 1) = e2.dot(x[i] - x[0]);
    f.d.col(i) = s.offset * e3;
  }
  return f;
}

}  // namespace

void ShellTria3Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const shell::ShellData s = shell::CheckShellInput(in, 3);
  double area = 0.0;
  const shell::LocalFrame<3> f = Frame(in, s, area);
  const Eigen::Matrix3d cm = shell::MembraneMatrix(s);
  const Eigen::Matrix3d cb = shell::BendingMatrix(s);
  const double ks = shell::kShearFactor * s.G * s.t;
  const double kd = shell::kDrillingStabilization * s.G * s.t;
  const double m0 = s.rho * s.t + s.nsm;
  const double m2 = s.rho * s.t * s.t * s.t / 12.0;

  // natural coordinates r, s: N = (1 - r - s, r, s); J rows d/dr, d/ds
  Eigen::Matrix<double, 2, 3> dn;
  dn << -1.0, 1.0, 0.0, -1.0, 0.0, 1.0;
  const Eigen::Matrix2d j = dn * f.xy;
  const Eigen::Matrix2d j_inv = j.inverse();
  const Eigen::Matrix<double, 2, 3> dx = j_inv * dn;  // rows d/dx, d/dy (constant)

  // constant strain membrane over (u_i, v_i)
  Eigen::Matrix<double, 3, 6> bm = Eigen::Matrix<double, 3, 6>::Zero();
  for (int i = 0; i < 3; ++i) {
    bm(0, 2 * i) = dx(0, i);
    bm(1, 2 * i + 1) = dx(1, i);
    bm(2, 2 * i) = dx(1, i);
    bm(2, 2 * i + 1) = dx(0, i);
  }
  const Eigen::Matrix<double, 6, 6> km = bm.transpose() * cm * bm * area;

  // constant curvature over (w, rx, ry) per node; beta_x = ry, beta_y = -rx
  Eigen::Matrix<double, 3, 9> bb = Eigen::Matrix<double, 3, 9>::Zero();
  for (int i = 0; i < 3; ++i) {
    bb(0, 3 * i + 2) = dx(0, i);
    bb(1, 3 * i + 1) = -dx(1, i);
    bb(2, 3 * i + 1) = -dx(0, i);
    bb(2, 3 * i + 2) = dx(1, i);
  }
  Eigen::Matrix<double, 9, 9> kp = bb.transpose() * cb * bb * area;

  // mitc3: covariant shear e_r, e_s tied at (1/2, 0), (0, 1/2), (1/2, 1/2)
  auto covariant = [&](double r, double sc, int dir) {
    const Eigen::Vector3d n(1.0 - r - sc, r, sc);
    Eigen::Matrix<double, 1, 9> row;
    for (int i = 0; i < 3; ++i) {
      row(3 * i) = dn(dir, i);
      row(3 * i + 1) = -n(i) * j(dir, 1);
      row(3 * i + 2) = n(i) * j(dir, 0);
    }
    return row;
  };
  const Eigen::Matrix<double, 1, 9> er1 = covariant(0.5, 0.0, 0);
  const Eigen::Matrix<double, 1, 9> es2 = covariant(0.0, 0.5, 1);
  const Eigen::Matrix<double, 1, 9> er3 = covariant(0.5, 0.5, 0);
  const Eigen::Matrix<double, 1, 9> es3 = covariant(0.5, 0.5, 1);
  // e_r = er1 + c s, e_s = es2 - c r; c from the tangential strain on edge 2-3
  const Eigen::Matrix<double, 1, 9> c = (es2 - er1) - (es3 - er3);
  // 3-point rule at the edge midpoints (exact for the quadratic integrands)
  const double qp[3][2] = {{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}};
  Mat18 kl = Mat18::Zero();
  Mat18 ml = Mat18::Zero();
  Eigen::Matrix<double, 9, 9> dd = Eigen::Matrix<double, 9, 9>::Zero();
  Eigen::Matrix3d nn = Eigen::Matrix3d::Zero();
  for (const auto& p : qp) {
    Eigen::Matrix<double, 2, 9> bn;
    bn.row(0) = er1 + c * p[1];
    bn.row(1) = es2 - c * p[0];
    const Eigen::Matrix<double, 2, 9> bs = j_inv * bn;
    kp += ks * bs.transpose() * bs * (area / 3.0);
    const Eigen::Vector3d n(1.0 - p[0] - p[1], p[0], p[1]);
    // drilling: theta_z - omega over (u, v, rz) per node
    Eigen::Matrix<double, 1, 9> bd;
    for (int i = 0; i < 3; ++i) {
      bd(3 * i) = 0.5 * dx(1, i);
      bd(3 * i + 1) = -0.5 * dx(0, i);
      bd(3 * i + 2) = n(i);
    }
    dd += bd.transpose() * bd * (area / 3.0);
    nn += n * n.transpose() * (area / 3.0);
  }

  // drilling tie at the centroid
  Eigen::Matrix<double, 9, 9> tie;
  {
    Eigen::Matrix<double, 1, 9> bd;
    for (int i = 0; i < 3; ++i) {
      bd(3 * i) = 0.5 * dx(1, i);
      bd(3 * i + 1) = -0.5 * dx(0, i);
      bd(3 * i + 2) = 1.0 / 3.0;
    }
    tie = shell::kDrillingFactor * s.G * s.t * area * bd.transpose() * bd;
  }

  constexpr int kPlate[3] = {2, 3, 4};
  constexpr int kDrill[3] = {0, 1, 5};
  for (int i = 0; i < 3; ++i)
    for (int jn = 0; jn < 3; ++jn) {
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          kl(6 * i + kPlate[a], 6 * jn + kPlate[b]) += kp(3 * i + a, 3 * jn + b);
          kl(6 * i + kDrill[a], 6 * jn + kDrill[b]) +=
              kd * dd(3 * i + a, 3 * jn + b) + tie(3 * i + a, 3 * jn + b);
          ml(6 * i + kDrill[a], 6 * jn + kDrill[b]) += m2 * dd(3 * i + a, 3 * jn + b);
        }
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) kl(6 * i + a, 6 * jn + b) += km(2 * i + a, 2 * jn + b);
      for (int a = 0; a < 3; ++a) ml(6 * i + a, 6 * jn + a) += m0 * nn(i, jn);
      for (int a = 3; a < 5; ++a) ml(6 * i + a, 6 * jn + a) += m2 * nn(i, jn);
    }

  if (in.mass_form == MassForm::kLumped) {
    ml.setZero();
    for (int i = 0; i < 3; ++i) {
      for (int a = 0; a < 3; ++a) ml(6 * i + a, 6 * i + a) = m0 * area / 3.0;
      for (int a = 3; a < 6; ++a) ml(6 * i + a, 6 * i + a) = m2 * area / 3.0;
    }
  }

  shell::ToBasic<3>(f, kl, K);
  shell::ToBasic<3>(f, ml, M);
}

}  // namespace flexmb::fe
