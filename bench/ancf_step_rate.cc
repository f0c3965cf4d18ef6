/// \file ancf_step_rate.cc
/// ancf_bench: steps per second of the generalized-alpha integrator on the
/// flexible pendulum of Berzeri and Shabana (L = 1.2 m, A = 0.0018 m^2,
/// I = 1.215e-8 m^4, rho = 5540 kg/m^3, E = 0.7 MPa, released horizontal)
/// as a planar ANCF beam (`ancf_beam`, revolute pin), as a 3D ANCF cable
/// (`ancf_cable`, spherical pin) and as a 3D ANCF beam with torsion
/// (`ancf_beam3d`, Iy = Iz = I, J = 2 I, nu = 0.3, spherical pin), with
/// N = 8, 32, 128 elements (issue 6).
/// For each model it also reports the non-zeros of the iteration matrix and
/// the time of one KLU factorization of it, to show how the linear solve
/// scales. Prints a markdown table; see docs/PERFORMANCE.md, "ANCF step
/// rate (issue 6)". Times are thread CPU times.
///
/// Usage: ancf_bench [--steps S]   (S timed steps per model, default 200)

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "bench/bench_clock.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/solver/sparse_lu.h"

namespace {

using namespace flexmb;

constexpr double kDt = 1e-3;
constexpr int kWarmupSteps = 10;

// the pendulum as model-file text: planar beam (kind 0), 3D cable (1) or 3D beam with torsion (2)
std::string Model(int kind, int n) {
  const bool cable = kind > 0;
  std::string text =
      "name: ancf_pendulum\n"
      "gravity: [0, -9.81, 0]\n"
      "ground:\n"
      "  markers:\n"
      "    - {name: pivot, position: [0, 0, 0]}\n"
      "bodies:\n"
      "  - name: beam\n";
  text += kind == 2 ? "    type: ancf_beam3d\n" : cable ? "    type: ancf_cable\n" : "    type: ancf_beam\n";
  text += "    length: 1.2\n    elements: " + std::to_string(n) + "\n";
  text += kind == 2 ? "    section: {area: 0.0018, Iy: 1.215e-8, Iz: 1.215e-8, J: 2.43e-8}\n"
                      "    material: {E: 0.7e6, nu: 0.3, rho: 5540}\n"
                    : "    section: {area: 0.0018, inertia: 1.215e-8}\n"
                      "    material: {E: 0.7e6, rho: 5540}\n";
  text +=
      "    direction: [1, 0, 0]\n"
      "    markers:\n"
      "      - {name: pin, end: start}\n"
      "joints:\n";
  text += cable ? "  - {name: pin, type: spherical, i: ground.pivot, j: beam.pin}\n"
                : "  - {name: pin, type: revolute, i: ground.pivot, j: beam.pin}\n";
  text += "solver: {t_end: 10.0, dt: 0.001, rho_inf: 0.95}\n";
  return text;
}

struct Result {
  int nv = 0;
  double steps_per_s = 0.0;
  double newton_per_step = 0.0;
  long nnz = 0;
  double factor_ms = 0.0;
};

Result Measure(int kind, int n, int steps) {
  auto model = LoadModelString(Model(kind, n), "ancf_bench.yaml");
  Simulator sim(*model);
  sim.Initialize();
  sim.Run(kWarmupSteps * kDt, 0.0, nullptr);
  const long it0 = sim.stats().newton_iterations;
  const double t0 = flexmb::bench::ThreadCpuNow();
  sim.Run((kWarmupSteps + steps) * kDt, 0.0, nullptr);
  const double wall = flexmb::bench::ThreadCpuNow() - t0;
  Result r;
  r.nv = model->nv;
  r.steps_per_s = steps / wall;
  r.newton_per_step = static_cast<double>(sim.stats().newton_iterations - it0) / steps;
  // one factorization of the iteration matrix at the current state
  const Workspace& ws = sim.workspace();
  r.nnz = ws.S.nonZeros();
  SparseLu lu;
  const int reps = n >= 128 ? 3 : 20;
  double best = 1e30;
  for (int k = 0; k < reps; ++k) {
    const double f0 = flexmb::bench::ThreadCpuNow();
    lu.Factorize(ws.S);
    best = std::min(best, flexmb::bench::ThreadCpuNow() - f0);
  }
  r.factor_ms = 1e3 * best;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 200;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--steps") == 0 && i + 1 < argc) {
      steps = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: ancf_bench [--steps S]\n");
      return 2;
    }
  }
  std::printf("| model | N | nv | steps/s | ms/step | ms/step/element | Newton it./step | nnz(S) | KLU factor [ms] |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  const char* names[3] = {"2D beam", "3D cable", "3D beam"};
  for (int kind : {0, 1, 2}) {
    for (int n : {8, 32, 128}) {
      const Result r = Measure(kind, n, steps);
      const double ms = 1e3 / r.steps_per_s;
      std::printf("| %s | %d | %d | %.1f | %.3f | %.4f | %.2f | %ld | %.3f |\n",
                  names[kind], n, r.nv, r.steps_per_s, ms, ms / n, r.newton_per_step,
                  r.nnz, r.factor_ms);
      std::fflush(stdout);
    }
  }
  return 0;
}
