#pragma once
/// \file progress.h
/// A one-line progress bar for long runs, redrawn in place on a terminal.

#include <chrono>
#include <cstdio>

namespace flexmb {

/// Progress of a simulation from t0 to t_end: bar, percent, simulated time,
/// real-time factor (simulated seconds per wall-clock second) and steps.
/// Redraws at most every `min_interval_s` wall seconds; does nothing when
/// disabled.
class ProgressBar {
 public:
  /// `out` is the stream drawn on (usually stderr); t0, t_end [s].
  ProgressBar(std::FILE* out, bool enabled, double t0, double t_end, double min_interval_s = 0.1);
  /// Ends the line if a bar was drawn and Finish() was not called.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Reports the simulated time t [s] and the accepted steps so far.
  void Update(double t, long steps);
  /// Draws the final state and ends the line (once; no-op if never drawn).
  void Finish(double t, long steps);

  /// The line that would be drawn for t and steps at the given wall time [s]
  /// since start (without carriage return), for tests.
  static int Format(char* buf, int size, double t0, double t_end, double t, long steps,
                    double wall_s);

 private:
  void Draw(double t, long steps);

  std::FILE* out_;
  bool enabled_;
  double t0_, t_end_, min_interval_;
  std::chrono::steady_clock::time_point start_, last_;
  bool drawn_ = false;
};

}  // namespace flexmb
