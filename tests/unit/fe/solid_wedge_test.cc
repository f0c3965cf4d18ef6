// Wedge elements (6-node and 15-node): exactness of the wedge quadrature
// rules (int xi^p eta^q over the triangle = p! q! / (p + q + 2)!, int
// zeta^r over [-1, 1] = 2 / (r + 1) for even r), symmetry and exactly six
// rigid-body modes on distorted elements (CalculiX's two-point C3D6 rule has
// one spurious mode more), the exact rigid-body mass and inertia of an
// oblique prism (three tetrahedra, analytic moments), rho V of a truncated
// pyramid, positive lumped masses, patch tests on a distorted box of wedges,
// the stress of a linear field, the geometric stiffness of a homogeneous
// stress (v^T KG v = V tr(B S B^T) for the linear field v = B x), and
// errors for inverted elements.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/solid_common.h"
#include "flexmb/fe/elements/solid_wedge15.h"
#include "flexmb/fe/elements/solid_wedge6.h"
#include "flexmb/fe/elements/wedge_rules.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace solid_wedge_test {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using testing::RandomRotation;
using testing::RigidModes;
using testing::TetsRigidMass;

// a wedge, id 5 on line 12 of part.inp
struct Wedge : testing::OneSolid {
  explicit Wedge(const std::vector<Vec3>& nodes)
      : OneSolid(nodes.size() == 6 ? kWedge6 : kWedge15, nodes, 5, {"part.inp", 12}) {}
};

// corners of an oblique prism: a triangle and its translate
std::vector<Vec3> ObliquePrism() {
  const std::vector<Vec3> b = {{0.0, 0.0, 0.0}, {1.1, 0.1, 0.05}, {0.2, 0.9, -0.05}};
  const Vec3 t(0.2, 0.1, 0.8);
  return {b[0], b[1], b[2], b[0] + t, b[1] + t, b[2] + t};
}

// the 15-node wedge on 6 corners, mid-edge nodes moved by `bow`
std::vector<Vec3> Wedge15(const std::vector<Vec3>& c, double bow = 0.0) {
  std::vector<Vec3> x = c;
  for (int k = 0; k < 9; ++k)
    x.push_back(0.5 * (c[kWedge15EdgeCorners[k][0]] + c[kWedge15EdgeCorners[k][1]]) +
                bow * Vec3(0.3 * k - 1.1, 0.6 - 0.15 * k, 0.05 * k * k - 0.9));
  return x;
}

std::vector<Vec3> Place(const std::vector<Vec3>& p, const Eigen::Matrix3d& R, const Vec3& c) {
  std::vector<Vec3> out;
  for (const Vec3& q : p) out.push_back(c + R * q);
  return out;
}

// a wedge with planar faces split into three tetrahedra
std::vector<std::array<Vec3, 4>> WedgeTets(const std::vector<Vec3>& c) {
  return {{c[0], c[1], c[2], c[3]}, {c[1], c[2], c[3], c[4]}, {c[2], c[3], c[4], c[5]}};
}

double Factorial(int n) { return n <= 1 ? 1.0 : n * Factorial(n - 1); }

TEST(WedgeElements, QuadratureRulesAreExact) {
  struct Case {
    std::span<const solid::TrianglePoint> triangle;
    int degree;
  };
  const Case cases[] = {{solid::kTriangleOnePoint, 1}, {solid::kTriangleThreePoint, 2}, {solid::kTriangleSixPoint, 4}};
  for (const Case& c : cases)
    for (int line = 1; line <= 3; ++line) {
      solid::QuadPoint pts[18];
      const int n = solid::WedgeRule(c.triangle, line, pts);
      ASSERT_EQ(n, static_cast<int>(c.triangle.size()) * line);
      for (int p = 0; p <= c.degree; ++p)
        for (int q = 0; p + q <= c.degree; ++q)
          for (int r = 0; r <= 2 * line - 1; ++r) {
            double sum = 0.0;
            for (int g = 0; g < n; ++g)
              sum += pts[g].w * std::pow(pts[g].xi, p) * std::pow(pts[g].eta, q) * std::pow(pts[g].zeta, r);
            const double exact = Factorial(p) * Factorial(q) / Factorial(p + q + 2) * (r % 2 == 0 ? 2.0 / (r + 1) : 0.0);
            EXPECT_NEAR(sum, exact, 1e-14) << "degree " << c.degree << " line " << line << " p q r " << p << q << r;
          }
    }
}

TEST(WedgeElements, SixRigidBodyModesOnDistortedElements) {
  const Eigen::Matrix3d R = RandomRotation(5);
  const Vec3 c(1.0, -2.0, 0.5);
  std::srand(7);
  std::vector<Vec3> corners = ObliquePrism();
  for (Vec3& p : corners) p += 0.07 * Vec3::Random();
  MatX K, M;
  const Wedge w6(Place(corners, R, c));
  w6.Compute(K, M);
  testing::ExpectSixRigidModes(K, w6.x, 3, 1e-6);
  const Wedge w15(Place(Wedge15(corners, 0.03), R, c));
  w15.Compute(K, M);
  testing::ExpectSixRigidModes(K, w15.x, 3, 1e-6);
  // CalculiX's C3D6 rule: a seventh zero-energy mode
  SolidWedge6Matrices(w6.Input(), K, M, Wedge6Integration::kTwoPoint);
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<MatX>(K).eigenvalues();
  EXPECT_LT(std::abs(ev(6)), 1e-11 * ev.maxCoeff());
  EXPECT_GT(ev(7), 1e-6 * ev.maxCoeff());
}

void ExpectRigidMass(const Wedge& w, const Mat6& ref, MassForm form) {
  MatX K, M;
  w.Compute(K, M, form);
  EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
  const MatX r = RigidModes(w.x, 3);
  const MatX got = r.transpose() * M * r;
  if (form == MassForm::kConsistent) {
    EXPECT_LT((got - ref).norm(), 1e-12 * ref.norm()) << TypeName(w.element.type) << "\n" << got << "\n\n" << ref;
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
  } else {
    EXPECT_NEAR(got(0, 0), ref(0, 0), 1e-12 * ref(0, 0));
    EXPECT_EQ((M - MatX(M.diagonal().asDiagonal())).norm(), 0.0);
    EXPECT_GT(M.diagonal().minCoeff(), 0.0);
  }
}

TEST(WedgeElements, ConsistentMassGivesExactRigidBodyInertia) {
  const std::vector<Vec3> c = Place(ObliquePrism(), RandomRotation(11), Vec3(0.5, 1.5, -2.0));
  const Mat6 ref = TetsRigidMass(WedgeTets(c), 7800.0);
  for (MassForm form : {MassForm::kConsistent, MassForm::kLumped}) {
    ExpectRigidMass(Wedge(c), ref, form);
    ExpectRigidMass(Wedge(Wedge15(c)), ref, form);
  }
  // CalculiX's nine-point C3D15 mass is exact for the rigid-body part too
  const Wedge w15(Wedge15(c));
  MatX K, M;
  SolidWedge15Matrices(w15.Input(), K, M, Wedge15Mass::kNinePoint);
  const MatX r = RigidModes(w15.x, 3);
  EXPECT_LT((r.transpose() * M * r - ref).norm(), 1e-12 * ref.norm());
}

// a truncated triangular pyramid (planar, non-parallel sides): mass rho V
TEST(WedgeElements, MassOfATruncatedPyramid) {
  const Vec3 apex(0.3, 0.3, 2.0);
  const std::vector<Vec3> b = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.1, 0.9, 0.0}};
  const double s = 0.6;
  std::vector<Vec3> c = b;
  for (const Vec3& p : b) c.push_back(apex + s * (p - apex));
  const double v = (b[1] - b[0]).cross(b[2] - b[0]).norm() / 2.0 * 2.0 / 3.0 * (1.0 - s * s * s);
  for (const std::vector<Vec3>& x : {c, Wedge15(c)}) {
    const Wedge w(x);
    MatX K, M;
    w.Compute(K, M);
    double total = 0.0;
    for (int i = 0; i < M.rows(); i += 3)
      for (int j = 0; j < M.cols(); j += 3) total += M(i, j);
    EXPECT_NEAR(total, 7800.0 * v, 1e-12 * 7800.0 * v) << TypeName(w.element.type);
  }
}

// 2 x 2 x 2 cells of the unit cube, each split into two wedges along z, the
// centre node moved off-centre; the 15-node version has a node on every edge
struct WedgePatch {
  std::vector<Vec3> x;
  std::vector<std::vector<int>> elements;
  std::vector<bool> interior;
};

WedgePatch MakeWedgePatch(bool quadratic) {
  WedgePatch p;
  auto id = [](int i, int j, int k) { return (k * 3 + j) * 3 + i; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) p.x.emplace_back(0.5 * i, 0.5 * j, 0.5 * k);
  p.x[id(1, 1, 1)] = Vec3(0.43, 0.58, 0.46);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const int a = id(i, j, k), b = id(i + 1, j, k), c = id(i + 1, j + 1, k), d = id(i, j + 1, k);
        const int up = id(0, 0, 1);
        p.elements.push_back({a, b, c, a + up, b + up, c + up});
        p.elements.push_back({a, c, d, a + up, c + up, d + up});
      }
  if (quadratic) {
    std::map<std::pair<int, int>, int> mid;
    for (std::vector<int>& e : p.elements) {
      const std::vector<int> corners = e;
      for (const auto& edge : kWedge15EdgeCorners) {
        const int a = corners[edge[0]], b = corners[edge[1]];
        const std::pair<int, int> key(std::min(a, b), std::max(a, b));
        if (!mid.count(key)) {
          mid[key] = static_cast<int>(p.x.size());
          p.x.push_back(0.5 * (p.x[a] + p.x[b]));
        }
        e.push_back(mid[key]);
      }
    }
  }
  for (const Vec3& q : p.x) {
    bool inside = true;
    for (int d = 0; d < 3; ++d) inside = inside && std::abs(q(d)) > 1e-12 && std::abs(q(d) - 1.0) > 1e-12;
    p.interior.push_back(inside);
  }
  return p;
}

TEST(WedgeElements, PatchTestsOnADistortedBox) {
  for (bool quadratic : {false, true}) {
    const WedgePatch p = MakeWedgePatch(quadratic);
    EXPECT_GE(std::count(p.interior.begin(), p.interior.end(), true), 1);
    const double error = testing::PatchTestError(p.x, p.elements, p.interior, [](const std::vector<Vec3>& xe) {
      MatX ke, me;
      Wedge(xe).Compute(ke, me);
      return ke;
    });
    EXPECT_LT(error, 1e-12) << (quadratic ? "wedge15" : "wedge6");
  }
}

// linear field u = u0 + A x: stress D eps(A) at the centroid; under the
// stress S of that field, v^T KG v = V tr(B S B^T) for the linear field v = B x
TEST(WedgeElements, StressAndGeometricStiffnessOfAHomogeneousField) {
  const std::vector<Vec3> c = Place(ObliquePrism(), RandomRotation(2), Vec3(0.1, 0.2, 0.3));
  Eigen::Matrix3d A, B;
  A << 1.0e-3, 2.0e-4, -3.0e-4, 5.0e-4, -2.0e-3, 1.0e-4, -4.0e-4, 6.0e-4, 1.5e-3;
  B << 0.3, -0.1, 0.2, 0.05, 0.4, -0.2, 0.1, 0.15, -0.3;
  const double v = (c[1] - c[0]).cross(c[2] - c[0]).dot(c[3] - c[0]) / 2.0;
  for (const std::vector<Vec3>& x : {c, Wedge15(c, 0.0)}) {
    const Wedge w(x);
    const ElementTraits& t = Traits(w.element.type);
    Eigen::VectorXd u(3 * x.size()), vb(3 * x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      u.segment<3>(3 * i) = Vec3(1e-3, 2e-3, -1e-3) + A * x[i];
      vb.segment<3>(3 * i) = B * x[i];
    }
    MatX S;
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    t.stress(w.Input(), S, axes);
    const Eigen::Matrix3d eps = 0.5 * (A + A.transpose());
    Eigen::Matrix<double, 6, 1> strain;
    strain << eps(0, 0), eps(1, 1), eps(2, 2), 2 * eps(0, 1), 2 * eps(1, 2), 2 * eps(2, 0);
    solid::SolidData sd;
    sd.E = w.material.E;
    sd.nu = w.material.nu;
    const Eigen::Matrix<double, 6, 1> sigma = solid::ElasticityMatrix(sd) * strain;
    EXPECT_LT((S * u - sigma).norm(), 1e-10 * sigma.norm()) << t.name;
    MatX KG;
    t.geometric_stiffness(w.Input(), u, KG, nullptr);
    EXPECT_LT((KG - KG.transpose()).norm(), 1e-14 * KG.norm());
    Eigen::Matrix3d st;
    st << sigma(0), sigma(3), sigma(5), sigma(3), sigma(1), sigma(4), sigma(5), sigma(4), sigma(2);
    const double ref = v * (B * st * B.transpose()).trace();
    EXPECT_NEAR(vb.dot(KG * vb), ref, 1e-10 * std::abs(ref)) << t.name;
    // rigid translations carry no geometric stiffness
    const MatX r = RigidModes(x, 3).leftCols(3);
    EXPECT_LT((KG * r).norm(), 1e-10 * KG.norm()) << t.name;
  }
}

TEST(WedgeElements, InvertedElementsAreInputErrors) {
  std::vector<Vec3> c = ObliquePrism();
  std::swap(c[1], c[2]);
  std::swap(c[4], c[5]);
  MatX K, M;
  testing::ExpectInputErrorWith([&] { Wedge(c).Compute(K, M); }, {"part.inp:12", "6-node wedge 5", "inverted"});
  testing::ExpectInputErrorWith([&] { Wedge(Wedge15(c)).Compute(K, M); },
                                {"part.inp:12", "15-node wedge 5", "inverted"});
}

}  // namespace solid_wedge_test
}  // namespace flexmb::fe
