/// \file truck_lane_change.cc
/// truck_lane_change_bench: real-time factor (simulated time / wall time,
/// and on process CPU time) of the 55 km/h lane change of
/// examples/truck_lane_change/truck.yaml with the rigid and the elastic
/// (Craig-Bampton) frame, in one process, alternating, best of R runs each;
/// the elastic frame is reduced once before the runs (its time is printed
/// separately). Prints a markdown table; see docs/PERFORMANCE.md, "Truck
/// lane change (issue 7)".
///
/// Usage: truck_lane_change_bench [--file F] [--speed KMH] [--keep N,..] [--repeat R]
///   --keep: flexible modes kept by the elastic frame, comma-separated, -1 = all
///           (the file's default); default "-1,30"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "flexmb/common/process_tuning.h"
#include "apps/flexmb/commands/lane_change.h"

int main(int argc, char** argv) {
  flexmb::TuneProcess(argv);
  std::string file = std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_lane_change/truck.yaml";
  double speed = 55.0;
  std::vector<int> keeps = {-1, 30};
  int repeat = 1;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--file") && i + 1 < argc) {
      file = argv[++i];
    } else if (!std::strcmp(argv[i], "--speed") && i + 1 < argc) {
      speed = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--keep") && i + 1 < argc) {
      keeps.clear();
      for (char* p = argv[++i]; *p;) {
        char* end = nullptr;
        keeps.push_back(static_cast<int>(std::strtol(p, &end, 10)));
        p = *end == ',' ? end + 1 : end;
        if (end == p && *p) break;
      }
    } else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: %s [--file F] [--speed KMH] [--keep N,..] [--repeat R]\n", argv[0]);
      return 2;
    }
  }
  using namespace flexmb::vehicle;
  const TruckData truck = LoadLaneChangeTruck(file);
  std::printf("lane change at %.0f km/h, %s, best of %d\n\n", speed, file.c_str(), repeat);
  std::printf("| frame | modal coordinates | reduction [s] | steps | Newton iterations | wall [s] | RTF (wall) | RTF (CPU) | wall / rigid wall | max elastic displacement [mm] |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  LaneChangeOptions base;
  base.file = file;
  base.speed_kmh = speed;
  auto best = [&](const LaneChangeOptions& o) {
    LaneChangeResult b;
    for (int k = 0; k < repeat; ++k) {
      const LaneChangeResult r = RunLaneChange(o);
      if (k == 0 || r.wall_time_s < b.wall_time_s) b = r;
    }
    return b;
  };
  for (int keep : keeps) {
    FrameReductionData red = LaneChangeFrameReduction(file);
    red.keep = keep;
    const auto t0 = std::chrono::steady_clock::now();
    LaneChangeOptions e = base;
    e.frame = "elastic";
    e.frame_body = ReduceTruckFrame(truck, red);
    const double t_red = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    LaneChangeOptions r = base;
    r.frame = "rigid";
    const LaneChangeResult rr = best(r);
    const LaneChangeResult er = best(e);
    for (const LaneChangeResult* x : {&rr, &er}) {
      const bool el = x == &er;
      std::printf("| %s | %d | %s | %ld | %ld | %.2f | %.2f | %.2f | %.2f | %s |\n", x->frame.c_str(),
                  x->frame_modal_coordinates, el ? std::to_string(t_red).substr(0, 5).c_str() : "-", x->steps,
                  x->newton_iterations, x->wall_time_s, x->real_time_factor,
                  x->cpu_time_s > 0 ? x->t_end / x->cpu_time_s : 0.0, x->wall_time_s / rr.wall_time_s,
                  el ? std::to_string(x->max_frame_displacement * 1e3).substr(0, 5).c_str() : "-");
    }
    std::fflush(stdout);
  }
  return 0;
}
