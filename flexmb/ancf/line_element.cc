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
void LineElement<D>::BendingTerms(const ShapeMat& Sx, const ShapeMat& Sxx, const Vec& e, int k,
                                  double& kap, Vec& dkap, Mat& ddkap) const {
  const Eigen::Matrix<double, D, D> A = CrossMatrix<D>(k);
  const VecD a = Sx * e;
  const VecD b = Sxx * e;
  const double g = a.squaredNorm();
  if (!(g > 0.0)) throw NumericalError("ANCF element slope r' vanished (element collapsed)");
  const double c = a.dot(A * b);
  const Vec dc = Sx.transpose() * (A * b) + Sxx.transpose() * (A.transpose() * a);
  const Vec dg = 2.0 * Sx.transpose() * a;
  kap = c / g;
  dkap = dc / g - (c / (g * g)) * dg;
  const Eigen::Matrix<double, D, kDof> ASxx = A * Sxx;
  ddkap.noalias() = Sx.transpose() * ASxx / g;
  ddkap.noalias() += ASxx.transpose() * Sx / g;
  ddkap.noalias() -= (dc * dg.transpose() + dg * dc.transpose()) / (g * g);
  ddkap.noalias() -= (2.0 * c / (g * g)) * Sx.transpose() * Sx;
  ddkap.noalias() += (2.0 * c / (g * g * g)) * dg * dg.transpose();
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
void LineElement<D>::AddStrainTerm(double stiffness, double strain, const Vec& d1, const Mat& d2,
                                   const Vec& edot, Vec& Q, Mat& dQde, Mat& dQdedot) const {
  AddAncfStrainTerm<kDof>(stiffness, section_.damping, strain, d1, d2, edot, Q, dQde, dQdedot);
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

template <int D>
void LineElement<D>::AddInternalForces(const Vec& e, const Vec& edot, Vec& Q, Mat& dQde,
                                       Mat& dQdedot) const {
  double val = 0.0;
  Vec d1;
  Mat d2;
  ForEachAxialPoint([&](double xi, double EA) {
    val = AncfAxialStrainTerms<D, kDof>(section_.axial_strain, ShapeSlope(xi), e, d1, d2);
    AddStrainTerm(EA, val, d1, d2, edot, Q, dQde, dQdedot);
  });
  ForEachBendingPoint([&](double xi, double EI) {
    const ShapeMat Sx = ShapeSlope(xi);
    const ShapeMat Sxx = ShapeCurvature(xi);
    for (int k = 0; k < kCurv; ++k) {
      BendingTerms(Sx, Sxx, e, k, val, d1, d2);
      AddStrainTerm(EI, val - kappa0_(k), d1, d2, edot, Q, dQde, dQdedot);
    }
  });
}

template <int D>
void LineElement<D>::AddInternalForceVector(const Vec& e, const Vec& edot, Vec& Q) const {
  const double beta = section_.damping;
  // Q -= k s ds/de (+ the Kelvin-Voigt term), as AddAncfStrainTerm without tangents
  auto add = [&](double k, double s, const Vec& d1) {
    Q.noalias() -= (k * s) * d1;
    if (beta > 0.0) Q.noalias() -= (beta * k * d1.dot(edot)) * d1;
  };
  const bool gl = section_.axial_strain == AxialStrainMeasure::kGreenLagrange;
  ForEachAxialPoint([&](double xi, double EA) {
    const ShapeMat Sx = ShapeSlope(xi);
    const VecD a = Sx * e;
    const double g = a.squaredNorm();
    if (gl) return add(EA, 0.5 * (g - 1.0), Sx.transpose() * a);
    const double l = std::sqrt(g);
    if (!(l > 0.0)) throw NumericalError("ANCF element slope r' vanished (element collapsed)");
    add(EA, l - 1.0, Sx.transpose() * a / l);
  });
  ForEachBendingPoint([&](double xi, double EI) {
    const ShapeMat Sx = ShapeSlope(xi);
    const ShapeMat Sxx = ShapeCurvature(xi);
    const VecD a = Sx * e;
    const VecD b = Sxx * e;
    const double g = a.squaredNorm();
    if (!(g > 0.0)) throw NumericalError("ANCF element slope r' vanished (element collapsed)");
    const Vec dg = 2.0 * Sx.transpose() * a;
    for (int k = 0; k < kCurv; ++k) {
      const Eigen::Matrix<double, D, D> A = CrossMatrix<D>(k);
      const double c = a.dot(A * b);
      const Vec dc = Sx.transpose() * (A * b) + Sxx.transpose() * (A.transpose() * a);
      add(EI, c / g - kappa0_(k), dc / g - (c / (g * g)) * dg);
    }
  });
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
