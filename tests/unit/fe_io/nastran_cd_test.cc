// Components in a grid's displacement system (GRID CD) in the Nastran
// reader (nastran_cd.cc): SPC / SPC1 / GRID PS, CELAS1/2 and RBE2 / RBAR
// components along the axes of a rotated or cylindrical system. References:
// the roller on an inclined plane (hand formula), the constraint equations
// themselves (every admissible motion of T satisfies them, and only those),
// and the same model turned rigidly so that the CD axes are basic axes
// (frequencies and static deflections are invariant).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io::nastran_cd_test {

using testing::WriteScratch;

// Nastran free-field number
std::string CdNum(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (s.find_first_of(".e") == std::string::npos) s += ".";
  return s;
}

fe::AssembledModel CdAssemble(const std::string& name, const std::string& deck) {
  return fe::Assemble(ReadNastran(WriteScratch(name, "BEGIN BULK\n" + deck + "ENDDATA\n")));
}

// rows of T for the translations (block 0) or rotations (block 3) of node index n
Eigen::MatrixXd CdRowsOfT(const fe::AssembledModel& m, int n, int block) {
  const Eigen::MatrixXd t(m.T);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(3, t.cols());
  for (int c = 0; c < 3; ++c)
    if (m.dofs.full[n][block + c] >= 0) out.row(c) = t.row(m.dofs.full[n][block + c]);
  return out;
}

// a rod from a fixed node to node 2 at (L, 0, 0) with a point mass; node 2
// may move only along x' = (cos a, sin a, 0) of its CD system (components
// 2 and 3 fixed): one DOF, omega^2 = (EA / L) cos^2 a / m
TEST(NastranCd, RollerOnAnInclinedPlane) {
  const double e = 2.1e11, area = 1e-4, len = 2.0, mass = 3.0;
  for (double deg : {0.0, 30.0, 60.0, 75.0}) {
    SCOPED_TRACE(deg);
    const double a = deg * M_PI / 180.0;
    const std::string deck = "MAT1,1," + CdNum(e) + ",,0.3\n" + "PROD,1,1," + CdNum(area) + ",1.E-9\n" +
                             "CORD2R,5,,0.,0.,0.,0.,0.,1.\n," + CdNum(std::cos(a)) + "," + CdNum(std::sin(a)) +
                             ",0.\n" + "GRID,1,,0.,0.,0.,,123456\n" + "GRID,2,,2.,0.,0.,5\n" +
                             "CROD,1,1,1,2\nCONM2,3,2,,3.\nSPC1,1,23,2\n";
    const fe::AssembledModel m = CdAssemble("roller.bdf", deck);
    ASSERT_EQ(m.dofs.n_free, 1);
    const double k = Eigen::MatrixXd(m.K)(0, 0), mm = Eigen::MatrixXd(m.M)(0, 0);
    EXPECT_NEAR(k / mm, e * area / len * std::cos(a) * std::cos(a) / mass, 1e-9 * e * area / len / mass);
  }
}

// the constraint equations: e_r . u = 0 on a cylinder (CORD2C, component 1)
// at several angles; every column of T satisfies it and two directions stay free
TEST(NastranCd, CylindricalRadialConstraint) {
  const fe::Vec3 axis = fe::Vec3(0.2, -0.3, 1.0).normalized();
  std::string deck = "CORD2C,7,,1.,2.,0.5," + CdNum(1.0 + axis.x()) + "," + CdNum(2.0 + axis.y()) + "," +
                     CdNum(0.5 + axis.z()) + "\n,5.,2.,0.5\n";
  // nodes given in the cylindrical system (CP = 7): r = 2, theta, z
  const double thetas[] = {0.0, 35.0, 90.0, 200.0};
  for (int i = 0; i < 4; ++i)
    deck += "GRID," + std::to_string(i + 1) + ",7,2.," + CdNum(thetas[i]) + ",0.3,7\n";
  // springs make every translation active; SPC1 1 (radial) on all four
  for (int i = 1; i <= 4; ++i)
    for (int c = 1; c <= 3; ++c)
      deck += "CELAS2," + std::to_string(10 * i + c) + ",1.," + std::to_string(i) + "," + std::to_string(c) + "\n";
  deck += "SPC1,1,1,1,THRU,4\n";
  const fe::Mesh mesh = ReadNastran(WriteScratch("cylinder.bdf", "BEGIN BULK\n" + deck + "ENDDATA\n"));
  const fe::AssembledModel m = fe::Assemble(mesh);
  EXPECT_EQ(m.dofs.n_free, 8);
  // the system's origin and axis, for the independent e_r
  const fe::Vec3 origin(1.0, 2.0, 0.5);
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    const fe::Vec3 d = mesh.nodes[i].x - origin;
    const fe::Vec3 er = (d - axis * axis.dot(d)).normalized();
    EXPECT_NEAR((d - axis * axis.dot(d)).norm(), 2.0, 1e-12);
    const Eigen::MatrixXd t = CdRowsOfT(m, i, 0);
    EXPECT_LT((er.transpose() * t).cwiseAbs().maxCoeff(), 1e-12);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(t);
    EXPECT_EQ(lu.rank(), 2);
  }
}

// a CD system that is the basic one turned by 90 degrees about z: SPC1 1
// there is SPC1 2 in basic, CELAS2 component 2 is component 1 and an RBE2
// CM = 1 is CM = 2: the same K, M and T (to round-off)
TEST(NastranCd, QuarterTurnIsTheBasicModel) {
  const std::string common =
      "MAT1,1,2.1E11,,0.3,7850.\nPBAR,1,1,3.E-4,2.E-8,3.E-8,4.E-8\n"
      "GRID,1,,0.,0.,0.,,123456\nGRID,2,,1.,0.,0.\nGRID,3,,1.5,0.2,0.1,%CD\nGRID,4,,2.,0.,0.,%CD\n"
      "CBAR,1,1,1,2,0.,1.,0.\nCBAR,2,1,2,4,0.,1.,0.\nCONM2,5,3,,2.\n,0.1,0.,0.1,0.,0.,0.1\n";
  auto deck = [&](bool cd) {
    std::string s = common;
    const std::string tag = cd ? "9" : "";
    for (size_t p; (p = s.find("%CD")) != std::string::npos;) s.replace(p, 3, tag);
    s += "CORD2R,9,,0.,0.,0.,0.,0.,1.\n,0.,1.,0.\n";
    s += cd ? "SPC1,1,1,4\nCELAS2,8,5.E4,3,2\nRBE2,7,2,145,3\n" : "SPC1,1,2,4\nCELAS2,8,5.E4,3,1\nRBE2,7,2,245,3\n";
    return s;
  };
  const fe::AssembledModel a = CdAssemble("quarter_cd.bdf", deck(true));
  const fe::AssembledModel b = CdAssemble("quarter_basic.bdf", deck(false));
  ASSERT_EQ(a.dofs.n_free, b.dofs.n_free);
  ASSERT_EQ(a.dofs.n_full, b.dofs.n_full);
  EXPECT_EQ(a.dofs.free, b.dofs.free);
  const double scale = Eigen::MatrixXd(b.K).cwiseAbs().maxCoeff();
  EXPECT_LT((Eigen::MatrixXd(a.K) - Eigen::MatrixXd(b.K)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((Eigen::MatrixXd(a.M) - Eigen::MatrixXd(b.M)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((Eigen::MatrixXd(a.T) - Eigen::MatrixXd(b.T)).cwiseAbs().maxCoeff(), 1e-12);
}

// ---- a model and the same model turned rigidly by R ------------------------------------------

// generalized eigenvalues 1 / omega^2 of (K, M) via the Cholesky factor of K
// (massless DOF give 0), sorted
std::vector<double> CdInverseEigen(const fe::AssembledModel& m) {
  const Eigen::MatrixXd k(m.K), mm(m.M);
  const Eigen::LLT<Eigen::MatrixXd> llt(k);
  EXPECT_EQ(llt.info(), Eigen::Success);
  const Eigen::MatrixXd l = llt.matrixL();
  const Eigen::MatrixXd a = l.triangularView<Eigen::Lower>().solve(
      l.triangularView<Eigen::Lower>().solve(mm).transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (a + a.transpose()));
  std::vector<double> v(eig.eigenvalues().data(), eig.eigenvalues().data() + eig.eigenvalues().size());
  std::sort(v.begin(), v.end());
  return v;
}

// full displacement under a force f (basic) on node index n: u = T K^-1 T^T f
Eigen::VectorXd CdStatic(const fe::AssembledModel& m, int n, const fe::Vec3& f) {
  Eigen::VectorXd ff = Eigen::VectorXd::Zero(m.dofs.n_full);
  for (int c = 0; c < 3; ++c)
    if (m.dofs.full[n][c] >= 0) ff(m.dofs.full[n][c]) = f[c];
  const Eigen::MatrixXd t(m.T);
  const Eigen::VectorXd q = Eigen::MatrixXd(m.K).ldlt().solve(t.transpose() * ff);
  return t * q;
}

fe::Vec3 CdNodeVector(const fe::AssembledModel& m, const Eigen::VectorXd& u, int n, int block) {
  fe::Vec3 v = fe::Vec3::Zero();
  for (int c = 0; c < 3; ++c)
    if (m.dofs.full[n][block + c] >= 0) v[c] = u(m.dofs.full[n][block + c]);
  return v;
}

// The reference model B is in basic components; model A is B turned by R,
// with every constrained or sprung component given in a CD system that
// turns with it (rectangular with axes R, and cylindrical about the turned
// z axis for nodes on the x axis of B, where e_r, e_theta are x, y). Both
// have the same frequencies; A's deflections are R times B's.
TEST(NastranCd, TurnedModelHasTheSameFrequenciesAndDeflections) {
  const fe::Mat3 r = (Eigen::AngleAxisd(0.7, fe::Vec3(1.0, 2.0, 0.5).normalized())).toRotationMatrix();
  struct CdGrid {
    int id;
    fe::Vec3 y;
    int cd;  // in model A: 0, 1 (rectangular R) or 2 (cylindrical about R e_z)
  };
  const CdGrid grids[] = {{1, {0.0, 0.0, 0.0}, 0},   {2, {0.5, 0.0, 0.0}, 2}, {3, {1.0, 0.0, 0.0}, 1},
                          {4, {1.2, 0.0, 0.1}, 1},   {5, {0.5, 0.0, 0.3}, 1}, {6, {1.0, 0.4, 0.0}, 0}};
  auto deck = [&](bool turned) {
    const fe::Mat3 q = turned ? r : fe::Mat3::Identity();
    std::string s = "MAT1,1,2.1E11,,0.3,7850.\nPBAR,1,1,3.E-4,2.E-8,3.E-8,4.E-8\n";
    s += "PBUSH,20,K,1.E6,2.E6,3.E6,4.E3,5.E3,6.E3\n";
    // CORD2R 1 with axes q; CORD2C 2 about q e_z through the origin
    auto cord = [&](const char* card, int id) {
      const fe::Vec3 b = q.col(2), c = q.col(0);
      return std::string(card) + "," + std::to_string(id) + ",,0.,0.,0.," + CdNum(b.x()) + "," + CdNum(b.y()) +
             "," + CdNum(b.z()) + "\n," + CdNum(c.x()) + "," + CdNum(c.y()) + "," + CdNum(c.z()) + "\n";
    };
    s += cord("CORD2R", 1) + cord("CORD2C", 2);
    for (const CdGrid& g : grids) {
      const fe::Vec3 x = q * g.y;
      s += "GRID," + std::to_string(g.id) + ",," + CdNum(x.x()) + "," + CdNum(x.y()) + "," + CdNum(x.z()) + "," +
           (turned && g.cd ? std::to_string(g.cd) : "") + "\n";
    }
    // CBAR X1-X3 are in GA's displacement system (OFFT G): e_z of that
    // system for bars from grids 2 and 3, R e_z from the basic grid 1
    const fe::Vec3 v = q * fe::Vec3(0.0, 0.0, 1.0);
    const std::string orient = CdNum(v.x()) + "," + CdNum(v.y()) + "," + CdNum(v.z());
    s += "CBAR,1,1,1,2," + orient + "\nCBAR,2,1,2,3,0.,0.,1.\nCBAR,3,1,3,6,0.,0.,1.\n";
    s += "SPC1,1,123456,1\n";
    // a roller under node 3 (component 2 of its system), a spring on node 2
    // along e_z (the cylinder's axis, component 3) and e_theta (2)
    s += "SPC1,1,2,3\nCELAS2,11,4.E5,2,3\nCELAS2,12,7.E5,2,2\n";
    // node 4 follows node 3 in 1, 3 and 5 only; springs hold the rest
    s += "RBE2,30,3,135,4\nCONM2,31,4,,5.\n,0.3,0.,0.3,0.,0.,0.3\nCELAS2,32,2.E5,4,2\nCELAS2,33,3.E3,4,4\n"
         "CELAS2,34,5.E3,4,6\n";
    // node 5 on a bush from node 2 (CID 1 in A, 0 in B) and a grounded bush (CID)
    s += std::string("CBUSH,40,20,2,5,,,,") + (turned ? "1" : "0") + "\n";
    s += std::string("CBUSH,41,20,5,,,,,") + (turned ? "1" : "0") + "\nCONM2,42,5,,1.5\n";
    s += "CONM2,43,6,,2.5\n";
    return s;
  };
  const fe::AssembledModel b = CdAssemble("turned_b.bdf", deck(false));
  const fe::AssembledModel a = CdAssemble("turned_a.bdf", deck(true));
  ASSERT_EQ(a.dofs.n_free, b.dofs.n_free);
  const std::vector<double> ea = CdInverseEigen(a), eb = CdInverseEigen(b);
  ASSERT_EQ(ea.size(), eb.size());
  for (size_t i = 0; i < ea.size(); ++i) EXPECT_NEAR(ea[i], eb[i], 1e-9 * eb.back()) << i;
  // deflection under a load on node 4 and on node 6
  for (int n : {3, 5}) {
    const fe::Vec3 f(100.0, -200.0, 50.0);
    const Eigen::VectorXd ua = CdStatic(a, n, r * f), ub = CdStatic(b, n, f);
    for (int node = 0; node < 6; ++node)
      for (int block : {0, 3}) {
        const fe::Vec3 xa = CdNodeVector(a, ua, node, block), xb = CdNodeVector(b, ub, node, block);
        EXPECT_LT((xa - r * xb).norm(), 1e-9 * ub.cwiseAbs().maxCoeff()) << n << ": " << node << " " << block;
      }
  }
}

// a CELAS2 along a 45-degree CD axis to ground: k d d^T on the node's translations
TEST(NastranCd, SpringAlongATurnedAxis) {
  const double c = std::sqrt(0.5);
  const fe::AssembledModel m = CdAssemble(
      "spring45.bdf", "CORD2R,3,,0.,0.,0.,0.,0.,1.\n,1.,1.,0.\nGRID,1,,0.,0.,0.,3\nCELAS2,1,8.,1,1\n"
                      "CELAS2,2,1.,1,3\n");
  ASSERT_EQ(m.dofs.n_free, 3);
  Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
  expected.topLeftCorner<2, 2>() << 8.0 * c * c, 8.0 * c * c, 8.0 * c * c, 8.0 * c * c;
  expected(2, 2) = 1.0;
  Eigen::Matrix3d k;
  const Eigen::MatrixXd kk(m.K);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) k(i, j) = kk(m.dofs.free[0][i], m.dofs.free[0][j]);
  EXPECT_LT((k - expected).cwiseAbs().maxCoeff(), 1e-14);
}

// components of one grid from several cards (GRID PS 1, SPC1 2, SPC 3 in a
// turned system) together fix all three translations: a plain constraint
TEST(NastranCd, ComponentsOfSeveralCardsAreMerged) {
  const fe::Mesh mesh = ReadNastran(WriteScratch(
      "merged.bdf", "CORD2R,3,,0.,0.,0.,0.,0.,1.\n,1.,1.,0.\nGRID,1,,0.,0.,0.,3,1\nCELAS2,1,8.,1,1\n"
                    "CELAS2,2,1.,1,2\nCELAS2,3,1.,1,3\nSPC1,1,2,1\nSPC,1,1,3\n"));
  EXPECT_TRUE(mesh.linear_constraints.empty());
  ASSERT_EQ(mesh.constraints.size(), 1u);
  EXPECT_EQ(mesh.constraints[0].dofs, 0b111);
  EXPECT_EQ(fe::Assemble(mesh).dofs.n_free, 0);
}

// a grid on a skew roller cannot be an interface node (all six DOF
// independent): an error naming the grid, not a crash
TEST(NastranCd, SkewConstrainedGridIsNoInterfaceNode) {
  const fe::Mesh mesh = ReadNastran(WriteScratch(
      "skew_interface.bdf", "CORD2R,3,,0.,0.,0.,0.,0.,1.\n,1.,1.,0.\nGRID,1,,0.,0.,0.,3\nCELAS2,1,8.,1,1\n"
                            "CELAS2,2,1.,1,2\nCELAS2,3,1.,1,3\nSPC1,1,2,1\n"));
  fe::AssemblyOptions options;
  options.independent_nodes = {0};
  testing::ExpectContains(testing::InputErrorOf([&] { fe::Assemble(mesh, options); }),
                          {"SPC 1", "node 1 must be independent (an interface node)"}, "interface");
}

}  // namespace flexmb::io::nastran_cd_test
