#pragma once
/// \file road_surface.h
/// The road surface under one wheel track for the Tire: the elevation h(x)
/// and its slope dh/dx along world x, from one track of a RoadProfile
/// (road_profile.h) by linear interpolation. The road runs along world x;
/// its elevation does not vary across it (each wheel side has its own
/// track). Without a RoadSurface a Tire rolls on the plane z = 0.

#include <memory>

#include "flexmb/vehicle/road_profile.h"

namespace flexmb::vehicle {

/// One track (left or right) of a road profile as a surface z = h(x) over
/// world x [m]. Beyond the profile's ends the end elevations continue level
/// (slope 0). Lookups allocate nothing (a binary search over the samples,
/// or an index computation when they are equally spaced).
class RoadSurface {
 public:
  /// side 0: the profile's left track (z_left), 1: the right track
  /// (z_right). Throws InputError for another side, a profile with fewer
  /// than two points or sizes that differ.
  RoadSurface(std::shared_ptr<const RoadProfile> profile, int side);
  /// Elevation h [m] and slope dh/dx [-] at world x [m]: linear
  /// interpolation between samples (the slope is the segment's).
  void Evaluate(double x, double* h, double* slope) const;
  /// The profile.
  const RoadProfile& profile() const { return *profile_; }
  /// The track: 0 left, 1 right.
  int side() const { return side_; }

 private:
  std::shared_ptr<const RoadProfile> profile_;
  const std::vector<double>* z_ = nullptr;
  int side_ = 0;
  double dx_ = 0.0;  // sample spacing when uniform, else 0
};

}  // namespace flexmb::vehicle
