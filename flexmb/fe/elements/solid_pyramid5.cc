#include "flexmb/fe/elements/solid_pyramid5.h"

#include "flexmb/fe/elements/solid_common.h"

namespace flexmb::fe {
namespace pyramid5 {

using Mat15 = Eigen::Matrix<double, 15, 15>;

// the base corners' natural coordinates
constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};

// the collapsed hexahedron's shape functions and natural derivatives
void Shape(const solid::QuadPoint& p, Eigen::Matrix<double, 5, 1>& n, Eigen::Matrix<double, 3, 5>& dn) {
  for (int i = 0; i < 4; ++i) {
    const double a = 1.0 + kXi[i] * p.xi, b = 1.0 + kEta[i] * p.eta, c = 1.0 - p.zeta;
    n(i) = a * b * c / 8.0;
    dn(0, i) = kXi[i] * b * c / 8.0;
    dn(1, i) = a * kEta[i] * c / 8.0;
    dn(2, i) = -a * b / 8.0;
  }
  n(4) = 0.5 * (1.0 + p.zeta);
  dn(0, 4) = 0.0;
  dn(1, 4) = 0.0;
  dn(2, 4) = 0.5;
}

// the base corners, for the Jacobian check, and the stress points of the
// corners (the apex: halfway up the axis)
constexpr solid::QuadPoint kCorners[5] = {{-1.0, -1.0, -1.0, 0.0},
                                          {1.0, -1.0, -1.0, 0.0},
                                          {1.0, 1.0, -1.0, 0.0},
                                          {-1.0, 1.0, -1.0, 0.0},
                                          {0.0, 0.0, 0.5, 0.0}};

constexpr solid::QuadPoint kCentre = {0.0, 0.0, 0.0, 0.0};

void CheckBaseCorners(const ElementInput& in, const solid::SolidData& s) {
  Eigen::Matrix<double, 5, 1> n;
  Eigen::Matrix<double, 3, 5> dn, dx;
  for (int c = 0; c < 4; ++c) {
    Shape(kCorners[c], n, dn);
    solid::CartesianDerivatives<5>(dn, in.x, s, *in.element, dx);
  }
}

}  // namespace pyramid5

void SolidPyramid5Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const solid::SolidData s = solid::CheckSolidInput(in, 5, 5);
  pyramid5::CheckBaseCorners(in, s);
  solid::QuadPoint pts[27];
  const int count = solid::HexGaussRule(3, pts);
  pyramid5::Mat15 k = pyramid5::Mat15::Zero();
  pyramid5::Mat15 m = pyramid5::Mat15::Zero();
  solid::AddStiffness<5>(pts, count, pyramid5::Shape, in.x, s, *in.element, k);
  solid::AddConsistentMass<5>(pts, count, pyramid5::Shape, in.x, s, *in.element, m);
  solid::Finish<15>(k, m, in.mass_form, solid::Lumping::kRowSum, K, M);
}

void SolidPyramid5Stress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 5, 5);
  S = solid::PointStress<5>(pyramid5::kCentre, pyramid5::Shape, in.x, s, *in.element);
}

void SolidPyramid5CornerStress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 5, 5);
  solid::CornerStress<5>(pyramid5::kCorners, 5, pyramid5::Shape, in.x, s, *in.element, S);
}

void SolidPyramid5GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const solid::SolidData s = solid::CheckSolidInput(in, 5, 5);
  const Eigen::Matrix<double, 6, 6> d = solid::ElasticityMatrix(s);
  const Eigen::Matrix<double, 15, 1> ue = u.head<15>();
  solid::QuadPoint pts[27];
  const int count = solid::HexGaussRule(3, pts);
  pyramid5::Mat15 kg = pyramid5::Mat15::Zero();
  solid::AddGeometricStiffness<5>(
      pts, count, pyramid5::Shape, in.x, s, *in.element,
      [&](const Eigen::Matrix<double, 3, 5>& dx) -> Eigen::Matrix<double, 6, 1> {
        return d * (solid::StrainMatrix<5>(dx) * ue);
      },
      kg);
  KG = 0.5 * (kg + kg.transpose());
}

}  // namespace flexmb::fe
