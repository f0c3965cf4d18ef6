#pragma once
/// \file solid_common.h
/// Pieces shared by the isoparametric solids (tet4, tet10, hex8): input
/// checks, the isotropic elasticity matrix, the Jacobian with its sign
/// check, the strain-displacement matrix, the stress at a point, and
/// quadrature loops for the stiffness and the consistent and lumped (HRZ)
/// mass. Strains are ordered
/// xx yy zz xy yz zx with engineering shear. Element DOF: ux uy uz per node,
/// node by node, basic frame. Details: docs/design.md, "FE: solid elements".

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/elements/element_common.h"

namespace flexmb::fe::solid {

/// Checked material values of a solid.
struct SolidData {
  double E = 0.0;    ///< Young's modulus [Pa]
  double nu = 0.0;   ///< Poisson's ratio
  double rho = 0.0;  ///< density [kg/m^3]
  double h = 0.0;    ///< longest edge between the first and the other corner nodes [m]
};

/// Checks element, material and coordinates of a solid with `n_nodes` nodes
/// (the first `n_corners` of them corners) and returns the values; throws
/// InputError naming the element otherwise (missing material, E <= 0, nu
/// outside (-1, 0.5), negative density, non-finite or coincident nodes).
SolidData CheckSolidInput(const ElementInput& in, int n_nodes, int n_corners);

/// Isotropic elasticity matrix [Pa], stress = D strain.
Eigen::Matrix<double, 6, 6> ElasticityMatrix(const SolidData& s);

/// One quadrature point in natural coordinates with its weight (the
/// reference element's measure included).
struct QuadPoint {
  double xi, eta, zeta, w;
};

/// 4-point rule on the reference tetrahedron (volume coordinates
/// 0.5854.../0.1381..., weights 1/24), exact for polynomials of degree 2.
inline constexpr double kTetRuleA = 0.5854101966249685, kTetRuleB = 0.1381966011250105;
inline constexpr QuadPoint kTetFourPoint[4] = {{kTetRuleB, kTetRuleB, kTetRuleB, 1.0 / 24.0},
                                               {kTetRuleA, kTetRuleB, kTetRuleB, 1.0 / 24.0},
                                               {kTetRuleB, kTetRuleA, kTetRuleB, 1.0 / 24.0},
                                               {kTetRuleB, kTetRuleB, kTetRuleA, 1.0 / 24.0}};

/// Tensor-product Gauss rule on the cube [-1, 1]^3 with `order` points per
/// direction (2 or 3: exact for polynomials of degree 3 or 5 in each
/// variable); fills pts (8 or 27 entries) and returns the count.
inline int HexGaussRule(int order, QuadPoint* pts) {
  const double g2[2] = {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
  const double w2[2] = {1.0, 1.0};
  const double g3[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double w3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double* g = order == 2 ? g2 : g3;
  const double* w = order == 2 ? w2 : w3;
  int k = 0;
  for (int i = 0; i < order; ++i)
    for (int j = 0; j < order; ++j)
      for (int l = 0; l < order; ++l) pts[k++] = {g[i], g[j], g[l], w[i] * w[j] * w[l]};
  return k;
}

/// Jacobian J = dX/dxi (rows: d/dxi, d/deta, d/dzeta of x y z) from the
/// natural derivatives `dn` (3 x N) and node coordinates; returns det J and
/// the cartesian derivatives `dx` (3 x N). Throws InputError naming the
/// element if det J <= tol = 1e-10 h^3: "inverted" below -tol, else
/// "degenerate".
template <int N>
double CartesianDerivatives(const Eigen::Matrix<double, 3, N>& dn, const Vec3* x,
                            const SolidData& s, const Element& e,
                            Eigen::Matrix<double, 3, N>& dx) {
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  for (int i = 0; i < N; ++i) j += dn.col(i) * x[i].transpose();
  const double det = j.determinant();
  const double tol = 1e-10 * s.h * s.h * s.h;
  if (!(det > tol))
    throw InputError(det < -tol ? "inverted element (negative Jacobian determinant " +
                                      std::to_string(det) + ")"
                                : "degenerate element (zero Jacobian determinant)",
                     ElementContext(e));
  dx = j.inverse() * dn;
  return det;
}

/// Strain-displacement matrix (6 x 3N) from cartesian derivatives.
template <int N>
Eigen::Matrix<double, 6, 3 * N> StrainMatrix(const Eigen::Matrix<double, 3, N>& dx) {
  Eigen::Matrix<double, 6, 3 * N> b = Eigen::Matrix<double, 6, 3 * N>::Zero();
  for (int i = 0; i < N; ++i) {
    b(0, 3 * i) = dx(0, i);
    b(1, 3 * i + 1) = dx(1, i);
    b(2, 3 * i + 2) = dx(2, i);
    b(3, 3 * i) = dx(1, i);
    b(3, 3 * i + 1) = dx(0, i);
    b(4, 3 * i + 1) = dx(2, i);
    b(4, 3 * i + 2) = dx(1, i);
    b(5, 3 * i) = dx(2, i);
    b(5, 3 * i + 2) = dx(0, i);
  }
  return b;
}

/// Stress recovery at the natural point `p`: D B there, the 6 x 3N map from
/// the nodal displacements (basic frame, node by node ux uy uz) to the
/// stresses (sxx, syy, szz, sxy, syz, szx) [Pa] in the basic frame, with the
/// strain-displacement matrix of the stiffness (StrainMatrix). Throws as
/// CartesianDerivatives.
template <int N, class Shape>
Eigen::Matrix<double, 6, 3 * N> PointStress(const QuadPoint& p, Shape&& shape, const Vec3* x,
                                            const SolidData& s, const Element& e) {
  Eigen::Matrix<double, N, 1> n;
  Eigen::Matrix<double, 3, N> dn, dx;
  shape(p, n, dn);
  CartesianDerivatives<N>(dn, x, s, e, dx);
  return ElasticityMatrix(s) * StrainMatrix<N>(dx);
}

/// Stress recovery at the corner nodes: PointStress at each of the `count`
/// natural points `corners` (the corner nodes, in node order), stacked in
/// S (6 rows per corner) x 3N. Throws as CartesianDerivatives (a Jacobian
/// that is singular or inverted at a corner).
template <int N, class Shape>
void CornerStress(const QuadPoint* corners, int count, Shape&& shape, const Vec3* x, const SolidData& s,
                  const Element& e, MatX& S) {
  S.resize(6 * count, 3 * N);
  for (int c = 0; c < count; ++c) S.middleRows(6 * c, 6) = PointStress<N>(corners[c], shape, x, s, e);
}

/// Adds rho int N^T N dV (3 DOF per node) over the given points to `m`;
/// `shape(p, n, dn)` gives shape functions and natural derivatives.
template <int N, class Shape>
void AddConsistentMass(const QuadPoint* pts, int count, Shape&& shape, const Vec3* x,
                       const SolidData& s, const Element& e,
                       Eigen::Matrix<double, 3 * N, 3 * N>& m) {
  Eigen::Matrix<double, N, 1> n;
  Eigen::Matrix<double, 3, N> dn, dx;
  for (int g = 0; g < count; ++g) {
    shape(pts[g], n, dn);
    const double det = CartesianDerivatives<N>(dn, x, s, e, dx);
    const Eigen::Matrix<double, N, N> nn = n * n.transpose() * (s.rho * det * pts[g].w);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        for (int a = 0; a < 3; ++a) m(3 * i + a, 3 * j + a) += nn(i, j);
  }
}

/// Adds int B^T D B dV over the given points to `k`.
template <int N, class Shape>
void AddStiffness(const QuadPoint* pts, int count, Shape&& shape, const Vec3* x,
                  const SolidData& s, const Element& e, Eigen::Matrix<double, 3 * N, 3 * N>& k) {
  const Eigen::Matrix<double, 6, 6> d = ElasticityMatrix(s);
  Eigen::Matrix<double, N, 1> n;
  Eigen::Matrix<double, 3, N> dn, dx;
  for (int g = 0; g < count; ++g) {
    shape(pts[g], n, dn);
    const double det = CartesianDerivatives<N>(dn, x, s, e, dx);
    const Eigen::Matrix<double, 6, 3 * N> b = StrainMatrix<N>(dx);
    k += b.transpose() * d * b * (det * pts[g].w);
  }
}

/// Adds the initial-stress (geometric) stiffness int G^T S G dV over the
/// given points to `kg` (3N x 3N, node by node ux uy uz): the block of nodes
/// i, j is int dN_i^T S dN_j dV times the 3 x 3 identity, S the symmetric
/// stress tensor at the point (the second variation of int S : E dV with the
/// Green-Lagrange strain E). `stress(dx)` returns the stress (sxx, syy, szz,
/// sxy, syz, szx) [Pa] at a point with cartesian derivatives `dx`.
template <int N, class Shape, class Stress>
void AddGeometricStiffness(const QuadPoint* pts, int count, Shape&& shape, const Vec3* x,
                           const SolidData& s, const Element& e, Stress&& stress,
                           Eigen::Matrix<double, 3 * N, 3 * N>& kg) {
  Eigen::Matrix<double, N, 1> n;
  Eigen::Matrix<double, 3, N> dn, dx;
  for (int g = 0; g < count; ++g) {
    shape(pts[g], n, dn);
    const double det = CartesianDerivatives<N>(dn, x, s, e, dx);
    const Eigen::Matrix<double, 6, 1> sg = stress(dx);
    Eigen::Matrix3d t;
    t << sg(0), sg(3), sg(5), sg(3), sg(1), sg(4), sg(5), sg(4), sg(2);
    const Eigen::Matrix<double, N, N> gij = dx.transpose() * t * dx * (det * pts[g].w);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        for (int a = 0; a < 3; ++a) kg(3 * i + a, 3 * j + a) += gij(i, j);
  }
}

/// HRZ lumping (Hinton, Rock, Zienkiewicz 1976): the diagonal of the
/// consistent mass scaled so that each direction carries the total mass.
/// Positive for every element here (row sums are not: tet10 corners); keeps
/// the centre of mass only where the element is symmetric enough (any
/// straight-sided tetrahedron, a parallelepiped), not on a tapered hexahedron.
template <int M>
void LumpHrz(Eigen::Matrix<double, M, M>& m) {
  const Eigen::Matrix<double, M, 1> diag = m.diagonal();
  // total mass: sum of the x-direction block of the consistent matrix
  double total = 0.0, dsum = 0.0;
  for (int i = 0; i < M; i += 3) {
    for (int j = 0; j < M; j += 3) total += m(i, j);
    dsum += diag(i);
  }
  m.setZero();
  if (dsum > 0.0) m.diagonal() = diag * (total / dsum);
}

/// Row-sum lumping: each node gets rho int N_i dV in every direction. Keeps
/// the total mass and its first moment (the centre of mass) exactly; positive
/// for elements whose shape functions are non-negative (tet4, hex8), not for
/// tet10, whose corner rows sum to a negative mass.
template <int M>
void LumpRowSum(Eigen::Matrix<double, M, M>& m) {
  const Eigen::Matrix<double, M, 1> rows = m.rowwise().sum();
  m.setZero();
  m.diagonal() = rows;
}

/// How a solid lumps its mass.
enum class Lumping { kHrz, kRowSum };

/// Final step of every solid: lumps the consistent mass `m` (HRZ or row
/// sums) if `form` asks for it, then returns the symmetric parts of k and m
/// in K and M.
template <int N>
void Finish(const Eigen::Matrix<double, N, N>& k, Eigen::Matrix<double, N, N>& m, MassForm form,
            Lumping lumping, MatX& K, MatX& M) {
  if (form == MassForm::kLumped) {
    if (lumping == Lumping::kHrz)
      LumpHrz<N>(m);
    else
      LumpRowSum<N>(m);
  }
  K = 0.5 * (k + k.transpose());
  M = 0.5 * (m + m.transpose());
}

}  // namespace flexmb::fe::solid
