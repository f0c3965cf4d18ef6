/// \file lu_threshold.cc
/// Chooses SparseLu's dense-path threshold (kDenseMinRows, kDenseMinFill):
/// CPU time of one numeric factorization plus one solve by KLU (pattern
/// analysed once, klu_refactor as in the integrator) and by the dense path
/// (Eigen PartialPivLU of a dense copy), for random matrices of n rows with a
/// given fill (fraction of stored entries, diagonal always stored, dominant).
/// A second table compares the dense path (flexmb's blocked LU, DenseLu in
/// sparse_lu.cc) with LAPACK's dgetrf + dgetrs from OpenBLAS (one thread)
/// and Eigen's PartialPivLU on fully stored matrices (issue 23: "LAPACK
/// dgetrf through OpenBLAS measured against the own blocked LU"); every
/// column includes the same copy of the sparse matrix into a dense one (the
/// dense path's) and one solve of a right-hand side of ones.
/// Usage: lu_threshold_bench. Output: markdown tables (docs/PERFORMANCE.md).

#include <ctime>
#include <cstdio>
#include <algorithm>
#include <random>
#include <vector>

#include <Eigen/LU>

#include "bench/bench_clock.h"
#include "flexmb/solver/sparse_lu.h"

#ifdef FLEXMB_BENCH_LAPACK
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info);
void openblas_set_num_threads(int threads);
}
#endif

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
      b.setOnes();
      lu.Solve(b);
    }
    best = std::min(best, (flexmb::bench::ThreadCpuNow() - t0) / reps * 1e6);
  }
  return best;
}

// best of 5 of the mean CPU time [us] of (dense copy as SparseLu's,
// factorize, solve) by LAPACK (OpenBLAS) or Eigen's PartialPivLU
double TimeDenseLibrary(bool lapack, flexmb::SparseMat A, int reps) {
  const int n = static_cast<int>(A.rows());
  Eigen::MatrixXd a(n, n);
  std::vector<int> ipiv(static_cast<size_t>(n));
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(n);
  flexmb::VecX b = flexmb::VecX::Ones(n);
  double best = 1e300;
  for (int r = 0; r < 5; ++r) {
    const double t0 = flexmb::bench::ThreadCpuNow();
    for (int k = 0; k < reps; ++k) {
      A.valuePtr()[0] += 1e-3;
      flexmb::CopyToDense(A, a);
      b.setOnes();
      if (lapack) {
#ifdef FLEXMB_BENCH_LAPACK
        int info = 0, one = 1;
        dgetrf_(&n, &n, a.data(), &n, ipiv.data(), &info);
        dgetrs_("N", &n, &one, a.data(), &n, ipiv.data(), b.data(), &n, &info);
        if (info != 0) std::fprintf(stderr, "dgetrf/dgetrs info %d\n", info);
#endif
      } else {
        lu.compute(a);
        b = lu.solve(b);
      }
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
#ifndef FLEXMB_BENCH_LAPACK
  std::printf("\n(no libopenblas found at configure time: the LAPACK table is left out)\n");
  return 0;
#else
  openblas_set_num_threads(1);
  std::printf("\n| n | flexmb dense path [us] | LAPACK dgetrf + dgetrs, OpenBLAS [us] | Eigen PartialPivLU [us] | LAPACK / flexmb | Eigen / flexmb |\n"
              "|---|---|---|---|---|---|\n");
  for (int n : {32, 64, 112, 166, 256}) {
    const flexmb::SparseMat A = RandomMatrix(n, 1.0, 29u + n);
    const int reps = std::max(3, 4000000 / (n * n * n));
    const double td = Time(flexmb::SparseLu::Path::kDense, A, reps);
    const double tl = TimeDenseLibrary(true, A, reps);
    const double te = TimeDenseLibrary(false, A, reps);
    std::printf("| %d | %.1f | %.1f | %.1f | %.2f | %.2f |\n", n, td, tl, te, tl / td, te / td);
  }
  return 0;
#endif
}
