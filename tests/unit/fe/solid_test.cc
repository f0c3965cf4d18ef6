// Solid elements (tet4, tet10, hex8 with and without incompatible modes):
// symmetry and exactly six rigid-body modes on distorted elements, exact
// rigid-body mass and inertia (analytic tetrahedron moments; a hexahedron
// with planar faces split into tetrahedra), the closed-form tet10 consistent
// mass (rho V / 420 [6 1 -4 -6 32 16 8], Zienkiewicz & Taylor), HRZ lumped
// masses, patch tests on distorted meshes (MacNeal & Harder 1985 seven-hex
// cube patch; twelve tetrahedra around an off-centre interior node), pure
// bending of a hex8 (exact with incompatible modes, locked without), and
// errors for inverted or degenerate elements.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe/elements/solid_tet10.h"
#include "flexmb/fe/elements/solid_tet4.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using testing::ExpectInputErrorWith;
using testing::RandomRotation;
using testing::RigidModes;
using testing::TetsRigidMass;

// a solid element with its material; hex8 formulation selectable
struct Solid {
  Element element;
  Material material;
  std::vector<Vec3> x;
  Hex8Formulation hex = Hex8Formulation::kIncompatibleModes;

  Solid(ElementType type, std::vector<Vec3> nodes, double E = 2.0e11, double nu = 0.3,
        double rho = 7800.0) {
    element.id = 9;
    element.type = type;
    element.origin = {"part.bdf", 7};
    for (size_t i = 0; i < nodes.size(); ++i) element.nodes.push_back(static_cast<int>(i));
    material.E = E;
    material.nu = nu;
    material.rho = rho;
    x = std::move(nodes);
  }
  void Compute(MatX& K, MatX& M, MassForm form = MassForm::kConsistent,
               const Material* mat = nullptr) const {
    ElementInput in;
    in.element = &element;
    in.x = x.data();
    in.material = mat != nullptr ? mat : &material;
    in.mass_form = form;
    switch (element.type) {
      case ElementType::kTet4: SolidTet4Matrices(in, K, M); break;
      case ElementType::kTet10: SolidTet10Matrices(in, K, M); break;
      default: SolidHex8Matrices(in, K, M, hex); break;
    }
  }
};

// element stiffness check; the positive eigenvalues of these distorted
// elements exceed 1e-6 of the largest
void ExpectSixRigidModes(const MatX& K, const std::vector<Vec3>& x) {
  testing::ExpectSixRigidModes(K, x, 3, 1e-6);
}

const std::vector<Vec3> kTet = {
    {0.0, 0.0, 0.0}, {1.2, 0.1, -0.1}, {0.2, 0.9, 0.1}, {0.1, 0.2, 1.1}};

std::vector<Vec3> Place(const std::vector<Vec3>& p, const Eigen::Matrix3d& R, const Vec3& c) {
  std::vector<Vec3> out;
  for (const Vec3& q : p) out.push_back(c + R * q);
  return out;
}

std::vector<Vec3> Tet10(const std::vector<Vec3>& c, double bow = 0.0) {
  std::vector<Vec3> x = c;
  for (int k = 0; k < 6; ++k)
    x.push_back(0.5 * (c[kTet10EdgeCorners[k][0]] + c[kTet10EdgeCorners[k][1]]) +
                bow * Vec3(0.3 * k - 0.7, 0.5 - 0.2 * k, 0.1 * k * k - 0.4));
  return x;
}

// hexahedron with planar faces: a unit square at z = 0 and a 0.6 square
// centred at (0.2, 0.1, 0.8) (a sheared frustum)
std::vector<Vec3> PlanarHex() {
  std::vector<Vec3> x;
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int i = 0; i < 4; ++i) x.emplace_back(0.5 * sx[i], 0.5 * sy[i], 0.0);
  for (int i = 0; i < 4; ++i) x.emplace_back(0.2 + 0.3 * sx[i], 0.1 + 0.3 * sy[i], 0.8);
  return x;
}

constexpr int kHexFace[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// tetrahedra fanned from the vertex centroid of a convex hexahedron
std::vector<std::array<Vec3, 4>> HexTets(const std::vector<Vec3>& x) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : x) c += p / 8.0;
  std::vector<std::array<Vec3, 4>> tets;
  for (const auto& f : kHexFace) {
    tets.push_back({c, x[f[0]], x[f[1]], x[f[2]]});
    tets.push_back({c, x[f[0]], x[f[2]], x[f[3]]});
  }
  return tets;
}

std::vector<Vec3> DistortedHex() {
  const double nat[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::srand(4);
  std::vector<Vec3> x;
  for (const auto& p : nat)
    x.push_back(Vec3(0.6 * p[0], 0.4 * p[1], 0.3 * p[2]) + 0.08 * Vec3::Random());
  return x;
}

TEST(SolidElements, SixRigidBodyModesOnDistortedElements) {
  const Eigen::Matrix3d R = RandomRotation(3);
  const Vec3 c(2.0, -1.0, 0.5);
  MatX K, M;
  Solid tet4(ElementType::kTet4, Place(kTet, R, c));
  tet4.Compute(K, M);
  ExpectSixRigidModes(K, tet4.x);
  Solid tet10(ElementType::kTet10, Place(Tet10(kTet, 0.05), R, c));
  tet10.Compute(K, M);
  ExpectSixRigidModes(K, tet10.x);
  for (Hex8Formulation f : {Hex8Formulation::kIncompatibleModes, Hex8Formulation::kFullIntegration}) {
    Solid hex(ElementType::kHex8, Place(DistortedHex(), R, c));
    hex.hex = f;
    hex.Compute(K, M);
    ExpectSixRigidModes(K, hex.x);
  }
}

void ExpectRigidMass(const Solid& s, const Mat6& ref, MassForm form) {
  MatX K, M;
  s.Compute(K, M, form);
  EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
  const MatX r = RigidModes(s.x, 3);
  const MatX got = r.transpose() * M * r;
  if (form == MassForm::kConsistent) {
    EXPECT_LT((got - ref).norm(), 1e-12 * ref.norm()) << got << "\n\n" << ref;
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
  } else {
    // lumped: diagonal, positive, total mass exact
    EXPECT_NEAR(got(0, 0), ref(0, 0), 1e-12 * ref(0, 0));
    EXPECT_EQ((M - MatX(M.diagonal().asDiagonal())).norm(), 0.0);
    EXPECT_GT(M.diagonal().minCoeff(), 0.0);
  }
}

TEST(SolidElements, ConsistentMassGivesExactRigidBodyInertia) {
  const Eigen::Matrix3d R = RandomRotation(8);
  const Vec3 c(0.5, 1.5, -2.0);
  const double rho = 7800.0;
  const std::vector<Vec3> tet = Place(kTet, R, c);
  const Mat6 tet_ref = TetsRigidMass({{tet[0], tet[1], tet[2], tet[3]}}, rho);
  const std::vector<Vec3> hex = Place(PlanarHex(), R, c);
  const Mat6 hex_ref = TetsRigidMass(HexTets(hex), rho);
  for (MassForm form : {MassForm::kConsistent, MassForm::kLumped}) {
    ExpectRigidMass(Solid(ElementType::kTet4, tet), tet_ref, form);
    ExpectRigidMass(Solid(ElementType::kTet10, Tet10(tet)), tet_ref, form);
    ExpectRigidMass(Solid(ElementType::kHex8, hex), hex_ref, form);
  }
}

// closed-form consistent mass of a straight-edged tet10 (rho V / 420 times:
// corner-corner 6 / 1, corner-midside -4 on its edges / -6 otherwise,
// midside 32, midside pairs sharing a corner 16, opposite 8); this checks the
// degree-4 exactness of the 14-point rule
TEST(SolidElements, Tet10ConsistentMassIsTheClosedForm) {
  Solid s(ElementType::kTet10, Tet10(kTet), 1.0, 0.3, 2.5);
  MatX K, M;
  s.Compute(K, M);
  const double v = (kTet[1] - kTet[0]).cross(kTet[2] - kTet[0]).dot(kTet[3] - kTet[0]) / 6.0;
  auto on_edge = [](int corner, int edge) {
    return kTet10EdgeCorners[edge][0] == corner || kTet10EdgeCorners[edge][1] == corner;
  };
  MatX ref = MatX::Zero(30, 30);
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) {
      double c = 0.0;
      if (i < 4 && j < 4) {
        c = i == j ? 6.0 : 1.0;
      } else if (i < 4 || j < 4) {
        const int corner = std::min(i, j), edge = std::max(i, j) - 4;
        c = on_edge(corner, edge) ? -4.0 : -6.0;
      } else if (i == j) {
        c = 32.0;
      } else {
        const int a = i - 4, b = j - 4;
        const bool share = on_edge(kTet10EdgeCorners[a][0], b) || on_edge(kTet10EdgeCorners[a][1], b);
        c = share ? 16.0 : 8.0;
      }
      for (int d = 0; d < 3; ++d) ref(3 * i + d, 3 * j + d) = 2.5 * v / 420.0 * c;
    }
  EXPECT_LT((M - ref).norm(), 1e-14 * ref.norm());
  // HRZ lumping: corners 1/36, midsides 4/27 of the mass
  s.Compute(K, M, MassForm::kLumped);
  for (int i = 0; i < 10; ++i)
    EXPECT_NEAR(M(3 * i, 3 * i), 2.5 * v * (i < 4 ? 1.0 / 36.0 : 4.0 / 27.0), 1e-14);
}

TEST(SolidElements, LumpedMassShares) {
  MatX K, M;
  Solid tet(ElementType::kTet4, kTet, 1.0, 0.3, 3.0);
  tet.Compute(K, M, MassForm::kLumped);
  const double v = (kTet[1] - kTet[0]).cross(kTet[2] - kTet[0]).dot(kTet[3] - kTet[0]) / 6.0;
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(M(i, i), 3.0 * v / 4.0, 1e-14);
  std::vector<Vec3> box;
  for (const auto& p : std::vector<Vec3>{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0},
                                         {0, 0, 3}, {2, 0, 3}, {2, 1, 3}, {0, 1, 3}})
    box.push_back(p);
  Solid hex(ElementType::kHex8, box, 1.0, 0.3, 3.0);
  hex.Compute(K, M, MassForm::kLumped);
  for (int i = 0; i < 24; ++i) EXPECT_NEAR(M(i, i), 3.0 * 6.0 / 8.0, 1e-13);
}

// A tapered hexahedron (bottom face 2 x 1, top face 1 x 1, height 1): the
// lumped mass keeps the mass and the centre of mass of the element, z_c =
// 4/9 (HRZ lumping, the former hex8 lumping, put it at 5/12).
TEST(SolidElements, Hex8LumpedMassKeepsTheCentreOfMassOfATaperedElement) {
  const std::vector<Vec3> x = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  Solid hex(ElementType::kHex8, x, 1.0, 0.3, 3.0);
  MatX K, M;
  hex.Compute(K, M, MassForm::kLumped);
  EXPECT_EQ((M - MatX(M.diagonal().asDiagonal())).norm(), 0.0);
  EXPECT_GT(M.diagonal().minCoeff(), 0.0);
  // volume 1.5; first moments int x dV = 7/6, int y dV = 3/4, int z dV = 2/3
  const MatX r = RigidModes(x, 3);
  const MatX got = r.transpose() * M * r;
  EXPECT_NEAR(got(0, 0), 3.0 * 1.5, 1e-13);
  // the translation-rotation block of R^T M R is -m skew(c)
  const Vec3 c = Vec3(got(5, 1), got(3, 2), got(4, 0)) / got(0, 0);
  EXPECT_NEAR(c.x(), 7.0 / 9.0, 1e-14);
  EXPECT_NEAR(c.y(), 0.5, 1e-14);
  EXPECT_NEAR(c.z(), 4.0 / 9.0, 1e-14);
}

// prescribes u = u0 + A x on the boundary nodes, solves for the interior and
// checks that the interior nodes follow the same linear field
void PatchTest(ElementType type, const std::vector<Vec3>& x,
               const std::vector<std::vector<int>>& elements, const std::vector<bool>& interior,
               Hex8Formulation f = Hex8Formulation::kIncompatibleModes) {
  const double error = testing::PatchTestError(x, elements, interior, [&](const std::vector<Vec3>& xe) {
    Solid s(type, xe, 1.0e3, 0.25, 1.0);
    s.hex = f;
    MatX ke, me;
    s.Compute(ke, me);
    return ke;
  });
  EXPECT_LT(error, 1e-12) << TypeName(type);
}

// MacNeal & Harder (1985) seven-element patch in the unit cube
TEST(SolidElements, Hex8PatchTestOnDistortedCube) {
  std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1},
                         {0.249, 0.342, 0.192}, {0.826, 0.288, 0.288}, {0.850, 0.649, 0.263},
                         {0.273, 0.750, 0.230}, {0.320, 0.186, 0.643}, {0.677, 0.305, 0.683},
                         {0.788, 0.693, 0.644}, {0.165, 0.745, 0.702}};
  std::vector<std::vector<int>> elements = {{8, 9, 10, 11, 12, 13, 14, 15}};
  for (const auto& f : kHexFace) {
    std::vector<int> e = {f[0], f[1], f[2], f[3], f[0] + 8, f[1] + 8, f[2] + 8, f[3] + 8};
    // orient: the inner face must lie on the side of positive zeta
    const Vec3 n = (x[e[2]] - x[e[0]]).cross(x[e[3]] - x[e[1]]);
    const Vec3 up = (x[e[4]] + x[e[6]] - x[e[0]] - x[e[2]]);
    if (n.dot(up) < 0.0) std::rotate(e.begin(), e.begin() + 4, e.end());
    elements.push_back(e);
  }
  std::vector<bool> interior(16, false);
  for (int i = 8; i < 16; ++i) interior[i] = true;
  PatchTest(ElementType::kHex8, x, elements, interior, Hex8Formulation::kIncompatibleModes);
  PatchTest(ElementType::kHex8, x, elements, interior, Hex8Formulation::kFullIntegration);
}

// twelve tetrahedra from the cube faces to an off-centre interior node;
// tet10 with a node on every edge, interior ones included
TEST(SolidElements, TetPatchTestsOnDistortedCube) {
  std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0.38, 0.61, 0.27}};
  std::vector<std::vector<int>> tets;
  for (const auto& f : kHexFace)
    for (const auto& t : {std::array<int, 3>{f[0], f[1], f[2]}, std::array<int, 3>{f[0], f[2], f[3]}}) {
      std::vector<int> e = {t[0], t[1], t[2], 8};
      if ((x[e[1]] - x[e[0]]).cross(x[e[2]] - x[e[0]]).dot(x[e[3]] - x[e[0]]) < 0.0)
        std::swap(e[1], e[2]);
      tets.push_back(e);
    }
  std::vector<bool> interior(9, false);
  interior[8] = true;
  PatchTest(ElementType::kTet4, x, tets, interior);

  std::map<std::pair<int, int>, int> mid;
  std::vector<std::vector<int>> tet10;
  for (const auto& t : tets) {
    std::vector<int> e = t;
    for (const auto& edge : kTet10EdgeCorners) {
      const int a = t[edge[0]], b = t[edge[1]];
      const std::pair<int, int> key(std::min(a, b), std::max(a, b));
      if (!mid.count(key)) {
        mid[key] = static_cast<int>(x.size());
        x.push_back(0.5 * (x[a] + x[b]));
        interior.push_back(b == 8 || a == 8);
      }
      e.push_back(mid[key]);
    }
    tet10.push_back(e);
  }
  PatchTest(ElementType::kTet10, x, tet10, interior);
}

// pure bending of a 2 x 0.5 x 0.4 box (nu = 0): nodal u = kappa x z,
// w = -kappa x^2 / 2; exact energy E kappa^2 I L / 2. Incompatible modes are
// exact, full integration locks (parasitic shear).
TEST(SolidElements, Hex8IncompatibleModesBendWithoutLocking) {
  const double a = 2.0, b = 0.5, c = 0.4, E = 1.0e4, kappa = 0.01;
  const double nat[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::vector<Vec3> x;
  for (const auto& p : nat) x.emplace_back(0.5 * a * p[0], 0.5 * b * p[1], 0.5 * c * p[2]);
  Eigen::VectorXd u(24);
  for (int i = 0; i < 8; ++i) u.segment<3>(3 * i) << kappa * x[i].x() * x[i].z(), 0.0,
      -0.5 * kappa * x[i].x() * x[i].x();
  const double exact = 0.5 * E * kappa * kappa * (b * c * c * c / 12.0) * a;
  MatX K, M;
  Solid im(ElementType::kHex8, x, E, 0.0);
  im.Compute(K, M);
  EXPECT_NEAR(0.5 * u.dot(K * u), exact, 1e-12 * exact);
  Solid full = im;
  full.hex = Hex8Formulation::kFullIntegration;
  full.Compute(K, M);
  // shear energy (G / E) (a / c)^2 = 12.5 times the bending energy
  EXPECT_NEAR(0.5 * u.dot(K * u), 13.5 * exact, 1e-10 * exact);
  // selectively reduced (Abaqus's C3D8): the normal strains at the points
  // become eps_ii + (mean dilatation - dilatation) / 3; here the dilatation
  // kappa z has mean 0, so (eps_xx, eps_yy, eps_zz) = kappa z (2/3, -1/3,
  // -1/3), whose energy at nu = 0 is 2/3 of the bending energy; the
  // parasitic shear stays
  Solid sel = im;
  sel.hex = Hex8Formulation::kSelectiveReduced;
  sel.Compute(K, M);
  EXPECT_NEAR(0.5 * u.dot(K * u), (2.0 / 3.0 + 12.5) * exact, 1e-10 * exact);
  ExpectSixRigidModes(K, x);
  // a homogeneous strain (any nu) stores the same energy as with full integration
  Eigen::VectorXd h(24);
  for (int i = 0; i < 8; ++i) h.segment<3>(3 * i) << 1e-3 * x[i].x() + 2e-4 * x[i].y(), -5e-4 * x[i].y(), 3e-4 * x[i].z();
  Solid sel3(ElementType::kHex8, x, E, 0.3), full3 = sel3;
  sel3.hex = Hex8Formulation::kSelectiveReduced;
  full3.hex = Hex8Formulation::kFullIntegration;
  MatX Ks, Kf;
  sel3.Compute(Ks, M);
  full3.Compute(Kf, M);
  EXPECT_NEAR(h.dot(Ks * h), h.dot(Kf * h), 1e-12 * h.dot(Kf * h));
}

void ExpectInputError(const Solid& s, const std::string& what, const Material* mat = nullptr) {
  MatX K, M;
  ExpectInputErrorWith([&] { s.Compute(K, M, MassForm::kConsistent, mat); },
                       {"part.bdf:7: " + std::string(TypeName(s.element.type)) + " 9", what});
}

TEST(SolidElements, InvertedOrDegenerateElementsAreInputErrors) {
  std::vector<Vec3> t = kTet;
  std::swap(t[1], t[2]);
  ExpectInputError(Solid(ElementType::kTet4, t), "inverted");
  ExpectInputError(Solid(ElementType::kTet10, Tet10(t)), "inverted");
  std::vector<Vec3> flat = kTet;
  flat[3] = 0.3 * flat[1] + 0.5 * flat[2];
  ExpectInputError(Solid(ElementType::kTet4, flat), "degenerate");
  // a mid-edge node pulled past the quarter point folds the tet10
  std::vector<Vec3> bad = Tet10(kTet);
  bad[4] = kTet[0] + 0.1 * (kTet[1] - kTet[0]);
  ExpectInputError(Solid(ElementType::kTet10, bad), "inverted");
  std::vector<Vec3> hex = PlanarHex();
  std::rotate(hex.begin(), hex.begin() + 4, hex.end());
  ExpectInputError(Solid(ElementType::kHex8, hex), "inverted");
  // a corner pushed through the opposite face (concave, negative corner Jacobian)
  hex = PlanarHex();
  hex[6] = Vec3(0.0, 0.0, 0.1);
  ExpectInputError(Solid(ElementType::kHex8, hex), "inverted");
  hex = PlanarHex();
  for (int i = 4; i < 8; ++i) hex[i] = hex[i - 4];
  ExpectInputError(Solid(ElementType::kHex8, hex), "degenerate");
  // material
  const Solid ok(ElementType::kHex8, PlanarHex());
  Material m = ok.material;
  m.E = 0.0;
  ExpectInputError(ok, "Young's modulus", &m);
  m = ok.material;
  m.nu = 0.5;
  ExpectInputError(ok, "Poisson", &m);
  ElementInput in;
  in.element = &ok.element;
  in.x = ok.x.data();
  MatX K, M;
  ExpectInputErrorWith([&] { SolidHex8Matrices(in, K, M); },
                       {"part.bdf:7: 8-node hexahedron 9: missing material"});
}

}  // namespace
}  // namespace flexmb::fe
