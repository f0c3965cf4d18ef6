// Second-order shells (8-node quadrilateral, 6-node triangle; macro
// elements of the 4- and 3-node shells, shell_macro.h): rigid-body modes
// of rotated, curved and offset elements; the consistent mass's exact
// rigid-body inertia of a flat plate (mass, first and second moments,
// rotary inertia); membrane and bending patch tests on the MacNeal-Harder
// patch meshed with second-order elements (a constant strain and a
// constant curvature state, w quadratic with Kirchhoff rotations, are
// reproduced at every interior node from the boundary nodes' values); the
// stress of a constant membrane strain; the material angle of a laminate
// carried to the parts; and errors naming the element.

#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/shell_quad8.h"
#include "flexmb/fe/elements/shell_tria6.h"
#include "tests/unit/fe/shell_test_util.h"

namespace flexmb::fe::testing {
namespace shell_quad8_test {

const std::vector<Eigen::Vector2d> kQuad8Corners = {{0.0, 0.0}, {1.3, 0.1}, {1.1, 0.9}, {-0.2, 0.8}};
const std::vector<Eigen::Vector2d> kTria6Corners = {{0.0, 0.0}, {1.3, 0.1}, {0.4, 0.9}};

// corners then the mid-edge points (edge k from corner k to k + 1)
std::vector<Eigen::Vector2d> WithMidNodes(const std::vector<Eigen::Vector2d>& c) {
  std::vector<Eigen::Vector2d> p = c;
  for (size_t k = 0; k < c.size(); ++k) p.push_back(0.5 * (c[k] + c[(k + 1) % c.size()]));
  return p;
}

ElementType SecondOrder(size_t corners) { return corners == 4 ? kQuad8 : kTria6; }

TEST(ShellQuad8, RigidBodyModesOfRotatedCurvedAndOffsetElements) {
  for (const auto* corners : {&kQuad8Corners, &kTria6Corners}) {
    const ElementType type = SecondOrder(corners->size());
    for (unsigned seed : {1u, 2u}) {
      ExpectRigidBodyModes(ShellFixture(type, Place(WithMidNodes(*corners), RandomRotation(seed), Vec3::Random() * 5.0), 0.02));
    }
    // mid-edge nodes off the plane (a curved element) and an offset
    std::vector<double> h(2 * corners->size(), 0.0);
    for (size_t k = corners->size(); k < h.size(); ++k) h[k] = 0.02 * (k % 2 ? 1.0 : -1.0);
    ShellFixture f(type, Place(WithMidNodes(*corners), RandomRotation(4), Vec3(1, 2, 3), h), 0.05);
    f.element.shell_offset = 0.03;
    ExpectRigidBodyModes(f);
  }
}

TEST(ShellQuad8, ConsistentMassGivesExactRigidBodyInertia) {
  for (const auto* corners : {&kQuad8Corners, &kTria6Corners}) {
    const double t = 0.08, rho = 2700.0, nsm = 3.5, offset = 0.02;
    const Eigen::Matrix3d R = RandomRotation(5);
    const Vec3 c0(0.3, -1.2, 2.0);
    ShellFixture f(SecondOrder(corners->size()), Place(WithMidNodes(*corners), R, c0), t, 7e10, 0.33, rho, nsm);
    f.element.shell_offset = offset;
    MatX K, M;
    f.Compute(K, M);
    const MatX r = RigidModes(f.x, 6);
    const Eigen::Matrix<double, 6, 6> expected = PlateRigidMass(*corners, R, c0, t, offset, rho, nsm);
    const MatX got = r.transpose() * M * r;
    EXPECT_LT((got - expected).norm(), 1e-12 * expected.norm()) << got << "\n\n" << expected;
  }
}

// the MacNeal-Harder patch with a mid node on every edge: quads (or each
// quad halved into triangles) of second order
struct SecondOrderPatch {
  std::vector<Eigen::Vector2d> p;
  std::vector<std::vector<int>> elements;
  std::vector<bool> boundary;
};

SecondOrderPatch MakePatch(bool triangles) {
  const Patch base;
  SecondOrderPatch out;
  out.p = base.p;
  std::map<std::pair<int, int>, int> mid;
  auto mid_node = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto [it, fresh] = mid.emplace(key, static_cast<int>(out.p.size()));
    if (fresh) out.p.push_back(0.5 * (out.p[a] + out.p[b]));
    return it->second;
  };
  std::vector<std::vector<int>> cells = triangles ? base.Trias() : base.quads;
  for (const auto& c : cells) {
    std::vector<int> e = c;
    for (size_t k = 0; k < c.size(); ++k) e.push_back(mid_node(c[k], c[(k + 1) % c.size()]));
    out.elements.push_back(e);
  }
  out.boundary.assign(out.p.size(), false);
  for (int k = 0; k < 4; ++k) {
    out.boundary[k] = true;
    out.boundary[mid_node(k, (k + 1) % 4)] = true;
  }
  return out;
}

// solves the patch with the boundary nodes' values from `field` (local u v
// w rx ry rz) and checks every interior node against it
void RunSecondOrderPatch(bool triangles, const std::function<Eigen::Matrix<double, 6, 1>(Eigen::Vector2d)>& field) {
  const SecondOrderPatch patch = MakePatch(triangles);
  const Eigen::Matrix3d R = RandomRotation(11);
  const Vec3 c0(0.7, -0.4, 1.1);
  std::vector<Vec3> x;
  for (const auto& q : patch.p) x.push_back(c0 + R * Vec3(q.x(), q.y(), 0.0));
  const int n = static_cast<int>(x.size());
  const MatX k = DenseStiffness(n, 6, patch.elements, [&](const std::vector<int>& conn) {
    std::vector<Vec3> xe;
    for (int i : conn) xe.push_back(x[i]);
    ShellFixture f(SecondOrder(conn.size() / 2), xe, 0.001, 1e6, 0.25);
    MatX ke, me;
    f.Compute(ke, me);
    return ke;
  });
  Eigen::VectorXd exact(6 * n);
  std::vector<bool> fixed(6 * n, false);
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix<double, 6, 1> l = field(patch.p[i]);
    exact.segment<3>(6 * i) = R * l.head<3>();
    exact.segment<3>(6 * i + 3) = R * l.tail<3>();
    for (int c = 0; c < 6; ++c) fixed[6 * i + c] = patch.boundary[i];
  }
  Eigen::VectorXd start = exact;
  for (int i = 0; i < n; ++i)
    if (!patch.boundary[i]) start.segment<6>(6 * i).setZero();
  const Eigen::VectorXd u = SolvePrescribed(k, fixed, start);
  Eigen::VectorXd err = u - exact, ref = exact;
  for (int i = 0; i < n; ++i) {
    err.segment<3>(6 * i + 3) *= 0.24;
    ref.segment<3>(6 * i + 3) *= 0.24;
  }
  EXPECT_LT(err.norm(), 1e-9 * ref.norm()) << (triangles ? "tria6" : "quad8") << ": " << err.transpose();
}

TEST(ShellQuad8, MembranePatchTest) {
  RunSecondOrderPatch(false, PatchMembraneField);
  RunSecondOrderPatch(true, PatchMembraneField);
}

TEST(ShellQuad8, BendingPatchTest) {
  RunSecondOrderPatch(false, PatchBendingField);
  RunSecondOrderPatch(true, PatchBendingField);
}

// a constant membrane strain (1, 2, 0.5) 1e-4 in the element's axes gives
// the plane-stress C eps on both surfaces, in the element's axes
TEST(ShellQuad8, ConstantStrainStress) {
  for (const auto* corners : {&kQuad8Corners, &kTria6Corners}) {
    const Eigen::Matrix3d R = RandomRotation(9);
    ShellFixture f(SecondOrder(corners->size()), Place(WithMidNodes(*corners), R, Vec3(0.1, 0.2, 0.3)), 0.01, 2e11, 0.3);
    MatX S;
    Eigen::Matrix3d axes;
    Traits(f.element.type).stress(f.Input(), S, axes);
    // axes: e3 the normal R z, e1 along corner 1 to corner 2
    EXPECT_LT((axes.col(2) - R.col(2)).norm(), 1e-12);
    const Eigen::Vector3d eps(1e-4, 2e-4, 0.5e-4);  // exx, eyy, gxy in the element's axes
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * static_cast<Eigen::Index>(f.x.size()));
    for (size_t i = 0; i < f.x.size(); ++i) {
      const Vec3 d = axes.transpose() * (f.x[i] - f.x[0]);
      const Vec3 local(eps(0) * d.x() + 0.5 * eps(2) * d.y(), eps(1) * d.y() + 0.5 * eps(2) * d.x(), 0.0);
      u.segment<3>(6 * static_cast<Eigen::Index>(i)) = axes * local;
    }
    const Eigen::VectorXd s = S * u;
    const double c = 2e11 / (1 - 0.09);
    const Eigen::Vector3d expected(c * (eps(0) + 0.3 * eps(1)), c * (eps(1) + 0.3 * eps(0)), 2e11 / 2.6 * eps(2));
    EXPECT_LT((s.head<3>() - expected).norm(), 1e-9 * expected.norm()) << s.transpose();
    EXPECT_LT((s.tail<3>() - expected).norm(), 1e-9 * expected.norm()) << s.transpose();
  }
}

TEST(ShellQuad8, DegenerateInputIsAnInputErrorNamingTheElement) {
  // mid-edge nodes pulled inwards until a quarter folds
  std::vector<Eigen::Vector2d> p = WithMidNodes(kQuad8Corners);
  p[4] = Eigen::Vector2d(0.65, 0.7);
  ShellFixture f(kQuad8, Place(p, Eigen::Matrix3d::Identity(), Vec3::Zero()));
  MatX K, M;
  try {
    f.Compute(K, M);
    ADD_FAILURE() << "a folded 8-node shell was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("8-node shell 7"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("plate.bdf:12"), std::string::npos) << e.what();
  }
}

}  // namespace shell_quad8_test
}  // namespace flexmb::fe::testing
