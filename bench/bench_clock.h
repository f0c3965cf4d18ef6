#pragma once
/// \file bench_clock.h
/// Clocks of the performance programs: wall time and the CPU time of the
/// calling thread (robust against other processes on a shared machine).

#include <time.h>

#include <chrono>

namespace flexmb::bench {

/// Monotonic wall-clock time [s] from an arbitrary origin.
inline double WallNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// CPU time of the calling thread [s].
inline double ThreadCpuNow() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace flexmb::bench
