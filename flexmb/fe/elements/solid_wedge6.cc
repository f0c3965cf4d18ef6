#include "flexmb/fe/elements/solid_wedge6.h"

#include "flexmb/fe/elements/solid_common.h"
#include "flexmb/fe/elements/wedge_rules.h"

namespace flexmb::fe {
namespace {

using Mat18 = Eigen::Matrix<double, 18, 18>;

// L_i (1 -+ zeta) / 2 and their natural derivatives
void Wedge6Shape(const solid::QuadPoint& p, Eigen::Matrix<double, 6, 1>& n, Eigen::Matrix<double, 3, 6>& dn) {
  const double l[3] = {1.0 - p.xi - p.eta, p.xi, p.eta};
  const double dl[3][2] = {{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}};
  for (int s = 0; s < 2; ++s) {
    const double sign = s == 0 ? -1.0 : 1.0, f = 0.5 * (1.0 + sign * p.zeta);
    for (int i = 0; i < 3; ++i) {
      const int k = 3 * s + i;
      n(k) = l[i] * f;
      dn(0, k) = dl[i][0] * f;
      dn(1, k) = dl[i][1] * f;
      dn(2, k) = 0.5 * sign * l[i];
    }
  }
}

// corners, for the Jacobian check
constexpr solid::QuadPoint kWedge6Corners[6] = {{0.0, 0.0, -1.0, 0.0}, {1.0, 0.0, -1.0, 0.0},
                                                {0.0, 1.0, -1.0, 0.0}, {0.0, 0.0, 1.0, 0.0},
                                                {1.0, 0.0, 1.0, 0.0},  {0.0, 1.0, 1.0, 0.0}};

constexpr solid::QuadPoint kWedge6Centroid = {1.0 / 3.0, 1.0 / 3.0, 0.0, 0.0};

void CheckWedge6Corners(const ElementInput& in, const solid::SolidData& s) {
  Eigen::Matrix<double, 6, 1> n;
  Eigen::Matrix<double, 3, 6> dn, dx;
  for (const solid::QuadPoint& c : kWedge6Corners) {
    Wedge6Shape(c, n, dn);
    solid::CartesianDerivatives<6>(dn, in.x, s, *in.element, dx);
  }
}

}  // namespace

void SolidWedge6Matrices(const ElementInput& in, MatX& K, MatX& M, Wedge6Integration integration) {
  const solid::SolidData s = solid::CheckSolidInput(in, 6, 6);
  CheckWedge6Corners(in, s);
  solid::QuadPoint pts[6];
  const int count = integration == Wedge6Integration::kSixPoint
                        ? solid::WedgeRule(solid::kTriangleThreePoint, 2, pts)
                        : solid::WedgeRule(solid::kTriangleOnePoint, 2, pts);
  Mat18 k = Mat18::Zero();
  Mat18 m = Mat18::Zero();
  solid::AddStiffness<6>(pts, count, Wedge6Shape, in.x, s, *in.element, k);
  solid::AddConsistentMass<6>(pts, count, Wedge6Shape, in.x, s, *in.element, m);
  solid::Finish<18>(k, m, in.mass_form, solid::Lumping::kRowSum, K, M);
}

void SolidWedge6Stress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 6, 6);
  S = solid::PointStress<6>(kWedge6Centroid, Wedge6Shape, in.x, s, *in.element);
}

void SolidWedge6CornerStress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 6, 6);
  solid::CornerStress<6>(kWedge6Corners, 6, Wedge6Shape, in.x, s, *in.element, S);
}

void SolidWedge6GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const solid::SolidData s = solid::CheckSolidInput(in, 6, 6);
  const Eigen::Matrix<double, 6, 6> d = solid::ElasticityMatrix(s);
  const Eigen::Matrix<double, 18, 1> ue = u.head<18>();
  solid::QuadPoint pts[6];
  const int count = solid::WedgeRule(solid::kTriangleThreePoint, 2, pts);
  Mat18 kg = Mat18::Zero();
  solid::AddGeometricStiffness<6>(
      pts, count, Wedge6Shape, in.x, s, *in.element,
      [&](const Eigen::Matrix<double, 3, 6>& dx) -> Eigen::Matrix<double, 6, 1> {
        return d * (solid::StrainMatrix<6>(dx) * ue);
      },
      kg);
  KG = 0.5 * (kg + kg.transpose());
}

}  // namespace flexmb::fe
