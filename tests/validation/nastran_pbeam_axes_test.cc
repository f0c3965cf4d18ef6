// Nastran PBEAM's neutral axis (N1, N2), non-structural mass centre (M1, M2)
// and inertia (NSI): the beam axis is the shear centre's; axial force and
// bending act about the neutral axis, which carries the structural mass.
// References:
// - beam theory: a cantilever pulled by an axial force P on its axis, the
//   neutral axis ez above it, is bent by the moment -ez P about the neutral
//   axis: tip w = ez P L^2 / (2 E Iy) (up: the fibres below the neutral axis
//   stretch more), tip rotation ez P L / (E Iy), and the axis (ez below the
//   neutral axis) stretches by P L / (E A) + ez^2 P L / (E Iy); exact for
//   one element and for ten;
// - the same beam modelled with its axis on the neutral axis and rigid end
//   offsets (CBEAM WA, WB) to the nodes: in the plane of the offset (ux, uz,
//   ry), where no twist is involved, both give the same K and M to 1e-12;
// - rigid-body mass properties of the element (Gamma^T M Gamma, exact for
//   the consistent and the lumped mass): mass (rho A + nsm) L, centre of
//   mass (rho A e_na + nsm e_nsm) / (rho A + nsm), and the axial moment of
//   inertia (rho (Iy + Iz) + NSI + rho A |e_na|^2 + nsm |e_nsm|^2) L;
// - the fibre stress of a pure axial force is N / A on the neutral axis
//   (docs/validation.md, "PBEAM neutral axis and non-structural mass").

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/elements/element_common.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/reduction/element_input.h"
#include "flexmb/reduction/stress_modes.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace nastran_pbeam_axes_test {

constexpr double kE = 2.1e11, kRho = 7850.0, kA = 1e-3, kIy = 2e-6, kIz = 3e-6, kJ = 4e-6, kL = 2.0;
constexpr double kEz = 0.05, kNsm = 10.0, kNsmZ = 0.1, kNsmY = -0.04, kNsi = 0.5;

// n CBEAMs along x from 0 to L (element z = basic z), on `pbeam`
std::string Cantilever(int n, const std::string& pbeam, const std::string& cbeam_tail = "") {
  std::string d = "BEGIN BULK\nMAT1,1,2.1e11,,0.3,7850.\n" + pbeam;
  for (int i = 0; i <= n; ++i) d += "GRID," + std::to_string(i + 1) + ",," + std::to_string(kL * i / n) + ",0.,0.\n";
  for (int i = 0; i < n; ++i)
    d += "CBEAM," + std::to_string(i + 1) + ",1," + std::to_string(i + 1) + "," + std::to_string(i + 2) +
         ",0.,1.,0." + cbeam_tail + "\n";
  return d + "ENDDATA\n";
}

// end A only, then the footer: NSI(A), M1(A) M2(A), N1(A) N2(A)
std::string Pbeam(double n2, double nsm = 0.0, double m1 = 0.0, double m2 = 0.0, double nsi = 0.0, double n1 = 0.0) {
  char b[400];
  std::snprintf(b, sizeof b,
                "PBEAM,1,1,%.17g,%.17g,%.17g,,%.17g,%.17g\n,,,,,,,,\n,,,,,%.17g\n,%.17g,%.17g,,,%.17g,%.17g\n", kA,
                kIz, kIy, kJ, nsm, nsi, m1, m2, n1, n2);
  return b;
}

TEST(PbeamAxes, AxialForceOnTheShearCentreBendsAboutTheNeutralAxis) {
  const double p = 1e4;
  for (int n : {1, 10}) {
    const Mesh m = ReadDeckText(Cantilever(n, Pbeam(kEz)), "pull.bdf");
    ASSERT_EQ(m.beam_sections[0].neutral_axis[1], kEz);
    Mesh fixed = m;
    testing::AddConstraint(fixed, 0, 0b111111);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * static_cast<Eigen::Index>(m.nodes.size()));
    f(6 * n) = p;
    const Eigen::VectorXd u = SolveStatic(fixed, f);
    const double u_exact = p * kL / (kE * kA) + kEz * kEz * p * kL / (kE * kIy), w_exact = kEz * p * kL * kL / (2 * kE * kIy),
                 r_exact = kEz * p * kL / (kE * kIy);
    std::printf("  %2d elements: tip u %.9e (exact %.9e), w %.9e (exact %.9e), ry %.9e (exact -%.9e)\n", n,
                u(6 * n), u_exact, u(6 * n + 2), w_exact, u(6 * n + 4), r_exact);
    EXPECT_NEAR(u(6 * n), u_exact, 1e-9 * u_exact);
    EXPECT_NEAR(u(6 * n + 2), w_exact, 1e-9 * w_exact);
    EXPECT_NEAR(u(6 * n + 4), -r_exact, 1e-9 * r_exact);  // ry = -dw/dx
    EXPECT_NEAR(u(6 * n + 1), 0.0, 1e-12);
    // contrast: without the neutral axis offset, no bending at all
    const Mesh plain = ReadDeckText(Cantilever(n, Pbeam(0.0)), "plain");
    Mesh plain_fixed = plain;
    testing::AddConstraint(plain_fixed, 0, 0b111111);
    EXPECT_NEAR(SolveStatic(plain_fixed, f)(6 * n + 2), 0.0, 1e-12);
    // the neutral axis ey beside the axis (N1): the same in the x-y plane,
    // v = ey P L^2 / (2 E Iz) towards +y, rz = +v', and no w
    const double ey = -0.03;
    Mesh side = ReadDeckText(Cantilever(n, Pbeam(0.0, 0.0, 0.0, 0.0, 0.0, ey)), "side");
    testing::AddConstraint(side, 0, 0b111111);
    const Eigen::VectorXd us = SolveStatic(side, f);
    const double v_exact = ey * p * kL * kL / (2 * kE * kIz), rz_exact = ey * p * kL / (kE * kIz);
    EXPECT_NEAR(us(6 * n + 1), v_exact, 1e-9 * std::abs(v_exact));
    EXPECT_NEAR(us(6 * n + 5), rz_exact, 1e-9 * std::abs(rz_exact));
    EXPECT_NEAR(us(6 * n), p * kL / (kE * kA) + ey * ey * p * kL / (kE * kIz), 1e-9 * u_exact);
    EXPECT_NEAR(us(6 * n + 2), 0.0, 1e-12);
  }
}

// the element's K and M in basic axes
void Matrices(const Mesh& m, MatX& K, MatX& M, MassForm form = MassForm::kConsistent) {
  std::vector<Vec3> x;
  ElementInput in = reduction::ResolveElementInput(m, m.elements[0], x);
  in.mass_form = form;
  ElementMatrices(in, K, M);
}

TEST(PbeamAxes, InThePlaneOfTheOffsetEqualsTheBeamOnRigidEndOffsets) {
  // the neutral-axis beam; the offset beam has its axis on the neutral axis
  // (WA = WB = (0, 0, ez) in basic axes, the default OFFT GGG)
  const Mesh na = ReadDeckText(Cantilever(1, Pbeam(kEz)), "na");
  const Mesh off = ReadDeckText(Cantilever(1, Pbeam(0.0), ",\n,,,0.,0.," + std::to_string(kEz) + ",0.,0.," +
                                                      std::to_string(kEz)),
                        "off");
  ASSERT_EQ(off.elements[0].offset_a.z(), kEz);
  for (MassForm form : {MassForm::kConsistent, MassForm::kLumped}) {
    MatX ka, ma, kb, mb;
    Matrices(na, ka, ma, form);
    Matrices(off, kb, mb, form);
    const std::vector<int> plane = {0, 2, 4, 6, 8, 10};
    double dk = 0, dm = 0;
    for (int i : plane)
      for (int j : plane) {
        dk = std::max(dk, std::abs(ka(i, j) - kb(i, j)));
        dm = std::max(dm, std::abs(ma(i, j) - mb(i, j)));
      }
    EXPECT_LT(dk, 1e-12 * ka.cwiseAbs().maxCoeff());
    EXPECT_LT(dm, 1e-12 * ma.cwiseAbs().maxCoeff());
  }
}

TEST(PbeamAxes, RigidBodyMassPropertiesHoldBothOffsetsAndTheNsmInertia) {
  const Mesh m = ReadDeckText(Cantilever(1, Pbeam(kEz, kNsm, kNsmY, kNsmZ, kNsi)), "mass");
  const BeamSection& s = m.beam_sections[0];
  EXPECT_EQ(s.nsm_offset[0], kNsmY);
  EXPECT_EQ(s.nsm_offset[1], kNsmZ);
  EXPECT_EQ(s.nsm_inertia, kNsi);
  const double ma = kRho * kA, mass = (ma + kNsm) * kL;
  const Vec3 c(kL / 2, kNsm * kNsmY / (ma + kNsm), (ma * kEz + kNsm * kNsmZ) / (ma + kNsm));
  // axial inertia about the beam axis
  const double ixx = (kRho * (kIy + kIz) + kNsi + ma * kEz * kEz + kNsm * (kNsmY * kNsmY + kNsmZ * kNsmZ)) * kL;
  for (MassForm form : {MassForm::kConsistent, MassForm::kLumped}) {
    MatX K, M;
    Matrices(m, K, M, form);
    // rigid-body modes about the origin (node 1)
    Eigen::Matrix<double, 12, 6> g = Eigen::Matrix<double, 12, 6>::Zero();
    for (int node = 0; node < 2; ++node) {
      const Vec3 x = m.nodes[node].x;
      g.block<3, 3>(6 * node, 0).setIdentity();
      g.block<3, 3>(6 * node, 3) = -Skew(x);
      g.block<3, 3>(6 * node + 3, 3).setIdentity();
    }
    const Eigen::Matrix<double, 6, 6> mr = g.transpose() * M * g;
    EXPECT_NEAR(mr(0, 0), mass, 1e-12 * mass);
    // first moments: mr(0:3, 3:6) = -m skew(c)
    const Eigen::Matrix3d first = -mr.block<3, 3>(0, 3) / mass;
    EXPECT_NEAR(first(2, 1), c.x(), 1e-12);
    EXPECT_NEAR(first(0, 2), c.y(), 1e-12);
    EXPECT_NEAR(first(1, 0), c.z(), 1e-12);
    EXPECT_NEAR(mr(3, 3), ixx, 1e-12 * ixx);
    EXPECT_LT((K * g).cwiseAbs().maxCoeff(), 1e-6 * K.cwiseAbs().maxCoeff());
  }
}

TEST(PbeamAxes, FibreStressOfAnAxialForceIsNOverAOnTheNeutralAxis) {
  const Mesh m = ReadDeckText(Cantilever(1, Pbeam(kEz)), "fibre");
  Eigen::Matrix<double, 6, 1> f = Eigen::Matrix<double, 6, 1>::Zero();
  f(0) = 1e4;
  EXPECT_NEAR(reduction::BeamNormalStress(f, m.beam_sections[0], 0.0, kEz), 1e4 / kA, 1e-9);
  // 0.03 above the neutral axis: N / A + My_n c / Iy with My_n = -ez N
  const double c = 0.03;
  EXPECT_NEAR(reduction::BeamNormalStress(f, m.beam_sections[0], 0.0, kEz + c), 1e4 / kA - kEz * 1e4 * c / kIy,
              1e-6);
}

}  // namespace nastran_pbeam_axes_test
}  // namespace flexmb::fe::validation
