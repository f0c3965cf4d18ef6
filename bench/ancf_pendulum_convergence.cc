/// \file ancf_pendulum_convergence.cc
/// ancf_pendulum_convergence_bench: convergence of the tip path of the
/// flexible pendulum of Berzeri and Shabana (2000) (L = 1.2 m,
/// A = 0.0018 m^2, I = 1.215e-8 m^4, rho = 5540 kg/m^3, E = 0.7 MPa, pinned
/// by a revolute joint at one end, released from rest horizontal, g = 9.81
/// along -y) with the element count, the time step and the element's
/// quadrature and the integrator's numerical damping (issue 6). Each run
/// records the tip position every 4 ms over [0, T]; the tables give the
/// largest distance between a run's tip path and the finest run's, its
/// ratio between successive refinements, the tip at t = 0.5 s and 1 s and
/// the thread CPU time. Prints markdown; see docs/validation.md, "ANCF
/// (issue 6, helper-39)", "Flexible pendulum: convergence of the tip path".
///
/// Usage: ancf_pendulum_convergence_bench [--t-end T] [--max-elements N] [--hourglass c]
///                                         [--elements-only] [--trace n]
///   T: simulated time [s] (default 1; give it before --trace), N: finest
///   element count (default 128); c: QuadratureOrder::hourglass of the runs
///   (default 0.1; give it before --trace); --elements-only: only the first
///   table; --trace n: only the time history of the
///   differences n vs 2n elements and dt vs dt/2, with the smallest axial
///   strain and the largest curvature at the axial Gauss points of the 2n run

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "bench/bench_clock.h"
#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/model/model.h"
#include "flexmb/solver/simulator.h"

namespace {

using flexmb::Mat3;
using flexmb::Vec3;

constexpr double kSample = 4e-3;  // sampling interval of the tip path [s]; every dt must divide it
// end of the first phase [s]: up to here no part of the beam is compressed by
// more than 0.3 % (afterwards by up to 42 %, and it buckles; see --trace)
constexpr double kEarly = 0.4;
// hourglass control factor of the runs that do not set their own (--hourglass)
double g_hourglass = 0.1;

/// One run: discretization and integrator settings.
struct PendulumRunSpec {
  int elements = 16;
  double dt = 2.5e-4;
  double rho_inf = 0.95;
  double hourglass = g_hourglass;  // QuadratureOrder::hourglass
  int axial = 2;           // QuadratureOrder::axial
};

/// Tip path (x, y per sample) and cost of one run.
struct PendulumPath {
  std::vector<Vec3> tip;
  std::vector<double> min_strain;  // smallest axial strain at the axial Gauss points per sample (< 0: compression)
  std::vector<double> max_curvature;  // largest |bending strain| at the axial Gauss points per sample [1/m]
  double cpu_s = 0.0;
  double min_tip_y = 0.0;
};

PendulumPath RunPendulum(const PendulumRunSpec& spec, double t_end) {
  flexmb::ancf::AncfBeam2dData d;
  d.length = 1.2;
  d.elements = spec.elements;
  d.section.E = 0.7e6;
  d.section.A = 0.0018;
  d.section.I = 1.215e-8;
  d.section.rho = 5540.0;
  d.order.hourglass = spec.hourglass;
  d.order.axial = spec.axial;
  flexmb::Model model;
  model.gravity_W = Vec3(0.0, -9.81, 0.0);
  model.solver.dt = spec.dt;
  model.solver.rho_inf = spec.rho_inf;
  model.solver.t_end = t_end;
  const int b = model.AddBody(std::make_unique<flexmb::ancf::AncfBeam2dBody>("beam", d));
  const int mi = model.AddMarker(0, "pivot", Vec3::Zero(), Mat3::Identity());
  const int mj = model.AddMarker(b, "pin", Vec3::Zero(), Mat3::Identity(), 0);
  model.AddJoint(std::make_unique<flexmb::RevoluteJoint>("pin"), mi, mj);
  model.Finalize();
  const auto& beam = dynamic_cast<const flexmb::ancf::AncfBeam2dBody&>(*model.bodies[b]);
  flexmb::Simulator sim(model);
  sim.Initialize();
  const int samples = static_cast<int>(std::lround(t_end / kSample)) + 1;
  PendulumPath path;
  path.tip.assign(samples, Vec3::Constant(NAN));
  path.min_strain.assign(samples, NAN);
  path.max_curvature.assign(samples, NAN);
  const double c0 = flexmb::bench::ThreadCpuNow();
  sim.Run(t_end, 0.0, [&](const flexmb::State& s, const flexmb::Workspace&) {
    const Vec3 tip = beam.PositionAt(s.q.data() + beam.q_offset, d.length);
    path.min_tip_y = std::min(path.min_tip_y, tip.y());
    const long k = std::lround(s.t / kSample);
    if (k < samples && std::abs(s.t - k * kSample) < 1e-3 * spec.dt) {
      path.tip[k] = tip;
      double emin = INFINITY, kmax = 0.0;
      for (int i = 0; i < beam.elements(); ++i) {
        const Eigen::Map<const flexmb::ancf::AncfBeam2d::Vec> e(s.q.data() + beam.q_offset + 4 * i);
        // at the 2 Gauss points of the reduced axial rule (between them the
        // strain also carries the hourglass mode)
        for (double xi : {0.21132486540518713, 0.7886751345948129}) {
          emin = std::min(emin, beam.element().AxialStrain(e, xi));
          kmax = std::max(kmax, std::abs(beam.element().Curvature(e, xi)(0)));
        }
      }
      path.min_strain[k] = emin;
      path.max_curvature[k] = kmax;
    }
  });
  path.cpu_s = flexmb::bench::ThreadCpuNow() - c0;
  return path;
}

// largest distance between two paths over the samples with t <= t_max [m]
// (NaN if a sample is missing)
double MaxDistance(const PendulumPath& a, const PendulumPath& b, double t_max) {
  double e = 0.0;
  const size_t n = std::min(a.tip.size(), b.tip.size());
  for (size_t k = 0; k < n && k * kSample <= t_max + 1e-12; ++k) {
    const double d = (a.tip[k] - b.tip[k]).norm();
    if (!std::isfinite(d)) return NAN;
    e = std::max(e, d);
  }
  return e;
}

Vec3 TipAt(const PendulumPath& p, double t) {
  const size_t k = static_cast<size_t>(std::lround(t / kSample));
  return k < p.tip.size() ? p.tip[k] : Vec3::Constant(NAN);
}

// one table of runs against the last (finest) one
void PrintTable(const char* title, const char* column, const std::vector<PendulumRunSpec>& specs,
                const std::vector<double>& labels, double t_end) {
  std::printf("\n%s\n\n", title);
  std::printf("| %s | max |tip - ref| [m], t <= %.2g s | ratio | max, t <= %.2g s | ratio | tip(0.5 s) [m] | "
              "tip(%.2g s) [m] | lowest tip y [m] | CPU [s] |\n",
              column, t_end, kEarly, t_end);
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::vector<PendulumPath> paths;
  for (const PendulumRunSpec& s : specs) paths.push_back(RunPendulum(s, t_end));
  const PendulumPath& ref = paths.back();
  double prev = NAN, prev_half = NAN;
  for (size_t i = 0; i < paths.size(); ++i) {
    const PendulumPath& p = paths[i];
    const Vec3 a = TipAt(p, 0.5), c = TipAt(p, t_end);
    if (i + 1 == paths.size()) {
      std::printf("| %g (reference) | - | - | - | - | (%.5f, %.5f) | (%.5f, %.5f) | %.5f | %.2f |\n", labels[i],
                  a.x(), a.y(), c.x(), c.y(), p.min_tip_y, p.cpu_s);
      break;
    }
    const double e = MaxDistance(p, ref, t_end), eh = MaxDistance(p, ref, kEarly);
    std::printf("| %g | %.3e | %.2f | %.3e | %.2f | (%.5f, %.5f) | (%.5f, %.5f) | %.5f | %.2f |\n", labels[i], e,
                prev / e, eh, prev_half / eh, a.x(), a.y(), c.x(), c.y(), p.min_tip_y, p.cpu_s);
    prev = e;
    prev_half = eh;
    std::fflush(stdout);
  }
}

}  // namespace

// time history of the difference between runs: N vs 2N and dt vs dt/2,
// with the smallest axial strain and the largest curvature of the finest run
void PrintTrace(int n, double t_end) {
  PendulumRunSpec a, b, c;
  a.elements = n;
  b.elements = 2 * n;
  c.elements = n;
  c.dt = a.dt / 2.0;
  const PendulumPath pa = RunPendulum(a, t_end), pb = RunPendulum(b, t_end), pc = RunPendulum(c, t_end);
  std::printf("\nTime history, N = %d and %d, dt = %g and %g s\n\n", n, 2 * n, a.dt, c.dt);
  std::printf("| t [s] | |tip(N) - tip(2N)| [m] | |tip(dt) - tip(dt/2)| [m] | min axial strain (2N) | "
              "max |curvature| (2N) [1/m] |\n|---|---|---|---|---|\n");
  for (size_t k = 0; k < pa.tip.size(); k += 6)
    std::printf("| %.3f | %.2e | %.2e | %.4f | %.1f |\n", k * kSample, (pa.tip[k] - pb.tip[k]).norm(),
                (pa.tip[k] - pc.tip[k]).norm(), pb.min_strain[k], pb.max_curvature[k]);
}

int main(int argc, char** argv) {
  double t_end = 1.0;
  int max_elements = 128;
  bool elements_only = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--hourglass") == 0 && i + 1 < argc) {
      g_hourglass = std::atof(argv[++i]);
    } else if (std::strcmp(argv[i], "--elements-only") == 0) {
      elements_only = true;
    } else if (std::strcmp(argv[i], "--trace") == 0 && i + 1 < argc) {
      PrintTrace(std::atoi(argv[++i]), t_end);
      return 0;
    } else if (std::strcmp(argv[i], "--t-end") == 0 && i + 1 < argc) {
      t_end = std::atof(argv[++i]);
    } else if (std::strcmp(argv[i], "--max-elements") == 0 && i + 1 < argc) {
      max_elements = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: ancf_pendulum_convergence_bench [--t-end T] [--max-elements N]\n");
      return 2;
    }
  }
  std::vector<PendulumRunSpec> specs;
  std::vector<double> labels;
  // 1. element count, small fixed step
  for (int n = 4; n <= max_elements; n *= 2) {
    PendulumRunSpec s;
    s.elements = n;
    s.dt = 2.5e-4;
    specs.push_back(s);
    labels.push_back(n);
  }
  char head[160];
  std::snprintf(head, sizeof head, "Element count N (dt = 2.5e-4 s, rho_inf = 0.95, hourglass %g)", g_hourglass);
  PrintTable(head, "N", specs, labels, t_end);
  if (elements_only) return 0;
  // 2. time step, 16 elements
  specs.clear();
  labels.clear();
  for (double dt = 4e-3; dt > 6e-5; dt /= 2.0) {
    PendulumRunSpec s;
    s.elements = 16;
    s.dt = dt;
    specs.push_back(s);
    labels.push_back(dt);
  }
  PrintTable("Time step dt (N = 16, rho_inf = 0.95)", "dt [s]", specs, labels, t_end);
  // 3. element count with the other quadrature and damping choices, each against the finest default run
  struct Choice {
    const char* name;
    double hourglass;
    int axial;
    double rho_inf;
  };
  const Choice choices[] = {{"hourglass 0 (2 points only)", 0.0, 2, 0.95},
                            {"hourglass 1", 1.0, 2, 0.95},
                            {"full axial integration (5 points)", 0.0, 5, 0.95},
                            {"rho_inf = 1 (no numerical damping)", 0.1, 2, 1.0},
                            {"rho_inf = 0.6", 0.1, 2, 0.6}};
  for (const Choice& c : choices) {
    specs.clear();
    labels.clear();
    for (int n = 4; n <= max_elements / 2; n *= 2) {
      PendulumRunSpec s;
      s.elements = n;
      s.hourglass = c.hourglass;
      s.axial = c.axial;
      s.rho_inf = c.rho_inf;
      specs.push_back(s);
      labels.push_back(n);
    }
    PendulumRunSpec ref;
    ref.elements = max_elements;
    specs.push_back(ref);
    labels.push_back(max_elements);
    char title[160];
    std::snprintf(title, sizeof title, "%s, dt = 2.5e-4 s, against the default N = %d run", c.name, max_elements);
    PrintTable(title, "N", specs, labels, t_end);
  }
  return 0;
}
