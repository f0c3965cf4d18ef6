#include "flexmb/joints/distance.h"

#include "flexmb/common/error.h"
#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

std::string DistanceJoint::EquationName(int k) const {
  static const char* names[] = {"|p_j - p_i| = length"};
  return names[k];
}

void DistanceJoint::Evaluate(const MarkerState& mi, const MarkerState& mj, double, JointEval& e) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  try {
    Distance(d, length_, e, 0);
  } catch (const NumericalError& err) {
    throw NumericalError(err.message(), {"", 0, "joint '" + name() + "'"});
  }
}

void DistanceJoint::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                                Mat12& H) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3& Rj = mj.R_WM;
  const Vec3 d = mj.p_WM - mi.p_WM;
  (void)Ri, (void)Rj, (void)d;
  DistanceStiffness(d, lambda[0], H);
}

}  // namespace flexmb
