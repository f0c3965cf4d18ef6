#pragma once
/// \file road_profile.h
/// Road elevation profiles for durability runs: the left and right wheel
/// tracks as functions of the distance x along the road, either generated
/// after ISO 8608:2016 (random profile of a road class A to H from the
/// standard's displacement PSD) or read from a CSV file of measured
/// elevations.
///
/// ISO 8608 displacement PSD (one-sided, spatial frequency n in
/// cycles/m): Gd(n) = Gd(n0) (n / n0)^-2 with n0 = 0.1 cycles/m and
/// Gd(n0) = 16e-6 m^3 times 4^k for class A (k = 0) to H (k = 7), the
/// geometric mean of each class. The profile is a sum of harmonics on the
/// grid n_k = k / L (L = N dx, N a power of two, the generated road
/// periodic over L) from n_min to n_max with amplitudes sqrt(2 Gd(n_k) /
/// L) and random phases, evaluated by one inverse FFT per track.
///
/// Left/right coherence model: every harmonic of the right track is
/// gamma(n) times the left one plus sqrt(1 - gamma(n)^2) times an
/// independent harmonic of the same amplitude, with gamma(n) =
/// exp(-a n B) (B the track width, a the decay, default 1): both tracks
/// have the class's PSD, long waves are common to both tracks (the road
/// lifts the axle), short waves independent (they roll it); the
/// magnitude-squared coherence is gamma(n)^2.

#include <string>
#include <vector>

namespace flexmb::vehicle {

/// Elevations of the two wheel tracks at increasing x [m].
struct RoadProfile {
  std::vector<double> x;        ///< distance along the road, strictly increasing [m]
  std::vector<double> z_left;   ///< left track elevation [m]
  std::vector<double> z_right;  ///< right track elevation [m]
  /// Elevation of the left (side 0) or right (side 1) track at x by linear
  /// interpolation; the end values beyond the ends [m].
  double Height(int side, double at) const;
};

/// Gd(n0) of an ISO 8608 road class 'A' to 'H' (case-insensitive) [m^3];
/// throws InputError for another letter.
double Iso8608Level(char road_class);

/// Settings of a generated profile.
struct Iso8608Options {
  char road_class = 'B';        ///< 'A' .. 'H'
  double length = 1000.0;       ///< at least this long [m]
  double dx = 0.05;             ///< sample spacing [m]
  unsigned seed = 1;            ///< random seed (same seed, same road)
  double n_min = 0.011;         ///< lowest spatial frequency [cycles/m] (ISO 8608 range)
  double n_max = 2.83;          ///< highest spatial frequency [cycles/m]
  double track_width = 2.0;     ///< distance of the wheel tracks B [m]
  double coherence_decay = 1.0; ///< a in gamma(n) = exp(-a n B)
};

/// Generates a profile (see the file comment); x from 0 in steps of dx over
/// N = the next power of two of length / dx samples. Throws InputError for
/// a bad class, non-positive sizes or n_max above the grid's Nyquist
/// frequency 1 / (2 dx).
RoadProfile GenerateIso8608(const Iso8608Options& options);

/// Reads a CSV file of lines "x, z_left, z_right" [m] (a header line and
/// '#' comments allowed). Throws InputError naming the file and line for a
/// line that is not three numbers, a NaN or infinite value, x not strictly
/// increasing, or fewer than two points.
RoadProfile ReadRoadCsv(const std::string& path);

}  // namespace flexmb::vehicle
