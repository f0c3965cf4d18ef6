#include "fuzz_input.h"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>

#include "flexmb/common/log.h"

namespace flexmb::fuzz {

std::string WriteScratchFile(const uint8_t* data, size_t size, const std::string& extension) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("flexmb_fuzz_" + std::to_string(getpid()) + extension)).string();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  }
  return path;
}

void SilenceWarnings() {
  static const bool quiet = [] {
    SetWarningSink([](const std::string&) {});
    return true;
  }();
  (void)quiet;
}

bool BitIdentical(const fe::SparseMat& a, const fe::SparseMat& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  for (int j = 0; j <= a.cols(); ++j) {
    if (a.outerIndexPtr()[j] != b.outerIndexPtr()[j]) return false;
  }
  for (int k = 0; k < a.nonZeros(); ++k) {
    if (a.innerIndexPtr()[k] != b.innerIndexPtr()[k]) return false;
    if (std::memcmp(&a.valuePtr()[k], &b.valuePtr()[k], sizeof(double)) != 0) return false;
  }
  return true;
}

}  // namespace flexmb::fuzz
