#include "flexmb/fe/elements/solid_hex20.h"

#include <cmath>

#include "flexmb/fe/elements/solid_common.h"

namespace flexmb::fe {
namespace {

using Mat60 = Eigen::Matrix<double, 60, 60>;

// natural coordinates of the 20 nodes: corners as the 8-node hexahedron,
// mid-edge nodes at the middle of their edges
struct Hex20Nodes {
  double xi[20], eta[20], zeta[20];
  constexpr Hex20Nodes() : xi(), eta(), zeta() {
    constexpr double cx[8] = {-1.0, 1.0, 1.0, -1.0, -1.0, 1.0, 1.0, -1.0};
    constexpr double cy[8] = {-1.0, -1.0, 1.0, 1.0, -1.0, -1.0, 1.0, 1.0};
    constexpr double cz[8] = {-1.0, -1.0, -1.0, -1.0, 1.0, 1.0, 1.0, 1.0};
    for (int i = 0; i < 8; ++i) {
      xi[i] = cx[i];
      eta[i] = cy[i];
      zeta[i] = cz[i];
    }
    for (int m = 0; m < 12; ++m) {
      const int a = kHex20EdgeCorners[m][0], b = kHex20EdgeCorners[m][1];
      xi[8 + m] = 0.5 * (cx[a] + cx[b]);
      eta[8 + m] = 0.5 * (cy[a] + cy[b]);
      zeta[8 + m] = 0.5 * (cz[a] + cz[b]);
    }
  }
};
constexpr Hex20Nodes kHex20Nodes;

// serendipity shape functions: corners (1 + xi xi_i)(1 + eta eta_i)(1 +
// zeta zeta_i)(xi xi_i + eta eta_i + zeta zeta_i - 2) / 8; a mid-edge node
// with xi_i = 0: (1 - xi^2)(1 + eta eta_i)(1 + zeta zeta_i) / 4 (and
// likewise for the other directions)
void Hex20Shape(const solid::QuadPoint& p, Eigen::Matrix<double, 20, 1>& n, Eigen::Matrix<double, 3, 20>& dn) {
  for (int i = 0; i < 20; ++i) {
    const double xi = kHex20Nodes.xi[i], et = kHex20Nodes.eta[i], ze = kHex20Nodes.zeta[i];
    const double a = 1.0 + p.xi * xi, b = 1.0 + p.eta * et, c = 1.0 + p.zeta * ze;
    if (i < 8) {
      const double s = p.xi * xi + p.eta * et + p.zeta * ze - 2.0;
      n(i) = 0.125 * a * b * c * s;
      dn(0, i) = 0.125 * xi * b * c * (s + a);
      dn(1, i) = 0.125 * et * a * c * (s + b);
      dn(2, i) = 0.125 * ze * a * b * (s + c);
    } else if (xi == 0.0) {
      const double q = 1.0 - p.xi * p.xi;
      n(i) = 0.25 * q * b * c;
      dn(0, i) = -0.5 * p.xi * b * c;
      dn(1, i) = 0.25 * q * et * c;
      dn(2, i) = 0.25 * q * b * ze;
    } else if (et == 0.0) {
      const double q = 1.0 - p.eta * p.eta;
      n(i) = 0.25 * a * q * c;
      dn(0, i) = 0.25 * xi * q * c;
      dn(1, i) = -0.5 * p.eta * a * c;
      dn(2, i) = 0.25 * a * q * ze;
    } else {
      const double q = 1.0 - p.zeta * p.zeta;
      n(i) = 0.25 * a * b * q;
      dn(0, i) = 0.25 * xi * b * q;
      dn(1, i) = 0.25 * a * et * q;
      dn(2, i) = -0.5 * p.zeta * a * b;
    }
  }
}

// the Jacobian must be positive at the corners (a badly placed mid-edge
// node folds the element there first)
void Hex20CheckCorners(const ElementInput& in, const solid::SolidData& s) {
  Eigen::Matrix<double, 20, 1> n;
  Eigen::Matrix<double, 3, 20> dn, dx;
  for (int i = 0; i < 8; ++i) {
    Hex20Shape({kHex20Nodes.xi[i], kHex20Nodes.eta[i], kHex20Nodes.zeta[i], 0.0}, n, dn);
    solid::CartesianDerivatives<20>(dn, in.x, s, *in.element, dx);
  }
}

}  // namespace

void SolidHex20Matrices(const ElementInput& in, MatX& K, MatX& M, Hex20Integration integration) {
  const solid::SolidData s = solid::CheckSolidInput(in, 20, 8);
  const Element& e = *in.element;
  Hex20CheckCorners(in, s);
  solid::QuadPoint g2[8], g3[27];
  solid::HexGaussRule(2, g2);
  solid::HexGaussRule(3, g3);
  Mat60 k = Mat60::Zero();
  Mat60 m = Mat60::Zero();
  if (integration == Hex20Integration::kFull)
    solid::AddStiffness<20>(g3, 27, Hex20Shape, in.x, s, e, k);
  else
    solid::AddStiffness<20>(g2, 8, Hex20Shape, in.x, s, e, k);
  solid::AddConsistentMass<20>(g3, 27, Hex20Shape, in.x, s, e, m);
  solid::Finish<60>(k, m, in.mass_form, solid::Lumping::kHrz, K, M);
}

void SolidHex20Stress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 20, 8);
  S = solid::PointStress<20>({0.0, 0.0, 0.0, 0.0}, Hex20Shape, in.x, s, *in.element);
}

// the corner nodes' natural coordinates, in node order
constexpr solid::QuadPoint kHex20CornerPoints[8] = {
    {-1.0, -1.0, -1.0, 0.0}, {1.0, -1.0, -1.0, 0.0}, {1.0, 1.0, -1.0, 0.0}, {-1.0, 1.0, -1.0, 0.0},
    {-1.0, -1.0, 1.0, 0.0},  {1.0, -1.0, 1.0, 0.0},  {1.0, 1.0, 1.0, 0.0},  {-1.0, 1.0, 1.0, 0.0}};

void SolidHex20CornerStress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 20, 8);
  solid::CornerStress<20>(kHex20CornerPoints, 8, Hex20Shape, in.x, s, *in.element, S);
}

void SolidHex20GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const solid::SolidData s = solid::CheckSolidInput(in, 20, 8);
  const Eigen::Matrix<double, 6, 6> d = solid::ElasticityMatrix(s);
  const Eigen::Matrix<double, 60, 1> ue = u.head<60>();
  solid::QuadPoint g3[27];
  solid::HexGaussRule(3, g3);
  Mat60 kg = Mat60::Zero();
  solid::AddGeometricStiffness<20>(
      g3, 27, Hex20Shape, in.x, s, *in.element,
      [&](const Eigen::Matrix<double, 3, 20>& dx) -> Eigen::Matrix<double, 6, 1> {
        return d * (solid::StrainMatrix<20>(dx) * ue);
      },
      kg);
  KG = 0.5 * (kg + kg.transpose());
}

}  // namespace flexmb::fe
