#pragma once
/// \file fuzz_input.h
/// Helpers for the reader fuzz targets: the readers take file paths (they
/// follow INCLUDEs and report file:line), so each input is written to a
/// per-process scratch file first.

#include <cstddef>
#include <cstdint>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"

namespace flexmb::fuzz {

/// Writes the fuzzer's bytes to a scratch file named with `extension`
/// (e.g. ".bdf") and returns its path; the file is reused between inputs.
std::string WriteScratchFile(const uint8_t* data, size_t size, const std::string& extension);

/// Runs `read` and swallows flexmb::Error (a clear error is the expected
/// outcome for bad input); anything else (a crash, a sanitizer report,
/// another exception type) is a finding.
template <class F>
void ExpectCleanError(F&& read) {
  try {
    read();
  } catch (const flexmb::Error&) {
  }
}

/// Writes the fuzzer's bytes to the scratch file (see WriteScratchFile) and
/// runs `read(path)` under ExpectCleanError.
template <class F>
void ReadScratchFile(const uint8_t* data, size_t size, const std::string& extension, F&& read) {
  const std::string path = WriteScratchFile(data, size, extension);
  ExpectCleanError([&] { read(path); });
}

/// Discards flexmb's warnings from now on (readers warn about unsupported
/// cards, which would flood the fuzzer's output).
void SilenceWarnings();

/// Same size, storage (column pointers, row indices) and bit-identical values.
bool BitIdentical(const fe::SparseMat& a, const fe::SparseMat& b);

}  // namespace flexmb::fuzz
