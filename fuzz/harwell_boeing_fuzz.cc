// libFuzzer target for io::ReadHarwellBoeing (header and token checks, then
// RBio): any input must give a matrix or a flexmb::Error, never a crash,
// hang or sanitizer report. A matrix that was read is written back with
// RBio and read again, and must come back bit for bit (negative zeros as
// +0 when RBio chose the integer format, which cannot write -0; see
// WriteHarwellBoeing). Seeds: fuzz/corpus/harwell_boeing/.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "flexmb/fe_io/harwell_boeing.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::ReadScratchFile(data, size, ".hb", [](const std::string& path) {
    const flexmb::io::HarwellBoeingMatrix m = flexmb::io::ReadHarwellBoeing(path);
    if (m.A.rows() > 5000 || m.A.nonZeros() > 20000) return;
    const std::string copy = path + ".copy.hb";
    flexmb::io::HarwellBoeingWriteOptions o;
    o.symmetric = m.symmetric;
    flexmb::io::WriteHarwellBoeing(m.A, copy, o);
    const flexmb::io::HarwellBoeingMatrix back = flexmb::io::ReadHarwellBoeing(copy);
    flexmb::fe::SparseMat expected = m.A;
    if (back.type[0] == 'I') {
      for (int k = 0; k < expected.nonZeros(); ++k) expected.valuePtr()[k] += 0.0;  // -0 + 0 = +0
    }
    if (!flexmb::fuzz::BitIdentical(expected, back.A)) std::abort();
  });
  return 0;
}
