/// \file reduce.cc
/// reduce_bench: time and peak memory of the Craig-Bampton reduction of the
/// generated shell ladder frame (bench/ladder_frame.h, about 33,000 DOF at
/// the default element size) with 26 interface nodes (156 static modes), for
/// several numbers of fixed-interface normal modes. Prints a markdown table
/// per run (wall time of each step, process CPU time of the whole
/// reduction, peak RSS) and the lowest flexible frequencies; see
/// docs/PERFORMANCE.md.
///
/// Usage: reduce_bench [--h H] [--modes 10,30] [--keep N] [--repeat R]
///   H: element size [m] (default 0.04; 0.0125 gives about 320,000 DOF)
///   --modes: comma-separated normal-mode counts (default 10,30)
///   N: flexible modes kept (default all)
///   R: repetitions per count, the fastest is reported (default 1)

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <ctime>
#include <string>
#include <vector>

#include "bench/ladder_frame.h"
#include "flexmb/common/process_tuning.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/fe_io/fe_model_file.h"
#include "flexmb/reduction/craig_bampton.h"

namespace {

double PeakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

double CpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<int> ParseList(const char* s) {
  std::vector<int> out;
  for (const char* p = s; *p;) {
    char* end = nullptr;
    out.push_back(static_cast<int>(std::strtol(p, &end, 10)));
    p = *end == ',' ? end + 1 : end;
    if (end == p && *p) break;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  flexmb::TuneProcess(argv);  // OpenBLAS kernels and malloc settings (docs/design.md)
  double h = 0.04;
  std::vector<int> modes = {10, 30};
  int keep = -1, repeat = 1;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--h") && i + 1 < argc) {
      h = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--modes") && i + 1 < argc) {
      modes = ParseList(argv[++i]);
    } else if (!std::strcmp(argv[i], "--keep") && i + 1 < argc) {
      keep = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: reduce_bench [--h H] [--modes 10,30] [--keep N] [--repeat R]\n");
      return 2;
    }
  }
  // the frame as Nastran bulk data, read back below as `flexmb reduce` does
  auto t0 = std::chrono::steady_clock::now();
  const flexmb::fe::Mesh frame = flexmb::bench::LadderFrame(h);
  const std::vector<int> interface = flexmb::bench::LadderFrameInterface(frame);
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::string bdf = (dir / "flexmb_reduce_bench.bdf").string(), h5 = (dir / "flexmb_reduce_bench.h5").string();
  flexmb::bench::WriteBulkData(frame, bdf);
  const double t_build = Seconds(t0);
  std::printf("ladder frame, h = %g m: %zu nodes, %zu shells, %zu interface nodes (generated and written in %.3f s)\n\n",
              h, frame.nodes.size(), frame.elements.size(), interface.size(), t_build);

  for (int k : modes) {
    flexmb::reduction::ReductionOptions options;
    options.interface_nodes = interface;
    options.normal_modes = k;
    options.keep = keep;
    flexmb::reduction::ReductionTimings best;
    double best_total = 1e300, best_cpu = 0.0, best_read = 0.0, best_write = 0.0, mb = 0.0;
    flexmb::reduction::ReducedBody body;
    for (int r = 0; r < repeat; ++r) {
      // the steps of `flexmb reduce` (apps/flexmb/commands/reduce_commands.cc): read, reduce, write
      flexmb::reduction::ReductionTimings t;
      const double cpu0 = CpuSeconds();
      t0 = std::chrono::steady_clock::now();
      const flexmb::fe::FeModel model = flexmb::io::LoadFeModel(bdf);
      const double read = Seconds(t0);
      body = flexmb::reduction::ReduceCraigBampton(model, options, &t);
      const auto tw = std::chrono::steady_clock::now();
      flexmb::io::WriteBody(body, h5);
      const double write = Seconds(tw);
      const double total = Seconds(t0), cpu = CpuSeconds() - cpu0;
      if (total < best_total) {
        best_total = total;
        best_cpu = cpu;
        best = t;
        best_read = read;
        best_write = write;
      }
      mb = static_cast<double>(std::filesystem::file_size(h5)) / 1e6;
    }
    std::printf("### %d normal modes: %d static + %d normal, %d rigid removed, %ld flexible kept\n\n", k,
                body.static_modes, body.normal_modes, body.rigid_modes_removed,
                static_cast<long>(body.frequencies_hz.size()));
    std::printf("| step | wall time [s] |\n|---|---:|\n");
    std::printf("| read the bulk data | %.3f |\n", best_read);
    std::printf("| assemble K, M | %.3f |\n", best.assemble);
    std::printf("| split, factorize K_ii (CHOLMOD) | %.3f |\n", best.factorize);
    std::printf("| static modes (multi-RHS solve; beside the normal modes) | %.3f |\n", best.static_modes);
    std::printf("| normal modes (block Lanczos on the K_ii factor) | %.3f |\n", best.normal_modes);
    std::printf("| reduced matrices, orthonormalize, rigid modes, expand | %.3f |\n", best.orthonormalize);
    std::printf("| inertia invariants (%ld modes) | %.3f |\n", static_cast<long>(body.invariants.n), best.invariants);
    std::printf("| stress modes | %.3f |\n", best.stress_modes);
    std::printf("| write the body file (%.0f MB) | %.3f |\n", mb, best_write);
    std::printf("| **whole `flexmb reduce` pipeline** | **%.3f** (process CPU %.3f) |\n\n", best_total, best_cpu);
    // baseline: the fixed-interface modes by Spectra on the same factor,
    // runs alternating with block Lanczos, best of `repeat` each
    double block = 1e300, spectra = 1e300;
    {
      const flexmb::fe::FeModel model = flexmb::io::LoadFeModel(bdf);
      for (int r = 0; r < repeat; ++r) {
        for (auto solver : {flexmb::reduction::ReductionOptions::EigenSolver::kBlockLanczos,
                            flexmb::reduction::ReductionOptions::EigenSolver::kSpectra}) {
          flexmb::reduction::ReductionOptions o = options;
          o.eigen_solver = solver;
          flexmb::reduction::ReductionTimings t;
          flexmb::reduction::ReduceCraigBampton(model, o, &t);
          double& best_solver =
              solver == flexmb::reduction::ReductionOptions::EigenSolver::kSpectra ? spectra : block;
          best_solver = std::min(best_solver, t.normal_modes);
        }
      }
    }
    std::printf("fixed-interface modes: block Lanczos %.3f s, Spectra on the same factor %.3f s (ratio Spectra / "
                "block %.2f)\n\n",
                block, spectra, spectra / block);
    std::printf("peak RSS %.0f MB; lowest flexible frequencies [Hz]:", PeakRssMb());
    for (int j = 0; j < std::min<int>(12, static_cast<int>(body.frequencies_hz.size())); ++j) {
      std::printf(" %.4g", body.frequencies_hz[j]);
    }
    std::printf("\n\n");
  }
  std::filesystem::remove(bdf);
  std::filesystem::remove(h5);
  return 0;
}
