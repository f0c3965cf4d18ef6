// Constraints along the axes of displacement systems (GRID CD) against
// CalculiX's *TRANSFORM (ccx 2.20): a steel block of hex8 elements (flexmb's
// default incompatible-mode hex8 = ccx's C3D8I on parallelepipeds, see
// "FE: solids" in docs/validation.md) clamped at x = 0; its tip face rides
// on a roller along the y axis of a rectangular system turned 30 degrees
// about x (SPC1 2 in CORD2R 1 / *TRANSFORM TYPE=R, *BOUNDARY 2), the outer
// nodes of its mid-length section on a radial roller of a cylindrical system
// about the block's axis (SPC1 1 in CORD2C 2 / *TRANSFORM TYPE=C,
// *BOUNDARY 1). A force on a free node; the static displacements of every
// node (basic axes) must equal ccx's to its printed digits. flexmb reads the
// model from a Nastran deck, so the test runs the reader too.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"

namespace flexmb::fe {
namespace nastran_cd_calculix_test {

using flexmb::testing::CcxScratchDir;
using flexmb::testing::HaveCcx;
using flexmb::testing::RunCcx;

constexpr int kCdNx = 8, kCdNy = 2, kCdNz = 2;

int CdNodeId(int i, int j, int k) { return (k * (kCdNy + 1) + j) * (kCdNx + 1) + i + 1; }

Vec3 CdNodeX(int i, int j, int k) { return Vec3(1.0 * i / kCdNx, 0.2 * j / kCdNy, 0.2 * k / kCdNz); }

// tip face (i = kCdNx) and the outer ring of the mid section (i = kCdNx / 2, not the centre)
bool CdOnTip(int i) { return i == kCdNx; }
bool CdOnRing(int i, int j, int k) { return i == kCdNx / 2 && !(j == 1 && k == 1); }

TEST(NastranCdCalculix, SkewAndRadialRollersMatchTransform) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const double beta = 30.0 * M_PI / 180.0;
  const Vec3 ey(0.0, std::cos(beta), std::sin(beta));  // the turned y axis
  const Vec3 force(300.0, -500.0, -1000.0);
  const int load_id = CdNodeId(6, 2, 2);
  CcxScratchDir dir("nastran_cd");
  // the Nastran deck
  std::ostringstream bdf;
  bdf.precision(17);
  bdf << "BEGIN BULK\nMAT1,1," << flexmb::testing::kCcxE << ",," << flexmb::testing::kCcxNu << ","
      << flexmb::testing::kCcxRho << "\nPSOLID,1,1\n";
  // CORD2R 1: z = e_x cross e_y' turned, x = e_x; CORD2C 2 about the line y = z = 0.1
  const Vec3 ez = Vec3::UnitX().cross(ey);
  bdf << "CORD2R,1,,0.,0.,0.," << ez.x() << "," << ez.y() << "," << ez.z() << "\n,1.,0.,0.\n";
  bdf << "CORD2C,2,,0.,0.1,0.1,1.,0.1,0.1\n,0.,1.1,0.1\n";
  for (int k = 0; k <= kCdNz; ++k)
    for (int j = 0; j <= kCdNy; ++j)
      for (int i = 0; i <= kCdNx; ++i) {
        const Vec3 x = CdNodeX(i, j, k);
        const int cd = CdOnTip(i) ? 1 : CdOnRing(i, j, k) ? 2 : 0;
        bdf << "GRID," << CdNodeId(i, j, k) << ",," << x.x() << "," << x.y() << "," << x.z() << ","
            << (cd ? std::to_string(cd) : "") << "\n";
      }
  std::ostringstream elements;
  int eid = 0;
  for (int k = 0; k < kCdNz; ++k)
    for (int j = 0; j < kCdNy; ++j)
      for (int i = 0; i < kCdNx; ++i) {
        const int n[8] = {CdNodeId(i, j, k),         CdNodeId(i + 1, j, k),     CdNodeId(i + 1, j + 1, k),
                          CdNodeId(i, j + 1, k),     CdNodeId(i, j, k + 1),     CdNodeId(i + 1, j, k + 1),
                          CdNodeId(i + 1, j + 1, k + 1), CdNodeId(i, j + 1, k + 1)};
        ++eid;
        bdf << "CHEXA," << eid << ",1";
        elements << eid;
        for (int m = 0; m < 8; ++m) {
          bdf << (m == 6 ? "\n," : ",") << n[m];
          elements << ", " << n[m];
        }
        bdf << "\n";
        elements << "\n";
      }
  std::ostringstream root, tip, ring;
  for (int k = 0; k <= kCdNz; ++k)
    for (int j = 0; j <= kCdNy; ++j) {
      root << CdNodeId(0, j, k) << "\n";
      tip << CdNodeId(kCdNx, j, k) << "\n";
      if (CdOnRing(kCdNx / 2, j, k)) ring << CdNodeId(kCdNx / 2, j, k) << "\n";
      bdf << "SPC1,1,123," << CdNodeId(0, j, k) << "\nSPC1,1,2," << CdNodeId(kCdNx, j, k) << "\n";
      if (CdOnRing(kCdNx / 2, j, k)) bdf << "SPC1,1,1," << CdNodeId(kCdNx / 2, j, k) << "\n";
    }
  bdf << "ENDDATA\n";
  const std::string bdf_path = (dir.path / "block.bdf").string();
  std::ofstream(bdf_path) << bdf.str();
  // the CalculiX deck
  std::ostringstream deck;
  deck.precision(17);
  deck << "*NODE, NSET=NALL\n";
  for (int k = 0; k <= kCdNz; ++k)
    for (int j = 0; j <= kCdNy; ++j)
      for (int i = 0; i <= kCdNx; ++i) {
        const Vec3 x = CdNodeX(i, j, k);
        deck << CdNodeId(i, j, k) << ", " << x.x() << ", " << x.y() << ", " << x.z() << "\n";
      }
  deck << "*ELEMENT, TYPE=C3D8I, ELSET=EALL\n" << elements.str();
  deck << "*NSET, NSET=ROOT\n" << root.str() << "*NSET, NSET=TIP\n" << tip.str() << "*NSET, NSET=RING\n"
       << ring.str();
  // TYPE=R: a point on the local x axis, a point in the local x-y plane
  deck << "*TRANSFORM, NSET=TIP, TYPE=R\n1., 0., 0., " << ey.x() << ", " << ey.y() << ", " << ey.z() << "\n";
  // TYPE=C: two points on the axis (local 1 radial, 2 tangential, 3 axial)
  deck << "*TRANSFORM, NSET=RING, TYPE=C\n0., 0.1, 0.1, 1., 0.1, 0.1\n";
  deck << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << flexmb::testing::kCcxE << ", " << flexmb::testing::kCcxNu
       << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*BOUNDARY\nROOT, 1, 3\nTIP, 2, 2\nRING, 1, 1\n"
       << "*STEP\n*STATIC\n*CLOAD\n"
       << load_id << ", 1, " << force.x() << "\n" << load_id << ", 2, " << force.y() << "\n" << load_id << ", 3, "
       << force.z() << "\n*NODE PRINT, NSET=NALL, GLOBAL=YES\nU\n*END STEP\n";
  ASSERT_TRUE(RunCcx(dir.path, "job", deck.str()));
  const std::map<int, Vec3> ccx = flexmb::testing::ParseCcxDisplacements(dir.path / "job.dat", "NALL");
  ASSERT_EQ(ccx.size(), static_cast<size_t>((kCdNx + 1) * (kCdNy + 1) * (kCdNz + 1)));
  // flexmb: the deck read, u = T K^-1 T^T f
  const Mesh mesh = io::ReadNastran(bdf_path);
  const AssembledModel a = Assemble(mesh);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(a.dofs.n_full);
  const int load = mesh.NodeIndex(load_id);
  for (int c = 0; c < 3; ++c) f[a.dofs.full[load][c]] = force[c];
  const Eigen::MatrixXd t(a.T);
  const Eigen::VectorXd u = t * Eigen::MatrixXd(a.K).ldlt().solve(t.transpose() * f);
  double diff = 0.0, scale = 0.0, skew = 0.0;
  for (const auto& entry : ccx) {
    const int n = mesh.NodeIndex(entry.first);
    Vec3 un = Vec3::Zero();
    for (int c = 0; c < 3; ++c)
      if (a.dofs.full[n][c] >= 0) un[c] = u[a.dofs.full[n][c]];
    scale = std::max(scale, entry.second.cwiseAbs().maxCoeff());
    diff = std::max(diff, (un - entry.second).cwiseAbs().maxCoeff());
    if (mesh.nodes[n].x.x() == 1.0) skew = std::max(skew, std::abs(ey.dot(un)));
  }
  const Vec3 tip_ccx = ccx.at(CdNodeId(kCdNx, 0, 0));
  std::printf("  tip corner u: ccx (%.7e, %.7e, %.7e)\n", tip_ccx.x(), tip_ccx.y(), tip_ccx.z());
  std::printf("  max |u_flexmb - u_ccx| / max |u_ccx| = %.2e; flexmb |e_y' . u_tip| = %.1e m\n", diff / scale, skew);
  // ccx prints 7 significant digits
  EXPECT_LT(diff / scale, 2e-6);
  EXPECT_LT(skew, 1e-12 * scale);
  // ccx's transform is the one meant: its tip does not move along e_y' either
  EXPECT_LT(std::abs(ey.dot(tip_ccx)), 1e-6 * scale);
}

}  // namespace nastran_cd_calculix_test
}  // namespace flexmb::fe
