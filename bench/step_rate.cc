/// \file step_rate.cc
/// flexmb_bench: steps per second of the generalized-alpha integrator
/// (fixed step dt = 1e-3 s, rho_inf = 0.8) on spherical-joint chains of
/// N = 10, 100, 1000 rigid rods and on the IFToMM A02 N-four-bar (N = 2),
/// plus a breakdown of one Newton iteration on the N = 1000 chain and a
/// comparison of the KLU factorization with Eigen::SparseLU on the same
/// iteration matrix. Prints markdown tables; see docs/PERFORMANCE.md.
///
/// Usage: flexmb_bench [--steps S] [--min-seconds T] [--profile N]
///   S: timed steps per repetition (default 250, i.e. t = 0.02 .. 0.27 s)
///   T: minimum total timed wall time per model [s] (default 1.5)
///   N: only run the N-link chain for S steps (for perf / callgrind)

#include <klu.h>
#include <time.h>

#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "bench/bench_clock.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/log.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/generalized_alpha.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/solver/sparse_lu.h"

namespace {

using namespace flexmb;

constexpr double kDt = 1e-3;
constexpr double kRho = 0.8;
constexpr int kWarmupSteps = 20;
// axial moment of inertia of the "slender" rods [kg m^2] (must be > 0)
constexpr double kAxialInertia = 1e-4;

// "prefix<i>" (std::string operator+ trips GCC 12's -Wrestrict false positive)
std::string Name(const char* prefix, int i) {
  std::string s(prefix);
  s += std::to_string(i);
  return s;
}

void SetSolver(Model& m) {
  m.gravity_W = Vec3(0, -9.81, 0);
  m.solver.dt = kDt;
  m.solver.rho_inf = kRho;
  m.solver.adaptive = false;
}

// uniform rod of 1 kg, 1 m along body axis `axis`, body frame at one end
RigidBodyData Rod(int axis, const Vec3& p_WB) {
  RigidBodyData d;
  d.mass = 1.0;
  Vec3 I = Vec3::Constant(1.0 / 12.0);
  I(axis) = kAxialInertia;
  d.inertia_C = I.asDiagonal();
  d.c_B = 0.5 * Vec3::Unit(axis);
  d.p_WB = p_WB;
  return d;
}

// chain of n rods along +x joined by spherical joints, the first pinned to
// the ground at the origin, released horizontal (gravity -y)
std::unique_ptr<Model> Chain(int n) {
  auto m = std::make_unique<Model>();
  SetSolver(*m);
  int prev_tip = m->AddMarker(0, "pin", Vec3::Zero(), Mat3::Identity());
  for (int k = 0; k < n; ++k) {
    const std::string name = Name("link", k);
    const int b = m->AddBody(std::make_unique<RigidBody>(name, Rod(0, Vec3(k, 0, 0))));
    const int a = m->AddMarker(b, "a", Vec3::Zero(), Mat3::Identity());
    m->AddJoint(std::make_unique<SphericalJoint>(Name("ball", k)), prev_tip, a);
    prev_tip = m->AddMarker(b, "b", Vec3(1, 0, 0), Mat3::Identity());
  }
  m->Finalize();
  return m;
}

// IFToMM A02 N-four-bar: vertical cranks pinned to ground at x = 0..n,
// horizontal couplers at y = 1; B0 (tip of crank 0) starts at 1 m/s in +x,
// so all cranks turn at -1 rad/s about z and the couplers translate
std::unique_ptr<Model> FourBar(int n) {
  auto m = std::make_unique<Model>();
  SetSolver(*m);
  std::vector<int> tips;
  for (int i = 0; i <= n; ++i) {
    RigidBodyData d = Rod(1, Vec3(i, 0, 0));
    d.w_WB = Vec3(0, 0, -1);
    const int b = m->AddBody(std::make_unique<RigidBody>(Name("crank", i), d));
    const int g = m->AddMarker(0, Name("g", i), Vec3(i, 0, 0), Mat3::Identity());
    const int p = m->AddMarker(b, "pin", Vec3::Zero(), Mat3::Identity());
    m->AddJoint(std::make_unique<RevoluteJoint>(Name("ground", i)), g, p);
    tips.push_back(m->AddMarker(b, "tip", Vec3(0, 1, 0), Mat3::Identity()));
  }
  for (int k = 1; k <= n; ++k) {
    RigidBodyData d = Rod(0, Vec3(k - 1, 1, 0));
    d.v_WB = Vec3(1, 0, 0);
    const int b = m->AddBody(std::make_unique<RigidBody>(Name("coupler", k), d));
    const int a = m->AddMarker(b, "a", Vec3::Zero(), Mat3::Identity());
    const int e = m->AddMarker(b, "b", Vec3(1, 0, 0), Mat3::Identity());
    m->AddJoint(std::make_unique<RevoluteJoint>(Name("left", k)), tips[k - 1], a);
    m->AddJoint(std::make_unique<RevoluteJoint>(Name("right", k)), e, tips[k]);
  }
  m->Finalize();
  return m;
}

struct RateResult {
  std::string name;
  int bodies = 0, nv = 0, active = 0, removed = 0;
  int reps = 0;
  double wall_per_step = 0.0;  // best repetition [s]
  double cpu_per_step = 0.0;   // best repetition, thread CPU time [s]
  double newton_per_step = 0.0;
  double init = 0.0;  // best Simulator::Initialize wall time [s]
  long rejected = 0;
};

// best-of-repetitions time of `steps` fixed steps after kWarmupSteps, each
// repetition from the same initial state (same simulated interval)
RateResult MeasureRate(const std::string& name, const std::function<std::unique_ptr<Model>()>& make,
                       int bodies, int steps, double min_seconds) {
  RateResult r;
  r.name = name;
  r.bodies = bodies;
  r.wall_per_step = r.cpu_per_step = r.init = INFINITY;
  double total = 0.0;
  for (int rep = 0; rep < 30 && (rep < 3 || total < min_seconds); ++rep) {
    auto model = make();
    Simulator sim(*model);
    const double i0 = bench::WallNow();
    const ConstraintReport& rep_c = sim.Initialize();
    r.init = std::min(r.init, bench::WallNow() - i0);
    r.nv = model->nv;
    r.removed = static_cast<int>(rep_c.redundant.size());
    r.active = sim.workspace().n_active;
    sim.Run(kWarmupSteps * kDt, 0.0, nullptr);
    const IntegratorStats s0 = sim.stats();
    const double t_end = (kWarmupSteps + steps) * kDt;
    const double w0 = bench::WallNow(), c0 = bench::ThreadCpuNow();
    sim.Run(t_end, 0.0, nullptr);
    const double w1 = bench::WallNow(), c1 = bench::ThreadCpuNow();
    const IntegratorStats& s1 = sim.stats();
    const long n = s1.steps - s0.steps;
    total += w1 - w0;
    r.wall_per_step = std::min(r.wall_per_step, (w1 - w0) / n);
    r.cpu_per_step = std::min(r.cpu_per_step, (c1 - c0) / n);
    r.newton_per_step = double(s1.newton_iterations - s0.newton_iterations) / n;
    r.rejected = s1.rejected - s0.rejected;
    r.reps = rep + 1;
  }
  return r;
}

// best-of-5 time per call of f [s]; the batch size is calibrated to >= 20 ms
double TimePerCall(const std::function<void()>& f) {
  f();
  long batch = 1;
  for (;;) {
    const double t0 = bench::WallNow();
    for (long i = 0; i < batch; ++i) f();
    const double dt = bench::WallNow() - t0;
    if (dt >= 0.02 || batch > (1L << 24)) break;
    batch *= 2;
  }
  double best = INFINITY;
  for (int rep = 0; rep < 5; ++rep) {
    const double t0 = bench::WallNow();
    for (long i = 0; i < batch; ++i) f();
    best = std::min(best, (bench::WallNow() - t0) / batch);
  }
  return best;
}

void Breakdown(int n) {
  auto model = Chain(n);
  const Model& m = *model;
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  GeneralizedAlpha ga(m, ws, kRho);
  ga.Start(s);
  for (int k = 0; k < kWarmupSteps; ++k) {
    if (ga.TryStep(s, kDt) != StepStatus::kConverged) {
      std::printf("warm-up step failed: %s\n", ga.failure_hint().c_str());
      return;
    }
    ga.Accept(s);
  }
  // coefficients of the iteration matrix as in GeneralizedAlpha::TryStep
  const double am = (2.0 * kRho - 1.0) / (kRho + 1.0), af = kRho / (kRho + 1.0);
  const double gamma = 0.5 + af - am, beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
  const double bp = (1.0 - am) / (kDt * kDt * beta * (1.0 - af)), gp = gamma / (kDt * beta);
  const MatrixCoefficients coef{1.0, gp / bp, 1.0 / bp, m.solver.geometric_stiffness};

  EvaluateMarkers(m, s, ws);
  EvaluateConstraints(m, s, ws);
  EvaluateForces(m, s, ws, true);
  AssembleIterationMatrix(m, s, ws, coef);
  const SparseMat S = ws.S;
  VecX rhs = VecX::Random(S.rows());
  const VecX rhs0 = rhs;
  VecX res(m.nv), lam = VecX::Random(ws.n_active), q1(m.nq), dx = 1e-6 * VecX::Random(m.nv);

  struct Row {
    std::string what;
    double t;
  };
  std::vector<Row> rows;
  auto add = [&](const std::string& what, const std::function<void()>& f) { rows.push_back({what, TimePerCall(f)}); };

  add("EvaluateMarkers", [&] { EvaluateMarkers(m, s, ws); });
  add("EvaluateConstraints", [&] { EvaluateConstraints(m, s, ws); });
  add("EvaluateForces (tangents)", [&] { EvaluateForces(m, s, ws, true); });
  add("residual (M vdot - Q + B^T lambda)", [&] {
    MassTimes(m, ws, ws.vdot, res);
    res -= ws.Q;
    res.noalias() += ws.B.transpose() * lam;
  });
  add("AssembleIterationMatrix", [&] { AssembleIterationMatrix(m, s, ws, coef); });
  SparseLu lu;
  lu.Factorize(S);
  add("SparseLu::Factorize (klu_refactor + klu_rcond)", [&] { lu.Factorize(S); });
  add("SparseLu::Solve (klu_solve)", [&] {
    rhs = rhs0;
    lu.Solve(rhs);
  });
  add("RetractAll", [&] { RetractAll(m, s.q, dx, q1); });
  double sum_parts = 0.0;
  for (const Row& r : rows) sum_parts += r.t;

  // one whole step (TryStep + Accept) from copies of the warmed-up state
  long its = 0;
  double step_t = 0.0;
  {
    State s2 = s;
    const long it0 = ga.stats.newton_iterations, st0 = ga.stats.steps;
    step_t = TimePerCall([&] {
      if (ga.TryStep(s2, kDt) == StepStatus::kConverged) ga.Accept(s2);
    });
    its = ga.stats.newton_iterations - it0;
    const long steps = ga.stats.steps - st0;
    const double it_per_step = double(its) / std::max(1L, steps);
    std::printf("\n### One Newton iteration on the N = %d chain (nv = %d, %d constraint rows, "
                "matrix %ld x %ld, %ld non-zeros)\n\n",
                n, m.nv, ws.n_active, long(S.rows()), long(S.cols()), long(S.nonZeros()));
    std::printf("| part | us per call | share of the parts |\n|---|---:|---:|\n");
    for (const Row& r : rows) std::printf("| %s | %.1f | %.1f %% |\n", r.what.c_str(), 1e6 * r.t, 100.0 * r.t / sum_parts);
    std::printf("| **sum of the parts (one Newton iteration)** | **%.1f** | 100 %% |\n", 1e6 * sum_parts);
    std::printf("\nWhole step (TryStep + Accept): %.1f us with %.2f Newton iterations per step, i.e. %.1f us "
                "per iteration (the step also re-evaluates markers and constraints at the converged state "
                "and updates the vectors).\n",
                1e6 * step_t, it_per_step, 1e6 * step_t / it_per_step);
  }

  // KLU against Eigen::SparseLU on the same matrix
  Eigen::SparseLU<SparseMat, Eigen::COLAMDOrdering<int>> elu;
  elu.analyzePattern(S);
  elu.factorize(S);
  if (elu.info() != Eigen::Success) {
    std::printf("Eigen::SparseLU failed: %s\n", elu.lastErrorMessage().c_str());
    return;
  }
  VecX xe = elu.solve(rhs0);
  VecX xk = rhs0;
  lu.Factorize(S);
  lu.Solve(xk);
  const double rel = (xe - xk).norm() / xk.norm();
  const double res_k = (S * xk - rhs0).norm() / rhs0.norm();
  const double res_e = (S * xe - rhs0).norm() / rhs0.norm();

  // direct KLU calls: analysis, fresh pivoting factorization, refactor
  klu_common common;
  klu_defaults(&common);
  auto* Ap = const_cast<int*>(S.outerIndexPtr());
  auto* Ai = const_cast<int*>(S.innerIndexPtr());
  auto* Ax = const_cast<double*>(S.valuePtr());
  const int nn = static_cast<int>(S.rows());
  klu_symbolic* sym = klu_analyze(nn, Ap, Ai, &common);
  klu_numeric* num = klu_factor(Ap, Ai, Ax, sym, &common);
  const long lu_nnz = num ? long(num->lnz + num->unz) : -1;
  const double t_klu_analyze = TimePerCall([&] {
    klu_symbolic* s2 = klu_analyze(nn, Ap, Ai, &common);
    klu_free_symbolic(&s2, &common);
  });
  const double t_klu_factor = TimePerCall([&] {
    klu_numeric* n2 = klu_factor(Ap, Ai, Ax, sym, &common);
    klu_free_numeric(&n2, &common);
  });
  const double t_klu_refactor = TimePerCall([&] { klu_refactor(Ap, Ai, Ax, sym, num, &common); });
  const double t_klu_rcond = TimePerCall([&] { klu_rcond(sym, num, &common); });
  const double t_klu_solve = TimePerCall([&] {
    rhs = rhs0;
    klu_solve(sym, num, nn, 1, rhs.data(), &common);
  });
  klu_free_numeric(&num, &common);
  // the same without KLU's row scaling (common.scale = 0; the engine keeps the default 2)
  common.scale = 0;
  num = klu_factor(Ap, Ai, Ax, sym, &common);
  const double t_klu_refactor_noscale = TimePerCall([&] { klu_refactor(Ap, Ai, Ax, sym, num, &common); });
  klu_free_numeric(&num, &common);
  klu_free_symbolic(&sym, &common);

  const double t_e_analyze = TimePerCall([&] { elu.analyzePattern(S); });
  elu.analyzePattern(S);
  const double t_e_factor = TimePerCall([&] { elu.factorize(S); });
  const double t_e_solve = TimePerCall([&] { rhs = elu.solve(rhs0); });
  const long e_nnz = long(elu.nnzL() + elu.nnzU());

  std::printf("\n### Sparse LU on the N = %d chain iteration matrix (%ld x %ld, %ld non-zeros)\n\n", n,
              long(S.rows()), long(S.cols()), long(S.nonZeros()));
  std::printf("| operation | KLU [us] | Eigen::SparseLU (COLAMD) [us] | Eigen / KLU |\n|---|---:|---:|---:|\n");
  std::printf("| symbolic analysis (once per pattern) | %.1f | %.1f | %.1f |\n", 1e6 * t_klu_analyze,
              1e6 * t_e_analyze, t_e_analyze / t_klu_analyze);
  std::printf("| numeric factorization with pivoting (klu_factor / factorize) | %.1f | %.1f | %.1f |\n",
              1e6 * t_klu_factor, 1e6 * t_e_factor, t_e_factor / t_klu_factor);
  std::printf("| numeric refactorization, same pivots (klu_refactor / -) | %.1f | - | %.1f |\n",
              1e6 * t_klu_refactor, t_e_factor / t_klu_refactor);
  std::printf("| klu_refactor without row scaling (common.scale = 0) | %.1f | - | %.1f |\n",
              1e6 * t_klu_refactor_noscale, t_e_factor / t_klu_refactor_noscale);
  std::printf("| reciprocal condition estimate (klu_rcond) | %.1f | - | - |\n", 1e6 * t_klu_rcond);
  std::printf("| solve | %.1f | %.1f | %.1f |\n", 1e6 * t_klu_solve, 1e6 * t_e_solve, t_e_solve / t_klu_solve);
  std::printf("| per Newton iteration as used (engine: refactor + rcond + solve; Eigen: factorize + solve) "
              "| %.1f | %.1f | %.1f |\n",
              1e6 * (t_klu_refactor + t_klu_rcond + t_klu_solve), 1e6 * (t_e_factor + t_e_solve),
              (t_e_factor + t_e_solve) / (t_klu_refactor + t_klu_rcond + t_klu_solve));
  std::printf("\nFill: nnz(L+U) KLU %ld, Eigen %ld. Solutions agree to %.1e (relative); residuals "
              "|S x - b|/|b|: KLU %.1e, Eigen %.1e.\n",
              lu_nnz, e_nnz, rel, res_k, res_e);
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 250, profile = 0;
  double min_seconds = 1.5;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--steps") && i + 1 < argc)
      steps = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--min-seconds") && i + 1 < argc)
      min_seconds = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--profile") && i + 1 < argc)
      profile = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--steps S] [--min-seconds T] [--profile N]\n", argv[0]);
      return 2;
    }
  }
  // model warnings (the A02 redundant equations) once each, at the end
  std::set<std::string> warnings;
  SetWarningSink([&](const std::string& w) { warnings.insert(w); });
  if (profile > 0) {
    auto model = Chain(profile);
    Simulator sim(*model);
    const double i0 = bench::WallNow();
    sim.Initialize();
    std::printf("Initialize: %.3f s\n", bench::WallNow() - i0);
    std::fflush(stdout);
    const double w0 = bench::WallNow();
    sim.Run(steps * kDt, 0.0, nullptr);
    const double w = bench::WallNow() - w0;
    std::printf("chain N = %d: %ld steps in %.3f s (%.1f steps/s), %.2f Newton it/step\n", profile,
                sim.stats().steps, w, sim.stats().steps / w, double(sim.stats().newton_iterations) / sim.stats().steps);
    return 0;
  }
  std::printf("## flexmb_bench: generalized-alpha, dt = %g s fixed, rho_inf = %g; %d warm-up steps, "
              "then %d timed steps (t = %.3f .. %.3f s), best of the repetitions\n\n",
              kDt, kRho, kWarmupSteps, steps, kWarmupSteps * kDt, (kWarmupSteps + steps) * kDt);
  std::vector<RateResult> results;
  try {
    for (int n : {10, 100, 1000})
      results.push_back(MeasureRate("spherical chain N = " + std::to_string(n), [n] { return Chain(n); }, n,
                                    steps, min_seconds));
    results.push_back(MeasureRate("A02 four-bar N = 2", [] { return FourBar(2); }, 5, steps, min_seconds));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  const RateResult& base = results.front();
  const double base_wall = base.wall_per_step / base.bodies, base_cpu = base.cpu_per_step / base.bodies;
  const double base_it = base_cpu / base.newton_per_step;
  std::printf("| model | bodies | nv | constraint rows (removed) | steps/s | Newton it/step | us/step "
              "| us/step/body | per-body ratio to chain N = 10 | same, CPU time | per-body per-iteration ratio (CPU) | reps | Initialize [ms] |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const RateResult& r : results) {
    const double pb = r.wall_per_step / r.bodies, pc = r.cpu_per_step / r.bodies;
    std::printf("| %s | %d | %d | %d (%d) | %.0f | %.2f | %.1f | %.2f | %.2f | %.2f | %.2f | %d | %.1f |\n",
                r.name.c_str(), r.bodies, r.nv, r.active, r.removed, 1.0 / r.wall_per_step, r.newton_per_step,
                1e6 * r.wall_per_step, 1e6 * pb, pb / base_wall, pc / base_cpu,
                pc / r.newton_per_step / base_it, r.reps, 1e3 * r.init);
    if (r.rejected) std::printf("<!-- %s: %ld rejected steps -->\n", r.name.c_str(), r.rejected);
  }
  Breakdown(1000);
  if (!warnings.empty()) {
    std::printf("\nModel warnings (each once):\n\n");
    for (const std::string& w : warnings) std::printf("- %s\n", w.c_str());
  }
  SetWarningSink(nullptr);
  return 0;
}
