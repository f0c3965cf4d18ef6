#pragma once
/// \file cli_runner.h
/// Runs the flexmb command line (the FLEXMB_CLI binary) for the end-to-end
/// tests, capturing its exit code, stdout and stderr, in a scratch
/// directory per test.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace flexmb::testing {

/// The whole content of a file ("" if it cannot be read).
inline std::string ReadFile(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Writes `text` to the file `p`, replacing it.
inline void WriteFile(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

/// Exit code (-1 if the binary did not exit normally) and output of one run.
struct CliResult {
  int code = -1;
  std::string out, err;
};

/// Runs the flexmb binary with `args` (shell syntax) in `dir`, capturing
/// stdout and stderr through the files cli_stdout.txt and cli_stderr.txt there.
inline CliResult RunCli(const std::filesystem::path& dir, const std::string& args) {
  const std::string cmd = "cd '" + dir.string() + "' && '" FLEXMB_CLI "' " + args +
                          " > cli_stdout.txt 2> cli_stderr.txt";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = ReadFile(dir / "cli_stdout.txt");
  r.err = ReadFile(dir / "cli_stderr.txt");
  return r;
}

/// A fixture whose tests run in a fresh scratch directory dir_,
/// <temp>/<prefix><pid>_<test name>, removed after the test.
class CliTest : public ::testing::Test {
 protected:
  explicit CliTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           (prefix_ + std::to_string(getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace flexmb::testing
