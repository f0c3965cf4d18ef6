// Beam axis offsets from Abaqus/CalculiX decks (*BEAM SECTION, OFFSET1=,
// OFFSET2=: the nodes' line at OFFSETk times the section's extent along
// local k from the beam's axis, CalculiX manual, *BEAM SECTION) against
// beam theory: a steel cantilever (2 m, RECT a = 0.04 along n1 = y, b = 0.1
// along n2 = z) with OFFSET2 = 0.5 (the nodes on the top surface, e = b / 2
// above the axis) under an axial load P = 10 kN on its tip node: the
// eccentric load bends it by the constant moment P e, the tip moves uz =
// -P e L^2 / (2 E I11) and ux = P L / (E A) + P e^2 L / (E I11) (I11 = a b^3
// / 12; Timoshenko and Gere, Mechanics of Materials, eccentric axial
// loads). B31 (ten elements) and B32R (five): exact to 1e-9. OFFSET1 = 0.5
// moves the nodes along y instead: the tip moves along y, with I22. Without
// the offset the tip does not move sideways (the contrast).
// Sources: docs/validation.md, "Abaqus beam offsets".

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include <Eigen/Dense>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::fe {
namespace abaqus_beam_offset_test {

constexpr double kOffL = 2.0, kOffA = 0.04, kOffB = 0.1, kOffP = 1.0e4, kOffE = 2.1e11;

std::string OffsetDeck(const std::string& type, const std::string& offset) {
  const int n = type == "B31" ? 10 : 5, per = type == "B31" ? 1 : 2;
  std::ostringstream d;
  d.precision(17);
  d << "*NODE, NSET=NALL\n";
  for (int i = 0; i <= per * n; ++i) d << i + 1 << ", " << kOffL * i / (per * n) << ", 0., 0.\n";
  d << "*ELEMENT, TYPE=" << type << ", ELSET=EB\n";
  for (int e = 0; e < n; ++e) {
    d << e + 1;
    for (int k = 0; k <= per; ++k) d << ", " << per * e + k + 1;
    d << "\n";
  }
  d << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << kOffE << ", 0.3\n*DENSITY\n7850.\n"
    << "*BEAM SECTION, ELSET=EB, MATERIAL=STEEL, SECTION=RECT" << offset << "\n" << kOffA << ", " << kOffB
    << "\n0., 1., 0.\n*BOUNDARY\n1, 1, 6\n";
  return d.str();
}

// the tip node's displacement under P along x
Vec3 TipUnderAxialLoad(const Mesh& m) {
  const AssembledModel a = Assemble(m);
  const int tip = static_cast<int>(m.nodes.size()) - 1;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(a.dofs.n_full);
  f[a.dofs.full[tip][0]] = kOffP;
  const Eigen::MatrixXd k(a.K);
  const Eigen::VectorXd u = a.T * k.ldlt().solve(a.T.transpose() * f);
  return Vec3(u[a.dofs.full[tip][0]], u[a.dofs.full[tip][1]], u[a.dofs.full[tip][2]]);
}

TEST(AbaqusBeamOffsets, EccentricAxialLoadBendsTheBeamByPE) {
  const double area = kOffA * kOffB, i11 = kOffA * std::pow(kOffB, 3) / 12, i22 = kOffB * std::pow(kOffA, 3) / 12;
  for (const std::string type : {"B31", "B32R"}) {
    const Mesh m2 = io::ReadAbaqus(io::testing::WriteScratch("offset2.inp", OffsetDeck(type, ", OFFSET2=0.5")));
    const Vec3 u2 = TipUnderAxialLoad(m2);
    const double e2 = 0.5 * kOffB;
    const double uz = -kOffP * e2 * kOffL * kOffL / (2 * kOffE * i11);
    const double ux = kOffP * kOffL / (kOffE * area) + kOffP * e2 * e2 * kOffL / (kOffE * i11);
    std::printf("  %s OFFSET2 = 0.5: tip ux %.9e (theory %.9e), uz %.9e (theory %.9e)\n", type.c_str(), u2.x(), ux,
                u2.z(), uz);
    EXPECT_NEAR(u2.z(), uz, 1e-9 * std::abs(uz)) << type;
    EXPECT_NEAR(u2.x(), ux, 1e-9 * ux) << type;
    EXPECT_NEAR(u2.y(), 0.0, 1e-12) << type;
    // OFFSET1: along y with I22 (the axis at -e1 y: a moment about -z, the tip moves along -y)
    const Mesh m1 = io::ReadAbaqus(io::testing::WriteScratch("offset1.inp", OffsetDeck(type, ", OFFSET1=0.5")));
    const Vec3 u1 = TipUnderAxialLoad(m1);
    const double e1 = 0.5 * kOffA, uy = -kOffP * e1 * kOffL * kOffL / (2 * kOffE * i22);
    EXPECT_NEAR(u1.y(), uy, 1e-9 * std::abs(uy)) << type;
    EXPECT_NEAR(u1.z(), 0.0, 1e-12) << type;
    // the contrast: no offset, no sideways motion
    const Vec3 u0 = TipUnderAxialLoad(io::ReadAbaqus(io::testing::WriteScratch("offset0.inp", OffsetDeck(type, ""))));
    EXPECT_LT(std::abs(u0.z()), 1e-12);
    EXPECT_GT(std::abs(u2.z()), 1e-3);
  }
}

}  // namespace abaqus_beam_offset_test
}  // namespace flexmb::fe
