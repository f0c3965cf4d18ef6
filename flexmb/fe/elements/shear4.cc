#include "flexmb/fe/elements/shear4.h"

#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/element_common.h"
#include "flexmb/fe/elements/shell_common.h"

namespace flexmb::fe {
// the panel's helpers (a named namespace: unity builds join element files)
namespace shear4 {

using Mat24 = Eigen::Matrix<double, 24, 24>;

// what stiffness, stress and geometric stiffness share: the frame, the
// area, the panel's shear operator and its compliance
struct Panel {
  shell::LocalFrame<4> frame;
  double t = 0.0, area = 0.0, rho = 0.0, nsm = 0.0;
  Eigen::Vector3d s = Eigen::Vector3d::Zero();  // S in Voigt (Sxx, Syy, Sxy): sigma = tau s
  Eigen::Matrix<double, 1, 8> b;                // g = S : eps_avg over the local (u, v) of the nodes
  double c = 0.0;                               // S : C^-1 : S [1/Pa]
};

Panel Setup(const ElementInput& in) {
  const Element& e = CheckElementNodes(in, 4, "shear panel");
  const ErrorContext ctx = ElementContext(e);
  if (in.shell == nullptr) throw InputError("missing shear panel property (PSHEAR)", ctx);
  if (in.material == nullptr) throw InputError("missing material of the shear panel", ctx);
  const Material& mat = *in.material;
  CheckElasticConstants(mat, ctx);
  Panel p;
  p.t = in.shell->thickness;
  p.rho = mat.rho;
  p.nsm = in.shell->nsm;
  if (!(p.t > 0.0) || !std::isfinite(p.t)) throw InputError("non-positive panel thickness " + std::to_string(p.t), ctx);
  if (!(p.rho >= 0.0) || !(p.nsm >= 0.0) || !std::isfinite(p.rho) || !std::isfinite(p.nsm))
    throw InputError("negative or non-finite density or non-structural mass", ctx);
  p.frame = shell::QuadFrame(in, 0.0);
  const auto& xy = p.frame.xy;
  // area and the exact mean strain: eps_avg = 1/A sum over the edges of
  // sym(u_mean m), m the outward normal times the edge length
  p.b.setZero();
  Eigen::Matrix<double, 3, 8> mean = Eigen::Matrix<double, 3, 8>::Zero();
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const Eigen::Vector2d d = xy.row(j) - xy.row(i);
    p.area += 0.5 * (xy(i, 0) * xy(j, 1) - xy(j, 0) * xy(i, 1));
    const double mx = d.y(), my = -d.x();
    for (int k : {i, j}) {
      mean(0, 2 * k) += 0.5 * mx;
      mean(1, 2 * k + 1) += 0.5 * my;
      mean(2, 2 * k) += 0.5 * my;
      mean(2, 2 * k + 1) += 0.5 * mx;
    }
  }
  mean /= p.area;
  // the edge pairs' mean directions
  const Eigen::Vector2d da = (xy.row(1) - xy.row(0) + xy.row(2) - xy.row(3)).transpose().normalized();
  const Eigen::Vector2d db = (xy.row(3) - xy.row(0) + xy.row(2) - xy.row(1)).transpose().normalized();
  p.s = Eigen::Vector3d(2 * da.x() * db.x(), 2 * da.y() * db.y(), da.x() * db.y() + da.y() * db.x());
  // g = S : eps with engineering shear: Sxx exx + Syy eyy + Sxy gamma
  p.b = p.s.transpose() * mean;
  const double G = mat.G > 0.0 ? mat.G : mat.E / (2.0 * (1.0 + mat.nu));
  Eigen::Matrix3d compliance;
  compliance << 1.0 / mat.E, -mat.nu / mat.E, 0.0, -mat.nu / mat.E, 1.0 / mat.E, 0.0, 0.0, 0.0, 1.0 / G;
  p.c = p.s.dot(compliance * p.s);
  return p;
}

// the local (u, v) of the nodes (8) from the element DOF (24, basic)
Eigen::Matrix<double, 8, 24> InPlane(const Panel& p) {
  const Mat24 t = shell::LocalTransform<4>(p.frame);
  Eigen::Matrix<double, 8, 24> r;
  for (int k = 0; k < 4; ++k) {
    r.row(2 * k) = t.row(6 * k);
    r.row(2 * k + 1) = t.row(6 * k + 1);
  }
  return r;
}

// bilinear shape functions at (xi, eta) and their derivatives over xi, eta
void Bilinear(double xi, double eta, Eigen::Vector4d& n, Eigen::Matrix<double, 2, 4>& dn) {
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int i = 0; i < 4; ++i) {
    n(i) = 0.25 * (1 + xi * sx[i]) * (1 + eta * sy[i]);
    dn(0, i) = 0.25 * sx[i] * (1 + eta * sy[i]);
    dn(1, i) = 0.25 * sy[i] * (1 + xi * sx[i]);
  }
}

// calls f(N, dN/dx (local), weight * det J) at the 2 x 2 Gauss points
template <class F>
void Gauss(const Panel& p, F&& f) {
  const double g = 1.0 / std::sqrt(3.0);
  Eigen::Vector4d n;
  Eigen::Matrix<double, 2, 4> dn;
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      Bilinear(xi, eta, n, dn);
      const Eigen::Matrix2d jac = dn * p.frame.xy;  // d(x, y) / d(xi, eta), transposed
      const Eigen::Matrix<double, 2, 4> dx = jac.inverse() * dn;
      f(n, dx, jac.determinant());
    }
}

}  // namespace shear4

using shear4::Mat24;
using shear4::Panel;

void Shear4Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const Panel p = shear4::Setup(in);
  const Eigen::Matrix<double, 8, 24> r = shear4::InPlane(p);
  const Eigen::Matrix<double, 1, 24> g = p.b * r;
  K = (p.t * p.area / p.c) * g.transpose() * g;
  // lumped translational mass: (rho t + nsm) int N_i dA per corner, in
  // every direction (rigid offsets to warped corners carry none)
  M = MatX::Zero(24, 24);
  Eigen::Vector4d share = Eigen::Vector4d::Zero();
  shear4::Gauss(p, [&](const Eigen::Vector4d& n, const Eigen::Matrix<double, 2, 4>&, double w) { share += n * w; });
  const double m0 = p.rho * p.t + p.nsm;
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 3; ++a) M(6 * k + a, 6 * k + a) = m0 * share(k);
}

void Shear4Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) {
  const Panel p = shear4::Setup(in);
  // sigma = tau s, tau = g / c
  const Eigen::Matrix<double, 3, 24> sigma = p.s * (p.b * shear4::InPlane(p)) / p.c;
  S.resize(6, 24);
  S.topRows<3>() = sigma;
  S.bottomRows<3>() = sigma;
  axes = p.frame.R;
}

void Shear4GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const Panel p = shear4::Setup(in);
  const double tau = (p.b * (shear4::InPlane(p) * u))(0) / p.c;
  Eigen::Matrix2d sigma;
  sigma << p.s(0), p.s(2), p.s(2), p.s(1);
  sigma *= tau;
  Mat24 local = Mat24::Zero();
  shear4::Gauss(p, [&](const Eigen::Vector4d&, const Eigen::Matrix<double, 2, 4>& dx, double w) {
    const Eigen::Matrix4d k = p.t * w * dx.transpose() * sigma * dx;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int a = 0; a < 3; ++a) local(6 * i + a, 6 * j + a) += k(i, j);
  });
  shell::ToBasic<4>(p.frame, local, KG);
}

}  // namespace flexmb::fe
