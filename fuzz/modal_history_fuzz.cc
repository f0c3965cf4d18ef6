// libFuzzer target for durability::ReadModalHistory (the run's
// modal_coordinates.bin): any input must give a history or a flexmb::Error,
// never a crash, hang or sanitizer report. A history that was read must be
// consistent (one column per record time, one row per modal coordinate,
// finite values) and, written again with ModalHistoryWriter, must read back
// bit for bit. Seeds: fuzz/corpus/modal_history/.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "flexmb/durability/modal_history.h"
#include "fuzz_input.h"

namespace {

bool ModalHistoryConsistent(const flexmb::durability::ModalHistory& h) {
  if (h.coordinates.size() != h.bodies.size()) return false;
  for (size_t b = 0; b < h.bodies.size(); ++b) {
    const Eigen::MatrixXd& w = h.coordinates[b];
    if (w.rows() != h.bodies[b].modes || w.cols() != static_cast<Eigen::Index>(h.times.size())) return false;
    if (!w.allFinite()) return false;
  }
  for (double t : h.times) {
    if (!std::isfinite(t)) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::ReadScratchFile(data, size, ".bin", [](const std::string& path) {
    const flexmb::durability::ModalHistory h = flexmb::durability::ReadModalHistory(path);
    if (!ModalHistoryConsistent(h)) std::abort();
    long total = 0;
    for (const auto& b : h.bodies) total += b.modes;
    if (total * static_cast<long>(h.times.size()) > 100000) return;
    const std::string copy = path + ".copy.bin";
    {
      flexmb::durability::ModalHistoryWriter writer(copy, h.bodies);
      std::vector<double> w(static_cast<size_t>(total));
      for (size_t r = 0; r < h.times.size(); ++r) {
        size_t k = 0;
        for (const Eigen::MatrixXd& c : h.coordinates) {
          for (Eigen::Index i = 0; i < c.rows(); ++i) w[k++] = c(i, static_cast<Eigen::Index>(r));
        }
        writer.Write(h.times[r], w.data(), static_cast<int>(total));
      }
    }
    const flexmb::durability::ModalHistory back = flexmb::durability::ReadModalHistory(copy);
    if (back.times.size() != h.times.size() || back.bodies.size() != h.bodies.size() || back.truncated) std::abort();
    if (!h.times.empty() && std::memcmp(back.times.data(), h.times.data(), h.times.size() * sizeof(double)) != 0) {
      std::abort();
    }
    for (size_t b = 0; b < h.bodies.size(); ++b) {
      if (back.bodies[b].name != h.bodies[b].name || back.bodies[b].modes != h.bodies[b].modes) std::abort();
      const Eigen::MatrixXd& x = h.coordinates[b];
      const Eigen::MatrixXd& y = back.coordinates[b];
      if (x.size() != 0 && std::memcmp(x.data(), y.data(), static_cast<size_t>(x.size()) * sizeof(double)) != 0) {
        std::abort();
      }
    }
  });
  return 0;
}
