// The model file's `tire` entry with a `.tir` property file: the tire is
// built from the file's coefficients (pky1 = -PKY1), one warning lists the
// ignored keys, and a file with a relaxation length (PTY1 > 0) needs the
// contact-patch marker `j` like YAML data do.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/model/model.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/vehicle/tire.h"

namespace flexmb {
namespace tir_model_file_test {

// a minimal SI property file; `extra` appends lines
std::string TirModelWrite(const std::string& name, const std::string& extra) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() / ("flexmb_tir_model_" + name);
  std::ofstream(p) << "[UNITS]\nLENGTH = 'meter'\nFORCE = 'newton'\n"
                      "[DIMENSION]\nUNLOADED_RADIUS = 0.5\nWIDTH = 0.3\n"
                      "[VERTICAL]\nFNOMIN = 25000\nVERTICAL_STIFFNESS = 8.0e5\n"
                      "[LONGITUDINAL_COEFFICIENTS]\nPCX1 = 1.65\nPDX1 = 0.8\nPKX1 = 15\n"
                      "[LATERAL_COEFFICIENTS]\nPCY1 = 1.3\nPDY1 = 0.8\nPKY1 = -9.5\n"
                   << extra;
  return p.string();
}

std::string TirModelText(const std::string& tire_entry) {
  return R"(name: tir_model
bodies:
  - name: wheel
    mass: 40
    inertia: [1, 2, 1]
    position: [0, 0, 0.5]
    markers:
      - {name: centre, orientation: {z_axis: [0, 1, 0]}}
forces:
  - )" + tire_entry + "\n";
}

TEST(TirModelFile, TireEntryReadsATirFileAndWarns) {
  const std::string path = TirModelWrite("plain.tir", "");
  std::vector<std::string> warnings;
  const LogSink old = SetWarningSink([&](const std::string& m) { warnings.push_back(m); });
  std::unique_ptr<Model> m;
  try {
    m = LoadModelString(TirModelText("{name: t, type: tire, i: wheel.centre, file: " + path + "}"), "tir.yaml");
  } catch (...) {
    SetWarningSink(old);
    throw;
  }
  SetWarningSink(old);
  ASSERT_EQ(m->forces.size(), 1u);
  const auto& tire = dynamic_cast<const vehicle::Tire&>(*m->forces[0]);
  EXPECT_EQ(tire.data().pky1, 9.5);
  EXPECT_EQ(tire.data().nominal_load, 25000.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("WIDTH"), std::string::npos) << warnings[0];
}

TEST(TirModelFile, RelaxedTirTireNeedsThePatchMarker) {
  const std::string path = TirModelWrite("relaxed.tir", "PTY1 = 1.2\nPTY2 = 2\n");
  const LogSink old = SetWarningSink([](const std::string&) {});
  try {
    LoadModelString(TirModelText("{name: t, type: tire, i: wheel.centre, file: " + path + "}"), "tir.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'j'"), std::string::npos) << e.what();
  }
  SetWarningSink(old);
}

}  // namespace tir_model_file_test
}  // namespace flexmb
