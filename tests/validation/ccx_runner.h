#pragma once
/// \file ccx_runner.h
/// Runs CalculiX (ccx, Debian package calculix-ccx) for the validation tests
/// that compare with it: a scratch directory per run, the run itself and
/// the natural frequencies of its eigenvalue output.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace flexmb::testing {

/// Whether the ccx binary is on the PATH (the tests skip without it).
inline bool HaveCcx() { return std::system("command -v ccx > /dev/null 2>&1") == 0; }

/// A fresh scratch directory flexmb_ccx_<pid>_<name> in the system's
/// temporary directory, removed with this object.
struct CcxScratchDir {
  std::filesystem::path path;
  explicit CcxScratchDir(const std::string& name) {
    path = std::filesystem::temp_directory_path() / ("flexmb_ccx_" + std::to_string(getpid()) + "_" + name);
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  CcxScratchDir(const CcxScratchDir&) = delete;
  CcxScratchDir& operator=(const CcxScratchDir&) = delete;
  ~CcxScratchDir() { std::filesystem::remove_all(path); }
};

/// Writes `deck` to dir/job.inp and runs `ccx -i job` in `dir` (output in
/// dir/job.log); fails the test (and returns false) if ccx exits with an
/// error, reports *ERROR or writes no job.dat.
inline bool RunCcx(const std::filesystem::path& dir, const std::string& job, const std::string& deck) {
  std::ofstream(dir / (job + ".inp")) << deck;
  const std::string cmd = "cd '" + dir.string() + "' && ccx -i " + job + " > " + job + ".log 2>&1";
  const int rc = std::system(cmd.c_str());
  std::stringstream log;
  log << std::ifstream(dir / (job + ".log")).rdbuf();
  const bool ok =
      rc == 0 && log.str().find("*ERROR") == std::string::npos && std::filesystem::exists(dir / (job + ".dat"));
  EXPECT_TRUE(ok) << "ccx failed (exit " << rc << "), " << (dir / (job + ".log")) << ":\n"
                  << log.str().substr(0, 3000);
  return ok;
}

/// The natural frequencies [Hz] of the eigenvalue table ccx 2.20 writes to
/// job.dat for a *FREQUENCY step:
///
///      E I G E N V A L U E   O U T P U T
///
///  MODE NO    EIGENVALUE                       FREQUENCY
///                                      REAL PART            IMAGINARY PART
///                            (RAD/TIME)      (CYCLES/TIME     (RAD/TIME)
///
///       1   0.1281829E+07   0.1132179E+04   0.1801918E+03   0.0000000E+00
///
/// one row per mode: mode number, eigenvalue omega^2 [rad^2/s^2], omega
/// [rad/s], f [Hz], imaginary part; 7 significant digits. The table ends at
/// the first line after it that is not such a row. Returns f = sqrt(omega^2)
/// / (2 pi) from the eigenvalue column (relative rounding <= 2.5e-7).
inline std::vector<double> ParseCcxFrequencies(const std::filesystem::path& dat) {
  constexpr double kPi = 3.14159265358979323846;
  std::ifstream in(dat);
  std::string line;
  std::vector<double> f;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.find("E I G E N V A L U E   O U T P U T") != std::string::npos) {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    int mode = 0;
    double lambda = 0.0, omega = 0.0, cycles = 0.0, imag = 0.0;
    char tail = 0;
    const int n = std::sscanf(line.c_str(), "%d %lf %lf %lf %lf %c", &mode, &lambda, &omega, &cycles, &imag, &tail);
    if (n == 5 && mode == static_cast<int>(f.size()) + 1) {
      f.push_back(std::sqrt(lambda) / (2.0 * kPi));
    } else if (!f.empty()) {
      break;
    }
  }
  return f;
}

}  // namespace flexmb::testing
