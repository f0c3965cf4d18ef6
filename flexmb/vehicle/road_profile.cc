#include "flexmb/vehicle/road_profile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <random>
#include <cstdio>
#include <unsupported/Eigen/FFT>

#include "flexmb/common/error.h"
#include "flexmb/common/number_table.h"

namespace flexmb::vehicle {
namespace {

// a number as it would be written in the file (%g)
std::string RoadNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

double RoadProfile::Height(int side, double at) const {
  const std::vector<double>& z = side == 0 ? z_left : z_right;
  if (x.empty()) return 0.0;
  if (at <= x.front()) return z.front();
  if (at >= x.back()) return z.back();
  const size_t i = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
  const double s = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return (1.0 - s) * z[i - 1] + s * z[i];
}

double Iso8608Level(char road_class) {
  const int k = std::toupper(static_cast<unsigned char>(road_class)) - 'A';
  if (k < 0 || k > 7)
    throw InputError(std::string("unknown ISO 8608 road class '") + road_class + "' (A to H)");
  return 16e-6 * std::pow(4.0, k);
}

RoadProfile GenerateIso8608(const Iso8608Options& o) {
  const double g0 = Iso8608Level(o.road_class);
  if (!(o.length > 0) || !(o.dx > 0) || !(o.n_min >= 0) || !(o.n_max > o.n_min) || !(o.track_width >= 0) ||
      !(o.coherence_decay >= 0))
    throw InputError("ISO 8608 road: length, dx, track width and decay must be positive and n_min < n_max");
  if (o.n_max > 0.5 / o.dx)
    throw InputError("ISO 8608 road: n_max above the Nyquist frequency 1 / (2 dx) of the sample spacing");
  int n = 2;
  while (n * o.dx < o.length) n *= 2;
  const double L = n * o.dx, dn = 1.0 / L;
  std::mt19937 gen(o.seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
  // one-sided spectra of both tracks; bin k has the frequency k / L
  std::vector<std::complex<double>> left(n, 0.0), right(n, 0.0);
  for (int k = 1; k < n / 2; ++k) {
    const double f = k * dn;
    const double p1 = phase(gen), p2 = phase(gen);
    if (f < o.n_min || f > o.n_max) continue;
    const double amp = std::sqrt(2.0 * g0 * std::pow(f / 0.1, -2.0) * dn);
    const double gamma = std::exp(-o.coherence_decay * f * o.track_width);
    const std::complex<double> a = std::polar(amp, p1), b = std::polar(amp, p2);
    // z(x) = sum amp cos(2 pi f x + phi) = Re sum amp e^{i phi} e^{2 pi i k j / n}
    left[k] = a;
    right[k] = gamma * a + std::sqrt(1.0 - gamma * gamma) * b;
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> zl, zr;
  fft.inv(zl, left);
  fft.inv(zr, right);
  RoadProfile r;
  r.x.resize(n);
  r.z_left.resize(n);
  r.z_right.resize(n);
  for (int j = 0; j < n; ++j) {
    // Eigen's inverse FFT divides by n
    r.x[j] = j * o.dx;
    r.z_left[j] = n * zl[j].real();
    r.z_right[j] = n * zr[j].real();
  }
  return r;
}

RoadProfile ReadRoadCsv(const std::string& path) {
  const NumberTable table = ReadNumberTable(path, 3, "road file", "x, z_left, z_right");
  RoadProfile r;
  for (size_t k = 0; k < table.rows.size(); ++k) {
    const std::vector<double>& v = table.rows[k];
    if (!r.x.empty() && !(v[0] > r.x.back())) {
      throw InputError("road file: x not increasing (" + RoadNumber(v[0]) + " after " + RoadNumber(r.x.back()) + ")",
                       {path, table.lines[k], ""});
    }
    r.x.push_back(v[0]);
    r.z_left.push_back(v[1]);
    r.z_right.push_back(v[2]);
  }
  if (r.x.size() < 2) throw InputError("road file: fewer than two points", {path, 0, ""});
  return r;
}

}  // namespace flexmb::vehicle
