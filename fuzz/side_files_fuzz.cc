// libFuzzer target for the smaller YAML and text inputs beside the model
// file: a tire data file (vehicle::LoadTireFile, as YAML and as a Magic
// Formula .tir property file), the FE model file
// (io::LoadFeModel of a .yaml) and the modes file of an exchange set
// (io::ReadModesFile). Every input goes to all three readers; each must
// give a result or a flexmb::Error, never a crash, hang or sanitizer
// report. Seeds: fuzz/corpus/side_files/ (the example tires, a .tir file
// written after tests/unit/vehicle/tir_file_test.cc, the gmsh test models'
// FE model files, a modes file).

#include <cstddef>
#include <cstdint>
#include <string>

#include "flexmb/body_file/modes_file.h"
#include "flexmb/fe_io/fe_model_file.h"
#include "flexmb/vehicle/truck.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::SilenceWarnings();
  flexmb::fuzz::ReadScratchFile(data, size, ".tire.yaml",
                                [](const std::string& path) { flexmb::vehicle::LoadTireFile(path); });
  flexmb::fuzz::ReadScratchFile(data, size, ".tir",
                                [](const std::string& path) { flexmb::vehicle::LoadTireFile(path); });
  flexmb::fuzz::ReadScratchFile(data, size, ".fe.yaml", [](const std::string& path) {
    const flexmb::fe::FeModel m = flexmb::io::LoadFeModel(path);
    (void)m;
  });
  flexmb::fuzz::ReadScratchFile(data, size, ".modes.mtx",
                                [](const std::string& path) { flexmb::io::ReadModesFile(path); });
  return 0;
}
