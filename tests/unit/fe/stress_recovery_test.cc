// Stress recovery of every element type (ShellQuad4Stress, ShellTria3Stress,
// Beam2SectionForces, SolidTet4/Tet10/Hex8Stress): zero for rigid-body
// motion; exact for the fields each element represents exactly, against
// closed-form references: shells under a constant membrane strain (plane
// stress Hooke's law) and a constant curvature (sigma = +-E/(1-nu^2) t/2
// (kappa + nu kappa')), with shell offsets; beams under a tip load of a
// cantilever (section forces from statics: the load transported to the
// ends, with offsets); solids under linear fields (Hooke's law with the Lame
// constants) and the tet10 under a quadratic field at its centroid.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <vector>

#include "flexmb/fe/elements/beam2.h"
#include "flexmb/fe/elements/shell_quad4.h"
#include "flexmb/fe/elements/shell_tria3.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe/elements/solid_tet10.h"
#include "flexmb/fe/elements/solid_tet4.h"
#include "tests/unit/fe/fe_test_models.h"
#include "tests/unit/fe/shell_test_util.h"

namespace flexmb::fe {
namespace {

using testing::Place;
using testing::RandomRotation;
using testing::RigidModes;
using testing::ShellFixture;
using Vec6 = Eigen::Matrix<double, 6, 1>;

void ShellStress(const ShellFixture& f, MatX& S, Mat3& axes) {
  if (f.element.type == ElementType::kQuad4)
    ShellQuad4Stress(f.Input(), S, axes);
  else
    ShellTria3Stress(f.Input(), S, axes);
}

// plane stress tensor of a shell surface (sxx, syy, sxy in the frame `axes`)
// in the basic frame
Mat3 ShellTensor(const Eigen::Vector3d& s, const Mat3& axes) {
  Mat3 local;
  local << s(0), s(2), 0.0, s(2), s(1), 0.0, 0.0, 0.0, 0.0;
  return axes * local * axes.transpose();
}

// plane stress Hooke's law, written out: (sxx, syy, sxy) of (exx, eyy, gxy)
Eigen::Vector3d PlaneStress(const Eigen::Vector3d& e, double E, double nu) {
  const double c = E / (1.0 - nu * nu);
  return Eigen::Vector3d(c * (e(0) + nu * e(1)), c * (e(1) + nu * e(0)),
                         E / (2.0 * (1.0 + nu)) * e(2));
}

const std::vector<Eigen::Vector2d> kQuad = {{0.0, 0.0}, {1.1, 0.1}, {0.9, 0.8}, {-0.1, 0.7}};
const std::vector<Eigen::Vector2d> kTria = {{0.0, 0.0}, {1.1, 0.1}, {0.4, 0.8}};

TEST(StressRecovery, ShellsRigidMotionGivesZeroStress) {
  for (ElementType type : {ElementType::kQuad4, ElementType::kTria3}) {
    const Mat3 R = RandomRotation(5);
    const auto& poly = type == ElementType::kQuad4 ? kQuad : kTria;
    const std::vector<double> warp = {0.02, -0.02, 0.02, -0.02};
    ShellFixture f(type, Place(poly, R, Vec3(1.0, -2.0, 0.5),
                               type == ElementType::kQuad4 ? warp : std::vector<double>{}),
                   0.05);
    f.element.shell_offset = 0.03;
    MatX S;
    Mat3 axes;
    ShellStress(f, S, axes);
    ASSERT_EQ(S.rows(), 6);
    ASSERT_EQ(S.cols(), 6 * static_cast<int>(poly.size()));
    const MatX r = RigidModes(f.x, 6);
    EXPECT_LT((S * r).norm(), 1e-13 * S.norm() * r.norm()) << TypeName(type);
    EXPECT_LT((axes.transpose() * axes - Mat3::Identity()).norm(), 1e-14);
    EXPECT_NEAR(axes.determinant(), 1.0, 1e-14);
  }
}

// u = G p in the plane (G with a rotation part, drilling rz = omega):
// both surfaces carry C sym(G); the shell offset does not matter
TEST(StressRecovery, ShellsConstantMembraneStrain) {
  const double E = 7.0e10, nu = 0.33;
  Eigen::Matrix2d G;
  G << 1.0e-3, -4.0e-4, 7.0e-4, -2.5e-4;
  const Eigen::Vector3d strain(G(0, 0), G(1, 1), G(0, 1) + G(1, 0));
  const Mat3 expected = ShellTensor(PlaneStress(strain, E, nu), Mat3::Identity());
  for (ElementType type : {ElementType::kQuad4, ElementType::kTria3}) {
    const Mat3 R = RandomRotation(8);
    const auto& poly = type == ElementType::kQuad4 ? kQuad : kTria;
    ShellFixture f(type, Place(poly, R, Vec3(0.3, 0.2, -1.0)), 0.02, E, nu);
    f.element.shell_offset = -0.015;
    const int n = static_cast<int>(poly.size());
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * n);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d d = G * poly[i];
      u.segment<3>(6 * i) = R * Vec3(d.x(), d.y(), 0.0);
      u.segment<3>(6 * i + 3) = R * Vec3(0.0, 0.0, 0.5 * (G(1, 0) - G(0, 1)));
    }
    MatX S;
    Mat3 axes;
    ShellStress(f, S, axes);
    const Eigen::VectorXd s = S * u;
    const Mat3 ref = R * expected * R.transpose();
    for (int side = 0; side < 2; ++side) {
      const Mat3 got = ShellTensor(s.segment<3>(3 * side), axes);
      EXPECT_LT((got - ref).norm(), 1e-12 * ref.norm()) << TypeName(type) << " side " << side;
    }
  }
}

// Kirchhoff field w = -(a x^2 + b y^2) / 2 - c x y: beta = (a x + c y,
// b y + c x), rx = -beta_y, ry = beta_x; curvatures (a, b, 2c) are constant;
// top and bottom carry +-t/2 C (a, b, 2c). Given at the mid-surface, offset
// from the nodes: u_node = u_mid - theta x d.
TEST(StressRecovery, ShellsConstantCurvatureWithOffset) {
  const double E = 2.1e11, nu = 0.3, t = 0.012, offset = 0.004;
  const double a = 0.8, b = -0.3, c = 0.45;
  const Eigen::Vector3d top = PlaneStress(Eigen::Vector3d(a, b, 2.0 * c) * (0.5 * t), E, nu);
  for (ElementType type : {ElementType::kQuad4, ElementType::kTria3}) {
    const Mat3 R = RandomRotation(21);
    const auto& poly = type == ElementType::kQuad4 ? kQuad : kTria;
    ShellFixture f(type, Place(poly, R, Vec3(-0.7, 0.4, 2.0)), t, E, nu);
    f.element.shell_offset = offset;
    const int n = static_cast<int>(poly.size());
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * n);
    // the element normal e3 = R z for these counter-clockwise polygons
    const Vec3 d = offset * R.col(2);
    for (int i = 0; i < n; ++i) {
      const double x = poly[i].x(), y = poly[i].y();
      const double w = -0.5 * (a * x * x + b * y * y) - c * x * y;
      const Vec3 theta = R * Vec3(-(b * y + c * x), a * x + c * y, 0.0);
      u.segment<3>(6 * i) = R * Vec3(0.0, 0.0, w) - theta.cross(d);
      u.segment<3>(6 * i + 3) = theta;
    }
    MatX S;
    Mat3 axes;
    ShellStress(f, S, axes);
    EXPECT_LT((axes.col(2) - R.col(2)).norm(), 1e-14);
    const Eigen::VectorXd s = S * u;
    const Mat3 ref = R * ShellTensor(top, Mat3::Identity()) * R.transpose();
    EXPECT_LT((ShellTensor(s.segment<3>(3), axes) - ref).norm(), 1e-11 * ref.norm())
        << TypeName(type);
    EXPECT_LT((ShellTensor(s.segment<3>(0), axes) + ref).norm(), 1e-11 * ref.norm())
        << TypeName(type);
  }
}

// a beam with an unsymmetric section, rotated, with offsets
struct BeamFixture {
  Element element;
  Material material;
  BeamSection section;
  std::vector<Vec3> x;
  ElementInput Input() const {
    ElementInput in;
    in.element = &element;
    in.x = x.data();
    in.material = &material;
    in.beam = &section;
    return in;
  }
};

BeamFixture MakeBeam(unsigned seed) {
  BeamFixture b;
  const Mat3 R = RandomRotation(seed);
  b.element.id = 3;
  b.element.type = ElementType::kBeam2;
  b.element.nodes = {0, 1};
  b.element.orientation = R * Vec3(0.3, 1.0, 0.5);
  b.element.offset_a = Vec3(0.05, -0.1, 0.2);
  b.element.offset_b = Vec3(-0.15, 0.07, 0.01);
  b.material.E = 2.1e11;
  b.material.nu = 0.3;
  b.material.rho = 7850.0;
  b.section.A = 3.0e-3;
  b.section.Iy = 4.0e-6;
  b.section.Iz = 9.0e-6;
  b.section.Iyz = 2.0e-6;
  b.section.J = 2.5e-6;
  b.section.ky = 0.8;
  b.section.kz = 0.6;
  const Vec3 a = Vec3(0.4, -1.0, 2.0);
  b.x = {a, a + R * Vec3(1.7, 0.2, -0.1)};
  return b;
}

TEST(StressRecovery, BeamRigidMotionGivesZeroSectionForces) {
  const BeamFixture b = MakeBeam(2);
  MatX S;
  Mat3 axes;
  Beam2SectionForces(b.Input(), S, axes);
  ASSERT_EQ(S.rows(), 12);
  ASSERT_EQ(S.cols(), 12);
  const MatX r = RigidModes(b.x, 6);
  EXPECT_LT((S * r).norm(), 1e-13 * S.norm() * r.norm());
}

// end A clamped, a load (force F, moment M) at node B: the section forces
// at end B are the load moved to end B (moment M - offset_b x F), at end A
// the same force and the moment about end A; element frame from the
// definition (x along A -> B, y from the orientation vector)
TEST(StressRecovery, BeamCantileverSectionForcesFromStatics) {
  for (unsigned seed : {2u, 7u}) {
    const BeamFixture b = MakeBeam(seed);
    const Vec3 F(120.0, -340.0, 75.0), Mo(-20.0, 15.0, 40.0);
    MatX K, M, S;
    Mat3 axes;
    Beam2Matrices(b.Input(), K, M);
    Beam2SectionForces(b.Input(), S, axes);
    Vec6 load;
    load << F, Mo;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
    u.tail<6>() = K.bottomRightCorner<6, 6>().ldlt().solve(load);
    const Eigen::VectorXd s = S * u;

    const Vec3 ea = b.x[0] + b.element.offset_a, eb = b.x[1] + b.element.offset_b;
    Mat3 R;
    R.col(0) = (eb - ea).normalized();
    const Vec3 v = b.element.orientation;
    R.col(1) = (v - R.col(0) * R.col(0).dot(v)).normalized();
    R.col(2) = R.col(0).cross(R.col(1));
    EXPECT_LT((axes - R).norm(), 1e-14);
    const Vec3 mb = Mo + (b.x[1] - eb).cross(F);
    const Vec3 ma = Mo + (b.x[1] - ea).cross(F);
    Vec6 ref_a, ref_b;
    ref_a << R.transpose() * F, R.transpose() * ma;
    ref_b << R.transpose() * F, R.transpose() * mb;
    EXPECT_LT((s.head<6>() - ref_a).norm(), 1e-9 * ref_a.norm()) << s.head<6>().transpose();
    EXPECT_LT((s.tail<6>() - ref_b).norm(), 1e-9 * ref_b.norm()) << s.tail<6>().transpose();
  }
}

// a solid element on nodes x
struct SolidFixture {
  Element element;
  Material material;
  std::vector<Vec3> x;
  SolidFixture(ElementType type, std::vector<Vec3> nodes) : x(std::move(nodes)) {
    element.id = 11;
    element.type = type;
    for (size_t i = 0; i < x.size(); ++i) element.nodes.push_back(static_cast<int>(i));
    material.E = 7.0e10;
    material.nu = 0.33;
    material.rho = 2700.0;
  }
  MatX Stress() const {
    ElementInput in;
    in.element = &element;
    in.x = x.data();
    in.material = &material;
    MatX S;
    switch (element.type) {
      case ElementType::kTet4: SolidTet4Stress(in, S); break;
      case ElementType::kTet10: SolidTet10Stress(in, S); break;
      default: SolidHex8Stress(in, S); break;
    }
    return S;
  }
};


std::vector<Vec3> SolidNodes(ElementType type, unsigned seed) {
  const Mat3 R = RandomRotation(seed);
  const Vec3 c(0.5, -0.3, 1.2);
  std::vector<Vec3> x;
  if (type == ElementType::kHex8) {
    const double nat[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    std::srand(seed);
    for (const auto& p : nat)
      x.push_back(c + R * (Vec3(0.6 * p[0], 0.4 * p[1], 0.3 * p[2]) + 0.06 * Vec3::Random()));
    return x;
  }
  const std::vector<Vec3> corners = {
      {0.0, 0.0, 0.0}, {1.2, 0.1, -0.1}, {0.2, 0.9, 0.1}, {0.1, 0.2, 1.1}};
  for (const Vec3& p : corners) x.push_back(c + R * p);
  if (type == ElementType::kTet10)
    for (const auto& e : kTet10EdgeCorners) x.push_back(0.5 * (x[e[0]] + x[e[1]]));
  return x;
}

// Hooke's law with the Lame constants, Voigt order xx yy zz xy yz zx
Vec6 Hooke(const Mat3& grad, double E, double nu) {
  const Mat3 eps = 0.5 * (grad + grad.transpose());
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = E / (2.0 * (1.0 + nu));
  const Mat3 s = lambda * eps.trace() * Mat3::Identity() + 2.0 * mu * eps;
  Vec6 v;
  v << s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(2, 0);
  return v;
}

TEST(StressRecovery, SolidsRigidMotionAndLinearFields) {
  Mat3 G;
  G << 1.0e-3, -4.0e-4, 2.0e-4, 7.0e-4, -2.5e-4, 5.0e-4, -3.0e-4, 1.0e-4, 6.0e-4;
  for (ElementType type : {ElementType::kTet4, ElementType::kTet10, ElementType::kHex8}) {
    const SolidFixture s(type, SolidNodes(type, 4));
    const MatX S = s.Stress();
    ASSERT_EQ(S.rows(), 6);
    ASSERT_EQ(S.cols(), 3 * static_cast<int>(s.x.size()));
    const MatX r = RigidModes(s.x, 3);
    EXPECT_LT((S * r).norm(), 1e-13 * S.norm() * r.norm()) << TypeName(type);
    Eigen::VectorXd u(S.cols());
    for (size_t i = 0; i < s.x.size(); ++i) u.segment<3>(3 * i) = Vec3(0.1, -0.2, 0.3) + G * s.x[i];
    const Vec6 ref = Hooke(G, s.material.E, s.material.nu);
    EXPECT_LT((S * u - ref).norm(), 1e-12 * ref.norm()) << TypeName(type);
  }
}

// u_a = x^T H_a x: strain at the centroid x_c from du_a/dx_b = 2 (H_a x_c)_b,
// represented exactly by the straight-edged tet10
TEST(StressRecovery, Tet10QuadraticFieldAtTheCentroid) {
  const SolidFixture s(ElementType::kTet10, SolidNodes(ElementType::kTet10, 9));
  Mat3 H[3];
  std::srand(12);
  for (Mat3& h : H) {
    h = Mat3::Random() * 1e-3;
    h = (0.5 * (h + h.transpose())).eval();
  }
  Eigen::VectorXd u(30);
  for (int i = 0; i < 10; ++i)
    for (int a = 0; a < 3; ++a) u(3 * i + a) = s.x[i].dot(H[a] * s.x[i]);
  Vec3 xc = Vec3::Zero();
  for (int i = 0; i < 4; ++i) xc += 0.25 * s.x[i];
  Mat3 grad;
  for (int a = 0; a < 3; ++a) grad.row(a) = 2.0 * (H[a] * xc).transpose();
  const Vec6 ref = Hooke(grad, s.material.E, s.material.nu);
  EXPECT_LT((s.Stress() * u - ref).norm(), 1e-12 * ref.norm());
}

}  // namespace
}  // namespace flexmb::fe
