#include "flexmb/durability/modal_history.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "flexmb/common/error.h"

namespace flexmb::durability {
namespace {

std::string ModalTestDir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("flexmb_modal_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d.string();
}

TEST(ModalHistory, RoundTripKeepsEveryRecordBitForBit) {
  const std::string dir = ModalTestDir("round_trip");
  const std::string path = dir + "/" + kModalHistoryFile;
  {
    ModalHistoryWriter w(path, {{"frame", "bodies/frame.h5", 3}, {"boom", "/abs/boom.h5", 2}});
    for (int r = 0; r < 4; ++r) {
      const double v[5] = {0.1 * r, -1.0 / 3 + r, 1e-9 * r, 2.0 * r, -r * 0.7};
      w.Write(0.01 * r, v, 5);
    }
    EXPECT_THROW(w.Write(1.0, nullptr, 4), InputError);
  }
  const ModalHistory h = ReadRunModalHistory(dir);
  ASSERT_EQ(h.bodies.size(), 2u);
  EXPECT_EQ(h.bodies[0].name, "frame");
  EXPECT_EQ(h.bodies[0].body_file, (std::filesystem::path(dir) / "bodies/frame.h5").string());
  EXPECT_EQ(h.bodies[1].body_file, "/abs/boom.h5");
  ASSERT_EQ(h.times.size(), 4u);
  EXPECT_FALSE(h.truncated);
  EXPECT_EQ(h.times[3], 0.01 * 3);
  EXPECT_EQ(h.coordinates[0](1, 2), -1.0 / 3 + 2);
  EXPECT_EQ(h.coordinates[1](1, 3), -3 * 0.7);
  EXPECT_EQ(h.Body("boom"), 1);
  try {
    h.Body("cab");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'frame', 'boom'"), std::string::npos) << e.what();
  }
}

TEST(ModalHistory, InterruptedFileKeepsCompleteRecordsAndDamageIsNamed) {
  const std::string dir = ModalTestDir("cut");
  const std::string path = dir + "/" + kModalHistoryFile;
  {
    ModalHistoryWriter w(path, {{"frame", "f.h5", 2}});
    const double v[2] = {1, 2};
    for (int r = 0; r < 3; ++r) w.Write(r, v, 2);
  }
  // a run killed in the middle of a record
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size - 5);
  ModalHistory h = ReadModalHistory(path);
  EXPECT_EQ(h.times.size(), 2u);
  EXPECT_TRUE(h.truncated);
  // a flipped byte in record 2
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(size - 3 * 32 + 32 + 4));
    f.put('\x55');
  }
  try {
    ReadModalHistory(path);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("record 2"), std::string::npos) << e.what();
  }
  // a folder without the file
  try {
    ReadRunModalHistory(ModalTestDir("empty"));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no modal coordinates"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace flexmb::durability
