// The 4-node shear panel (fe/elements/shear4.h) against closed forms:
// - a rectangle a x b in simple shear (u = gamma y) stores G t a b gamma^2 /
//   2, and a uniform extension or a rigid motion stores nothing;
// - a parallelogram with edge directions d_a, d_b under any uniform strain
//   stores t A (S : eps)^2 / (2 S : C^-1 : S), S = d_a d_b^T + d_b d_a^T
//   (the uniform stress with no normal traction on its edges);
// - the stress of simple shear is (0, 0, G gamma) at both surfaces;
// - the mass is (rho t + nsm) A in each direction, none on rotations;
// - the geometric stiffness is symmetric, zero without displacement, and
//   under a uniform pre-shear tau equals t int grad^T sigma grad (a single
//   square: by hand);
// and the Nastran cards: a panel that is not a parallelogram warns once,
// PSHEAR's F1 / F2, a CQUAD4 on a PSHEAR and a CSHEAR on a PSHELL are
// errors naming the card.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/elements/element_common.h"
#include "flexmb/fe/elements/shear4.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/fe_io/nastran/nastran_writer.h"
#include "flexmb/reduction/element_input.h"
#include "tests/unit/fe/fe_test_models.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::fe {
namespace shear4_test {

constexpr double kE = 7e10, kNu = 0.33, kRho = 2700.0, kT = 0.002, kNsm = 0.5;
constexpr double kG = kE / (2 * (1 + kNu));

// one panel on the corners x (counter-clockwise), PSHEAR-like section
Mesh Panel(const std::vector<Vec3>& x) {
  Mesh m;
  const int mat = testing::AddMaterial(m, kE, kNu, kRho);
  ShellSection s;
  s.id = 1;
  s.material = mat;
  s.thickness = kT;
  s.nsm = kNsm;
  m.shell_sections.push_back(s);
  std::vector<int> nodes;
  for (const Vec3& p : x) nodes.push_back(testing::AddNode(m, p));
  testing::AddElement(m, kShear4, 0, nodes);
  return m;
}

void Matrices(const Mesh& m, MatX& K, MatX& M, MassForm form = MassForm::kConsistent) {
  std::vector<Vec3> x;
  ElementInput in = reduction::ResolveElementInput(m, m.elements[0], x);
  in.mass_form = form;
  ElementMatrices(in, K, M);
}

// the element DOF (24) of the displacement field u(x) at the corners
Eigen::VectorXd Field(const Mesh& m, const std::function<Vec3(const Vec3&)>& u) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(24);
  for (int k = 0; k < 4; ++k) v.segment<3>(6 * k) = u(m.nodes[m.elements[0].nodes[k]].x);
  return v;
}

TEST(Shear4, RectangleStoresTheShearEnergyOnly) {
  const double a = 1.2, b = 0.7, gamma = 1e-3;
  // tilted out of the x-y plane: the panel's frame is its own
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Mesh m = Panel({r * Vec3(0, 0, 0), r * Vec3(a, 0, 0), r * Vec3(a, b, 0), r * Vec3(0, b, 0)});
  MatX K, M;
  Matrices(m, K, M);
  auto energy = [&](const std::function<Vec3(const Vec3&)>& u) {
    const Eigen::VectorXd v = Field(m, u);
    return 0.5 * v.dot(K * v);
  };
  const double shear = energy([&](const Vec3& x) { return Vec3(r * Vec3(gamma * (r.transpose() * x).y(), 0, 0)); });
  const double exact = 0.5 * kG * kT * a * b * gamma * gamma;
  EXPECT_NEAR(shear, exact, 1e-12 * exact);
  // the same shear split symmetrically
  EXPECT_NEAR(energy([&](const Vec3& x) {
                const Vec3 l = r.transpose() * x;
                return Vec3(r * Vec3(0.5 * gamma * l.y(), 0.5 * gamma * l.x(), 0));
              }),
              exact, 1e-12 * exact);
  // uniform extensions: no normal stress, no energy
  EXPECT_NEAR(energy([&](const Vec3& x) {
                const Vec3 l = r.transpose() * x;
                return Vec3(r * Vec3(1e-3 * l.x(), -4e-4 * l.y(), 0));
              }),
              0.0, 1e-12 * exact);
  // rigid motions (translation, rotation about any axis, as large as the
  // shear above): none
  for (int k = 0; k < 6; ++k) {
    const Vec3 e = gamma * Vec3::Unit(k % 3);
    const double rigid = k < 3 ? energy([&](const Vec3&) { return e; })
                               : energy([&](const Vec3& x) { return Vec3(e.cross(x)); });
    EXPECT_NEAR(rigid, 0.0, 1e-12 * exact) << k;
  }
  // no rotational stiffness (round-off through the rigid offsets of the
  // tilted corners, 1e-17 m off the plane) or inertia
  for (int n = 0; n < 4; ++n) {
    EXPECT_LT(K.middleRows(6 * n + 3, 3).cwiseAbs().maxCoeff(), 1e-14 * K.cwiseAbs().maxCoeff());
    EXPECT_EQ(M.middleRows(6 * n + 3, 3).cwiseAbs().maxCoeff(), 0.0);
  }
  // mass (rho t + nsm) a b in every direction, both mass forms
  for (MassForm form : {MassForm::kConsistent, MassForm::kLumped}) {
    MatX k2, m2;
    Matrices(m, k2, m2, form);
    for (int d = 0; d < 3; ++d) {
      double total = 0;
      for (int i = 0; i < 4; ++i) total += m2(6 * i + d, 6 * i + d);
      EXPECT_NEAR(total, (kRho * kT + kNsm) * a * b, 1e-12);
    }
  }
  // stress of simple shear: (0, 0, G gamma) at both surfaces
  std::vector<Vec3> x;
  const ElementInput in = reduction::ResolveElementInput(m, m.elements[0], x);
  MatX S;
  Eigen::Matrix3d axes;
  Shear4Stress(in, S, axes);
  const Eigen::VectorXd sigma = S * Field(m, [&](const Vec3& p) { return Vec3(r * Vec3(gamma * (r.transpose() * p).y(), 0, 0)); });
  for (int s = 0; s < 2; ++s) {
    EXPECT_NEAR(sigma(3 * s), 0.0, 1e-6 * kG * gamma);
    EXPECT_NEAR(sigma(3 * s + 1), 0.0, 1e-6 * kG * gamma);
    EXPECT_NEAR(sigma(3 * s + 2), kG * gamma, 1e-9 * kG * gamma);
  }
}

TEST(Shear4, ParallelogramStoresTheEdgeShearEnergyOfAnyUniformStrain) {
  // edges along d_a = x and d_b at 60 degrees
  const double a = 1.0, b = 0.8, skew = M_PI / 3;
  const Eigen::Vector2d da(1, 0), db(std::cos(skew), std::sin(skew));
  const Mesh m = Panel({Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a + b * db.x(), b * db.y(), 0), Vec3(b * db.x(), b * db.y(), 0)});
  MatX K, M;
  Matrices(m, K, M);
  const Eigen::Matrix2d s = da * db.transpose() + db * da.transpose();
  Eigen::Matrix3d compliance;
  compliance << 1 / kE, -kNu / kE, 0, -kNu / kE, 1 / kE, 0, 0, 0, 1 / kG;
  // the compliance of the edge-shear stress by hand: with S = d_a d_b^T +
  // d_b d_a^T, S : C^-1 : S = (2 / E) ((1 + nu) + (1 - nu) cos^2 theta),
  // theta the angle between the edges (1 / G for a rectangle); checked
  // against the Voigt product
  const Eigen::Vector3d sv(s(0, 0), s(1, 1), s(0, 1));
  const double c = 2.0 / kE * ((1 + kNu) + (1 - kNu) * std::cos(skew) * std::cos(skew)), area = a * b * std::sin(skew);
  EXPECT_NEAR(sv.dot(compliance * sv), c, 1e-12 * c);
  for (const Eigen::Matrix2d& eps : {Eigen::Matrix2d((Eigen::Matrix2d() << 1e-3, 2e-4, 2e-4, -5e-4).finished()),
                                     Eigen::Matrix2d((Eigen::Matrix2d() << 0, 1e-3, 1e-3, 0).finished())}) {
    const Eigen::VectorXd v = Field(m, [&](const Vec3& x) {
      const Eigen::Vector2d u = eps * x.head<2>();
      return Vec3(u.x(), u.y(), 0);
    });
    const double g = (s.cwiseProduct(eps)).sum();
    const double exact = 0.5 * kT * area * g * g / c;
    EXPECT_NEAR(0.5 * v.dot(K * v), exact, 1e-12 * exact);
  }
}

TEST(Shear4, GeometricStiffnessOfAPreShearedSquare) {
  const double a = 0.5, gamma = 1e-3;
  const Mesh m = Panel({Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a, a, 0), Vec3(0, a, 0)});
  std::vector<Vec3> x;
  const ElementInput in = reduction::ResolveElementInput(m, m.elements[0], x);
  MatX KG;
  Shear4GeometricStiffness(in, Eigen::VectorXd::Zero(24), KG);
  EXPECT_EQ(KG.cwiseAbs().maxCoeff(), 0.0);
  const Eigen::VectorXd u = Field(m, [&](const Vec3& p) { return Vec3(gamma * p.y(), 0, 0); });
  Shear4GeometricStiffness(in, u, KG);
  EXPECT_LT((KG - KG.transpose()).cwiseAbs().maxCoeff(), 1e-12 * KG.cwiseAbs().maxCoeff());
  // a transverse "twist" w = x y of the pre-sheared square: tau t int 2 w_x w_y dA
  // = tau t int 2 y x dA = tau t a^4 / 2 (twice the energy)
  const double tau = kG * gamma;
  const Eigen::VectorXd w = Field(m, [&](const Vec3& p) { return Vec3(0, 0, p.x() * p.y()); });
  EXPECT_NEAR(w.dot(KG * w), tau * kT * std::pow(a, 4) / 2, 1e-9 * tau * kT * std::pow(a, 4));
}

TEST(Shear4, NastranCardsAndTheirErrors) {
  const std::string grids = "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,1.,1.,0.\nGRID,4,,0.,1.,0.\nGRID,5,,1.5,1.,0.\n";
  const std::string mat = "MAT1,1,7.e10,,0.33,2700.\n";
  {
    io::testing::WarningCapture warnings;
    const Mesh m = io::ReadNastran(io::testing::WriteScratch(
        "shear_ok.bdf", grids + mat + "PSHEAR,7,1,0.002,0.5\nCSHEAR,1,7,1,2,3,4\n"));
    ASSERT_EQ(m.elements.size(), 1u);
    EXPECT_EQ(m.elements[0].type, kShear4);
    EXPECT_EQ(m.shell_sections[0].thickness, 0.002);
    EXPECT_EQ(m.shell_sections[0].nsm, 0.5);
    EXPECT_EQ(warnings.Count("not parallelograms"), 0);
    const Mesh t = io::ReadNastran(io::testing::WriteScratch(
        "shear_trapezoid.bdf", grids + mat + "PSHEAR,7,1,0.002\nCSHEAR,1,7,1,2,5,4\nCSHEAR,2,7,1,2,5,4\n"));
    EXPECT_EQ(warnings.Count("not parallelograms"), 1);
  }
  io::testing::ExpectBadFiles(
      {{"pshear_f1.bdf", grids + mat + "PSHEAR,7,1,0.002,,0.5\nCSHEAR,1,7,1,2,3,4\n", ":7: PSHEAR 7: ",
        {"F1 != 0", "CROD"}},
       {"cquad4_pshear.bdf", grids + mat + "PSHEAR,7,1,0.002\nCQUAD4,1,7,1,2,3,4\n", ":8: CQUAD4 1: ",
        {"PSHEAR", "PSHELL"}},
       {"cshear_pshell.bdf", grids + mat + "PSHELL,7,1,0.002,1\nCSHEAR,1,7,1,2,3,4\n", ":8: CSHEAR 1: ",
        {"PSHELL", "needs a PSHEAR"}}},
      [](const std::string& p) { io::ReadNastran(p); });
  // neither writer has a shear panel: both refuse it, naming the element
  const Mesh m = io::ReadNastran(io::testing::WriteScratch(
      "shear_write.bdf", grids + mat + "PSHEAR,7,1,0.002\nCSHEAR,1,7,1,2,3,4\n"));
  io::testing::ExpectContains(io::testing::InputErrorOf([&] { io::WriteAbaqus(m, io::testing::ScratchPath("w.inp")); }),
                              {"shear panel", "element 1"}, "abaqus");
  io::testing::ExpectContains(
      io::testing::InputErrorOf([&] { io::WriteNastranBulk(m, io::testing::ScratchPath("w.bdf"), {}); }),
      {"element 1", "shear panel"}, "nastran");
}

}  // namespace shear4_test
}  // namespace flexmb::fe
