#pragma once
/// \file lane_change_course.h
/// The marked corridor of the lane-change test ("perestavka", GOST R
/// 52302-2004 as described in the seed, section 6): section 1 straight,
/// section 2 the lane change, section 3 straight in the new lane.

namespace flexmb::vehicle {

/// Geometry of the corridor in the road plane: x along the original lane
/// (world x; section 1 begins at start_x), y to the left [m]. Defaults and their
/// reasoning: examples/truck_lane_change/README.md.
struct LaneChangeCourseData {
  double section1_length = 20.0;  ///< L0: straight before the lane change [m]
  double section2_length = 20.0;  ///< L2: the lane change (20 m in the seed) [m]
  double section1_width = 3.0;    ///< corridor width in section 1 [m]
  double section3_width = 3.0;    ///< corridor width in section 3 [m]
  double offset = 3.5;            ///< lateral offset of the section-3 centre line [m], to the left
  /// World x where section 1 begins [m]; the road before it is straight
  /// with section 1's corridor (the truck's run-up).
  double start_x = 0.0;
};

/// The corridor and its centre line. The centre line is y = 0 in section 1,
/// offset * (1 - cos(pi u)) / 2 in section 2 (u the fraction of section 2
/// travelled) and `offset` in section 3. Section 2 has no lines of its own:
/// there the corridor is bounded by the outer lines of sections 1 and 3
/// (right line of section 1, left line of section 3).
class LaneChangeCourse {
 public:
  /// Throws InputError for non-positive lengths or widths.
  explicit LaneChangeCourse(const LaneChangeCourseData& data);
  /// Centre-line lateral position y(x) [m].
  double CentreLine(double x) const;
  /// Section (1, 2, 3) containing world x; x < start_x counts as section 1.
  int Section(double x) const;
  /// Signed distance of the point (x, y) inside the corridor to its nearest
  /// line [m]: positive inside, negative outside.
  double Margin(double x, double y) const;
  /// Travel after which the test ends, (L0 + 4 L2) * 1.2 [m] (seed, section 6).
  double TestDistance() const;
  /// The geometry.
  const LaneChangeCourseData& data() const { return data_; }

 private:
  LaneChangeCourseData data_;
};

}  // namespace flexmb::vehicle
