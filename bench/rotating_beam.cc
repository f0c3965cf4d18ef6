// Simo and Vu-Quoc's / Kane's spin-up of a flexible beam over the full 30 s
// (bench/rotating_beam.h; docs/validation.md, "Rotating beam: geometric
// stiffening"): tip deflection in the hub frame of the floating-frame beam
// (root-attached and free frame, with and without geometric stiffening)
// against planar ANCF beams of 10, 20 and 40 elements. Prints a table every
// 0.5 s and the largest differences; `--csv FILE` also writes every step.

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "bench/rotating_beam.h"

using namespace flexmb;
using namespace flexmb::rotating_beam;

int main(int argc, char** argv) {
  const double t_end = 30.0, dt = 0.01;
  std::string csv;
  for (int k = 1; k + 1 < argc; ++k) {
    if (std::strcmp(argv[k], "--csv") == 0) csv = argv[k + 1];
  }
  std::vector<std::string> names;
  std::vector<Result> runs;
  for (int ne : {10, 20, 40}) {
    names.push_back("ancf" + std::to_string(ne));
    runs.push_back(RunAncf(ne, t_end, dt));
  }
  const auto root = ReducedBeam(20, 8, Frame::kRootAttached);
  const auto free = ReducedBeam(20, 8, Frame::kFree);
  names.insert(names.end(), {"root_gs", "root_lin", "free_gs", "free_lin"});
  runs.push_back(RunFloatingFrame(root, true, t_end, dt));
  runs.push_back(RunFloatingFrame(root, false, t_end, dt));
  runs.push_back(RunFloatingFrame(free, true, t_end, dt));
  runs.push_back(RunFloatingFrame(free, false, t_end, dt));
  for (size_t r = 0; r < runs.size(); ++r) {
    if (!runs[r].failure.empty()) std::printf("%s stopped: %s\n", names[r].c_str(), runs[r].failure.c_str());
  }
  const Result& ref = runs[2];  // ANCF, 40 elements
  std::printf("%7s", "t [s]");
  for (const auto& n : names) std::printf(" %11s", n.c_str());
  std::printf("   tip deflection in the hub frame [m]\n");
  for (size_t k = 0; k < ref.samples.size(); k += 50) {
    std::printf("%7.2f", ref.samples[k].t);
    for (const Result& r : runs) {
      if (k < r.samples.size()) {
        std::printf(" %11.5f", r.samples[k].deflection);
      } else {
        std::printf(" %11s", "-");
      }
    }
    std::printf("\n");
  }
  double peak = 0.0;
  for (const auto& s : ref.samples) peak = std::max(peak, std::abs(s.deflection));
  std::printf("ANCF 40 elements: peak |deflection| %.5f m\n", peak);
  for (size_t r = 0; r < runs.size(); ++r) {
    if (r == 2) continue;
    double d = 0.0;
    const size_t n = std::min(runs[r].samples.size(), ref.samples.size());
    for (size_t k = 0; k < n; ++k) d = std::max(d, std::abs(runs[r].samples[k].deflection - ref.samples[k].deflection));
    std::printf("%-9s max |d - d_ancf40| over 0..%.2f s: %.5f m (%.2f %% of the peak)\n", names[r].c_str(),
                n ? runs[r].samples[n - 1].t : 0.0, d, 100.0 * d / peak);
  }
  if (!csv.empty()) {
    FILE* f = std::fopen(csv.c_str(), "w");
    if (!f) {
      std::fprintf(stderr, "cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(f, "t");
    for (const auto& n : names) std::fprintf(f, ",%s", n.c_str());
    std::fprintf(f, "\n");
    for (size_t k = 0; k < ref.samples.size(); ++k) {
      std::fprintf(f, "%.4f", ref.samples[k].t);
      for (const Result& r : runs) {
        if (k < r.samples.size()) {
          std::fprintf(f, ",%.8g", r.samples[k].deflection);
        } else {
          std::fprintf(f, ",");
        }
      }
      std::fprintf(f, "\n");
    }
    std::fclose(f);
  }
  return 0;
}
