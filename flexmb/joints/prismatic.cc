#include "flexmb/joints/prismatic.h"

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

std::string PrismaticJoint::EquationName(int k) const {
  static const char* names[] = {"z_i . x_j = 0", "z_i . y_j = 0", "x_i . y_j = 0", "x_i . (p_j - p_i) = 0", "y_i . (p_j - p_i) = 0"};
  return names[k];
}

void PrismaticJoint::Evaluate(const MarkerState& mi, const MarkerState& mj, double, JointEval& e) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  Perpendicular(Ri.col(2), Rj.col(0), e, 0);
  Perpendicular(Ri.col(2), Rj.col(1), e, 1);
  Perpendicular(Ri.col(0), Rj.col(1), e, 2);
  PointInPlane(Ri.col(0), d, e, 3);
  PointInPlane(Ri.col(1), d, e, 4);
}

void PrismaticJoint::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                                Mat12& H) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  PerpendicularStiffness(Ri.col(2), Rj.col(0), lambda[0], H);
  PerpendicularStiffness(Ri.col(2), Rj.col(1), lambda[1], H);
  PerpendicularStiffness(Ri.col(0), Rj.col(1), lambda[2], H);
  PointInPlaneStiffness(Ri.col(0), d, lambda[3], H);
  PointInPlaneStiffness(Ri.col(1), d, lambda[4], H);
}

double PrismaticJoint::Coordinate(int, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const {
  return AxialTranslation(mi, mj, dq);
}

}  // namespace flexmb
