#include "flexmb/joints/planar.h"

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

std::string PlanarJoint::EquationName(int k) const {
  static const char* names[] = {"z_i . x_j = 0", "z_i . y_j = 0", "z_i . (p_j - p_i) = 0"};
  return names[k];
}

void PlanarJoint::Evaluate(const MarkerState& mi, const MarkerState& mj, double, JointEval& e) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  Perpendicular(Ri.col(2), Rj.col(0), e, 0);
  Perpendicular(Ri.col(2), Rj.col(1), e, 1);
  PointInPlane(Ri.col(2), d, e, 2);
}

void PlanarJoint::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                                Mat12& H) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  PerpendicularStiffness(Ri.col(2), Rj.col(0), lambda[0], H);
  PerpendicularStiffness(Ri.col(2), Rj.col(1), lambda[1], H);
  PointInPlaneStiffness(Ri.col(2), d, lambda[2], H);
}

}  // namespace flexmb
