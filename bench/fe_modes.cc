/// \file fe_modes.cc
/// fe_modes_bench: time and peak memory of reading, assembling and solving
/// 20 modes of a generated truck ladder frame of 4-node shells (two C-channel
/// rails joined by flat cross members, free-free, consistent mass), about
/// 5,400 nodes / 33,000 DOF at the default element size. The frame is
/// written as Nastran bulk data first, so "read" is the reader users meet.
/// Baselines in the same process: the factorization of K - sigma M by
/// Eigen's SimplicialLDLT against CHOLMOD's supernodal Cholesky, and the
/// modes by block Lanczos against Spectra on the same factor. Prints a
/// markdown table; see docs/PERFORMANCE.md, "FE: read, assemble, modes".
///
/// Usage: fe_modes_bench [--h H] [--count N] [--lumped] [--no-eigen]
///   H: element size [m] (default 0.04; 0.0125 gives about 320,000 DOF)
///   N: number of modes (default 20)
///   --no-eigen: skip the Eigen SimplicialLDLT baseline (slow on big models)

#include <sys/resource.h>

#include <Eigen/SparseCholesky>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "bench/ladder_frame.h"
#include "flexmb/common/process_tuning.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/block_lanczos.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe/sparse_cholesky.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"

namespace {

using Clock = std::chrono::steady_clock;

double PeakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

double Seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

int main(int argc, char** argv) {
  flexmb::TuneProcess(argv);  // OpenBLAS kernels and malloc settings (docs/design.md)
  namespace fe = flexmb::fe;
  double h = 0.04;
  int count = 20;
  bool lumped = false, eigen_baseline = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--h") && i + 1 < argc) {
      h = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--count") && i + 1 < argc) {
      count = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--lumped")) {
      lumped = true;
    } else if (!std::strcmp(argv[i], "--no-eigen")) {
      eigen_baseline = false;
    } else {
      std::fprintf(stderr, "usage: fe_modes_bench [--h H] [--count N] [--lumped] [--no-eigen]\n");
      return 2;
    }
  }
  const std::filesystem::path bdf = std::filesystem::temp_directory_path() / "flexmb_fe_modes_bench.bdf";
  flexmb::bench::WriteBulkData(flexmb::bench::LadderFrame(h), bdf.string());
  const double mb = std::filesystem::file_size(bdf) / 1e6;
  const double rss_start = PeakRssMb();

  auto t0 = Clock::now();
  const fe::Mesh mesh = flexmb::io::ReadNastran(bdf.string());
  const double t_read = Seconds(t0);
  const double rss_read = PeakRssMb();
  std::filesystem::remove(bdf);

  fe::AssemblyOptions options;
  options.mass_form = lumped ? fe::MassForm::kLumped : fe::MassForm::kConsistent;
  t0 = Clock::now();
  const fe::AssembledModel model = fe::Assemble(mesh, options);
  const double t_assemble = Seconds(t0);
  const double rss_assemble = PeakRssMb();

  t0 = Clock::now();
  const fe::MassProperties mp = fe::ComputeMassProperties(mesh, model);
  const double t_mass = Seconds(t0);

  // the automatic shift of SolveModes for this model: (2 pi * 1 Hz)^2
  const double sigma = -std::pow(2.0 * M_PI, 2);
  const fe::SparseMat shifted = model.K - sigma * model.M;
  t0 = Clock::now();
  fe::SparseCholesky factor;
  factor.Factorize(shifted, "K - sigma M");
  const double t_factor = Seconds(t0);
  t0 = Clock::now();
  const fe::ModalResult r = fe::SolveModesFactorized(model.K, model.M, factor, sigma, count);
  const double t_spectra = Seconds(t0);
  const double rss_modes = PeakRssMb();
  t0 = Clock::now();
  fe::BlockLanczosOptions bl;
  bl.count = count;
  const fe::ModalResult rb = fe::SolveModesBlockLanczos(model.K, model.M, factor, sigma, bl);
  const double t_block = Seconds(t0);
  double t_whole = 0.0;
  {
    fe::ModalOptions modal;
    modal.count = count;
    t0 = Clock::now();
    (void)fe::SolveModes(model, modal);
    t_whole = Seconds(t0);
  }
  double t_eigen = 0.0;
  if (eigen_baseline) {
    t0 = Clock::now();
    Eigen::SimplicialLDLT<fe::SparseMat> ldlt(shifted);
    t_eigen = Seconds(t0);
    if (ldlt.info() != Eigen::Success) std::printf("Eigen SimplicialLDLT failed\n");
  }
  double max_diff = 0.0;
  for (int k = 6; k < count; ++k) max_diff = std::max(max_diff, std::abs(rb.frequencies_hz[k] / r.frequencies_hz[k] - 1));

  std::printf("ladder frame, h = %g m: %zu nodes, %zu shells, %d DOF, nnz(K) = %lld, nnz(L) = %lld, mass %.3f kg\n\n",
              h, mesh.nodes.size(), mesh.elements.size(), model.dofs.n_free,
              static_cast<long long>(model.K.nonZeros()), static_cast<long long>(factor.FactorNonZeros()), mp.mass);
  std::printf("| step | time [s] | peak RSS after [MB] |\n|---|---:|---:|\n");
  std::printf("| (generate and write %.1f MB of bulk data: not timed) | | %.0f |\n", mb, rss_start);
  std::printf("| read Nastran bulk data | %.3f | %.0f |\n", t_read, rss_read);
  std::printf("| assemble K, M (%s) | %.3f | %.0f |\n", lumped ? "lumped" : "consistent", t_assemble, rss_assemble);
  std::printf("| mass properties | %.3f | %.0f |\n", t_mass, rss_assemble);
  std::printf("| factorize K - sigma M (CHOLMOD supernodal) | %.3f | |\n", t_factor);
  std::printf("| %d modes, Spectra on the factor | %.3f | %.0f |\n", count, t_spectra, rss_modes);
  std::printf("| **read + assemble + %d modes (SolveModes: factor and Spectra)** | **%.3f** | %.0f |\n\n", count,
              t_read + t_assemble + t_whole, PeakRssMb());
  std::printf("baselines in the same process:\n\n");
  if (eigen_baseline) {
    std::printf("- factorization: Eigen SimplicialLDLT %.3f s, CHOLMOD %.3f s: CHOLMOD %.1fx faster\n", t_eigen,
                t_factor, t_eigen / t_factor);
  }
  std::printf("- %d modes on the same factor: Spectra %.3f s, block Lanczos %.3f s: ratio Spectra / block %.2f "
              "(flexible frequencies agree to %.1e)\n\n",
              count, t_spectra, t_block, t_spectra / t_block, max_diff);
  std::printf("frequencies [Hz]:");
  for (int k = 0; k < r.frequencies_hz.size(); ++k) std::printf(" %.4g", r.frequencies_hz[k]);
  std::printf("\n");
  return 0;
}
