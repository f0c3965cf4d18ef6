#include "flexmb/fe/elements/shell_quad4.h"

#include <Eigen/Dense>
#include <cmath>

#include "flexmb/fe/elements/shell_common.h"

namespace flexmb::fe {
namespace {

using Mat24 = Eigen::Matrix<double, 24, 24>;
using Mat2x4 = Eigen::Matrix<double, 2, 4>;

constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};

// bilinear shape functions and their natural derivatives (rows d/dxi, d/deta)
void Shape(double xi, double eta, Eigen::Vector4d& n, Mat2x4& dn) {
  for (int i = 0; i < 4; ++i) {
    n(i) = 0.25 * (1.0 + xi * kXi[i]) * (1.0 + eta * kEta[i]);
    dn(0, i) = 0.25 * kXi[i] * (1.0 + eta * kEta[i]);
    dn(1, i) = 0.25 * kEta[i] * (1.0 + xi * kXi[i]);
  }
}

// mean-plane frame, projected coordinates and rigid offsets of the nodes
shell::LocalFrame<4> Frame(const ElementInput& in, const shell::ShellData& s) {
  const ErrorContext ctx = shell::Context(*in.element);
  const Vec3* x = in.x;
  double max_edge = 0.0, min_edge = INFINITY;
  for (int i = 0; i < 4; ++i) {
    const double len = (x[(i + 1) % 4] - x[i]).norm();
    max_edge = std::max(max_edge, len);
    min_edge = std::min(min_edge, len);
  }
  if (!(min_edge > 1e-8 * max_edge)) throw InputError("coincident nodes", ctx);
  const Vec3 c = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  const Vec3 n_raw = (x[2] - x[0]).cross(x[3] - x[1]);
  const double area = 0.5 * n_raw.norm();
  if (!(area > 1e-10 * max_edge * max_edge)) throw InputError("zero area", ctx);
  const Vec3 e3 = n_raw.normalized();
  Vec3 e1 = (x[1] - x[0]) - e3 * e3.dot(x[1] - x[0]);
  e1.normalize();
  const Vec3 e2 = e3.cross(e1);
  shell::LocalFrame<4> f;
  f.R.col(0) = e1;
  f.R.col(1) = e2;
  f.R.col(2) = e3;
  double warp = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Vec3 r = x[i] - c;
    const double h = e3.dot(r);
    warp = std::max(warp, std::abs(h));
    f.xy(i, 0) = e1.dot(r);
    f.xy(i, 1) = e2.dot(r);
    f.d.col(i) = (s.offset - h) * e3;
  }
  if (warp > shell::kMaxWarpRatio * std::sqrt(area))
    throw InputError("badly warped quad: corner " + std::to_string(warp) +
                         " off the mean plane, limit " + std::to_string(shell::kMaxWarpRatio) +
                         " * sqrt(area)",
                     ctx);
  // convex, positively ordered: every corner turns the same way
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d a = f.xy.row((i + 1) % 4) - f.xy.row(i);
    const Eigen::Vector2d b = f.xy.row((i + 3) % 4) - f.xy.row(i);
    if (!(a.x() * b.y() - a.y() * b.x() > 1e-6 * area))
      throw InputError("non-convex or degenerate quad at its node " + std::to_string(i + 1), ctx);
  }
  return f;
}

}  // namespace

void ShellQuad4Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const shell::ShellData s = shell::CheckShellInput(in, 4);
  const shell::LocalFrame<4> f = Frame(in, s);
  const Eigen::Matrix3d cm = shell::MembraneMatrix(s);
  const Eigen::Matrix3d cb = shell::BendingMatrix(s);
  const double ks = shell::kShearFactor * s.G * s.t;
  const double kd = shell::kDrillingStabilization * s.G * s.t;
  const double m0 = s.rho * s.t + s.nsm;
  const double m2 = s.rho * s.t * s.t * s.t / 12.0;
  const Eigen::Matrix<double, 4, 2> xy = f.xy;

  Eigen::Vector4d n;
  Mat2x4 dn;
  Shape(0.0, 0.0, n, dn);
  const Eigen::Matrix2d j0 = dn * xy;
  const Eigen::Matrix2d j0_inv = j0.inverse();
  const double det0 = j0.determinant();

  // mitc4 tying points: A (0, 1), C (0, -1) for e_xi; B (-1, 0), D (1, 0) for e_eta;
  // rows of each: covariant strain over node (w, rx, ry)
  Eigen::Matrix<double, 4, 12> tie = Eigen::Matrix<double, 4, 12>::Zero();
  const double tp[4][2] = {{0.0, 1.0}, {0.0, -1.0}, {-1.0, 0.0}, {1.0, 0.0}};
  for (int k = 0; k < 4; ++k) {
    Shape(tp[k][0], tp[k][1], n, dn);
    const Eigen::Matrix2d j = dn * xy;
    const int dir = k < 2 ? 0 : 1;
    for (int i = 0; i < 4; ++i) {
      // beta_x = ry, beta_y = -rx; e = dw/ds + beta . dx/ds
      tie(k, 3 * i + 0) = dn(dir, i);
      tie(k, 3 * i + 1) = -n(i) * j(dir, 1);
      tie(k, 3 * i + 2) = n(i) * j(dir, 0);
    }
  }

  Eigen::Matrix<double, 8, 8> kcc = Eigen::Matrix<double, 8, 8>::Zero();
  Eigen::Matrix<double, 8, 4> kci = Eigen::Matrix<double, 8, 4>::Zero();
  Eigen::Matrix4d kii = Eigen::Matrix4d::Zero();
  Mat24 kl = Mat24::Zero();
  Mat24 ml = Mat24::Zero();
  const double g = 1.0 / std::sqrt(3.0);
  for (int gp = 0; gp < 4; ++gp) {
    const double xi = kXi[gp] * g, eta = kEta[gp] * g;
    Shape(xi, eta, n, dn);
    const Eigen::Matrix2d j = dn * xy;
    const double det = j.determinant();
    if (!(det > 0.0)) throw InputError("inverted quad (negative Jacobian)", shell::Context(*in.element));
    const Eigen::Matrix2d j_inv = j.inverse();
    const Mat2x4 dx = j_inv * dn;  // rows d/dx, d/dy

    // membrane: compatible part over (u_i, v_i) ordered u1 v1 u2 v2 ...
    Eigen::Matrix<double, 3, 8> bm = Eigen::Matrix<double, 3, 8>::Zero();
    for (int i = 0; i < 4; ++i) {
      bm(0, 2 * i) = dx(0, i);
      bm(1, 2 * i + 1) = dx(1, i);
      bm(2, 2 * i) = dx(1, i);
      bm(2, 2 * i + 1) = dx(0, i);
    }
    // incompatible modes (1 - xi^2), (1 - eta^2) in u and v, with J0 and det0 / det
    Eigen::Matrix2d dp;
    dp << -2.0 * xi, 0.0, 0.0, -2.0 * eta;
    const Eigen::Matrix2d dpx = j0_inv * dp * (det0 / det);  // rows d/dx, d/dy; cols mode
    Eigen::Matrix<double, 3, 4> bi = Eigen::Matrix<double, 3, 4>::Zero();
    for (int a = 0; a < 2; ++a) {
      bi(0, a) = dpx(0, a);
      bi(1, 2 + a) = dpx(1, a);
      bi(2, a) = dpx(1, a);
      bi(2, 2 + a) = dpx(0, a);
    }
    kcc += bm.transpose() * cm * bm * det;
    kci += bm.transpose() * cm * bi * det;
    kii += bi.transpose() * cm * bi * det;

    // bending over (w, rx, ry) per node
    Eigen::Matrix<double, 3, 12> bb = Eigen::Matrix<double, 3, 12>::Zero();
    for (int i = 0; i < 4; ++i) {
      bb(0, 3 * i + 2) = dx(0, i);
      bb(1, 3 * i + 1) = -dx(1, i);
      bb(2, 3 * i + 1) = -dx(0, i);
      bb(2, 3 * i + 2) = dx(1, i);
    }
    // assumed covariant shear, then cartesian: gamma = J^-1 e
    Eigen::Matrix<double, 2, 12> bn;
    bn.row(0) = 0.5 * (1.0 + eta) * tie.row(0) + 0.5 * (1.0 - eta) * tie.row(1);
    bn.row(1) = 0.5 * (1.0 - xi) * tie.row(2) + 0.5 * (1.0 + xi) * tie.row(3);
    const Eigen::Matrix<double, 2, 12> bs = j_inv * bn;
    const Eigen::Matrix<double, 12, 12> kp =
        (bb.transpose() * cb * bb + ks * bs.transpose() * bs) * det;

    // drilling: theta_z - omega over (u, v, rz) per node
    Eigen::Matrix<double, 1, 12> bd;
    for (int i = 0; i < 4; ++i) {
      bd(3 * i) = 0.5 * dx(1, i);
      bd(3 * i + 1) = -0.5 * dx(0, i);
      bd(3 * i + 2) = n(i);
    }
    const Eigen::Matrix<double, 12, 12> dd = bd.transpose() * bd * det;

    constexpr int kPlate[3] = {2, 3, 4};
    constexpr int kDrill[3] = {0, 1, 5};
    for (int i = 0; i < 4; ++i)
      for (int jn = 0; jn < 4; ++jn)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) {
            kl(6 * i + kPlate[a], 6 * jn + kPlate[b]) += kp(3 * i + a, 3 * jn + b);
            kl(6 * i + kDrill[a], 6 * jn + kDrill[b]) += kd * dd(3 * i + a, 3 * jn + b);
            ml(6 * i + kDrill[a], 6 * jn + kDrill[b]) += m2 * dd(3 * i + a, 3 * jn + b);
          }

    // mass: translations and the two bending rotations
    const Eigen::Matrix4d nn = n * n.transpose() * det;
    for (int i = 0; i < 4; ++i)
      for (int jn = 0; jn < 4; ++jn) {
        for (int a = 0; a < 3; ++a) ml(6 * i + a, 6 * jn + a) += m0 * nn(i, jn);
        for (int a = 3; a < 5; ++a) ml(6 * i + a, 6 * jn + a) += m2 * nn(i, jn);
      }
  }

  // drilling tie at the centroid
  {
    Shape(0.0, 0.0, n, dn);
    const Mat2x4 dx = j0_inv * dn;
    Eigen::Matrix<double, 1, 12> bd;
    for (int i = 0; i < 4; ++i) {
      bd(3 * i) = 0.5 * dx(1, i);
      bd(3 * i + 1) = -0.5 * dx(0, i);
      bd(3 * i + 2) = n(i);
    }
    const Eigen::Matrix<double, 12, 12> dd =
        bd.transpose() * bd * (4.0 * det0 * shell::kDrillingFactor * s.G * s.t);
    constexpr int kDrill[3] = {0, 1, 5};
    for (int i = 0; i < 4; ++i)
      for (int jn = 0; jn < 4; ++jn)
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) kl(6 * i + kDrill[a], 6 * jn + kDrill[b]) += dd(3 * i + a, 3 * jn + b);
  }

  // condense the incompatible modes
  const Eigen::Matrix<double, 8, 8> km = kcc - kci * kii.ldlt().solve(kci.transpose());
  for (int i = 0; i < 4; ++i)
    for (int jn = 0; jn < 4; ++jn)
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) kl(6 * i + a, 6 * jn + b) += km(2 * i + a, 2 * jn + b);

  if (in.mass_form == MassForm::kLumped) {
    // area shares int N_i dA; translations and all rotations diagonal
    Eigen::Vector4d share = Eigen::Vector4d::Zero();
    for (int gp = 0; gp < 4; ++gp) {
      Shape(kXi[gp] * g, kEta[gp] * g, n, dn);
      share += n * (dn * xy).determinant();
    }
    ml.setZero();
    for (int i = 0; i < 4; ++i) {
      for (int a = 0; a < 3; ++a) ml(6 * i + a, 6 * i + a) = m0 * share(i);
      for (int a = 3; a < 6; ++a) ml(6 * i + a, 6 * i + a) = m2 * share(i);
    }
  }

  shell::ToBasic<4>(f, kl, K);
  shell::ToBasic<4>(f, ml, M);
}

}  // namespace flexmb::fe
