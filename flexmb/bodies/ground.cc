#include "flexmb/bodies/ground.h"

namespace flexmb {

void Ground::EvaluateMarker(const double*, const double*, const Marker& m, MarkerState& out) const {
  out.p_WM = m.p_BM;
  out.R_WM = m.R_BM;
  out.v_WM.setZero();
  out.w_WM.setZero();
  out.J.resize(6, 0);
  out.v_offset = 0;
  out.nv = 0;
}

}  // namespace flexmb
