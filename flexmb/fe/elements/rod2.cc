#include "flexmb/fe/elements/rod2.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/element_common.h"

namespace flexmb::fe {
namespace {

// what the stiffness, mass and section forces share: checks, axis, moduli
struct RodLocal {
  const Material* mat = nullptr;
  const BeamSection* sec = nullptr;
  double L = 0.0;
  double G = 0.0;
  Vec3 e = Vec3::UnitX();  // unit axis, node 1 to node 2
};

RodLocal RodSetup(const ElementInput& in) {
  RodLocal r;
  const Element& el = CheckElementNodes(in, 2, "rod");
  const ErrorContext ctx = ElementContext(el);
  if (in.beam == nullptr) throw InputError("missing rod section (property)", ctx);
  if (in.material == nullptr) throw InputError("missing material of the rod section", ctx);
  const BeamSection& sec = *in.beam;
  const Material& mat = *in.material;
  r.mat = &mat;
  r.sec = &sec;
  if (!(mat.E > 0.0) || !std::isfinite(mat.E))
    throw InputError("material Young's modulus must be positive, got " + std::to_string(mat.E), ctx);
  r.G = mat.G > 0.0 ? mat.G : mat.E / (2.0 * (1.0 + mat.nu));
  if (!(mat.rho >= 0.0) || !std::isfinite(mat.rho) || !(sec.nsm >= 0.0) || !std::isfinite(sec.nsm))
    throw InputError("negative or non-finite density or non-structural mass", ctx);
  if (!(sec.A > 0.0) || !std::isfinite(sec.A))
    throw InputError("rod section area A must be positive, got " + std::to_string(sec.A), ctx);
  if (!(sec.J >= 0.0) || !std::isfinite(sec.J))
    throw InputError("rod torsion constant J must not be negative, got " + std::to_string(sec.J), ctx);
  if (sec.J > 0.0 && !(r.G > 0.0 && std::isfinite(r.G)))
    throw InputError("material shear modulus must be positive for a rod with torsion (J > 0)", ctx);
  if (!IsRodSection(sec))
    throw InputError("section " + std::to_string(sec.id) + " has bending moments Iy, Iz or Iyz: not a rod section",
                     ctx);
  const Vec3 d = in.x[1] - in.x[0];
  r.L = d.norm();
  const double scale = std::max(in.x[0].norm(), in.x[1].norm());
  if (!(r.L > 1e-10 * scale) || !(r.L > 0.0)) throw InputError("zero length (its two nodes coincide)", ctx);
  r.e = d / r.L;
  return r;
}

// 12 x 12 [k -k; -k k] with the 3 x 3 blocks kt (translations), kr (rotations)
void RodPattern(const Mat3& kt, const Mat3& kr, MatX& K) {
  K.setZero(12, 12);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double s = a == b ? 1.0 : -1.0;
      K.block<3, 3>(6 * a, 6 * b) = s * kt;
      K.block<3, 3>(6 * a + 3, 6 * b + 3) = s * kr;
    }
}

}  // namespace

void Rod2Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const RodLocal r = RodSetup(in);
  const Mat3 ee = r.e * r.e.transpose();
  RodPattern(r.mat->E * r.sec->A / r.L * ee, r.G * r.sec->J / r.L * ee, K);
  const double m = (r.mat->rho * r.sec->A + r.sec->nsm) * r.L;
  M.setZero(12, 12);
  const bool lumped = in.mass_form == MassForm::kLumped;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const double mab = lumped ? (a == b ? m / 2.0 : 0.0) : (a == b ? m / 3.0 : m / 6.0);
      M.block<3, 3>(6 * a, 6 * b).diagonal().setConstant(mab);
    }
}

void Rod2SectionForces(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) {
  const RodLocal r = RodSetup(in);
  // y: the basic axis least aligned with x, made orthogonal
  int least = 0;
  r.e.cwiseAbs().minCoeff(&least);
  const Vec3 ey = (Vec3::Unit(least) - r.e * r.e(least)).normalized();
  axes.col(0) = r.e;
  axes.col(1) = ey;
  axes.col(2) = r.e.cross(ey);
  const double ka = r.mat->E * r.sec->A / r.L, kt = r.G * r.sec->J / r.L;
  S.setZero(12, 12);
  for (int end = 0; end < 2; ++end) {
    // N = ka e.(u2 - u1), T = kt e.(theta2 - theta1)
    S.block<1, 3>(6 * end, 0) = -ka * r.e.transpose();
    S.block<1, 3>(6 * end, 6) = ka * r.e.transpose();
    S.block<1, 3>(6 * end + 3, 3) = -kt * r.e.transpose();
    S.block<1, 3>(6 * end + 3, 9) = kt * r.e.transpose();
  }
}

void Rod2GeometricStiffness(const ElementInput& in, double N, MatX& KG) {
  const RodLocal r = RodSetup(in);
  RodPattern(N / r.L * (Mat3::Identity() - r.e * r.e.transpose()), Mat3::Zero(), KG);
}

Eigen::Vector2d RodStresses(const BeamSection& section, double N, double T) {
  if (!(section.A > 0.0))
    throw InputError("rod stress: section " + std::to_string(section.id) + " needs A > 0");
  double c = 0.0;
  if (!section.stress_points.empty())
    c = std::hypot(section.stress_points.front()[0], section.stress_points.front()[1]);
  const double tau = c > 0.0 && section.J > 0.0 ? c * T / section.J : 0.0;
  return Eigen::Vector2d(N / section.A, tau);
}

}  // namespace flexmb::fe
