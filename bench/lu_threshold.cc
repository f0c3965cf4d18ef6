/// \file lu_threshold.cc
/// Chooses SparseLu's dense-path threshold (kDenseMinRows, kDenseMinFill):
/// CPU time of one numeric factorization plus one solve by KLU (pattern
/// analysed once, klu_refactor as in the integrator) and by the dense path
/// (Eigen PartialPivLU of a dense copy), for random matrices of n rows with a
/// given fill (fraction of stored entries, diagonal always stored, dominant).
/// Usage: lu_threshold_bench. Output: a markdown table (docs/PERFORMANCE.md).

#include <ctime>
#include <cstdio>
#include <algorithm>
#include <random>
#include <vector>

#include "bench/bench_clock.h"
#include "flexmb/solver/sparse_lu.h"

namespace {

flexmb::SparseMat RandomMatrix(int n, double fill, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pick(0.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (i == j || pick(gen) < fill) t.emplace_back(i, j, u(gen) + (i == j ? 2.0 * n : 0.0));
  flexmb::SparseMat A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// best of 5 of the mean CPU time [us] of factorize + solve over reps calls
double Time(flexmb::SparseLu::Path path, flexmb::SparseMat A, int reps) {
  flexmb::SparseLu lu(path);
  flexmb::VecX b = flexmb::VecX::Ones(A.rows());
  lu.Factorize(A);
  double best = 1e300;
  for (int r = 0; r < 5; ++r) {
    const double t0 = flexmb::bench::ThreadCpuNow();
    for (int k = 0; k < reps; ++k) {
      A.valuePtr()[0] += 1e-3;
      if (!lu.Factorize(A)) std::fprintf(stderr, "singular\n");
      lu.Solve(b);
    }
    best = std::min(best, (flexmb::bench::ThreadCpuNow() - t0) / reps * 1e6);
  }
  return best;
}

}  // namespace

int main() {
  std::printf("| n | fill | nnz / n^2 | KLU [us] | dense [us] | KLU / dense |\n|---|---|---|---|---|---|\n");
  for (int n : {16, 32, 48, 64, 96, 128, 166, 256}) {
    for (double fill : {1.0, 0.5, 0.25, 0.1}) {
      const flexmb::SparseMat A = RandomMatrix(n, fill, 17u + n);
      const int reps = std::max(3, 2000000 / (n * n * n));
      const double tk = Time(flexmb::SparseLu::Path::kKlu, A, reps);
      const double td = Time(flexmb::SparseLu::Path::kDense, A, reps);
      std::printf("| %d | %.2f | %.2f | %.1f | %.1f | %.2f |\n", n, fill,
                  static_cast<double>(A.nonZeros()) / (static_cast<double>(n) * n), tk, td, tk / td);
    }
  }
  return 0;
}
