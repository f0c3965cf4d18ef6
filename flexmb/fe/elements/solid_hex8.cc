#include "flexmb/fe/elements/solid_hex8.h"

#include <Eigen/Cholesky>
#include <cmath>

#include "flexmb/fe/elements/solid_common.h"

namespace flexmb::fe {
namespace {

using Mat24 = Eigen::Matrix<double, 24, 24>;

constexpr double kHexXi[8] = {-1.0, 1.0, 1.0, -1.0, -1.0, 1.0, 1.0, -1.0};
constexpr double kHexEta[8] = {-1.0, -1.0, 1.0, 1.0, -1.0, -1.0, 1.0, 1.0};
constexpr double kHexZeta[8] = {-1.0, -1.0, -1.0, -1.0, 1.0, 1.0, 1.0, 1.0};

// trilinear shape functions and their natural derivatives
void Hex8Shape(const solid::QuadPoint& p, Eigen::Matrix<double, 8, 1>& n,
           Eigen::Matrix<double, 3, 8>& dn) {
  for (int i = 0; i < 8; ++i) {
    const double a = 1.0 + p.xi * kHexXi[i], b = 1.0 + p.eta * kHexEta[i], c = 1.0 + p.zeta * kHexZeta[i];
    n(i) = 0.125 * a * b * c;
    dn(0, i) = 0.125 * kHexXi[i] * b * c;
    dn(1, i) = 0.125 * kHexEta[i] * a * c;
    dn(2, i) = 0.125 * kHexZeta[i] * a * b;
  }
}

}  // namespace

void SolidHex8Matrices(const ElementInput& in, MatX& K, MatX& M, Hex8Formulation formulation) {
  const solid::SolidData s = solid::CheckSolidInput(in, 8, 8);
  const Element& e = *in.element;
  Eigen::Matrix<double, 8, 1> n;
  Eigen::Matrix<double, 3, 8> dn, dx;
  solid::QuadPoint g2[8], g3[27];
  solid::HexGaussRule(2, g2);
  solid::HexGaussRule(3, g3);

  Mat24 k = Mat24::Zero();
  if (formulation == Hex8Formulation::kFullIntegration) {
    solid::AddStiffness<8>(g2, 8, Hex8Shape, in.x, s, e, k);
  } else if (formulation == Hex8Formulation::kSelectiveReduced) {
    // the mean of the shape functions' gradients: the mean dilatation
    Eigen::Matrix<double, 3, 8> mean = Eigen::Matrix<double, 3, 8>::Zero();
    double volume = 0.0;
    for (const solid::QuadPoint& p : g2) {
      Hex8Shape(p, n, dn);
      const double det = solid::CartesianDerivatives<8>(dn, in.x, s, e, dx);
      mean += dx * (det * p.w);
      volume += det * p.w;
    }
    mean /= volume;
    const Eigen::Matrix<double, 6, 6> d = solid::ElasticityMatrix(s);
    for (const solid::QuadPoint& p : g2) {
      Hex8Shape(p, n, dn);
      const double det = solid::CartesianDerivatives<8>(dn, in.x, s, e, dx);
      Eigen::Matrix<double, 6, 24> b = solid::StrainMatrix<8>(dx);
      // normal strains: eps_ii + (mean dilatation - dilatation) / 3
      for (int a = 0; a < 8; ++a)
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i) b(i, 3 * a + j) += (mean(j, a) - dx(j, a)) / 3.0;
      k += b.transpose() * d * b * (det * p.w);
    }
  } else {
    // centre Jacobian for Taylor's correction
    Hex8Shape({0.0, 0.0, 0.0, 0.0}, n, dn);
    Eigen::Matrix3d j0 = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 8; ++i) j0 += dn.col(i) * in.x[i].transpose();
    const double det0 = j0.determinant();
    const Eigen::Matrix3d j0_inv = j0.inverse();
    const Eigen::Matrix<double, 6, 6> d = solid::ElasticityMatrix(s);
    Eigen::Matrix<double, 24, 9> kci = Eigen::Matrix<double, 24, 9>::Zero();
    Eigen::Matrix<double, 9, 9> kii = Eigen::Matrix<double, 9, 9>::Zero();
    for (const solid::QuadPoint& p : g2) {
      Hex8Shape(p, n, dn);
      const double det = solid::CartesianDerivatives<8>(dn, in.x, s, e, dx);
      const Eigen::Matrix<double, 6, 24> b = solid::StrainMatrix<8>(dx);
      // modes 1 - xi^2, 1 - eta^2, 1 - zeta^2: natural derivatives, then cartesian
      const Eigen::Matrix3d dp = Eigen::Vector3d(-2.0 * p.xi, -2.0 * p.eta, -2.0 * p.zeta).asDiagonal();
      const Eigen::Matrix3d dpx = j0_inv * dp * (det0 / det);
      const Eigen::Matrix<double, 6, 9> bi = solid::StrainMatrix<3>(dpx);
      const Eigen::Matrix<double, 6, 24> db = d * b * (det * p.w);
      k += b.transpose() * db;
      kci += db.transpose() * bi;
      kii += bi.transpose() * d * bi * (det * p.w);
    }
    k -= kci * kii.ldlt().solve(kci.transpose());
  }

  Mat24 m = Mat24::Zero();
  solid::AddConsistentMass<8>(g3, 27, Hex8Shape, in.x, s, e, m);
  solid::Finish<24>(k, m, in.mass_form, solid::Lumping::kRowSum, K, M);
}

void SolidHex8Stress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 8, 8);
  S = solid::PointStress<8>({0.0, 0.0, 0.0, 0.0}, Hex8Shape, in.x, s, *in.element);
}

// the corner nodes' natural coordinates, in node order
constexpr solid::QuadPoint kHex8CornerPoints[8] = {
    {-1.0, -1.0, -1.0, 0.0}, {1.0, -1.0, -1.0, 0.0}, {1.0, 1.0, -1.0, 0.0}, {-1.0, 1.0, -1.0, 0.0},
    {-1.0, -1.0, 1.0, 0.0},  {1.0, -1.0, 1.0, 0.0},  {1.0, 1.0, 1.0, 0.0},  {-1.0, 1.0, 1.0, 0.0}};

void SolidHex8CornerStress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 8, 8);
  solid::CornerStress<8>(kHex8CornerPoints, 8, Hex8Shape, in.x, s, *in.element, S);
}

void SolidHex8GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const solid::SolidData s = solid::CheckSolidInput(in, 8, 8);
  const Element& e = *in.element;
  const Eigen::Matrix<double, 6, 1> sigma =
      solid::PointStress<8>({0.0, 0.0, 0.0, 0.0}, Hex8Shape, in.x, s, e) * u.head<24>();
  solid::QuadPoint g2[8];
  solid::HexGaussRule(2, g2);
  Mat24 kg = Mat24::Zero();
  solid::AddGeometricStiffness<8>(
      g2, 8, Hex8Shape, in.x, s, e,
      [&](const Eigen::Matrix<double, 3, 8>&) -> Eigen::Matrix<double, 6, 1> { return sigma; }, kg);
  KG = 0.5 * (kg + kg.transpose());
}

}  // namespace flexmb::fe
