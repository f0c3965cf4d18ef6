#include "flexmb/ancf/ancf_cable3d.h"

namespace flexmb::ancf {

AncfCable3d::AncfCable3d(double length, const BeamSection& section, const QuadratureOrder& order)
    : LineElement<3>(length, section, order) {}

}  // namespace flexmb::ancf
