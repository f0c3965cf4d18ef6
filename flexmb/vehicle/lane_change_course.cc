#include "flexmb/vehicle/lane_change_course.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flexmb/common/error.h"

namespace flexmb::vehicle {

LaneChangeCourse::LaneChangeCourse(const LaneChangeCourseData& d) : data_(d) {
  for (double v : {d.section1_length, d.section2_length, d.section1_width, d.section3_width})
    if (!(v > 0) || !std::isfinite(v))
      throw InputError("lane-change course: lengths and widths must be positive", {"", 0, "course"});
  if (!std::isfinite(d.offset) || !std::isfinite(d.start_x)) throw InputError("lane-change course: offset and start must be finite", {"", 0, "course"});
}

int LaneChangeCourse::Section(double x_W) const {
  const double x = x_W - data_.start_x;
  if (x < data_.section1_length) return 1;
  if (x < data_.section1_length + data_.section2_length) return 2;
  return 3;
}

double LaneChangeCourse::CentreLine(double x) const {
  const double u = std::clamp((x - data_.start_x - data_.section1_length) / data_.section2_length, 0.0, 1.0);
  return data_.offset * 0.5 * (1.0 - std::cos(std::numbers::pi * u));
}

double LaneChangeCourse::Margin(double x, double y) const {
  const double h1 = 0.5 * data_.section1_width, h3 = 0.5 * data_.section3_width;
  const double y3 = data_.offset;
  double lo = 0, hi = 0;
  switch (Section(x)) {
    case 1: lo = -h1; hi = h1; break;
    case 3: lo = y3 - h3; hi = y3 + h3; break;
    default:
      lo = std::min(-h1, y3 - h3);
      hi = std::max(h1, y3 + h3);
  }
  return std::min(y - lo, hi - y);
}

double LaneChangeCourse::TestDistance() const {
  return (data_.section1_length + 4.0 * data_.section2_length) * 1.2;
}

}  // namespace flexmb::vehicle
