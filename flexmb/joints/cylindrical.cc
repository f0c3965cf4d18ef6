#include "flexmb/joints/cylindrical.h"

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

double CylindricalJoint::Coordinate(int k, const MarkerState& mi, const MarkerState& mj,
                                    Vec12* dq) const {
  return k == 0 ? AxialTranslation(mi, mj, dq) : RelativeAngle(mi, mj, dq);
}

}  // namespace flexmb
