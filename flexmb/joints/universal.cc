#include "flexmb/joints/universal.h"

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

std::string UniversalJoint::EquationName(int k) const {
  static const char* names[] = {"x: origins coincide", "y: origins coincide", "z: origins coincide", "z_i . z_j = 0"};
  return names[k];
}

void UniversalJoint::Evaluate(const MarkerState& mi, const MarkerState& mj, double, JointEval& e) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  PointCoincidence(mi, mj, e, 0);
  Perpendicular(Ri.col(2), Rj.col(2), e, 3);
}

void UniversalJoint::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                                Mat12& H) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  PerpendicularStiffness(Ri.col(2), Rj.col(2), lambda[3], H);
}

}  // namespace flexmb
