#include "flexmb/ancf/ancf_beam2d.h"

namespace flexmb::ancf {

AncfBeam2d::AncfBeam2d(double length, const BeamSection& section, double curvature0,
                       const QuadratureOrder& order)
    : LineElement<2>(length, section, order) {
  kappa0_(0) = curvature0;
}

}  // namespace flexmb::ancf
