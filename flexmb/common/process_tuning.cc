#include "flexmb/common/process_tuning.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <strings.h>

namespace flexmb {

namespace {

// set in the environment of the re-executed program, so it happens once
constexpr const char* kMarker = "FLEXMB_TUNED";

// keep freed memory (no trimming, no mmap for large blocks) and back the
// heap with transparent huge pages where the kernel allows it (madvise mode)
constexpr const char* kTunables =
    "glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967296:glibc.malloc.hugetlb=1";

// OpenBLAS's own name of the kernels it chose, or nullptr if it is not loaded
const char* OpenBlasCoreName() {
  using Fn = char* (*)();
  auto fn = reinterpret_cast<Fn>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  return fn != nullptr ? fn() : nullptr;
}

bool IsSet(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && v[0] != '\0';
}

}  // namespace

ProcessTuning PlanProcessTuning() {
  ProcessTuning plan;
  if (IsSet(kMarker) || IsSet("FLEXMB_NO_TUNING")) return plan;
  const char* core = OpenBlasCoreName();
  // a fallback to the generic kernels on a CPU that has AVX2 and FMA: the
  // Haswell kernels are the newest that every such CPU runs at full clock
  if (core != nullptr && !IsSet("OPENBLAS_CORETYPE") &&
      (strcasecmp(core, "prescott") == 0 || strcasecmp(core, "unknown") == 0 ||
       strcasecmp(core, "core2") == 0 || strcasecmp(core, "nehalem") == 0)) {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) plan.openblas_coretype = "Haswell";
  }
  if (!IsSet("GLIBC_TUNABLES")) plan.glibc_tunables = kTunables;
  return plan;
}

void TuneProcess(char** argv) {
  const ProcessTuning plan = PlanProcessTuning();
  if (plan.openblas_coretype[0] == '\0' && plan.glibc_tunables[0] == '\0') return;
  if (plan.openblas_coretype[0] != '\0') setenv("OPENBLAS_CORETYPE", plan.openblas_coretype, 1);
  if (plan.glibc_tunables[0] != '\0') setenv("GLIBC_TUNABLES", plan.glibc_tunables, 1);
  setenv(kMarker, "1", 1);
  execv("/proc/self/exe", argv);
  // execv returned: it failed; go on untuned (the marker stays, so a child
  // flexmb process does not try again)
}

BlasThreadLimit::BlasThreadLimit(int threads) {
  using Get = int (*)();
  using Set = void (*)(int);
  auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (get == nullptr || set == nullptr) return;
  previous_ = get();
  if (previous_ > threads) {
    set(threads);
  } else {
    previous_ = 0;
  }
}

BlasThreadLimit::~BlasThreadLimit() {
  if (previous_ <= 0) return;
  using Set = void (*)(int);
  auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (set != nullptr) set(previous_);
}

}  // namespace flexmb
