#include "flexmb/joints/joint.h"

#include "flexmb/common/error.h"

namespace flexmb {

const char* Joint::CoordinateName(int) const { return ""; }

double Joint::Coordinate(int, const MarkerState&, const MarkerState&, Vec12*) const {
  throw InputError(std::string("a ") + type() + " joint has no joint coordinate",
                   {"", 0, "joint '" + name() + "'"});
}

Vec3 Joint::CoordinateAxis(int, const MarkerState& mi) const { return mi.R_WM.col(2); }

}  // namespace flexmb
