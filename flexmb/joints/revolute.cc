#include "flexmb/joints/revolute.h"

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

double RevoluteJoint::Coordinate(int, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const {
  return RelativeAngle(mi, mj, dq);
}

}  // namespace flexmb
