#include "flexmb/fe/elements/solid_tet10.h"

#include "flexmb/fe/elements/solid_common.h"

namespace flexmb::fe {
namespace {

using Mat30 = Eigen::Matrix<double, 30, 30>;

// mid-edge node k (5..10) between corners kTet10EdgeCorners[k - 5]

// quadratic shape functions from the volume coordinates L = (1 - xi - eta - zeta, xi, eta, zeta)
void Tet10Shape(const solid::QuadPoint& p, Eigen::Matrix<double, 10, 1>& n,
           Eigen::Matrix<double, 3, 10>& dn) {
  const double l[4] = {1.0 - p.xi - p.eta - p.zeta, p.xi, p.eta, p.zeta};
  // dL_i / d(xi, eta, zeta)
  const double dl[4][3] = {{-1.0, -1.0, -1.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  for (int i = 0; i < 4; ++i) {
    n(i) = l[i] * (2.0 * l[i] - 1.0);
    for (int d = 0; d < 3; ++d) dn(d, i) = (4.0 * l[i] - 1.0) * dl[i][d];
  }
  for (int k = 0; k < 6; ++k) {
    const int a = kTet10EdgeCorners[k][0], b = kTet10EdgeCorners[k][1];
    n(4 + k) = 4.0 * l[a] * l[b];
    for (int d = 0; d < 3; ++d) dn(d, 4 + k) = 4.0 * (dl[a][d] * l[b] + l[a] * dl[b][d]);
  }
}

// symmetric 14-point rule with positive weights, exact for degree 5 (the
// rule of Walkington 2000 and quadpy; weights sum to the reference volume
// 1/6; exactness checked in tests/unit/fe/solid_test.cc)
constexpr double kA1 = 0.0927352503108912, kW1 = 0.01224884051939366;
constexpr double kA2 = 0.3108859192633006, kW2 = 0.01878132095300264;
constexpr double kB3 = 0.0455037041256496, kW3 = 0.007091003462846911;
constexpr double kC1 = 1.0 - 3.0 * kA1, kC2 = 1.0 - 3.0 * kA2, kC3 = 0.5 - kB3;
constexpr solid::QuadPoint kFourteenPoint[14] = {
    {kA1, kA1, kA1, kW1}, {kC1, kA1, kA1, kW1}, {kA1, kC1, kA1, kW1}, {kA1, kA1, kC1, kW1},
    {kA2, kA2, kA2, kW2}, {kC2, kA2, kA2, kW2}, {kA2, kC2, kA2, kW2}, {kA2, kA2, kC2, kW2},
    {kC3, kC3, kB3, kW3}, {kC3, kB3, kC3, kW3}, {kC3, kB3, kB3, kW3}, {kB3, kC3, kC3, kW3},
    {kB3, kC3, kB3, kW3}, {kB3, kB3, kC3, kW3}};

// corners, for the Jacobian check
constexpr solid::QuadPoint kCorners[4] = {
    {0.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}};

}  // namespace

void SolidTet10Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const solid::SolidData s = solid::CheckSolidInput(in, 10, 4);
  const Element& e = *in.element;
  Eigen::Matrix<double, 10, 1> n;
  Eigen::Matrix<double, 3, 10> dn, dx;
  for (const solid::QuadPoint& c : kCorners) {
    Tet10Shape(c, n, dn);
    solid::CartesianDerivatives<10>(dn, in.x, s, e, dx);
  }
  Mat30 k = Mat30::Zero();
  Mat30 m = Mat30::Zero();
  solid::AddStiffness<10>(solid::kTetFourPoint, 4, Tet10Shape, in.x, s, e, k);
  solid::AddConsistentMass<10>(kFourteenPoint, 14, Tet10Shape, in.x, s, e, m);
  solid::Finish<30>(k, m, in.mass_form, solid::Lumping::kHrz, K, M);
}

void SolidTet10Stress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 10, 4);
  S = solid::PointStress<10>({0.25, 0.25, 0.25, 0.0}, Tet10Shape, in.x, s, *in.element);
}

// the corner nodes' natural coordinates, in node order
constexpr solid::QuadPoint kTet10Corners[4] = {{0.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}};

void SolidTet10CornerStress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 10, 4);
  solid::CornerStress<10>(kTet10Corners, 4, Tet10Shape, in.x, s, *in.element, S);
}

void SolidTet10GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const solid::SolidData s = solid::CheckSolidInput(in, 10, 4);
  const Eigen::Matrix<double, 6, 6> d = solid::ElasticityMatrix(s);
  const Eigen::Matrix<double, 30, 1> ue = u.head<30>();
  Mat30 kg = Mat30::Zero();
  solid::AddGeometricStiffness<10>(
      kFourteenPoint, 14, Tet10Shape, in.x, s, *in.element,
      [&](const Eigen::Matrix<double, 3, 10>& dx) -> Eigen::Matrix<double, 6, 1> {
        return d * (solid::StrainMatrix<10>(dx) * ue);
      },
      kg);
  KG = 0.5 * (kg + kg.transpose());
}

}  // namespace flexmb::fe
