// libFuzzer target for the small matrix side files: flexmb's DOF map
// (io::ReadDofMap), CalculiX's job.dof (io::ReadCalculixDofs) and job.sti /
// job.mas (io::ReadCalculixMatrix, for a 1..64 DOF model chosen by the
// first byte). Any input must give a result or a flexmb::Error, never a
// crash, hang or sanitizer report. Seeds: fuzz/corpus/matrix_files/.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "flexmb/fe_io/calculix_matrices.h"
#include "flexmb/fe_io/dof_map.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const int n = size > 0 ? 1 + data[0] % 64 : 1;
  const std::string path = flexmb::fuzz::WriteScratchFile(data, size, ".txt");
  flexmb::fuzz::ExpectCleanError([&] {
    const flexmb::io::MatrixRowMap m = flexmb::io::ReadDofMap(path);
    for (const flexmb::io::DofMapRow& r : m.rows) {
      if (r.node_id <= 0 || r.component < 1 || r.component > 6) std::abort();
    }
  });
  flexmb::fuzz::ExpectCleanError([&] { flexmb::io::ReadCalculixDofs(path); });
  flexmb::fuzz::ExpectCleanError([&] {
    const flexmb::fe::SparseMat A = flexmb::io::ReadCalculixMatrix(path, n);
    if (A.rows() != n || A.cols() != n) std::abort();
  });
  return 0;
}
