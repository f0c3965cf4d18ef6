#pragma once
/// \file process_tuning.h
/// Start-up settings of a flexmb program that the C++ code cannot make once
/// the shared libraries are loaded (docs/design.md, "Process tuning at
/// start-up"):
///  - OpenBLAS (the BLAS under CHOLMOD) picks its kernels by the CPU model
///    number when it is loaded; Debian's 0.3.21 does not know recent Intel
///    models and falls back to its oldest (Prescott, SSE3) kernels, which
///    makes CHOLMOD's supernodal steps several times slower. It reads
///    OPENBLAS_CORETYPE only at load time.
///  - glibc's malloc serves blocks above 32 MB by mmap and gives them back on
///    free, so every large temporary (a 33,000 x 166 matrix is 44 MB) is
///    page-faulted in again, 4 KiB at a time; the GLIBC_TUNABLES malloc
///    settings keep freed memory and ask for transparent huge pages.
/// TuneProcess sets both in the environment, when the user has not set them,
/// and starts the program again once (execv of /proc/self/exe) so that they
/// take effect; FLEXMB_NO_TUNING=1 turns it off. Failure to re-execute is
/// harmless: the program goes on untuned.

namespace flexmb {

/// What TuneProcess would set: the OpenBLAS core type ("" if none is
/// needed: OpenBLAS absent, the user's own choice, a known CPU, or a CPU
/// without AVX2) and the glibc tunables ("" if the user set their own).
struct ProcessTuning {
  const char* openblas_coretype = "";
  const char* glibc_tunables = "";
};

/// Decides the tuning for this process (reads the environment, the loaded
/// OpenBLAS's core name and the CPU's features; changes nothing).
ProcessTuning PlanProcessTuning();

/// Applies PlanProcessTuning by re-executing the program with `argv` once.
/// Call first thing in main(); returns normally if nothing is to be done or
/// the re-execution failed.
void TuneProcess(char** argv);

/// Limits OpenBLAS to `threads` threads while it lives (and restores the
/// previous count): for code that already runs its own threads, each
/// calling BLAS (CHOLMOD solves), where OpenBLAS's own threads would only
/// spin and yield for the cores. Does nothing without OpenBLAS.
class BlasThreadLimit {
 public:
  explicit BlasThreadLimit(int threads);
  ~BlasThreadLimit();
  BlasThreadLimit(const BlasThreadLimit&) = delete;
  BlasThreadLimit& operator=(const BlasThreadLimit&) = delete;

 private:
  int previous_ = 0;   ///< OpenBLAS's thread count before, 0 if OpenBLAS is absent
};

}  // namespace flexmb
