#pragma once
/// \file parallel_rows.h
/// Splits a loop over the rows of large dense blocks (n x a few hundred)
/// into contiguous ranges run on std::threads, for the memory- and
/// GEMM-bound products of the reduction. Small ranges run inline.

#include <Eigen/Core>
#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace flexmb::reduction {

/// Number of worker ranges ParallelRows uses for n rows: at most the
/// hardware threads (capped at 8), at least `min_rows` rows per range.
inline int ParallelRanges(Eigen::Index n, Eigen::Index min_rows) {
  const int hw = std::max(1, std::min(8, static_cast<int>(std::thread::hardware_concurrency())));
  return static_cast<int>(std::max<Eigen::Index>(1, std::min<Eigen::Index>(hw, n / std::max<Eigen::Index>(min_rows, 1))));
}

/// Calls f(range, begin, end) for `ranges` contiguous row ranges covering
/// [0, n), each on its own thread (the first on the calling thread). An
/// exception thrown by f is rethrown here after all ranges finished.
template <class F>
void ParallelRows(Eigen::Index n, int ranges, F&& f) {
  if (ranges <= 1) {
    f(0, Eigen::Index{0}, n);
    return;
  }
  Eigen::initParallel();
  std::vector<std::exception_ptr> errors(static_cast<size_t>(ranges));
  auto run = [&](int r) {
    const Eigen::Index begin = n * r / ranges, end = n * (r + 1) / ranges;
    try {
      f(r, begin, end);
    } catch (...) {
      errors[static_cast<size_t>(r)] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(static_cast<size_t>(ranges - 1));
  for (int r = 1; r < ranges; ++r) workers.emplace_back(run, r);
  run(0);
  for (std::thread& t : workers) t.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace flexmb::reduction
