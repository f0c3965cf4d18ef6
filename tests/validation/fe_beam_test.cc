// 2-node beams against beam theory, natural frequencies through flexmb's
// assembly and modal solver (fe::Assemble, fe::SolveModes) on sequences of
// meshes:
// - the reference solver itself: its Euler-Bernoulli limit against the
//   eigenvalues of Blevins (1979) and its pinned-pinned Timoshenko roots
//   against the closed form (Timoshenko 1921);
// - a slender beam without shear flexibility (L / h = 100), cantilever and
//   free-free, three bending modes, against the Euler-Bernoulli beam with
//   the section's rotary inertia (the element carries it);
// - a thick beam (L / h = 5, kappa = 5/6), cantilever and free-free,
//   against the Timoshenko beam;
// - a free-free beam along a skew axis with all six DOF per node: six
//   rigid modes near zero, then the bending pairs of the square section.
// Sources: docs/validation.md, "FE: beams and solids".

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "flexmb/fe/elements/beam3.h"
#include "tests/validation/fe_beam_theory.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace fe_beam_test {

constexpr double kE = 2.1e11, kNu = 0.3, kRho = 7850.0;

// n equal beam elements of a square b x b section from the origin along
// `axis`, length L, orientation vector v: 2-node beams, or with `beam3`
// 3-node beams (B32) with their mid nodes
Mesh BeamMesh(int n, double L, double b, double k_shear, const Vec3& axis = Vec3::UnitX(),
              const Vec3& v = Vec3::UnitY(), bool beam3 = false) {
  Mesh mesh;
  const int mat = testing::AddMaterial(mesh, kE, kNu, kRho);
  BeamSection sec;
  sec.material = mat;
  sec.A = b * b;
  sec.Iy = sec.Iz = b * b * b * b / 12.0;
  sec.J = 0.1406 * b * b * b * b;
  sec.ky = sec.kz = k_shear;
  mesh.beam_sections.push_back(sec);
  if (beam3) {
    for (int i = 0; i <= 2 * n; ++i) testing::AddNode(mesh, axis.normalized() * (L * i / (2 * n)));
    for (int i = 0; i < n; ++i)
      mesh.elements[testing::AddElement(mesh, kBeam3, 0, {2 * i, 2 * i + 1, 2 * i + 2})].orientation = v;
    return mesh;
  }
  for (int i = 0; i <= n; ++i) testing::AddNode(mesh, axis.normalized() * (L * i / n));
  for (int i = 0; i < n; ++i) testing::AddBeam(mesh, 0, i, i + 1, v);
  return mesh;
}

BeamProperties Theory(double L, double b, double k_shear) {
  BeamProperties p;
  p.EI = kE * b * b * b * b / 12.0;
  p.shear_compliance = k_shear > 0.0 ? 1.0 / (k_shear * kE / (2.0 * (1.0 + kNu)) * b * b) : 0.0;
  p.rhoA = kRho * b * b;
  p.rhoI = kRho * b * b * b * b / 12.0;
  p.L = L;
  return p;
}

// omega [rad/s] of the three lowest bending modes in the x-y plane: every
// node keeps only uy and rz (ux, uz, rx, ry fixed; they do not couple with
// x-y bending of a straight beam along x), node 0 clamped for a cantilever
std::vector<double> PlanarOmegas(int n, double L, double b, double k_shear, BeamSupport support,
                                 bool beam3 = false) {
  Mesh mesh = BeamMesh(n, L, b, k_shear, Vec3::UnitX(), Vec3::UnitY(), beam3);
  for (int i = 0; i < static_cast<int>(mesh.nodes.size()); ++i) testing::AddConstraint(mesh, i, 0b011101);
  if (support == BeamSupport::kCantilever) testing::AddConstraint(mesh, 0, 0b111111);
  const int rigid = support == BeamSupport::kFreeFree ? 2 : 0;
  const ModalResult r = SolveMeshModes(mesh, rigid + 3);
  std::vector<double> out;
  for (int k = rigid; k < rigid + 3; ++k) out.push_back(2.0 * kPi * r.frequencies_hz[k]);
  return out;
}

TEST(FeBeamValidation, ReferenceSolverAgainstClosedForms) {
  BeamProperties p;
  p.EI = 2.0;
  p.rhoA = 3.0;
  p.L = 1.7;
  const double scale = std::sqrt(p.EI / (p.rhoA * std::pow(p.L, 4)));
  for (int k = 0; k < 3; ++k) {
    // Blevins quotes beta L to 9 significant digits: half a unit of the last
    // one is at most 5e-8
    EXPECT_NEAR(std::sqrt(TimoshenkoOmega(p, BeamSupport::kCantilever, k + 1) / scale),
                kCantileverBetaL[k], 5e-8);
    EXPECT_NEAR(std::sqrt(TimoshenkoOmega(p, BeamSupport::kFreeFree, k + 1) / scale),
                kFreeFreeBetaL[k], 5e-8);
  }
  // a thick beam: shear and rotary inertia lower the frequencies by 20-60 %
  p.shear_compliance = 1.0 / (5.0 / 6.0 * 100.0);
  p.rhoI = 0.05;
  for (int n = 1; n <= 4; ++n) {
    const double closed = PinnedPinnedOmega(p, n);
    EXPECT_NEAR(TimoshenkoOmega(p, BeamSupport::kPinnedPinned, n), closed, 1e-12 * closed);
  }
}

void CheckPlanarBeam(const char* name, double L, double b, double k_shear,
                     const std::vector<int>& meshes, double min_ratio, bool beam3 = false) {
  const BeamProperties p = Theory(L, b, k_shear);
  for (BeamSupport support : {BeamSupport::kCantilever, BeamSupport::kFreeFree}) {
    std::vector<std::vector<double>> omegas;
    for (int n : meshes) omegas.push_back(PlanarOmegas(n, L, b, k_shear, support, beam3));
    for (int k = 0; k < 3; ++k) {
      Convergence c{std::string(name) +
                        (support == BeamSupport::kCantilever ? " cantilever" : " free-free") +
                        " mode " + std::to_string(k + 1),
                    meshes,
                    {},
                    TimoshenkoOmega(p, support, k + 1)};
      for (const auto& o : omegas) c.values.push_back(o[k]);
      c.Report();
      c.ExpectConverges();
      c.ExpectErrorFallsBy(min_ratio);
      c.ExpectFinestWithinLastChange(1e-10);
    }
  }
}

// Euler-Bernoulli element (shear factors 0): cubic Hermite interpolation
// with consistent mass, frequency error O(h^4) (linear curvature per
// element); we ask for at least O(h^3) per halving, from 8 elements on (4
// elements are too few for the third free-free mode to be in the asymptotic
// range). The reference keeps the rotary inertia rho I the element carries
// (Rayleigh beam); it differs from the plain Euler-Bernoulli value by a
// relative 1e-5 here.
TEST(FeBeamValidation, SlenderBeamAgainstEulerBernoulli) {
  CheckPlanarBeam("slender beam2", 1.0, 0.01, 0.0, {8, 16, 32}, 8.0);
}

// Timoshenko element: its exact static shape functions have a constant
// shear strain per element (the shear force of a span without loads), so
// the shear part of the strain energy converges at O(h) and the frequency
// error at O(h^2) once shear matters (here L / h = 5: 4.0 per halving); we
// ask for at least O(h) per halving, from 8 elements on as above
TEST(FeBeamValidation, ThickBeamAgainstTimoshenko) {
  CheckPlanarBeam("thick beam2", 1.0, 0.2, 5.0 / 6.0, {8, 16, 32}, 2.0);
}

// 3-node beams (B32): two exact halves per element, so n elements are the
// 2n-element beam2 mesh and converge as it does: O(h^4) per halving slender
// (at least 8 asked), O(h^2) thick (at least 2), to the same references
TEST(FeBeamValidation, SlenderBeam3AgainstEulerBernoulli) {
  CheckPlanarBeam("slender beam3", 1.0, 0.01, 0.0, {4, 8, 16}, 8.0, true);
}

TEST(FeBeamValidation, ThickBeam3AgainstTimoshenko) {
  CheckPlanarBeam("thick beam3", 1.0, 0.2, 5.0 / 6.0, {4, 8, 16}, 2.0, true);
}

// full 3D: a free-free beam of square section along a skew axis has six
// rigid modes (|f| < 1e-4 f7) and then the bending pairs 1, 2, 3 (torsion
// and axial modes lie far above for L / b = 50)
TEST(FeBeamValidation, SkewFreeFreeBeamIn3D) {
  const double L = 2.0, b = 0.04;
  const Vec3 axis(1.0, 2.0, 2.0);
  const BeamProperties p = Theory(L, b, 5.0 / 6.0);
  const std::vector<int> meshes = {8, 16, 32};
  std::vector<ModalResult> results;
  for (int n : meshes)
    results.push_back(SolveMeshModes(BeamMesh(n, L, b, 5.0 / 6.0, axis, Vec3(0, 0, 1)), 12));
  for (const ModalResult& r : results)
    for (int k = 0; k < 6; ++k)
      EXPECT_LT(std::abs(r.frequencies_hz[k]), 1e-4 * r.frequencies_hz[6]);
  for (int k = 0; k < 3; ++k) {
    const double ref = TimoshenkoOmega(p, BeamSupport::kFreeFree, k + 1) / (2.0 * kPi);
    for (int pair = 0; pair < 2; ++pair) {
      Convergence c{"skew free-free beam2 mode " + std::to_string(k + 1) + (pair ? "b" : "a"),
                    meshes,
                    {},
                    ref};
      for (const ModalResult& r : results) c.values.push_back(r.frequencies_hz[6 + 2 * k + pair]);
      c.Report();
      c.ExpectConverges();
      c.ExpectFinestWithinLastChange(1e-10);
    }
  }
}

}  // namespace fe_beam_test
}  // namespace flexmb::fe::validation
