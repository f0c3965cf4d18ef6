// CBUSH / PBUSH in the Nastran reader (nastran_bush.cc): six springs K1..K6
// along the element axes at the point S of GA-GB, rigidly offset to both
// grids. References: hand formulas (a mass on a grounded bush in a turned
// system, an offset shear spring, a cantilever tip on a turned bush), the
// rigid-body modes of a free two-node bush (no strain energy) and the rules
// of the Quick Reference Guide (errors and warnings).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io::nastran_bush_test {

using testing::WriteScratch;

fe::AssembledModel BushAssemble(const std::string& name, const std::string& deck) {
  return fe::Assemble(ReadNastran(WriteScratch(name, "BEGIN BULK\n" + deck + "ENDDATA\n")));
}

// the 6 x 6 (or 12 x 12) stiffness of nodes (indices) in free numbering, basic DOF order
Eigen::MatrixXd BushNodeK(const fe::AssembledModel& m, std::initializer_list<int> nodes) {
  const Eigen::MatrixXd k(m.K);
  std::vector<int> idx;
  for (int n : nodes)
    for (int c = 0; c < 6; ++c) idx.push_back(m.dofs.free[n][c]);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<int>(idx.size()), static_cast<int>(idx.size()));
  for (size_t i = 0; i < idx.size(); ++i)
    for (size_t j = 0; j < idx.size(); ++j)
      if (idx[i] >= 0 && idx[j] >= 0) out(i, j) = k(idx[i], idx[j]);
  return out;
}

const char* const kBushPbush = "PBUSH,1,K,1.E6,2.E6,3.E6,4.E3,5.E3,6.E3\n";

// a grounded bush with CID = 3 (axes Q): K = blkdiag(Q Kt Q^T, Q Kr Q^T)
TEST(NastranBush, GroundedBushInATurnedSystem) {
  const fe::AssembledModel m =
      BushAssemble("grounded.bdf", std::string(kBushPbush) +
                                       "CORD2R,3,,0.,0.,0.,1.,0.,1.\n,1.,1.,0.\nGRID,1,,0.5,0.2,0.1\n"
                                       "CBUSH,7,1,1,,,,,3\nCONM2,8,1,,2.\n");
  // the system's axes: z = (1, 0, 1)/sqrt 2, x in the plane of (1, 1, 0)
  const fe::Vec3 z = fe::Vec3(1.0, 0.0, 1.0).normalized();
  const fe::Vec3 x = (fe::Vec3(1.0, 1.0, 0.0) - z * z.dot(fe::Vec3(1.0, 1.0, 0.0))).normalized();
  fe::Mat3 q;
  q << x, z.cross(x), z;
  const Eigen::MatrixXd k = BushNodeK(m, {0});
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(6, 6);
  expected.topLeftCorner(3, 3) = q * fe::Vec3(1e6, 2e6, 3e6).asDiagonal() * q.transpose();
  expected.bottomRightCorner(3, 3) = q * fe::Vec3(4e3, 5e3, 6e3).asDiagonal() * q.transpose();
  EXPECT_LT((k - expected).cwiseAbs().maxCoeff(), 1e-9);
  // the mass on it: omega^2 = K1 / m along the system's x
  const Eigen::MatrixXd kt = k.topLeftCorner(3, 3);
  EXPECT_NEAR(x.dot(kt * x), 1e6, 1e-6);
}

// GA at 0, GB at L on x, only K2 (shear along y, CID = 0), spring at S:
// g = (u_B + theta_B x r_B - u_A - theta_A x r_A) . e_y with r = x_P - x_node,
// so for GB (A fixed) K = k [1, -(1-S)L; -(1-S)L, (1-S)^2 L^2] on (u_y, theta_z)
TEST(NastranBush, OffsetShearSpringCouplesRotation) {
  const double len = 2.0, k2 = 5e5;
  for (double s : {0.5, 0.0, 0.25, 1.0}) {
    SCOPED_TRACE(s);
    char buf[160];
    std::snprintf(buf, sizeof buf, "PBUSH,1,K,,%.17g\nGRID,1,,0.,0.,0.,,123456\nGRID,2,,%.17g,0.,0.\n"
                                   "CBUSH,7,1,1,2,,,,0\n,%.17g\n", k2, len, s);
    const fe::AssembledModel m = BushAssemble("offset.bdf", buf);
    const Eigen::MatrixXd k = BushNodeK(m, {1});
    const double a = (1.0 - s) * len;  // x_B - x_P
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(6, 6);
    expected(1, 1) = k2;
    expected(1, 5) = expected(5, 1) = -k2 * a;
    expected(5, 5) = k2 * a * a;
    EXPECT_LT((k - expected).cwiseAbs().maxCoeff(), 1e-9 * k2) << k;
  }
}

// a free two-node bush with an offset point and turned axes: K symmetric,
// every rigid motion of both nodes has no strain energy, rank 6
TEST(NastranBush, FreeBushHasSixRigidBodyModes) {
  const fe::AssembledModel m = BushAssemble(
      "free.bdf", std::string(kBushPbush) +
                      "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.5,-0.3\nGRID,3,,0.,0.,2.\n"
                      "CBUSH,7,1,1,2,3\n,,0,0.2,0.4,0.7\n"
                      "CBUSH,8,1,1,2,0.3,1.,0.2\n,0.3\n");
  const Eigen::MatrixXd k = BushNodeK(m, {0, 1});
  ASSERT_EQ(m.dofs.n_free, 12);
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-9 * k.cwiseAbs().maxCoeff());
  const fe::Vec3 xs[2] = {fe::Vec3(0.0, 0.0, 0.0), fe::Vec3(1.0, 0.5, -0.3)};
  for (int mode = 0; mode < 6; ++mode) {
    fe::Vec3 t = fe::Vec3::Zero(), w = fe::Vec3::Zero();
    (mode < 3 ? t : w)[mode % 3] = 1.0;
    Eigen::VectorXd u(12);
    for (int n = 0; n < 2; ++n) {
      u.segment<3>(6 * n) = t + w.cross(xs[n]);
      u.segment<3>(6 * n + 3) = w;
    }
    EXPECT_LT((k * u).norm(), 1e-9 * k.norm()) << mode;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k);
  int nonzero = 0;
  for (int i = 0; i < 12; ++i) nonzero += eig.eigenvalues()(i) > 1e-9 * eig.eigenvalues().maxCoeff();
  EXPECT_EQ(nonzero, 6);
}

// a cantilever (Euler-Bernoulli, exact for tip loads) along x with its tip
// on a grounded bush whose y axis is turned by b about x (K2 = k only): the
// tip stiffness is kb I + k e e^T on (u_y, u_z), kb = 3 E I / L^3, e =
// (cos b, sin b); a tip force P e_y moves the tip by (kb I + k e e^T)^-1 P e_y
TEST(NastranBush, CantileverTipOnATurnedBush) {
  const double e = 2.1e11, i = 2e-8, len = 1.5, k = 4e4, p = 100.0, b = 0.6;
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "MAT1,1,%.17g,,0.3\nPBAR,1,1,3.E-4,%.17g,%.17g,4.E-8\nGRID,1,,0.,0.,0.,,123456\n"
                "GRID,2,,%.17g,0.,0.\nCBAR,1,1,1,2,0.,0.,1.\nPBUSH,2,K,,%.17g\n"
                "CORD2R,4,,0.,0.,0.,0.,%.17g,%.17g\n,1.,0.,0.\nCBUSH,5,2,2,,,,,4\n",
                e, i, i, len, k, -std::sin(b), std::cos(b));
  const fe::AssembledModel m = BushAssemble("tip.bdf", buf);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.dofs.n_free);
  f(m.dofs.free[1][1]) = p;
  const Eigen::VectorXd u = Eigen::MatrixXd(m.K).ldlt().solve(f);
  const double kb = 3.0 * e * i / (len * len * len);
  Eigen::Matrix2d kt = kb * Eigen::Matrix2d::Identity();
  const Eigen::Vector2d dir(std::cos(b), std::sin(b));
  kt += k * dir * dir.transpose();
  const Eigen::Vector2d expected = kt.ldlt().solve(Eigen::Vector2d(p, 0.0));
  EXPECT_NEAR(u(m.dofs.free[1][1]), expected(0), 1e-9 * expected.norm());
  EXPECT_NEAR(u(m.dofs.free[1][2]), expected(1), 1e-9 * expected.norm());
}

// G0 and X1-X3 in GA's displacement system give the element y axis: the
// same K as CID with those axes
TEST(NastranBush, OrientationVectorIsTheElementXyPlane) {
  const std::string grids = std::string(kBushPbush) + "GRID,1,,0.,0.,0.\nGRID,2,,0.,0.,1.\nGRID,3,,1.,1.,0.\n"
                                                      "CORD2R,6,,0.,0.,0.,0.,0.,1.\n,0.,1.,0.\n"
                                                      "GRID,4,,0.,0.,0.,6\nGRID,5,,0.,0.,1.\n";
  // element x = e_z (GA to GB), y toward (1, 1, 0): the system (z, (1,1,0)/sqrt 2, ...)
  const fe::AssembledModel g0 = BushAssemble("g0.bdf", grids + "CBUSH,7,1,1,2,3\nCONM2,9,3,,1.\n");
  const fe::AssembledModel cid =
      BushAssemble("cid.bdf", grids + "CORD2R,8,,0.,0.,0.,1.,-1.,0.\n,0.,0.,1.\nCBUSH,7,1,1,2,,,,8\nCONM2,9,3,,1.\n");
  // X1-X3 = (1, -1, 0) in GA's CD (axes: x' = e_y, y' = -e_x): (1, 1, 0) in basic
  const fe::AssembledModel x = BushAssemble("x.bdf", grids + "CBUSH,7,1,4,5,1.,-1.,0.\nCONM2,9,3,,1.\n");
  const Eigen::MatrixXd a = BushNodeK(g0, {0, 1}), c = BushNodeK(cid, {0, 1}), xx = BushNodeK(x, {3, 4});
  EXPECT_LT((a - c).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((xx - c).cwiseAbs().maxCoeff(), 1e-6);
}

// the QRG rules: CID needed for coincident or grounded ends, only K1 and K4
// without orientation, PBUSH mass not supported; damping is ignored with a warning
TEST(NastranBush, RulesAndWarnings) {
  testing::WarningCapture quiet;
  const std::string base = "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,0.,0.,0.\n";
  testing::ExpectBadFiles(
      {
          {"bush_grounded_no_cid.bdf", base + kBushPbush + "CBUSH,7,1,1\n",
           ":5: CBUSH 7: GB is blank (grounded): CID must be given", {}},
          {"bush_coincident_no_cid.bdf", base + kBushPbush + "CBUSH,7,1,1,3,0.,1.,0.\n",
           ":5: CBUSH 7: GA and GB coincide (closer than 1e-4): CID must be given", {}},
          {"bush_no_orientation.bdf", base + kBushPbush + "CBUSH,7,1,1,2\n",
           ":5: CBUSH 7: neither CID nor an orientation vector", {"K2 = 2e+06"}},
          {"bush_mass.bdf", base + "PBUSH,1,K,1.\n,,M,2.\nCBUSH,7,1,1,2,,,,0\n",
           ":5: PBUSH 1: mass M of PBUSH is not supported", {}},
          {"bush_negative.bdf", base + "PBUSH,1,K,-1.\n", ":4: PBUSH 1: stiffness K1 must not be negative", {}},
          {"bush_keyword.bdf", base + "PBUSH,1,KX,1.\n", ":4: PBUSH 1: PBUSH keyword 'KX' is not supported", {}},
          {"bush_wrong_property.bdf", base + "PELAS,1,1.\nCBUSH,7,1,1,2,,,,0\n",
           ":5: CBUSH 7: property 1 is a PELAS; CBUSH needs a PBUSH", {}},
          {"bush_s.bdf", base + kBushPbush + "CBUSH,7,1,1,2,,,,0\n,1.5\n", ":6: CBUSH 7: S = 1.5 must be in [0, 1]",
           {}},
      },
      [](const std::string& path) { ReadNastran(path); });
  testing::WarningCapture capture;
  const fe::Mesh mesh = ReadNastran(WriteScratch(
      "bush_damping.bdf", "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nPBUSH,1,K,1.E3\n,,B,2.\n,,GE,0.05\n,,RCV,1.,1.\n"
                          "CBUSH,7,1,1,2\n"));
  ASSERT_EQ(capture.messages.size(), 2u);
  testing::ExpectContains(capture.messages[0], {"PBUSH 1", "viscous damping B of PBUSH is ignored"}, "B");
  testing::ExpectContains(capture.messages[1], {"PBUSH 1", "structural damping GE of PBUSH is ignored"}, "GE");
  // K1 only, along GA-GB: one spring
  ASSERT_EQ(mesh.springs.size(), 1u);
  EXPECT_EQ(mesh.springs[0].coef_a[0], 1.0);
}

}  // namespace flexmb::io::nastran_bush_test
