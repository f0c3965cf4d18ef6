// libFuzzer target for the truck map of a lane-change file
// (vehicle::ParseTruck: axles, bogies, parts, suspensions, steering,
// brakes, the frame and its generated mesh), then the static axle loads and
// the frame's attachments of what it read. The input is the whole file; its
// axles' tires may name fuzz_tire.yaml, a valid tire file written beside the
// scratch file. Each input must give a truck or a flexmb::Error, never a
// crash, hang or sanitizer report. Seeds: fuzz/corpus/truck_file/ (the 4x2
// and 6x4 examples with their tires as fuzz_tire.yaml, the 6x4 with its
// platform, the 4x2 in the two-axle form).

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "flexmb/vehicle/truck.h"
#include "flexmb/yaml/yaml_context.h"
#include "fuzz_input.h"

namespace {

// a valid tire file beside the scratch file, written once
void WriteFuzzTire(const std::filesystem::path& dir) {
  static const bool written = [&] {
    std::ofstream(dir / "fuzz_tire.yaml") << "tire:\n  count: 1\n  unloaded_radius: 0.527\n  vertical_stiffness: 9.0e5\n"
                                             "  nominal_load: 25000\n";
    return true;
  }();
  (void)written;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::SilenceWarnings();
  flexmb::fuzz::ReadScratchFile(data, size, ".truck.yaml", [](const std::string& path) {
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    WriteFuzzTire(dir);
    YAML::Node root;
    try {
      root = YAML::LoadFile(path);
    } catch (const YAML::Exception&) {
      return;  // the reader's "cannot read the lane-change file"
    }
    if (!root.IsMap() || !root["truck"]) return;
    flexmb::YamlContext ctx(path);
    const flexmb::vehicle::TruckData d = flexmb::vehicle::ParseTruck(root["truck"], ctx, dir.string());
    (void)flexmb::vehicle::StaticAxleLoads(d, 9.81);
    (void)flexmb::vehicle::FrameAttachments(d);
  });
  return 0;
}
