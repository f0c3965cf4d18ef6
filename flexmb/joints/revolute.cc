#include "flexmb/joints/revolute.h"

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

std::string RevoluteJoint::EquationName(int k) const {
  static const char* names[] = {"x: origins coincide", "y: origins coincide", "z: origins coincide", "z_i . x_j = 0", "z_i . y_j = 0"};
  return names[k];
}

void RevoluteJoint::Evaluate(const MarkerState& mi, const MarkerState& mj, double, JointEval& e) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  PointCoincidence(mi, mj, e, 0);
  Perpendicular(Ri.col(2), Rj.col(0), e, 3);
  Perpendicular(Ri.col(2), Rj.col(1), e, 4);
}

void RevoluteJoint::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                                Mat12& H) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  PerpendicularStiffness(Ri.col(2), Rj.col(0), lambda[3], H);
  PerpendicularStiffness(Ri.col(2), Rj.col(1), lambda[4], H);
}

double RevoluteJoint::Coordinate(int, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const {
  return RelativeAngle(mi, mj, dq);
}

}  // namespace flexmb
