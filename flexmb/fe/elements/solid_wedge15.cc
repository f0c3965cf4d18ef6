#include "flexmb/fe/elements/solid_wedge15.h"

#include "flexmb/fe/elements/solid_common.h"
#include "flexmb/fe/elements/wedge_rules.h"

namespace flexmb::fe {
namespace {

using Mat45 = Eigen::Matrix<double, 45, 45>;

// serendipity shape functions with L = (1 - xi - eta, xi, eta), s = -1 on
// the bottom and +1 on the top triangle: corners L (1 + s zeta) (2 L + s
// zeta - 2) / 2, triangle edges 2 L_a L_b (1 + s zeta), vertical edges
// L (1 - zeta^2)
void Wedge15Shape(const solid::QuadPoint& p, Eigen::Matrix<double, 15, 1>& n,
                  Eigen::Matrix<double, 3, 15>& dn) {
  const double l[3] = {1.0 - p.xi - p.eta, p.xi, p.eta};
  const double dl[3][2] = {{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}};
  const double z = p.zeta;
  for (int s = 0; s < 2; ++s) {
    const double sign = s == 0 ? -1.0 : 1.0, f = 1.0 + sign * z;
    for (int i = 0; i < 3; ++i) {
      const int k = 3 * s + i;
      n(k) = 0.5 * l[i] * f * (2.0 * l[i] + sign * z - 2.0);
      const double dndl = 0.5 * f * (4.0 * l[i] + sign * z - 2.0);
      dn(0, k) = dndl * dl[i][0];
      dn(1, k) = dndl * dl[i][1];
      dn(2, k) = 0.5 * l[i] * sign * (2.0 * l[i] + 2.0 * sign * z - 1.0);
    }
    for (int m = 0; m < 3; ++m) {
      const int k = 6 + 3 * s + m;
      const int a = kWedge15EdgeCorners[m][0], b = kWedge15EdgeCorners[m][1];
      n(k) = 2.0 * l[a] * l[b] * f;
      for (int d = 0; d < 2; ++d) dn(d, k) = 2.0 * (dl[a][d] * l[b] + l[a] * dl[b][d]) * f;
      dn(2, k) = 2.0 * l[a] * l[b] * sign;
    }
  }
  for (int i = 0; i < 3; ++i) {
    const int k = 12 + i;
    n(k) = l[i] * (1.0 - z * z);
    dn(0, k) = dl[i][0] * (1.0 - z * z);
    dn(1, k) = dl[i][1] * (1.0 - z * z);
    dn(2, k) = -2.0 * l[i] * z;
  }
}

// corners, for the Jacobian check
constexpr solid::QuadPoint kWedge15Corners[6] = {{0.0, 0.0, -1.0, 0.0}, {1.0, 0.0, -1.0, 0.0},
                                                 {0.0, 1.0, -1.0, 0.0}, {0.0, 0.0, 1.0, 0.0},
                                                 {1.0, 0.0, 1.0, 0.0},  {0.0, 1.0, 1.0, 0.0}};

constexpr solid::QuadPoint kWedge15Centroid = {1.0 / 3.0, 1.0 / 3.0, 0.0, 0.0};

// the 18-point rule (exact mass, geometric stiffness)
int Wedge15FineRule(solid::QuadPoint* pts) { return solid::WedgeRule(solid::kTriangleSixPoint, 3, pts); }

}  // namespace

void SolidWedge15Matrices(const ElementInput& in, MatX& K, MatX& M, Wedge15Mass mass) {
  const solid::SolidData s = solid::CheckSolidInput(in, 15, 6);
  const Element& e = *in.element;
  Eigen::Matrix<double, 15, 1> n;
  Eigen::Matrix<double, 3, 15> dn, dx;
  for (const solid::QuadPoint& c : kWedge15Corners) {
    Wedge15Shape(c, n, dn);
    solid::CartesianDerivatives<15>(dn, in.x, s, e, dx);
  }
  solid::QuadPoint nine[9], fine[18];
  const int n9 = solid::WedgeRule(solid::kTriangleThreePoint, 3, nine);
  const int n18 = Wedge15FineRule(fine);
  Mat45 k = Mat45::Zero();
  Mat45 m = Mat45::Zero();
  solid::AddStiffness<15>(nine, n9, Wedge15Shape, in.x, s, e, k);
  if (mass == Wedge15Mass::kExact)
    solid::AddConsistentMass<15>(fine, n18, Wedge15Shape, in.x, s, e, m);
  else
    solid::AddConsistentMass<15>(nine, n9, Wedge15Shape, in.x, s, e, m);
  solid::Finish<45>(k, m, in.mass_form, solid::Lumping::kHrz, K, M);
}

void SolidWedge15Stress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 15, 6);
  S = solid::PointStress<15>(kWedge15Centroid, Wedge15Shape, in.x, s, *in.element);
}

// the corner nodes' natural coordinates, in node order
constexpr solid::QuadPoint kWedge15CornerPoints[6] = {{0.0, 0.0, -1.0, 0.0}, {1.0, 0.0, -1.0, 0.0}, {0.0, 1.0, -1.0, 0.0}, {0.0, 0.0, 1.0, 0.0}, {1.0, 0.0, 1.0, 0.0}, {0.0, 1.0, 1.0, 0.0}};

void SolidWedge15CornerStress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 15, 6);
  solid::CornerStress<15>(kWedge15CornerPoints, 6, Wedge15Shape, in.x, s, *in.element, S);
}

void SolidWedge15GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const solid::SolidData s = solid::CheckSolidInput(in, 15, 6);
  const Eigen::Matrix<double, 6, 6> d = solid::ElasticityMatrix(s);
  const Eigen::Matrix<double, 45, 1> ue = u.head<45>();
  solid::QuadPoint fine[18];
  const int n18 = Wedge15FineRule(fine);
  Mat45 kg = Mat45::Zero();
  solid::AddGeometricStiffness<15>(
      fine, n18, Wedge15Shape, in.x, s, *in.element,
      [&](const Eigen::Matrix<double, 3, 15>& dx) -> Eigen::Matrix<double, 6, 1> {
        return d * (solid::StrainMatrix<15>(dx) * ue);
      },
      kg);
  KG = 0.5 * (kg + kg.transpose());
}

}  // namespace flexmb::fe
