// Units of body files (body_file/unit_system.h): the known systems are consistent
// (their force and stress units, derived from length, mass and time, are
// the ones they name: N = kg m / s^2 by definition), the attribute text reads
// back to its system, a body file in mm-t-s used in an (SI) model is refused
// naming the body file, both systems, the model file and the body, a body
// file without a recorded system loads with a warning, and the plausibility
// check warns about a body whose numbers look like mm-t-s (a truck frame of
// 8000 "m", density 7.85e-9) and not about the same frame in SI.

#include "flexmb/body_file/unit_system.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/model/model.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb::io {
namespace {

namespace fs = std::filesystem;

TEST(UnitSystem, KnownSystemsNameTheirDerivedUnits) {
  // force [N] and stress [Pa] units each system's attribute names
  struct Expected {
    const char* key;
    double force_n, stress_pa;
  };
  const Expected expected[] = {{"SI", 1.0, 1.0},         {"mm-t-s", 1.0, 1e6},   {"mm-kg-ms", 1e3, 1e9},
                               {"mm-kg-s", 1e-3, 1e3},   {"mm-g-ms", 1.0, 1e6},  {"cm-g-s", 1e-5, 0.1},
                               {"in-lbf-s", 4.4482216152605, 4.4482216152605 / (0.0254 * 0.0254)}};
  ASSERT_EQ(KnownUnitSystems().size(), std::size(expected));
  for (const Expected& e : expected) {
    const UnitSystem* u = FindUnitSystem(e.key);
    ASSERT_NE(u, nullptr) << e.key;
    const double force = u->mass_kg * u->length_m / (u->time_s * u->time_s);
    EXPECT_NEAR(force, e.force_n, 1e-12 * e.force_n) << e.key;
    EXPECT_NEAR(force / (u->length_m * u->length_m), e.stress_pa, 1e-12 * e.stress_pa) << e.key;
    // the attribute text written to a body file reads back to the same system
    EXPECT_EQ(FindUnitSystem(u->attribute), u) << u->attribute;
  }
  EXPECT_EQ(FindUnitSystem("si"), &SiUnits());
  EXPECT_EQ(FindUnitSystem(""), nullptr);
  EXPECT_EQ(FindUnitSystem("unknown"), nullptr);
  EXPECT_EQ(FindUnitSystem("mm, t, s, N, MPa"), nullptr);
  try {
    ParseUnitsOption("furlong-firkin-fortnight");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("furlong-firkin-fortnight"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mm-t-s"), std::string::npos) << e.what();
  }
}

// a frame-like body: nodes spanning `size` along x, one material, total mass `mass`
reduction::ReducedBody UnitsFrame(double size, double rho, double mass) {
  reduction::ReducedBody b;
  for (int k = 0; k < 3; ++k) {
    fe::Node n;
    n.id = k + 1;
    n.x = fe::Vec3(size * k / 2.0, 0.1 * size * (k % 2), 0.0);
    b.mesh.nodes.push_back(n);
  }
  fe::Material m;
  m.id = 3;
  m.E = 2.1e11;
  m.rho = rho;
  b.mesh.materials.push_back(m);
  b.invariants.mvv = mass * Mat3::Identity();
  return b;
}

TEST(UnitSystem, PlausibilityWarnsAboutMillimetreTonneNumbers) {
  // an 8 m, 500 kg steel frame in SI: no warning
  EXPECT_TRUE(UnitPlausibilityWarnings(UnitsFrame(8.0, 7850.0, 500.0), "frame.h5").empty());
  // the same in mm-t-s: density, size and mass per size all warn, naming the file
  const std::vector<std::string> w = UnitPlausibilityWarnings(UnitsFrame(8000.0, 7.85e-9, 0.5), "frame.h5");
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NE(w[0].find("material 3 has the density 7.85e-09"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("8000 long"), std::string::npos) << w[1];
  EXPECT_NE(w[2].find("implausible in kg/m^3"), std::string::npos) << w[2];
  for (const std::string& s : w) EXPECT_NE(s.find("frame.h5"), std::string::npos) << s;
  // a 100 mm part in mm-kg-s (size plausible as metres, mass per size not)
  EXPECT_EQ(UnitPlausibilityWarnings(UnitsFrame(100.0, 0.0, 1.0), "part.h5").size(), 1u);
}

struct UnitsFolder {
  fs::path dir;
  UnitsFolder() {
    dir = fs::temp_directory_path() / ("flexmb_units_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  ~UnitsFolder() { fs::remove_all(dir); }
  // bar.h5 with the units attribute `units` and a model file using it
  std::string Model(const std::string& units) const {
    reduction::ReducedBody body = *flexmb::testing::FreeBentBar(3, 3);
    body.units = units;
    WriteBody(body, (dir / "bar.h5").string());
    const fs::path p = dir / "model.yaml";
    std::ofstream(p) << "gravity: [0, 0, -9.81]\n"
                        "bodies:\n"
                        "  - name: bar\n"
                        "    type: flexible\n"
                        "    file: bar.h5\n";
    return p.string();
  }
};

TEST(UnitSystem, ModelRefusesBodyFileInOtherUnits) {
  const UnitsFolder f;
  const std::string model = f.Model(FindUnitSystem("mm-t-s")->attribute);
  try {
    LoadModelFile(model);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const char* part : {"model.yaml:5", "body 'bar'", "bar.h5", "mm-t-s (mm, t, s, N, MPa)",
                             "SI (m, kg, s, N, Pa)", "convert the FE model to SI"})
      EXPECT_NE(msg.find(part), std::string::npos) << part << " in " << msg;
  }
}

TEST(UnitSystem, BodyFileWithoutUnitsLoadsWithAWarning) {
  const UnitsFolder f;
  std::vector<std::string> warnings;
  const LogSink old = SetWarningSink([&](const std::string& w) { warnings.push_back(w); });
  EXPECT_NO_THROW(LoadModelFile(f.Model("")));
  SetWarningSink(old);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("does not record a known unit system"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("bar.h5"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("body 'bar'"), std::string::npos) << warnings[0];
  // SI: no warning
  warnings.clear();
  SetWarningSink([&](const std::string& w) { warnings.push_back(w); });
  EXPECT_NO_THROW(LoadModelFile(f.Model(SiUnits().attribute)));
  SetWarningSink(old);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

}  // namespace
}  // namespace flexmb::io
