// IFToMM benchmark A01 (simple pendulum), run from examples/pendulum_a01:
// the official reference data, energy conservation, the exact period from
// the complete elliptic integral, and the command line on the same file.
// References and measured values: docs/validation.md, "IFToMM A01".

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "example_model.h"

namespace flexmb::validation {
namespace pendulum_a01_test {

// x, y of P1 [m] from the official A01_solution_data.txt (6 digits), copied
// from the notes in docs/notes/benchmark-references.md section 1.
struct RefPoint {
  double t, x, y;
};
constexpr RefPoint kReference[] = {
    {0.5, -3.91049e-01, -9.20370e-01},  {1.0, 9.86292e-01, -1.65011e-01},
    {2.0, -7.93566e-01, -6.08484e-01},  {5.0, -9.42305e-01, -3.34754e-01},
    {10.0, -2.75087e-01, -9.61419e-01}, {1995.0, 9.99094e-01, -4.25533e-02},
    {2000.0, 8.14603e-01, -5.80019e-01}};

// complete elliptic integral of the first kind K(k) (modulus k) by the
// arithmetic-geometric mean, K = pi / (2 AGM(1, sqrt(1 - k^2)))
double EllipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 30; ++i) {
    const double an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
  }
  return std::numbers::pi / (2.0 * a);
}

TEST(IftommA01, ReferenceDataOver2000sAndEnergy) {
  auto model = LoadExample("pendulum_a01");
  ASSERT_DOUBLE_EQ(model->solver.t_end, 2000.0);
  Simulator sim(*model);
  const ConstraintReport& rep = sim.Initialize();
  // planar pin in 3D: 5 independent equations, 1 degree of freedom
  EXPECT_EQ(rep.dof, 1);
  EXPECT_TRUE(rep.redundant.empty());
  SensorValue x(*model, "p1", "x"), y(*model, "p1", "y"), e(*model, "energy", "total");
  const double e0 = e(sim.state(), sim.workspace());
  EXPECT_NEAR(e0, 0.0, 1e-12);  // at rest at the height of the pivot
  double max_de = 0.0, max_de_bodies = 0.0, err_short = 0.0, err_long = 0.0;
  int hits = 0;
  sim.Run(model->solver.t_end, model->output.interval, [&](const State& s, const Workspace& ws) {
    max_de = std::max(max_de, std::abs(e(s, ws) - e0));
    max_de_bodies = std::max(max_de_bodies, std::abs(BodyEnergy(*model, s)));
    for (const RefPoint& r : kReference) {
      if (std::abs(s.t - r.t) > 1e-6) continue;
      ++hits;
      const double err = std::max(std::abs(x(s, ws) - r.x), std::abs(y(s, ws) - r.y));
      (r.t <= 10.0 ? err_short : err_long) = std::max(r.t <= 10.0 ? err_short : err_long, err);
    }
  });
  EXPECT_EQ(hits, 7);
  // the benchmark's high-precision limit (1e-3) up to 10 s (measured 1.4e-4)
  EXPECT_LT(err_short, 1e-3);
  // its low-precision limit (1e-1) at 1995 s and 2000 s: the O(h^2) phase
  // error of 845 periods at h = 1 ms (measured 1.8e-2)
  EXPECT_LT(err_long, 1e-1);
  // energy: bounded O(h^2) oscillation, no drift (measured 7.5e-5 J)
  EXPECT_LT(max_de, 2e-4);
  EXPECT_NEAR(max_de_bodies, max_de, 1e-12);
  std::printf("A01: max error <= 10 s %.3e m, at 1995/2000 s %.3e m, max |E - E0| %.3e J\n",
              err_short, err_long, max_de);
}

TEST(IftommA01, PeriodMatchesEllipticIntegral) {
  auto model = LoadExample("pendulum_a01");
  Simulator sim(*model);
  sim.Initialize();
  SensorValue x(*model, "p1", "x");
  // times at which P1 passes under the pivot moving in +x (once per period)
  std::vector<double> crossings;
  double t_prev = 0.0, x_prev = -1.0;
  sim.Run(12.0, 0.0, [&](const State& s, const Workspace& ws) {
    const double xs = x(s, ws);
    if (s.t > 0 && x_prev < 0 && xs >= 0) crossings.push_back(t_prev + (s.t - t_prev) * (-x_prev) / (xs - x_prev));
    t_prev = s.t;
    x_prev = xs;
  });
  ASSERT_GE(crossings.size(), 4u);
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  // T = 4 sqrt(L/g) K(sin(theta0/2)), theta0 = 90 degrees
  const double k = std::sin(std::numbers::pi / 4);
  EXPECT_NEAR(EllipticK(k), 1.854074677301371918, 1e-15);  // OEIS A093341
  const double exact = 4.0 * std::sqrt(1.0 / 9.81) * EllipticK(k);
  EXPECT_NEAR(exact, 2.367841947576237449, 1e-14);
  // measured relative error 3.3e-6 at h = 1 ms (second order in h)
  EXPECT_NEAR(period / exact - 1.0, 0.0, 1e-5);
  std::printf("A01: period %.10f s, exact %.10f s, relative error %.2e\n", period, exact,
              period / exact - 1.0);
}

// the same file through the command line: results.csv columns and values
TEST(IftommA01, CommandLineResults) {
  namespace fs = std::filesystem;
  const fs::path out = fs::path(::testing::TempDir()) / "flexmb_a01_cli";
  fs::remove_all(out);
  const std::string cmd = std::string(FLEXMB_CLI) + " run " + FLEXMB_SOURCE_DIR +
                          "/examples/pendulum_a01/model.yaml --out " + out.string() +
                          " --t-end 10 --quiet";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream csv(out / "results.csv");
  ASSERT_TRUE(csv.good());
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> header;
  {
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) header.push_back(c);
  }
  auto column = [&](const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    ADD_FAILURE() << "no column " << name << " in results.csv";
    return 0;
  };
  const int ct = column("time"), cx = column("p1.x"), cy = column("p1.y");
  int rows = 0, hits = 0;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) v.push_back(std::stod(c));
    ++rows;
    for (const RefPoint& r : kReference) {
      if (std::abs(v[ct] - r.t) > 1e-6) continue;
      ++hits;
      EXPECT_NEAR(v[cx], r.x, 1e-3) << "t = " << r.t;
      EXPECT_NEAR(v[cy], r.y, 1e-3) << "t = " << r.t;
    }
  }
  EXPECT_EQ(rows, 21);  // t = 0, 0.5, ..., 10
  EXPECT_EQ(hits, 5);
  std::ifstream js(out / "summary.json");
  std::stringstream summary;
  summary << js.rdbuf();
  EXPECT_NE(summary.str().find("\"ok\""), std::string::npos) << summary.str();
}

}  // namespace pendulum_a01_test
}  // namespace flexmb::validation
