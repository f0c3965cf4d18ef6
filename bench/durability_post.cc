/// \file durability_post.cc
/// Post-processing speed of "flexmb post" (issue 22): stress recovery,
/// extremes, rainflow counting and Miner damage for every element of a
/// 5,000-element shell body over 10,000 output instants (30 modal
/// coordinates), on one core. Stress modes and modal coordinate histories
/// are synthetic (random modes; each coordinate a sum of sines and filtered
/// noise), which has the sizes and the cycle density of a rough-road run.
/// Baseline in the same process: the same analysis element by element
/// (block of 1, a matrix-vector-like product per element), against the
/// batches of 64 elements of `flexmb post`; and the batches without S-N
/// curve (recovery and extremes only, no rainflow). Prints wall and thread
/// CPU times. Usage: durability_post_bench [elements] [instants] [modes]
#include <cstdio>
#include <cstdlib>
#include <random>

#include "bench_clock.h"
#include "flexmb/durability/element_fatigue.h"

int main(int argc, char** argv) {
  using flexmb::bench::ThreadCpuNow;
  using flexmb::bench::WallNow;
  const int ne = argc > 1 ? std::atoi(argv[1]) : 5000;
  const int nt = argc > 2 ? std::atoi(argv[2]) : 10000;
  const int n = argc > 3 ? std::atoi(argv[3]) : 30;
  std::mt19937 gen(22);
  std::normal_distribution<double> noise(0.0, 1.0);
  flexmb::reduction::StressTable t;
  t.name = "shell";
  t.components = {"sxx", "syy", "sxy"};
  t.locations = {"bottom", "top"};
  for (int k = 0; k < ne; ++k) t.elements.push_back(k);
  t.axes.assign(ne, Eigen::Matrix3d::Identity());
  t.modes.resize(6 * ne, n);
  for (Eigen::Index i = 0; i < t.modes.size(); ++i) t.modes.data()[i] = 5e6 * noise(gen);
  Eigen::MatrixXd W(n, nt);
  for (int j = 0; j < n; ++j) {
    double a = 0;
    for (int r = 0; r < nt; ++r) {
      a = 0.9 * a + 0.3 * noise(gen);
      W(j, r) = std::sin(0.01 * (j + 1) * r) + a;
    }
  }
  flexmb::durability::StressRecovery rec(t, W);
  flexmb::durability::FatigueOptions opt;
  opt.curve = flexmb::durability::SnCurve::Eurocode(71);
  double sum = 0;
  std::printf("%d elements x 3 points x %d instants, %d modes\n", ne, nt, n);
  for (int run = 0; run < 3; ++run) {
    // batches of 64 with damage; element by element (baseline); batches without damage (extremes only)
    const int block = run == 1 ? 1 : 64;
    opt.block = block;
    if (run == 2) opt.curve.reset();
    const double w0 = WallNow(), c0 = ThreadCpuNow();
    const flexmb::durability::ElementResults r = flexmb::durability::AnalyzeElements(rec, opt);
    const double wall = WallNow() - w0, cpu = ThreadCpuNow() - c0;
    for (double d : r.damage) sum += d;
    std::printf("block %3d%s: wall %.2f s, thread CPU %.2f s (damage sum %.6e)\n", block,
                run == 2 ? ", extremes only" : "", wall, cpu, sum);
  }
  return 0;
}
