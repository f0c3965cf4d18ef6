#include "flexmb/vehicle/road_surface.h"

#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb::vehicle {

RoadSurface::RoadSurface(std::shared_ptr<const RoadProfile> profile, int side)
    : profile_(std::move(profile)), side_(side) {
  const ErrorContext ctx{"", 0, "road surface"};
  if (!profile_) throw InputError("no road profile", ctx);
  if (side != 0 && side != 1) throw InputError("road side must be 0 (left) or 1 (right)", ctx);
  const RoadProfile& p = *profile_;
  z_ = side == 0 ? &p.z_left : &p.z_right;
  if (p.x.size() < 2 || z_->size() != p.x.size()) throw InputError("a road track needs at least two points of x and z", ctx);
  // equally spaced samples (generated roads): index by division
  const double dx = (p.x.back() - p.x.front()) / static_cast<double>(p.x.size() - 1);
  bool uniform = dx > 0;
  for (size_t i = 1; uniform && i < p.x.size(); ++i)
    uniform = std::abs(p.x[i] - p.x.front() - static_cast<double>(i) * dx) <= 1e-9 * (1.0 + std::abs(p.x[i]));
  dx_ = uniform ? dx : 0.0;
}

void RoadSurface::Evaluate(double at, double* h, double* slope) const {
  const std::vector<double>& x = profile_->x;
  const std::vector<double>& z = *z_;
  if (!(at > x.front())) {
    *h = z.front();
    *slope = 0.0;
    return;
  }
  if (!(at < x.back())) {
    *h = z.back();
    *slope = 0.0;
    return;
  }
  size_t i = 0;  // segment [i - 1, i] holding at
  if (dx_ > 0) {
    i = std::min(x.size() - 1, static_cast<size_t>((at - x.front()) / dx_) + 1);
    // rounding at a sample: step to the segment that holds it
    while (i > 1 && at < x[i - 1]) --i;
    while (i + 1 < x.size() && at >= x[i]) ++i;
  } else {
    i = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
  }
  const double len = x[i] - x[i - 1];
  const double s = (at - x[i - 1]) / len;
  *h = (1.0 - s) * z[i - 1] + s * z[i];
  *slope = (z[i] - z[i - 1]) / len;
}

}  // namespace flexmb::vehicle
