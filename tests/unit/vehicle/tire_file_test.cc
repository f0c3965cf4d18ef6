// LoadTireFile (vehicle/truck.h): the example tire file reads with the
// values written in it; files that are not a 'tire' map are InputErrors
// naming the file (a YAML scalar, e.g. another kind of file, reached the
// reader's subscript before; found by the side_files fuzz target).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/vehicle/truck.h"

namespace flexmb::vehicle {
namespace tire_file_test {

std::string TireFileError(const std::string& name, const std::string& text) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() / ("flexmb_tire_file_" + name);
  std::ofstream(p) << text;
  try {
    LoadTireFile(p.string());
  } catch (const InputError& e) {
    EXPECT_EQ(e.context().file, p.string()) << e.what();
    return e.what();
  }
  return "no error";
}

TEST(TireFile, ExampleFileReadsItsValues) {
  const TireData d = LoadTireFile(std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_lane_change/tire_11r22_5.yaml");
  EXPECT_EQ(d.count, 1);
  EXPECT_EQ(d.unloaded_radius, 0.527);
  EXPECT_EQ(d.vertical_stiffness, 9.0e5);
}

TEST(TireFile, FilesThatAreNotATireMapAreNamedErrors) {
  EXPECT_NE(TireFileError("scalar.yaml", "%%MatrixMarket matrix array real general\n3 3\n1\n").find("'tire' map"),
            std::string::npos);
  EXPECT_NE(TireFileError("list.yaml", "- 1\n- 2\n").find("'tire' map"), std::string::npos);
  EXPECT_NE(TireFileError("missing.yaml", "wheel: {count: 1}\n").find("'tire' map"), std::string::npos);
  EXPECT_NE(TireFileError("tire_scalar.yaml", "tire: 5\n"), "no error");
  EXPECT_NE(TireFileError("unknown_key.yaml", "tire:\n  count: 1\n  radius: 0.5\n").find("radius"), std::string::npos);
  EXPECT_NE(TireFileError("bad_yaml.yaml", "tire: [1, 2\n").find("cannot read the tire file"), std::string::npos);
}

}  // namespace tire_file_test
}  // namespace flexmb::vehicle
