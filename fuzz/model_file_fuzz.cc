// libFuzzer target for LoadModelFile (the YAML model file: parsing, the
// element registry's parsers, references between entries, solver settings
// and the model's finalization with its consistent initial state): any
// input must give a model or a flexmb::Error, never a crash, hang or
// sanitizer report. Seeds: fuzz/corpus/model_file/ (the examples' model
// files and the complete models of docs/model-file.md).

#include <cstddef>
#include <cstdint>
#include <string>

#include "flexmb/model_file/model_file.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::SilenceWarnings();
  flexmb::fuzz::ReadScratchFile(data, size, ".yaml",
                                [](const std::string& path) { flexmb::LoadModelFile(path); });
  return 0;
}
