#include "flexmb/fe/elements/solid_tet4.h"

#include "flexmb/fe/elements/solid_common.h"

namespace flexmb::fe {
namespace {

using Mat12 = Eigen::Matrix<double, 12, 12>;

// linear shape functions N = (1 - xi - eta - zeta, xi, eta, zeta)
void Tet4Shape(const solid::QuadPoint& p, Eigen::Matrix<double, 4, 1>& n,
           Eigen::Matrix<double, 3, 4>& dn) {
  n << 1.0 - p.xi - p.eta - p.zeta, p.xi, p.eta, p.zeta;
  dn << -1.0, 1.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0;
}

// centroid, weight = reference volume 1/6
constexpr solid::QuadPoint kOnePoint[1] = {{0.25, 0.25, 0.25, 1.0 / 6.0}};

}  // namespace

void SolidTet4Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const solid::SolidData s = solid::CheckSolidInput(in, 4, 4);
  const Element& e = *in.element;
  Mat12 k = Mat12::Zero();
  Mat12 m = Mat12::Zero();
  solid::AddStiffness<4>(kOnePoint, 1, Tet4Shape, in.x, s, e, k);
  solid::AddConsistentMass<4>(solid::kTetFourPoint, 4, Tet4Shape, in.x, s, e, m);
  solid::Finish<12>(k, m, in.mass_form, solid::Lumping::kHrz, K, M);
}

void SolidTet4Stress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 4, 4);
  S = solid::PointStress<4>(kOnePoint[0], Tet4Shape, in.x, s, *in.element);
}

// the corner nodes' natural coordinates, in node order
constexpr solid::QuadPoint kTet4Corners[4] = {{0.0, 0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}};

void SolidTet4CornerStress(const ElementInput& in, MatX& S) {
  const solid::SolidData s = solid::CheckSolidInput(in, 4, 4);
  solid::CornerStress<4>(kTet4Corners, 4, Tet4Shape, in.x, s, *in.element, S);
}

void SolidTet4GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const solid::SolidData s = solid::CheckSolidInput(in, 4, 4);
  const Eigen::Matrix<double, 6, 6> d = solid::ElasticityMatrix(s);
  const Eigen::Matrix<double, 12, 1> ue = u.head<12>();
  Mat12 kg = Mat12::Zero();
  solid::AddGeometricStiffness<4>(
      kOnePoint, 1, Tet4Shape, in.x, s, *in.element,
      [&](const Eigen::Matrix<double, 3, 4>& dx) -> Eigen::Matrix<double, 6, 1> {
        return d * (solid::StrainMatrix<4>(dx) * ue);
      },
      kg);
  KG = 0.5 * (kg + kg.transpose());
}

}  // namespace flexmb::fe
