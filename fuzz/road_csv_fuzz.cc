// libFuzzer target for vehicle::ReadRoadCsv (measured road elevations, CSV
// of x, z_left, z_right): any input must give a profile or a flexmb::Error,
// never a crash, hang or sanitizer report. A profile that was read must
// hold what the reader promises: at least two points, x strictly
// increasing, finite elevations, and finite interpolated heights anywhere.
// Seeds: fuzz/corpus/road_csv/.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "flexmb/vehicle/road_profile.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::ReadScratchFile(data, size, ".csv", [](const std::string& path) {
    const flexmb::vehicle::RoadProfile road = flexmb::vehicle::ReadRoadCsv(path);
    const size_t n = road.x.size();
    if (n < 2 || road.z_left.size() != n || road.z_right.size() != n) std::abort();
    for (size_t i = 0; i < n; ++i) {
      if (!std::isfinite(road.x[i]) || !std::isfinite(road.z_left[i]) || !std::isfinite(road.z_right[i])) std::abort();
      if (i > 0 && !(road.x[i] > road.x[i - 1])) std::abort();
    }
    const double probes[] = {road.x.front() - 1.0, road.x.front(), 0.5 * (road.x.front() + road.x.back()),
                             road.x.back(), road.x.back() + 1.0};
    for (double x : probes) {
      for (int side = 0; side < 2; ++side) {
        if (!std::isfinite(road.Height(side, x))) std::abort();
      }
    }
  });
  return 0;
}
