// libFuzzer target for durability::SnCurve::ReadCsv (S-N table of lines
// "N, range_Pa"): any input must give a curve or a flexmb::Error, never a
// crash, hang or sanitizer report. A curve that was read must be what the
// reader promises: cycles to failure not negative and not increasing with
// the stress range, damage per cycle not negative, neither ever NaN.
// Seeds: fuzz/corpus/sn_curve/.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "flexmb/durability/sn_curve.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::ReadScratchFile(data, size, ".csv", [](const std::string& path) {
    const flexmb::durability::SnCurve curve = flexmb::durability::SnCurve::ReadCsv(path);
    double last_cycles = INFINITY;
    for (double s = 1.0; s < 1e13; s *= 1.7) {
      const double n = curve.Cycles(s);
      const double d = curve.Damage(s);
      if (std::isnan(n) || n < 0.0 || n > last_cycles) std::abort();
      if (std::isnan(d) || d < 0.0) std::abort();
      last_cycles = n;
    }
  });
  return 0;
}
