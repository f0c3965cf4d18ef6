// ISO 8608 road profiles (vehicle/road_profile.h) against the standard's
// displacement PSD Gd(n) = Gd(n0) (n / n0)^-2, Gd(0.1) = 256e-6 m^3 for
// class C (ISO 8608:2016, Table C.1 geometric means): the PSD of the
// generated profile is estimated here independently (Hann-windowed
// periodograms by direct Fourier sums, no FFT, averaged over 400 m
// segments) and fitted in log-log space between 0.1 and 2 cycles/m: slope
// -2 and level at n0 within 5 %. Also the road file's bad input
// (docs/validation.md, "Durability").
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>  // getpid: ctest -j runs each test in its own process

#include "flexmb/common/error.h"
#include "flexmb/vehicle/road_profile.h"

namespace road_profile_test {

using flexmb::InputError;
using flexmb::vehicle::GenerateIso8608;
using flexmb::vehicle::Iso8608Options;
using flexmb::vehicle::ReadRoadCsv;
using flexmb::vehicle::RoadProfile;

// one-sided PSD of z (spacing dx) at frequency f [cycles/m]: averaged
// Hann-windowed periodograms of non-overlapping segments of `seg` samples
double RoadPsdAt(const std::vector<double>& z, double dx, double f, int seg) {
  double sum = 0, w2 = 0;
  for (int j = 0; j < seg; ++j) {
    const double w = 0.5 - 0.5 * std::cos(2 * M_PI * j / seg);
    w2 += w * w;
  }
  int count = 0;
  for (size_t s = 0; s + seg <= z.size(); s += seg, ++count) {
    std::complex<double> x = 0;
    for (int j = 0; j < seg; ++j) {
      const double w = 0.5 - 0.5 * std::cos(2 * M_PI * j / seg);
      x += w * z[s + j] * std::polar(1.0, -2 * M_PI * f * j * dx);
    }
    sum += 2.0 * dx * std::norm(x) / w2;
  }
  return sum / count;
}

TEST(RoadProfile, Iso8608ClassCPsdSlopeAndLevel) {
  Iso8608Options o;
  o.road_class = 'C';
  o.length = 100e3;
  o.dx = 0.1;
  o.seed = 8608;
  const RoadProfile r = GenerateIso8608(o);
  ASSERT_GE(r.x.back(), 100e3 - 1);
  for (int side = 0; side < 2; ++side) {
    const std::vector<double>& z = side == 0 ? r.z_left : r.z_right;
    // least-squares line through (log n, log G) at 20 log-spaced frequencies
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const int m = 20;
    for (int i = 0; i < m; ++i) {
      const double f = 0.1 * std::pow(20.0, i / (m - 1.0));
      const double lx = std::log(f / 0.1), ly = std::log(RoadPsdAt(z, o.dx, f, 4096));
      sx += lx;
      sy += ly;
      sxx += lx * lx;
      sxy += lx * ly;
    }
    const double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    const double level = std::exp((sy - slope * sx) / m);
    std::printf("side %d: slope %.4f (ISO 8608: -2), Gd(0.1) %.4e m^3 (class C: 2.56e-4)\n", side, slope, level);
    EXPECT_NEAR(slope, -2.0, 0.05 * 2.0);
    EXPECT_NEAR(level, 256e-6, 0.05 * 256e-6);
  }
  // the same seed gives the same road; another seed another one
  o.length = 1000;
  EXPECT_EQ(GenerateIso8608(o).z_left, GenerateIso8608(o).z_left);
  Iso8608Options p = o;
  p.seed = 1;
  EXPECT_NE(GenerateIso8608(o).z_left, GenerateIso8608(p).z_left);
  EXPECT_THROW(flexmb::vehicle::Iso8608Level('J'), InputError);
}

TEST(RoadProfile, RoadFileBadInputNamesTheLine) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() / ("road_profile_test_" + std::to_string(::getpid()) + ".csv");
  auto error_of = [&](const std::string& text) {
    std::ofstream(p) << text;
    try {
      ReadRoadCsv(p.string());
    } catch (const InputError& e) {
      EXPECT_EQ(e.context().file, p.string());
      return std::to_string(e.context().line) + ": " + e.message();
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("x, zl, zr\n0, 0, 0\n1, 0.01, 0\n1, 0.02, 0\n").substr(0, 2), "4:");
  EXPECT_NE(error_of("0, 0, 0\n1, 0.01, 0\n0.5, 0.02, 0\n").find("x not increasing"), std::string::npos);
  EXPECT_EQ(error_of("0, 0, 0\n1, nan, 0\n").substr(0, 2), "2:");
  EXPECT_NE(error_of("0, 0, 0\n1, nan, 0\n").find("NaN"), std::string::npos);
  EXPECT_NE(error_of("0, 0, 0\n1, 2\n").find("three numbers"), std::string::npos);
  std::ofstream(p) << "# measured\nx,zl,zr\n0, 0, 0.1\n2, 0.02, 0.3\n";
  const RoadProfile r = ReadRoadCsv(p.string());
  EXPECT_DOUBLE_EQ(r.Height(0, 0.5), 0.005);
  EXPECT_DOUBLE_EQ(r.Height(1, 1.0), 0.2);
  EXPECT_DOUBLE_EQ(r.Height(1, 5.0), 0.3);
  std::filesystem::remove(p);
}

}  // namespace road_profile_test
