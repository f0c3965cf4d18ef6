/// \file flexible_step_rate.cc
/// flexible_step_rate_bench: steps per second of one free-floating elastic
/// body (floating frame of reference, bodies/flexible_body.h) with n = 8,
/// 20, 50, 100 and 160 modal coordinates, and with the same number of modes
/// built from a ~1,000-node and a ~100,000-node FE model, each as a ratio
/// to a free-floating rigid body run in the same process (issue 5,
/// docs/PERFORMANCE.md "Flexible body step rate (issue 5)").
///
/// The bodies are Craig-Bampton reductions of generated straight steel beams
/// (round bar r = 2 cm, nodes 1 mm apart, so 1 m for 1,000 nodes and 100 m
/// for 100,000; both ends as interface: 6 static
/// modes after the 6 rigid ones are removed, plus n - 6 fixed-interface
/// normal modes). No gravity, an initial spin (1, 2, 5) rad/s and a small
/// modal deformation; fixed step 1e-4 s, rho_inf = 0.8. The node-count rows
/// use plane grids of beams (r = 1 mm) over 1 m x 0.5 m with 40 x 25,
/// 125 x 80 and 400 x 250 nodes, opposite corners as interface. Time per step is
/// the best of the repetitions of `steps` steps after 20 warm-up steps.
///
/// With --conservation it runs instead the 10-s conservation study of a
/// free-floating elastic body (issue 5): a bent steel bar (two legs of 8
/// beam elements, 0.8 m along x, then (0, 0.5, 0.2) m), reduced with its ends
/// as interface and its 4 lowest flexible modes kept, given a spin
/// (2, 6, -3) rad/s, a translation and an initial modal deformation,
/// undamped, no gravity, generalized-alpha with rho_inf = 1; it prints the
/// largest relative deviation of the energy and of the linear and angular
/// momentum over 10 s at three step sizes (docs/validation.md).
///
/// Every flexible body runs twice: with full Newton (the default) and with
/// SolverSettings::jacobian_reuse (modified Newton).
///
/// Usage: flexible_step_rate_bench [--steps S] [--min-seconds T] [--no-large] [--modes a,b,...]
///        flexible_step_rate_bench --conservation
///   S: timed steps per repetition (default 2000)
///   T: minimum total timed wall time per body and setting [s] (default 1.0)
///   --no-large: skip the 100,000-node model (its reduction takes a while)
///   --modes: only the bar with these mode counts (no grids), e.g. for perf

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_clock.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/math/rotation.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/solver/simulator.h"

namespace {

using namespace flexmb;

constexpr double kDt = 1e-4;
constexpr int kWarmupSteps = 20;
const Vec3 kSpin(1.0, 2.0, 5.0);  // initial angular velocity, world [rad/s]

// steel round bar r = 2 cm: material and section 0 of the mesh
void SteelRoundBar(fe::Mesh& mesh) {
  fe::Material mat;
  mat.id = 1;
  mat.E = 2.1e11;
  mat.nu = 0.3;
  mat.G = mat.E / (2.0 * (1.0 + mat.nu));
  mat.rho = 7850.0;
  mesh.materials.push_back(mat);
  const double r = 0.02;
  fe::BeamSection s;
  s.id = 1;
  s.material = 0;
  s.A = M_PI * r * r;
  s.Iy = s.Iz = M_PI * std::pow(r, 4) / 4.0;
  s.J = 2.0 * s.Iy;
  mesh.beam_sections.push_back(s);
}

// a polyline of beams through the points x (node ids 1..)
fe::FeModel Polyline(const std::vector<fe::Vec3>& x, const fe::Vec3& orientation) {
  fe::FeModel model;
  fe::Mesh& mesh = model.mesh;
  mesh.source = "generated_beam";
  SteelRoundBar(mesh);
  const int nodes = static_cast<int>(x.size());
  mesh.nodes.resize(nodes);
  for (int k = 0; k < nodes; ++k) mesh.nodes[k].id = k + 1, mesh.nodes[k].x = x[k];
  mesh.IndexNodes();
  mesh.elements.resize(nodes - 1);
  for (int k = 0; k + 1 < nodes; ++k) {
    fe::Element& e = mesh.elements[k];
    e.id = k + 1;
    e.type = fe::ElementType::kBeam2;
    e.property = 0;
    e.nodes = {k, k + 1};
    e.orientation = orientation;
  }
  return model;
}

// straight steel round bar along x, `nodes` nodes 1 mm apart (the element
// shape is the same for every node count: a 1 m bar would have elements
// 20000 times shorter than thick at 100,000 nodes, ill-conditioned)
fe::FeModel Beam(int nodes) {
  std::vector<fe::Vec3> x(nodes);
  for (int k = 0; k < nodes; ++k) x[k] = fe::Vec3(1e-3 * k, 0.0, 0.0);
  return Polyline(x, fe::Vec3(0, 1, 0));
}

// a plane grid of beams (r = 1 mm) over 1 m x 0.5 m, nx x ny nodes, joined
// along x and y: a body whose size does not change with the node count
fe::FeModel Grid(int nx, int ny) {
  fe::FeModel model;
  fe::Mesh& mesh = model.mesh;
  mesh.source = "generated_grid";
  SteelRoundBar(mesh);
  fe::BeamSection& s = mesh.beam_sections[0];
  const double r = 1e-3;
  s.A = M_PI * r * r;
  s.Iy = s.Iz = M_PI * std::pow(r, 4) / 4.0;
  s.J = 2.0 * s.Iy;
  mesh.nodes.resize(static_cast<size_t>(nx) * ny);
  const auto id = [&](int i, int j) { return j * nx + i; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      fe::Node& nd = mesh.nodes[id(i, j)];
      nd.id = id(i, j) + 1;
      nd.x = fe::Vec3(1.0 * i / (nx - 1), 0.5 * j / (ny - 1), 0.0);
    }
  }
  mesh.IndexNodes();
  const auto add = [&](int a, int b) {
    fe::Element e;
    e.id = static_cast<int>(mesh.elements.size()) + 1;
    e.type = fe::ElementType::kBeam2;
    e.property = 0;
    e.nodes = {a, b};
    e.orientation = fe::Vec3(0, 0, 1);
    mesh.elements.push_back(e);
  };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (i + 1 < nx) add(id(i, j), id(i + 1, j));
      if (j + 1 < ny) add(id(i, j), id(i, j + 1));
    }
  }
  return model;
}

// the --conservation study; returns the exit code
int Conservation() {
  const int per_leg = 8;
  std::vector<fe::Vec3> x;
  for (int k = 0; k <= per_leg; ++k) x.emplace_back(0.8 * k / per_leg, 0.0, 0.0);
  for (int k = 1; k <= per_leg; ++k) x.emplace_back(0.8, 0.5 * k / per_leg, 0.2 * k / per_leg);
  const fe::FeModel model = Polyline(x, fe::Vec3(0, 0, 1));
  reduction::ReductionOptions o;
  o.interface_nodes = {0, 2 * per_leg};
  o.normal_modes = 4;
  o.keep = 4;
  const auto reduced = std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(model, o));
  const int n = reduced->invariants.n;
  std::printf("free bent bar, %d flexible modes %.1f .. %.1f Hz, 10 s, undamped, no gravity, rho_inf = 1\n\n", n,
              reduced->frequencies_hz(0), reduced->frequencies_hz(n - 1));
  std::printf("| h [s] | steps | E0 [J] | strain energy t = 0 / max [J] | max dE/E0 | max dL/L0 | max dH/H0 "
              "| wall [s] |\n|---|---|---|---|---|---|---|---|\n");
  for (double h : {1e-4, 5e-5, 2.5e-5}) {
    Model m;
    m.gravity_W = Vec3::Zero();
    FlexibleBodyData d;
    d.reduced = reduced;
    d.p_WB = Vec3(0.1, 0.2, 0.3);
    d.R_WB = ExpSO3(Vec3(0.3, -0.2, 0.5));
    d.v_WB = Vec3(0.5, -0.3, 0.2);
    d.w_WB = Vec3(2.0, 6.0, -3.0);
    d.w0 = VecX::Zero(n);
    d.w0(0) = 0.02;
    d.w0(n - 1) = -0.005;
    d.damping = MatX::Zero(n, n);
    const int b = m.AddBody(std::make_unique<FlexibleBody>("bar", d));
    m.solver.dt = h;
    m.solver.rho_inf = 1.0;
    m.solver.newton_tol = 1e-12;
    m.Finalize();
    const auto& body = static_cast<const FlexibleBody&>(*m.bodies[b]);
    Simulator sim(m);
    sim.Initialize();
    const auto energy = [&](const State& st) {
      const double* q = st.q.data() + body.q_offset;
      return body.KineticEnergy(q, st.v.data() + body.v_offset) + body.ElasticEnergy(q);
    };
    const auto momentum = [&](const State& st) {
      return body.Momentum(st.q.data() + body.q_offset, st.v.data() + body.v_offset);
    };
    const double E0 = energy(sim.state());
    const double S0 = body.ElasticEnergy(sim.state().q.data() + body.q_offset);
    const Vec6 p0 = momentum(sim.state());
    double dE = 0, dL = 0, dH = 0, smax = 0;
    const double w0 = bench::WallNow();
    sim.Run(10.0, 0.0, [&](const State& st, const Workspace&) {
      const Vec6 p = momentum(st);
      dE = std::max(dE, std::abs(energy(st) - E0) / E0);
      dL = std::max(dL, (p.head<3>() - p0.head<3>()).norm() / p0.head<3>().norm());
      dH = std::max(dH, (p.tail<3>() - p0.tail<3>()).norm() / p0.tail<3>().norm());
      smax = std::max(smax, body.ElasticEnergy(st.q.data() + body.q_offset));
    });
    std::printf("| %.1e | %ld | %.4f | %.4f / %.4f | %.2e | %.2e | %.2e | %.1f |\n", h, sim.stats().steps, E0, S0,
                smax, dE, dL, dH, bench::WallNow() - w0);
    std::fflush(stdout);
  }
  return 0;
}

// the beam of `nodes` nodes, or with nx > 0 the nx x ny grid
std::shared_ptr<const reduction::ReducedBody> Reduced(int nodes, int modes, double* seconds, int nx = 0,
                                                      int ny = 0) {
  const double t0 = bench::WallNow();
  const fe::FeModel model = nx > 0 ? Grid(nx, ny) : Beam(nodes);
  if (nx > 0) nodes = nx * ny;
  reduction::ReductionOptions o;
  o.interface_nodes = {0, nodes - 1};
  o.normal_modes = modes - 6;
  auto r = std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(model, o));
  *seconds = bench::WallNow() - t0;
  if (r->invariants.n != modes) {
    std::fprintf(stderr, "reduction gave %d modes, expected %d\n", r->invariants.n, modes);
    std::exit(1);
  }
  return r;
}

std::unique_ptr<Model> FlexibleModel(const std::shared_ptr<const reduction::ReducedBody>& reduced, bool reuse) {
  auto m = std::make_unique<Model>();
  m->gravity_W = Vec3::Zero();
  FlexibleBodyData d;
  d.reduced = reduced;
  const int n = reduced->invariants.n;
  d.w_WB = kSpin;
  d.R_WB = ExpSO3(Vec3(0.2, -0.1, 0.3));
  d.w0 = VecX::Zero(n);
  d.w0(0) = 1e-3;
  d.w0(n - 1) = -1e-4;
  m->AddBody(std::make_unique<FlexibleBody>("body", d));
  m->solver.dt = kDt;
  m->solver.rho_inf = 0.8;
  m->solver.jacobian_reuse = reuse;
  m->Finalize();
  return m;
}

std::unique_ptr<Model> RigidModel() {
  auto m = std::make_unique<Model>();
  m->gravity_W = Vec3::Zero();
  RigidBodyData d;
  d.mass = 9.86;
  d.inertia_C = Vec3(2e-3, 0.82, 0.82).asDiagonal();
  d.w_WB = kSpin;
  d.R_WB = ExpSO3(Vec3(0.2, -0.1, 0.3));
  m->AddBody(std::make_unique<RigidBody>("body", d));
  m->solver.dt = kDt;
  m->solver.rho_inf = 0.8;
  m->Finalize();
  return m;
}

struct Rate {
  double wall = INFINITY, cpu = INFINITY, newton = 0.0;  // per step [s], iterations per step
  double factorizations = 0.0;                            // per step
  int reps = 0;
};

Rate Measure(const std::function<std::unique_ptr<Model>()>& make, int steps, double min_seconds) {
  Rate r;
  double total = 0.0;
  for (int rep = 0; rep < 30 && (rep < 3 || total < min_seconds); ++rep) {
    auto model = make();
    Simulator sim(*model);
    sim.Initialize();
    sim.Run(kWarmupSteps * kDt, 0.0, nullptr);
    const IntegratorStats s0 = sim.stats();
    const double w0 = bench::WallNow(), c0 = bench::ThreadCpuNow();
    sim.Run((kWarmupSteps + steps) * kDt, 0.0, nullptr);
    const double w1 = bench::WallNow(), c1 = bench::ThreadCpuNow();
    const IntegratorStats& s1 = sim.stats();
    const long n = s1.steps - s0.steps;
    total += w1 - w0;
    r.wall = std::min(r.wall, (w1 - w0) / n);
    r.cpu = std::min(r.cpu, (c1 - c0) / n);
    r.newton = double(s1.newton_iterations - s0.newton_iterations) / n;
    r.factorizations = double(s1.factorizations - s0.factorizations) / n;
    r.reps = rep + 1;
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 2000;
  double min_seconds = 1.0;
  bool large = true, grids = true;
  std::vector<int> mode_list = {8, 20, 50, 100, 160};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--conservation")) return Conservation();
    if (!std::strcmp(argv[i], "--steps") && i + 1 < argc) {
      steps = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--min-seconds") && i + 1 < argc) {
      min_seconds = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--no-large")) {
      large = false;
    } else if (!std::strcmp(argv[i], "--modes") && i + 1 < argc) {
      mode_list.clear();
      for (const char* p = argv[++i]; *p;) {
        char* end = nullptr;
        mode_list.push_back(static_cast<int>(std::strtol(p, &end, 10)));
        p = *end == ',' ? end + 1 : end;
      }
      grids = false;
    } else {
      std::fprintf(stderr,
                   "usage: %s [--steps S] [--min-seconds T] [--no-large] [--modes a,b,...] | --conservation\n",
                   argv[0]);
      return 2;
    }
  }
  std::printf("fixed step %g s, rho_inf 0.8, %d warm-up + %d timed steps per repetition, best of >= 3\n"
              "full: full Newton (default); reuse: SolverSettings::jacobian_reuse (modified Newton)\n\n",
              kDt, kWarmupSteps, steps);
  const Rate rigid = Measure(RigidModel, steps, min_seconds);
  std::printf("| body | FE nodes | modes n | nv | full: us/step (wall) | full: us/step (CPU) | full: steps/s (CPU) "
              "| full: Newton it./step | reuse: us/step (wall) | reuse: us/step (CPU) | reuse: steps/s (CPU) "
              "| reuse: Newton it./step | reuse: LU/step | reuse / full (CPU) | full / rigid (CPU) "
              "| reuse / rigid (CPU) | reduction [s] |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| rigid | - | 0 | 6 | %.2f | %.2f | %.0f | %.2f | | | | | | | 1.00 | | - |\n", 1e6 * rigid.wall,
              1e6 * rigid.cpu, 1.0 / rigid.cpu, rigid.newton);
  std::fflush(stdout);
  auto row = [&](int nodes, int modes, int nx = 0, int ny = 0) {
    double red = 0.0;
    const auto reduced = Reduced(nodes, modes, &red, nx, ny);
    if (nx > 0) nodes = nx * ny;
    const Rate f = Measure([&] { return FlexibleModel(reduced, false); }, steps, min_seconds);
    const Rate r = Measure([&] { return FlexibleModel(reduced, true); }, steps, min_seconds);
    std::printf("| flexible | %d | %d | %d | %.2f | %.2f | %.0f | %.2f | %.2f | %.2f | %.0f | %.2f | %.3f | %.3f | %.1f "
                "| %.1f | %.1f |\n",
                nodes, modes, 6 + modes, 1e6 * f.wall, 1e6 * f.cpu, 1.0 / f.cpu, f.newton, 1e6 * r.wall,
                1e6 * r.cpu, 1.0 / r.cpu, r.newton, r.factorizations, r.cpu / f.cpu, f.cpu / rigid.cpu,
                r.cpu / rigid.cpu, red);
    std::fflush(stdout);
  };
  for (int modes : mode_list) row(1000, modes);
  if (!grids) return 0;
  // node count at fixed modes: plane beam grids of the same size
  std::printf("| (grids below: 1 m x 0.5 m plane grids of r = 1 mm beams) | | | | | | | | | | | | | | | | |\n");
  row(0, 20, 40, 25);
  row(0, 20, 125, 80);
  if (large) row(0, 20, 400, 250);
  return 0;
}
