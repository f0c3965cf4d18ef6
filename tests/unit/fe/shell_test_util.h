#pragma once
// Helpers shared by the shell element unit tests: element set-up, rigid-body
// modes, analytic mass properties of a flat polygonal plate, and a small
// dense assembly for patch tests.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/shell_quad4.h"
#include "flexmb/fe/elements/shell_tria3.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe::testing {

// A shell element with its section and material (owned here).
struct ShellFixture {
  Element element;
  Material material;
  ShellSection section;
  std::vector<Vec3> x;

  ShellFixture(ElementType type, std::vector<Vec3> nodes, double t = 0.1, double E = 2.1e11,
               double nu = 0.3, double rho = 7800.0, double nsm = 0.0) {
    element.id = 7;
    element.type = type;
    element.origin = {"plate.bdf", 12};
    for (size_t i = 0; i < nodes.size(); ++i) element.nodes.push_back(static_cast<int>(i));
    material.id = 1;
    material.E = E;
    material.nu = nu;
    material.rho = rho;
    section.id = 1;
    section.material = 0;
    section.thickness = t;
    section.nsm = nsm;
    x = std::move(nodes);
  }

  ElementInput Input(MassForm form = MassForm::kConsistent) const {
    ElementInput in;
    in.element = &element;
    in.x = x.data();
    in.material = &material;
    in.shell = &section;
    in.mass_form = form;
    return in;
  }

  void Compute(MatX& K, MatX& M, MassForm form = MassForm::kConsistent) const {
    Traits(element.type).matrices(Input(form), K, M);
  }
};

// Rigid-body mass matrix [[m I, -skew(S)], [skew(S), J_O]] of a flat plate
// (polygon `poly` in local plane coordinates, fan-triangulated from vertex 0),
// placed at p = c0 + R (x, y, z), occupying z in [zc - t/2, zc + t/2], with
// density rho and non-structural mass nsm per area at z = zc.
inline Eigen::Matrix<double, 6, 6> PlateRigidMass(const std::vector<Eigen::Vector2d>& poly,
                                                  const Eigen::Matrix3d& R, const Vec3& c0,
                                                  double t, double zc, double rho, double nsm) {
  double area = 0.0;
  Eigen::Vector2d s1 = Eigen::Vector2d::Zero();
  Eigen::Matrix2d s2 = Eigen::Matrix2d::Zero();
  for (size_t k = 1; k + 1 < poly.size(); ++k) {
    const Eigen::Vector2d a = poly[0], b = poly[k], c = poly[k + 1];
    const double ak = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    const Eigen::Vector2d sum = a + b + c;
    area += ak;
    s1 += ak * sum / 3.0;
    s2 += ak / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  // moments per unit mass density per area of the mid-surface, local frame
  Vec3 m1(s1.x(), s1.y(), zc * area);
  Eigen::Matrix3d m2;
  m2 << s2(0, 0), s2(0, 1), zc * s1.x(), s2(1, 0), s2(1, 1), zc * s1.y(), zc * s1.x(), zc * s1.y(),
      zc * zc * area;
  const double mu = rho * t + nsm;
  const double mass = mu * area;
  Vec3 f1 = mu * m1;
  Eigen::Matrix3d f2 = mu * m2;
  f2(2, 2) += rho * t * t * t / 12.0 * area;
  // to the basic frame
  const Vec3 s = mass * c0 + R * f1;
  const Eigen::Matrix3d q = mass * c0 * c0.transpose() + c0 * (R * f1).transpose() +
                            (R * f1) * c0.transpose() + R * f2 * R.transpose();
  Eigen::Matrix<double, 6, 6> out;
  out.block<3, 3>(0, 0) = mass * Eigen::Matrix3d::Identity();
  out.block<3, 3>(0, 3) = -Skew(s);
  out.block<3, 3>(3, 0) = Skew(s);
  out.block<3, 3>(3, 3) = q.trace() * Eigen::Matrix3d::Identity() - q;
  return out;
}

// Polygon p (local plane coordinates) placed at c0 + R (x, y, h), h the
// optional heights off the plane (warping).
inline std::vector<Vec3> Place(const std::vector<Eigen::Vector2d>& p, const Eigen::Matrix3d& R,
                               const Vec3& c0, const std::vector<double>& h = {}) {
  std::vector<Vec3> x;
  for (size_t i = 0; i < p.size(); ++i)
    x.push_back(c0 + R * Vec3(p[i].x(), p[i].y(), h.empty() ? 0.0 : h[i]));
  return x;
}

// Area of a polygon given in plane coordinates [m^2].
inline double PolygonArea(const std::vector<Eigen::Vector2d>& poly) {
  double a = 0.0;
  for (size_t k = 0; k < poly.size(); ++k) {
    const Eigen::Vector2d &p = poly[k], &q = poly[(k + 1) % poly.size()];
    a += 0.5 * (p.x() * q.y() - p.y() * q.x());
  }
  return a;
}

// The element on nodes x (any rotation, offset, warping): zero strain energy
// in the six rigid motions, exactly six zero eigenvalues, positive definite
// consistent mass.
inline void ExpectRigidBodyModes(const ShellFixture& f) {
  MatX K, M;
  f.Compute(K, M);
  const MatX r = RigidModes(f.x, 6);
  EXPECT_LT((K * r).norm(), 1e-12 * K.norm() * r.norm());
  ExpectSixRigidModes(K, f.x, 6);
  EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
}

// Consistent mass of the plate `poly` (rotated by R to c0, thickness t,
// offset along the normal): R^T M R equals the rigid-body mass matrix of the
// plate, with its non-structural mass and rotary inertia, exactly.
inline void ExpectExactRigidBodyMass(ElementType type, const std::vector<Eigen::Vector2d>& poly,
                                     const Eigen::Matrix3d& R, const Vec3& c0, double offset) {
  const double t = 0.08, rho = 2700.0, nsm = 3.5;
  ShellFixture f(type, Place(poly, R, c0), t, 7e10, 0.33, rho, nsm);
  f.element.shell_offset = offset;
  MatX K, M;
  f.Compute(K, M);
  const MatX r = RigidModes(f.x, 6);
  const Eigen::Matrix<double, 6, 6> expected = PlateRigidMass(poly, R, c0, t, offset, rho, nsm);
  const MatX got = r.transpose() * M * r;
  EXPECT_LT((got - expected).norm(), 1e-12 * expected.norm()) << got << "\n\n" << expected;
}

// Lumped mass of a flat element without offset: diagonal and positive on
// the translations, one 3 x 3 rotation block per node, exact total mass and
// first moment (the top rows of the rigid-body mass); on the rotations
// rho t^3 / 12 per area about the in-plane axes and the drilling inertia
// (shell_drilling.h, at most rho t^3 / 12 per area) about the normal.
inline void ExpectLumpedMass(ElementType type, const std::vector<Eigen::Vector2d>& poly,
                             const Eigen::Matrix3d& R, const Vec3& c0) {
  const double t = 0.08, rho = 2700.0, nsm = 3.5;
  ShellFixture f(type, Place(poly, R, c0), t, 7e10, 0.33, rho, nsm);
  MatX K, M;
  f.Compute(K, M, MassForm::kLumped);
  MatX blocks = MatX::Zero(M.rows(), M.cols());
  for (size_t i = 0; i < poly.size(); ++i) {
    blocks.diagonal().segment<3>(6 * i) = M.diagonal().segment<3>(6 * i);
    blocks.block<3, 3>(6 * i + 3, 6 * i + 3) = M.block<3, 3>(6 * i + 3, 6 * i + 3);
  }
  EXPECT_LT((M - blocks).norm(), 1e-12 * M.norm());
  EXPECT_GT(M.diagonal().minCoeff(), 0.0);
  const MatX r = RigidModes(f.x, 6);
  const Eigen::Matrix<double, 6, 6> expected = PlateRigidMass(poly, R, c0, t, 0.0, rho, nsm);
  EXPECT_LT(((r.transpose() * M * r).topRows(3) - expected.topRows(3)).norm(),
            1e-12 * expected.norm());
  // rotation block in the element's axes (normal R e3): diag(a, a, b)
  double in_plane = 0.0, drilling = 0.0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Matrix3d b = R.transpose() * M.block<3, 3>(6 * i + 3, 6 * i + 3) * R;
    EXPECT_NEAR(b(0, 0), b(1, 1), 1e-12 * b.norm());
    EXPECT_LT((b - Eigen::Matrix3d(b.diagonal().asDiagonal())).norm(), 1e-12 * b.norm());
    in_plane += b(0, 0);
    drilling += b(2, 2);
  }
  EXPECT_NEAR(in_plane, rho * t * t * t / 12.0 * PolygonArea(poly), 1e-12 * in_plane);
  EXPECT_LE(drilling, in_plane * (1.0 + 1e-12));
}

// Renumbering the nodes cyclically by `shift` only permutes K and M.
inline void ExpectInvariantToCyclicNodeOrder(ElementType type, const std::vector<Vec3>& x,
                                             int shift) {
  const int n = static_cast<int>(x.size());
  ShellFixture f(type, x, 0.03);
  MatX K, M;
  f.Compute(K, M);
  std::vector<Vec3> y;
  for (int i = 0; i < n; ++i) y.push_back(x[(i + shift) % n]);
  ShellFixture g(type, y, 0.03);
  MatX K2, M2;
  g.Compute(K2, M2);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const int pa = (a + n - shift) % n, pb = (b + n - shift) % n;
      EXPECT_LT((K.block<6, 6>(6 * a, 6 * b) - K2.block<6, 6>(6 * pa, 6 * pb)).norm(),
                1e-10 * K.norm());
      EXPECT_LT((M.block<6, 6>(6 * a, 6 * b) - M2.block<6, 6>(6 * pa, 6 * pb)).norm(),
                1e-12 * M.norm());
    }
}

// Dense assembly of shell elements (6 dof per node) given connectivity.
struct DensePatch {
  std::vector<Vec3> x;
  std::vector<std::vector<int>> elements;
  double t = 0.1, E = 1.0e6, nu = 0.25;

  MatX Stiffness() const {
    return DenseStiffness(static_cast<int>(x.size()), 6, elements, [&](const std::vector<int>& conn) {
      std::vector<Vec3> xe;
      for (int i : conn) xe.push_back(x[i]);
      ShellFixture f(conn.size() == 4 ? ElementType::kQuad4 : ElementType::kTria3, xe, t, E, nu);
      MatX ke, me;
      f.Compute(ke, me);
      return ke;
    });
  }
};

// MacNeal & Harder (1985) patch: rectangle 0.24 x 0.12, four interior nodes.
struct Patch {
  std::vector<Eigen::Vector2d> p = {{0.0, 0.0},    {0.24, 0.0},  {0.24, 0.12}, {0.0, 0.12},
                                    {0.04, 0.02},  {0.18, 0.03}, {0.16, 0.08}, {0.08, 0.08}};
  std::vector<std::vector<int>> quads = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7},
                                         {4, 5, 6, 7}};
  std::vector<std::vector<int>> Trias() const {
    std::vector<std::vector<int>> out;
    for (const auto& q : quads) {
      out.push_back({q[0], q[1], q[2]});
      out.push_back({q[0], q[2], q[3]});
    }
    return out;
  }
};

// equivalent nodal loads on the boundary corners of the patch from a
// constant resultant: `vec(n)` is the traction (or moment) vector per length
inline std::vector<Eigen::Vector2d> EdgeLoads(const Patch& patch,
                                       const std::function<Eigen::Vector2d(Eigen::Vector2d)>& vec) {
  std::vector<Eigen::Vector2d> f(4, Eigen::Vector2d::Zero());
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector2d a = patch.p[k], b = patch.p[(k + 1) % 4];
    const double len = (b - a).norm();
    const Eigen::Vector2d n = Eigen::Vector2d((b - a).y(), -(b - a).x()) / len;
    f[k] += 0.5 * len * vec(n);
    f[(k + 1) % 4] += 0.5 * len * vec(n);
  }
  return f;
}

// Runs the patch with boundary values from a field (local u v w rx ry rz at
// a point), checks interior nodes reproduce it and returns the local nodal
// forces of the four corners.
inline std::vector<Eigen::Matrix<double, 6, 1>> RunPatch(
    const Patch& patch, const std::vector<std::vector<int>>& elements,
    const std::function<Eigen::Matrix<double, 6, 1>(Eigen::Vector2d)>& field, double tol) {
  const Eigen::Matrix3d R = RandomRotation(11);
  const Vec3 c0(0.7, -0.4, 1.1);
  DensePatch dp;
  dp.t = 0.001;
  dp.E = 1e6;
  dp.nu = 0.25;
  for (const auto& q : patch.p) dp.x.push_back(c0 + R * Vec3(q.x(), q.y(), 0.0));
  dp.elements = elements;
  const MatX k = dp.Stiffness();
  const int n = static_cast<int>(patch.p.size());
  Eigen::VectorXd exact(6 * n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix<double, 6, 1> l = field(patch.p[i]);
    exact.segment<3>(6 * i) = R * l.head<3>();
    exact.segment<3>(6 * i + 3) = R * l.tail<3>();
  }
  std::vector<bool> fixed(6 * n, false);
  for (int i = 0; i < 4 * 6; ++i) fixed[i] = true;
  Eigen::VectorXd start = exact;
  start.tail(6 * (n - 4)).setZero();
  const Eigen::VectorXd u = SolvePrescribed(k, fixed, start);
  // rotations weighted by the patch size for a dimensionally consistent norm
  Eigen::VectorXd err = u - exact, ref = exact;
  for (int i = 0; i < n; ++i) {
    err.segment<3>(6 * i + 3) *= 0.24;
    ref.segment<3>(6 * i + 3) *= 0.24;
  }
  EXPECT_LT(err.norm(), tol * ref.norm()) << err.transpose();
  const Eigen::VectorXd f = k * u;
  std::vector<Eigen::Matrix<double, 6, 1>> out(4);
  for (int i = 0; i < 4; ++i) {
    out[i].head<3>() = R.transpose() * f.segment<3>(6 * i);
    out[i].tail<3>() = R.transpose() * f.segment<3>(6 * i + 3);
  }
  return out;
}

// the patch tests' fields (local u v w rx ry rz at a point): a constant
// membrane strain, u = 1e-3 (x + y / 2), v = 1e-3 (y + x / 2): eps = 1e-3
// (1, 1, 1), omega = 0
inline Eigen::Matrix<double, 6, 1> PatchMembraneField(Eigen::Vector2d p) {
  Eigen::Matrix<double, 6, 1> l = Eigen::Matrix<double, 6, 1>::Zero();
  l(0) = 1e-3 * (p.x() + 0.5 * p.y());
  l(1) = 1e-3 * (p.y() + 0.5 * p.x());
  return l;
}

// and a constant curvature, w = 1e-3 (x^2 + x y + y^2) / 2 with Kirchhoff
// rotations rx = dw/dy, ry = -dw/dx
inline Eigen::Matrix<double, 6, 1> PatchBendingField(Eigen::Vector2d p) {
  Eigen::Matrix<double, 6, 1> l = Eigen::Matrix<double, 6, 1>::Zero();
  l(2) = 1e-3 * (p.x() * p.x() + p.x() * p.y() + p.y() * p.y()) / 2.0;
  l(3) = 1e-3 * (p.y() + 0.5 * p.x());
  l(4) = -1e-3 * (p.x() + 0.5 * p.y());
  return l;
}

inline void MembranePatch(const std::vector<std::vector<int>>& elements) {
  const Patch patch;
  const auto field = PatchMembraneField;
  const double c = 1e6 * 0.001 / (1.0 - 0.0625);
  const Eigen::Vector3d nres = c * Eigen::Vector3d(1e-3 * 1.25, 1e-3 * 1.25, 1e-3 * 0.375);
  const auto loads = EdgeLoads(patch, [&](Eigen::Vector2d n) {
    return Eigen::Vector2d(nres(0) * n.x() + nres(2) * n.y(), nres(2) * n.x() + nres(1) * n.y());
  });
  const auto f = RunPatch(patch, elements, field, 1e-9);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(f[i](0), loads[i].x(), 1e-10 * nres.norm());
    EXPECT_NEAR(f[i](1), loads[i].y(), 1e-10 * nres.norm());
    EXPECT_NEAR(f[i].tail<4>().norm(), 0.0, 1e-10 * nres.norm());
  }
}

inline void BendingPatch(const std::vector<std::vector<int>>& elements) {
  const Patch patch;
  const auto field = PatchBendingField;
  // curvatures of beta = (ry, -rx): (-1e-3, -1e-3, -1e-3); M = D kappa
  const double d = 1e6 * 1e-9 / 12.0 / (1.0 - 0.0625);
  const Eigen::Vector3d m = d * Eigen::Vector3d(-1e-3 * 1.25, -1e-3 * 1.25, -1e-3 * 0.375);
  const auto loads = EdgeLoads(patch, [&](Eigen::Vector2d n) {
    return Eigen::Vector2d(m(0) * n.x() + m(2) * n.y(), m(2) * n.x() + m(1) * n.y());
  });
  const auto f = RunPatch(patch, elements, field, 1e-9);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(f[i](4), loads[i].x(), 1e-9 * m.norm());   // on ry = beta_x
    EXPECT_NEAR(f[i](3), -loads[i].y(), 1e-9 * m.norm());  // on rx = -beta_y
    EXPECT_NEAR(f[i].head<3>().norm() + std::abs(f[i](5)), 0.0, 1e-9 * m.norm());
  }
}

// an InputError naming the fixture's element (plate.bdf:12, shell 7) and `what`
inline void ExpectInputError(const ShellFixture& f, const std::string& what) {
  MatX K, M;
  ExpectInputErrorWith([&] { f.Compute(K, M); }, {"plate.bdf:12", "shell 7", what});
}

// a missing material is named with the element: "plate.bdf:12: <type> 7: missing material"
inline void ExpectMissingMaterialError(const ShellFixture& f) {
  ElementInput in = f.Input();
  in.material = nullptr;
  MatX K, M;
  ExpectInputErrorWith(
      [&] {
        if (f.element.type == ElementType::kQuad4)
          ShellQuad4Matrices(in, K, M);
        else
          ShellTria3Matrices(in, K, M);
      },
                       {"plate.bdf:12: " + std::string(TypeName(f.element.type)) +
                        " 7: missing material"});
}

}  // namespace flexmb::fe::testing
