#include "flexmb/joints/prismatic.h"

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

double PrismaticJoint::Coordinate(int, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const {
  return AxialTranslation(mi, mj, dq);
}

}  // namespace flexmb
