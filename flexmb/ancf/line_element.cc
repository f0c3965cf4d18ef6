#include "flexmb/ancf/line_element.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"

namespace flexmb::ancf {

namespace {

// gauss-legendre nodes and weights on [-1, 1], n = 1..6
constexpr double kX[6][6] = {
    {0.0},
    {-0.5773502691896257, 0.5773502691896257},
    {-0.7745966692414834, 0.0, 0.7745966692414834},
    {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526},
    {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640},
    {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969, 0.2386191860831969,
     0.6612093864662645, 0.9324695142031521}};
constexpr double kW[6][6] = {
    {2.0},
    {1.0, 1.0},
    {0.5555555555555556, 0.8888888888888888, 0.5555555555555556},
    {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538},
    {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
     0.2369268850561891},
    {0.1713244923791704, 0.3607615730481386, 0.4679139345726910, 0.4679139345726910,
     0.3607615730481386, 0.1713244923791704}};

struct Table01 {
  double xi[6][6];
  double w[6][6];
  Table01() {
    for (int n = 0; n < 6; ++n) {
      for (int i = 0; i <= n; ++i) {
        xi[n][i] = 0.5 * (kX[n][i] + 1.0);
        w[n][i] = 0.5 * kW[n][i];
      }
    }
  }
};

const Table01& Table() {
  static const Table01 table;
  return table;
}

// c_k = a^T A_k b: the k-th component of a x b (the scalar cross product in 2D)
template <int D>
Eigen::Matrix<double, D, D> CrossMatrix(int k) {
  Eigen::Matrix<double, D, D> A = Eigen::Matrix<double, D, D>::Zero();
  if constexpr (D == 2) {
    A(0, 1) = 1.0;
    A(1, 0) = -1.0;
  } else {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    A(i, j) = 1.0;
    A(j, i) = -1.0;
  }
  return A;
}

// D x 4D shape matrix from the 4 scalar Hermite functions (or derivatives)
template <int D>
Eigen::Matrix<double, D, 4 * D> Expand(const double (&s)[4]) {
  Eigen::Matrix<double, D, 4 * D> S = Eigen::Matrix<double, D, 4 * D>::Zero();
  for (int a = 0; a < 4; ++a) {
    for (int d = 0; d < D; ++d) S(d, a * D + d) = s[a];
  }
  return S;
}

// K -= (x y^T) (x) G, block by block (x, y: 4 scalar shape values each)
template <int D, class MatK>
void AddShapeProduct(MatK& K, const double (&x)[4], const double (&y)[4], const Eigen::Matrix<double, D, D>& G) {
  for (int q = 0; q < 4; ++q)
    for (int p = 0; p < 4; ++p) K.template block<D, D>(D * p, D * q) -= (x[p] * y[q]) * G;
}

// K -= (x x^T) (x) Gxx + (x y^T) (x) Gxy + (y x^T) (x) Gyx + (y y^T) (x) Gyy
template <int D, class MatK>
void AddShapeProducts(MatK& K, const double (&x)[4], const double (&y)[4], const Eigen::Matrix<double, D, D>& Gxx,
                      const Eigen::Matrix<double, D, D>& Gxy, const Eigen::Matrix<double, D, D>& Gyx,
                      const Eigen::Matrix<double, D, D>& Gyy) {
  for (int q = 0; q < 4; ++q)
    for (int p = 0; p < 4; ++p)
      K.template block<D, D>(D * p, D * q) -=
          (x[p] * x[q]) * Gxx + (x[p] * y[q]) * Gxy + (y[p] * x[q]) * Gyx + (y[p] * y[q]) * Gyy;
}

}  // namespace

void GaussPoints01(int n, const double*& xi, const double*& w) {
  if (n < 1 || n > 6) {
    throw InputError("Gauss quadrature order " + std::to_string(n) + " is not in 1..6");
  }
  xi = Table().xi[n - 1];
  w = Table().w[n - 1];
}

template <int D>
LineElement<D>::LineElement(double length, const BeamSection& section, const QuadratureOrder& order)
    : length_(length), section_(section), order_(order) {
  if (!(length > 0.0)) throw InputError("ANCF element length must be positive");
  if (!(section.E > 0.0)) throw InputError("ANCF element Young's modulus E must be positive");
  if (!(section.A > 0.0)) throw InputError("ANCF element section area A must be positive");
  if (!(section.I > 0.0)) throw InputError("ANCF element second moment of area I must be positive");
  if (!(section.rho > 0.0)) throw InputError("ANCF element density rho must be positive");
  if (!(section.damping >= 0.0)) throw InputError("ANCF element damping must not be negative");
  const double* xi = nullptr;
  const double* w = nullptr;
  GaussPoints01(order.axial, xi, w);
  GaussPoints01(order.bending, xi, w);
  GaussPoints01(order.axial_full_points, xi, w);
  if (!(order.hourglass >= 0.0) || !std::isfinite(order.hourglass))
    throw InputError("ANCF element: the hourglass control factor must not be negative");
  axial_full_ = std::min(1.0, order.hourglass * section.I / (section.A * length * length));
  if (order.axial == order.axial_full_points) axial_full_ = 0.0;
  // the kernels' point tables: shape slopes and curvatures, weighted stiffness
  const auto scalar = [](const ShapeMat& S, double (&out)[4]) {
    for (int a = 0; a < 4; ++a) out[a] = S(0, D * a);
  };
  ForEachAxialPoint([&](double x, double EA) {
    AxialPoint& pt = axial_pts_[n_axial_++];
    pt.k = EA;
    scalar(ShapeSlope(x), pt.sx);
  });
  ForEachBendingPoint([&](double x, double EI) {
    BendingPoint& pt = bending_pts_[n_bending_++];
    pt.k = EI;
    scalar(ShapeSlope(x), pt.sx);
    scalar(ShapeCurvature(x), pt.sxx);
  });
  // S^T S is of degree 6 in xi: 4 points are exact
  GaussPoints01(4, xi, w);
  mass_.setZero();
  for (int g = 0; g < 4; ++g) {
    const ShapeMat S = Shape(xi[g]);
    mass_.noalias() += (w[g] * length_ * section_.rho * section_.A) * S.transpose() * S;
  }
}

template <int D>
typename LineElement<D>::ShapeMat LineElement<D>::Shape(double x) const {
  const double L = length_;
  const double s[4] = {1.0 - 3.0 * x * x + 2.0 * x * x * x, L * (x - 2.0 * x * x + x * x * x),
                       3.0 * x * x - 2.0 * x * x * x, L * (x * x * x - x * x)};
  return Expand<D>(s);
}

template <int D>
typename LineElement<D>::ShapeMat LineElement<D>::ShapeSlope(double x) const {
  const double L = length_;
  const double s[4] = {(-6.0 * x + 6.0 * x * x) / L, 1.0 - 4.0 * x + 3.0 * x * x,
                       (6.0 * x - 6.0 * x * x) / L, 3.0 * x * x - 2.0 * x};
  return Expand<D>(s);
}

template <int D>
typename LineElement<D>::ShapeMat LineElement<D>::ShapeCurvature(double x) const {
  const double L = length_;
  const double s[4] = {(-6.0 + 12.0 * x) / (L * L), (-4.0 + 6.0 * x) / L,
                       (6.0 - 12.0 * x) / (L * L), (6.0 * x - 2.0) / L};
  return Expand<D>(s);
}

template <int D>
double LineElement<D>::AxialStrain(const Vec& e, double xi) const {
  const double l = (ShapeSlope(xi) * e).norm();
  if (section_.axial_strain == AxialStrainMeasure::kGreenLagrange) return 0.5 * (l * l - 1.0);
  return l - 1.0;
}

template <int D>
typename LineElement<D>::VecK LineElement<D>::Curvature(const Vec& e, double xi) const {
  const VecD a = ShapeSlope(xi) * e;
  const VecD b = ShapeCurvature(xi) * e;
  VecK k;
  for (int c = 0; c < kCurv; ++c) k(c) = a.dot(CrossMatrix<D>(c) * b) / a.squaredNorm();
  return k;
}

template <int D>
template <class F>
void LineElement<D>::ForEachAxialPoint(F&& f) const {
  const double* xi = nullptr;
  const double* w = nullptr;
  for (int rule = 0; rule < 2; ++rule) {
    const int np = rule == 0 ? order_.axial : order_.axial_full_points;
    const double frac = rule == 0 ? 1.0 - axial_full_ : axial_full_;
    if (frac == 0.0) continue;
    GaussPoints01(np, xi, w);
    for (int g = 0; g < np; ++g) f(xi[g], frac * w[g] * length_ * section_.E * section_.A);
  }
}

template <int D>
template <class F>
void LineElement<D>::ForEachBendingPoint(F&& f) const {
  const double* xi = nullptr;
  const double* w = nullptr;
  GaussPoints01(order_.bending, xi, w);
  for (int g = 0; g < order_.bending; ++g) f(xi[g], w[g] * length_ * section_.E * section_.I);
}

template <int D>
double LineElement<D>::StrainEnergy(const Vec& e) const {
  double W = 0.0;
  ForEachAxialPoint([&](double xi, double EA) {
    const double eps = AxialStrain(e, xi);
    W += 0.5 * EA * eps * eps;
  });
  ForEachBendingPoint([&](double xi, double EI) {
    W += 0.5 * EI * (Curvature(e, xi) - kappa0_).squaredNorm();
  });
  return W;
}

// The element kernels below use the structure of the shape matrices,
// S(xi) = s(xi)^T (x) I_D with the 4 scalar Hermite functions s: the slope
// a = r' = E s' and b = r'' = E s'' (E the D x 4 matrix of nodal vectors),
// every strain gradient is s' (x) alpha + s'' (x) gamma with D-vectors alpha,
// gamma, and every Hessian a sum of (x y^T) (x) G over x, y in {s', s''}
// with D x D blocks G. The element tangent is assembled from these D x D
// blocks instead of products of zero-padded D x 4D shape matrices (issue
// 23; docs/design.md "ANCF element kernel"). StrainEnergy, AxialStrain and
// Curvature keep the plain formulas: the tests check the kernels against them.

template <int D>
void LineElement<D>::AddInternalForces(const Vec& e, const Vec& edot, Vec& Q, Mat& dQde,
                                       Mat& dQdedot) const {
  using MatDD = Eigen::Matrix<double, D, D>;
  using Vec4 = Eigen::Matrix<double, 4, 1>;
  const Eigen::Map<const Eigen::Matrix<double, D, 4>> E(e.data()), Ed(edot.data());
  const double beta = section_.damping;
  const bool damped = beta > 0.0;
  const MatDD I = MatDD::Identity();
  const MatDD Z = MatDD::Zero();
  const VecD zero = VecD::Zero();
  for (int g = 0; g < n_axial_; ++g) {
    const AxialPoint& pt = axial_pts_[g];
    const Eigen::Map<const Vec4> sx(pt.sx);
    const VecD a = E * sx;
    const VecD ad = damped ? VecD(Ed * sx) : zero;
    const double k = pt.k;
    const double gg = a.squaredNorm();
    MatDD G;
    VecD f;
    if (section_.axial_strain == AxialStrainMeasure::kGreenLagrange) {
      // eps = (|a|^2 - 1) / 2: d1 = s' (x) a, d2 = (s' s'^T) (x) I
      const double c2 = k * (0.5 * (gg - 1.0) + beta * a.dot(ad));
      f = c2 * a;
      G.noalias() = k * a * a.transpose();
      G += c2 * I;
      if (damped) G.noalias() += (beta * k) * a * ad.transpose();
      if (damped) AddShapeProduct(dQdedot, pt.sx, pt.sx, MatDD((beta * k) * a * a.transpose()));
    } else {
      // eps = |a| - 1: d1 = s' (x) n, d2 = (s' s'^T) (x) (I - n n^T) / |a|
      const double l = std::sqrt(gg);
      if (!(l > 0.0)) throw NumericalError("ANCF element slope r' vanished (element collapsed)");
      const VecD n = a / l;
      const double c2 = k * (l - 1.0 + beta * n.dot(ad));
      f = c2 * n;
      const MatDD nn = n * n.transpose();
      G = k * nn + (c2 / l) * (I - nn);
      if (damped) {
        const VecD w = (ad - n * n.dot(ad)) / l;  // d2 edot = s' (x) w
        G.noalias() += (beta * k) * n * w.transpose();
        AddShapeProduct(dQdedot, pt.sx, pt.sx, MatDD((beta * k) * nn));
      }
    }
    for (int p = 0; p < 4; ++p) Q.template segment<D>(D * p) -= pt.sx[p] * f;
    AddShapeProduct(dQde, pt.sx, pt.sx, G);
  }
  for (int g = 0; g < n_bending_; ++g) {
    const BendingPoint& pt = bending_pts_[g];
    const Eigen::Map<const Vec4> sx(pt.sx), sxx(pt.sxx);
    const VecD a = E * sx;
    const VecD b = E * sxx;
    const VecD ad = damped ? VecD(Ed * sx) : zero;
    const VecD bd = damped ? VecD(Ed * sxx) : zero;
    const double gg = a.squaredNorm();
    if (!(gg > 0.0)) throw NumericalError("ANCF element slope r' vanished (element collapsed)");
    const double K = pt.k;
    VecD fa = zero, fb = zero;
    MatDD Gss = Z, Gsx = Z, Gxs = Z, Gxx = Z, Css = Z, Csx = Z, Cxs = Z, Cxx = Z;
    for (int k = 0; k < kCurv; ++k) {
      // kappa = c / g with c = a . A b, g = a . a; d kappa/de = s' (x) alpha + s'' (x) gamma
      const MatDD A = CrossMatrix<D>(k);
      const VecD Ab = A * b;
      const double c = a.dot(Ab);
      const VecD alpha = Ab / gg - (2.0 * c / (gg * gg)) * a;
      const VecD gamma = A.transpose() * a / gg;
      // Hessian: (s' s'^T) (x) Hss + (s' s''^T) (x) Hsx + (s'' s'^T) (x) Hsx^T
      MatDD Hss = (-2.0 / gg) * (alpha * a.transpose() + a * alpha.transpose());
      Hss.diagonal().array() -= 2.0 * c / (gg * gg);
      const MatDD Hsx = (A - 2.0 * a * gamma.transpose()) / gg;
      const double rate = damped ? alpha.dot(ad) + gamma.dot(bd) : 0.0;
      const double c2 = K * (c / gg - kappa0_(k) + beta * rate);
      fa += c2 * alpha;
      fb += c2 * gamma;
      Gss.noalias() += K * alpha * alpha.transpose();
      Gsx.noalias() += K * alpha * gamma.transpose();
      Gxs.noalias() += K * gamma * alpha.transpose();
      Gxx.noalias() += K * gamma * gamma.transpose();
      Gss += c2 * Hss;
      Gsx += c2 * Hsx;
      Gxs += c2 * Hsx.transpose();
      if (damped) {
        const double bk = beta * K;
        const VecD w1 = Hss * ad + Hsx * bd;  // d2 edot = s' (x) w1 + s'' (x) w2
        const VecD w2 = Hsx.transpose() * ad;
        Gss.noalias() += bk * alpha * w1.transpose();
        Gsx.noalias() += bk * alpha * w2.transpose();
        Gxs.noalias() += bk * gamma * w1.transpose();
        Gxx.noalias() += bk * gamma * w2.transpose();
        Css.noalias() += bk * alpha * alpha.transpose();
        Csx.noalias() += bk * alpha * gamma.transpose();
        Cxs.noalias() += bk * gamma * alpha.transpose();
        Cxx.noalias() += bk * gamma * gamma.transpose();
      }
    }
    for (int p = 0; p < 4; ++p) Q.template segment<D>(D * p) -= pt.sx[p] * fa + pt.sxx[p] * fb;
    AddShapeProducts(dQde, pt.sx, pt.sxx, Gss, Gsx, Gxs, Gxx);
    if (damped) AddShapeProducts(dQdedot, pt.sx, pt.sxx, Css, Csx, Cxs, Cxx);
  }
}

template <int D>
void LineElement<D>::AddInternalForceVector(const Vec& e, const Vec& edot, Vec& Q) const {
  using Vec4 = Eigen::Matrix<double, 4, 1>;
  const Eigen::Map<const Eigen::Matrix<double, D, 4>> E(e.data()), Ed(edot.data());
  const double beta = section_.damping;
  const bool damped = beta > 0.0;
  const bool gl = section_.axial_strain == AxialStrainMeasure::kGreenLagrange;
  for (int g = 0; g < n_axial_; ++g) {
    const AxialPoint& pt = axial_pts_[g];
    const Eigen::Map<const Vec4> sx(pt.sx);
    const VecD a = E * sx;
    const double gg = a.squaredNorm();
    VecD f;
    if (gl) {
      f = pt.k * (0.5 * (gg - 1.0) + (damped ? beta * a.dot(Ed * sx) : 0.0)) * a;
    } else {
      const double l = std::sqrt(gg);
      if (!(l > 0.0)) throw NumericalError("ANCF element slope r' vanished (element collapsed)");
      const VecD n = a / l;
      f = pt.k * (l - 1.0 + (damped ? beta * n.dot(Ed * sx) : 0.0)) * n;
    }
    for (int p = 0; p < 4; ++p) Q.template segment<D>(D * p) -= pt.sx[p] * f;
  }
  for (int g = 0; g < n_bending_; ++g) {
    const BendingPoint& pt = bending_pts_[g];
    const Eigen::Map<const Vec4> sx(pt.sx), sxx(pt.sxx);
    const VecD a = E * sx;
    const VecD b = E * sxx;
    const double gg = a.squaredNorm();
    if (!(gg > 0.0)) throw NumericalError("ANCF element slope r' vanished (element collapsed)");
    VecD fa = VecD::Zero(), fb = VecD::Zero();
    for (int k = 0; k < kCurv; ++k) {
      const Eigen::Matrix<double, D, D> A = CrossMatrix<D>(k);
      const VecD Ab = A * b;
      const double c = a.dot(Ab);
      const VecD alpha = Ab / gg - (2.0 * c / (gg * gg)) * a;
      const VecD gamma = A.transpose() * a / gg;
      const double rate = damped ? alpha.dot(Ed * sx) + gamma.dot(Ed * sxx) : 0.0;
      const double c2 = pt.k * (c / gg - kappa0_(k) + beta * rate);
      fa += c2 * alpha;
      fb += c2 * gamma;
    }
    for (int p = 0; p < 4; ++p) Q.template segment<D>(D * p) -= pt.sx[p] * fa + pt.sxx[p] * fb;
  }
}

template <int D>
typename LineElement<D>::Vec LineElement<D>::DistributedLoad(const VecD& f) const {
  const double* xi = nullptr;
  const double* w = nullptr;
  // S is cubic: 2 points are exact
  GaussPoints01(2, xi, w);
  Vec Q = Vec::Zero();
  for (int g = 0; g < 2; ++g) Q.noalias() += (w[g] * length_) * Shape(xi[g]).transpose() * f;
  return Q;
}

template <int D>
typename LineElement<D>::Vec LineElement<D>::StraightCoordinates(const VecD& p0,
                                                                 const VecD& dir) const {
  Vec e;
  e.template segment<D>(0) = p0;
  e.template segment<D>(D) = dir;
  e.template segment<D>(2 * D) = p0 + length_ * dir;
  e.template segment<D>(3 * D) = dir;
  return e;
}

template class LineElement<2>;
template class LineElement<3>;

}  // namespace flexmb::ancf
