#include "flexmb/joints/spherical.h"

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

std::string SphericalJoint::EquationName(int k) const {
  static const char* names[] = {"x: origins coincide", "y: origins coincide", "z: origins coincide"};
  return names[k];
}

void SphericalJoint::Evaluate(const MarkerState& mi, const MarkerState& mj, double, JointEval& e) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  PointCoincidence(mi, mj, e, 0);
}

void SphericalJoint::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                                Mat12& H) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  (void)lambda, (void)H;
}

}  // namespace flexmb
