// Magic Formula .tir property files (vehicle/tir_file.h): every mapped key
// lands in its TireData member with the value worked out by hand from the MF
// equations (docs/model-file.md, "Tire property files"); the Tire built from
// the file gives bit for bit the wrench of the Tire built from the same
// values written as TireData; unused non-neutral keys are listed and warned
// by LoadTireFile; errors name the file, the line and the key.

#include "flexmb/vehicle/tir_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/vehicle/truck.h"

namespace flexmb::vehicle {
namespace tir_file_test {

// a property file in the MF 5.2 (PAC2002) layout with every mapped key,
// comments of both kinds, quoted strings, C number formats and a table
const char* const kTirText = R"(
[MDI_HEADER]
FILE_TYPE                = 'tir'
FILE_VERSION             = 3.0
! : TIRE_VERSION : PAC2002
$----------------------------------------------------------------units
[UNITS]
LENGTH                   = 'meter'
FORCE                    = 'newton'
ANGLE                    = 'radians'
MASS                     = 'kg'
TIME                     = 'second'
[MODEL]
PROPERTY_FILE_FORMAT     = 'PAC2002'
TYRESIDE                 = 'LEFT'      $ a string: never listed
[INERTIA]
MASS                     = 0                   $ MASS of [UNITS] again: MF 6.1 files do so
[DIMENSION]
UNLOADED_RADIUS          = 0.5         $Free tyre radius
WIDTH                    = 0.2
[SHAPE]
{radial width}
 1.0    0.0
 0.9    1.0
[VERTICAL]
VERTICAL_STIFFNESS       = 2.0E+05     $Tyre vertical stiffness
VERTICAL_DAMPING         = 5e2
FNOMIN                   = 4000.0      ! nominal wheel load

[SCALING_COEFFICIENTS]
LMUX                     = 1
LKY                      = 0.9
[LONGITUDINAL_COEFFICIENTS]
PCX1                     = 1.6
PDX1                     = 1.25
PDX2                     = -0.25
PDX3                     = 0.1
PEX1                     = +0.5
PEX2                     = 0
PKX1                     = 20
PHX1                     = 0.002
RBX1                     = 10
RCX1                     = 1
PTX1                     = 0.8
[LATERAL_COEFFICIENTS]
PCY1                     = 1.3
PDY1                     = 0.5
PDY2                     = -0.125
PEY1                     = -0.5
PKY1                     = -12
PKY2                     = 1.5
PKY4                     = 2
RBY1                     = 8
PTY1                     = 2
PTY2                     = 1
[ROLLING_COEFFICIENTS]
QSY1                     = 0.01
[ALIGNING_COEFFICIENTS]
QBZ1                     = 9
QDZ1                     = 0.1
)";

std::string TirWrite(const std::string& name, const std::string& text) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() / ("flexmb_tir_file_" + name);
  std::ofstream(p) << text;
  return p.string();
}

// the values of kTirText as TireData, mapped by hand
TireData TirHandData() {
  TireData d;
  d.unloaded_radius = 0.5;
  d.vertical_stiffness = 2.0e5;
  d.vertical_damping = 500.0;
  d.nominal_load = 4000.0;
  d.pcx1 = 1.6;
  d.pdx1 = 1.25;
  d.pdx2 = -0.2;  // PDX2 / PDX1
  d.pex1 = 0.5;
  d.pkx1 = 20.0;
  d.pcy1 = 1.3;
  d.pdy1 = 0.5;
  d.pdy2 = -0.25;  // PDY2 / PDY1
  d.pey1 = -0.5;
  d.pky1 = 12.0;  // -PKY1
  d.pky2 = 1.5;
  d.rbx1 = 10.0;
  d.rby1 = 8.0;
  d.rolling_resistance = 0.01;
  d.trail = 0.05;        // QDZ1 R0
  d.trail_decay = 9.0;   // QBZ1
  d.relaxation_length = 1.0;                // PTY1 sin(2 atan(1 / PTY2)) R0 = 2 sin(pi / 2) 0.5
  d.longitudinal_relaxation_length = 0.4;   // PTX1 R0
  return d;
}

TEST(TirFile, MappedKeysGiveTheHandValues) {
  const TirFile f = ReadTirFile(TirWrite("mapped.tir", kTirText));
  const TireData& d = f.data;
  const TireData h = TirHandData();
  EXPECT_EQ(d.count, 1);
  EXPECT_EQ(d.unloaded_radius, h.unloaded_radius);
  EXPECT_EQ(d.vertical_stiffness, h.vertical_stiffness);
  EXPECT_EQ(d.vertical_damping, h.vertical_damping);
  EXPECT_EQ(d.nominal_load, h.nominal_load);
  EXPECT_EQ(d.pcx1, h.pcx1);
  EXPECT_EQ(d.pdx1, h.pdx1);
  EXPECT_EQ(d.pdx2, h.pdx2);
  EXPECT_EQ(d.pex1, h.pex1);
  EXPECT_EQ(d.pkx1, h.pkx1);
  EXPECT_EQ(d.pcy1, h.pcy1);
  EXPECT_EQ(d.pdy1, h.pdy1);
  EXPECT_EQ(d.pdy2, h.pdy2);
  EXPECT_EQ(d.pey1, h.pey1);
  EXPECT_EQ(d.pky1, h.pky1);
  EXPECT_EQ(d.pky2, h.pky2);
  EXPECT_EQ(d.rbx1, h.rbx1);
  EXPECT_EQ(d.rby1, h.rby1);
  EXPECT_EQ(d.rolling_resistance, h.rolling_resistance);
  EXPECT_EQ(d.trail, h.trail);
  EXPECT_EQ(d.trail_decay, h.trail_decay);
  EXPECT_DOUBLE_EQ(d.relaxation_length, h.relaxation_length);
  EXPECT_EQ(d.longitudinal_relaxation_length, h.longitudinal_relaxation_length);
  // members without a .tir key keep their defaults
  EXPECT_EQ(d.rolling_radius_factor, TireData().rolling_radius_factor);
  EXPECT_EQ(d.low_speed, TireData().low_speed);
  EXPECT_EQ(d.patch_mass, TireData().patch_mass);
  // unused keys with values other than neutral, in file order; LMUX = 1,
  // PEX2 = 0, RCX1 = 1, PKY4 = 2 and the strings are neutral
  const std::vector<std::string> ignored = {"WIDTH", "[SHAPE]", "LKY", "PDX3", "PHX1"};
  EXPECT_EQ(f.ignored, ignored);
}

// MF-Tyre 5.0 files write PDY1 < 0: Fy = Dy sin(Cy atan(By a ...)) with
// By = Ky / (Cy Dy) is unchanged when Dy changes sign, so the magnitude maps
TEST(TirFile, NegativePeakFrictionMapsToItsMagnitude) {
  std::string text = kTirText;
  text.replace(text.find("= 0.5\nPDY2"), 5, "= -0.5");
  text.replace(text.find("= -0.125"), 8, "= 0.125");
  const TireData d = ReadTirFile(TirWrite("negative_pdy1.tir", text)).data;
  EXPECT_EQ(d.pdy1, 0.5);
  EXPECT_EQ(d.pdy2, -0.25);
}

TEST(TirFile, TireFromTheFileGivesTheWrenchOfTheSameTireData) {
  const TireData h = TirHandData();
  const Tire from_file("f", ReadTirFile(TirWrite("wrench.tir", kTirText)).data, 0.9);
  const Tire from_data("d", h, 0.9);
  // wheel centre 2 cm below R0, spin axis (marker z) along world +y
  Mat3 R;
  R << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  const Vec3 p(0.0, 0.0, 0.48);
  struct SlipState {
    Vec3 v;
    double omega;
  };
  const std::vector<SlipState> states = {
      {Vec3(10, 0, 0), 20.0}, {Vec3(10, 0.4, 0), 21.5}, {Vec3(8, -1.5, 0.1), 15.0}, {Vec3(-3, 0.2, 0), -5.0}};
  for (const SlipState& s : states) {
    TireContact c;
    const Vec6 a = from_file.Wrench(p, R, s.v, Vec3(0, s.omega, 0), &c);
    const Vec6 b = from_data.Wrench(p, R, s.v, Vec3(0, s.omega, 0), nullptr);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(a[k], b[k]) << "component " << k << " at v = " << s.v.transpose();
    EXPECT_GT(c.fz, 0.0);
  }
  // the states slip: the wrench is not trivially equal
  TireContact c;
  from_file.Wrench(p, R, states[1].v, Vec3(0, states[1].omega, 0), &c);
  EXPECT_NE(c.fx, 0.0);
  EXPECT_NE(c.fy, 0.0);
}

// MF 5.2 pure-slip forces in the ISO sign convention of the file, written
// from Pacejka, 3rd ed., sec. 4.3.2 with the file's coefficients as they
// stand (PKY1 < 0), shifts, camber and scaling neutral, times the combined
// slip weights G = cos(atan(RB*1 slip)) (RC*1 = 1)
TEST(TirFile, ForcesFollowTheMagicFormulaInIsoSigns) {
  const Tire tire("f", ReadTirFile(TirWrite("iso.tir", kTirText)).data, 1.0);
  Mat3 R;
  R << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  auto mf = [](double x, double b, double c, double d, double e) {
    return d * std::sin(c * std::atan(b * x - e * (b * x - std::atan(b * x))));
  };
  const double fz0 = 4000.0;
  for (const Vec3& v : {Vec3(10, 0.6, 0), Vec3(10, -0.3, 0), Vec3(6, 1.2, 0)}) {
    for (double omega : {20.4, 21.0, 19.0}) {
      TireContact c;
      tire.Wrench(Vec3(0, 0, 0.485), R, v, Vec3(0, omega, 0), &c);
      const double fz = c.fz, dfz = (fz - fz0) / fz0;
      const double dx = (1.25 - 0.25 * dfz) * fz, kx = 20.0 * fz;
      const double dy = (0.5 - 0.125 * dfz) * fz, ky = -12.0 * fz0 * std::sin(2.0 * std::atan(fz / (1.5 * fz0)));
      const double fx = mf(c.kappa, kx / (1.6 * dx), 1.6, dx, 0.5) * std::cos(std::atan(10.0 * c.alpha));
      const double fy = mf(c.alpha, ky / (1.3 * dy), 1.3, dy, -0.5) * std::cos(std::atan(8.0 * c.kappa));
      EXPECT_NEAR(c.fx, fx, 1e-12 * fz) << v.transpose() << " " << omega;
      EXPECT_NEAR(c.fy, fy, 1e-12 * fz) << v.transpose() << " " << omega;
      // a side slip velocity to the left (ISO alpha > 0) gives a force to the right
      EXPECT_EQ(c.alpha > 0, c.fy < 0);
    }
  }
}

TEST(TirFile, LoadTireFileReadsTirAndWarnsOfIgnoredKeys) {
  std::vector<std::string> warnings;
  const LogSink old = SetWarningSink([&](const std::string& m) { warnings.push_back(m); });
  const std::string path = TirWrite("load.tir", kTirText);
  const TireData d = LoadTireFile(path);
  SetWarningSink(old);
  EXPECT_EQ(d.pky1, 12.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find(path), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("WIDTH, [SHAPE], LKY, PDX3, PHX1"), std::string::npos) << warnings[0];
}

// the InputError of reading `text`: its file must be the written file
InputError TirError(const std::string& name, const std::string& text) {
  const std::string path = TirWrite(name, text);
  try {
    ReadTirFile(path);
  } catch (const InputError& e) {
    EXPECT_EQ(e.context().file, path) << e.what();
    return e;
  }
  ADD_FAILURE() << name << ": no error";
  return InputError("no error");
}

// kTirText with the line starting with `key` replaced by `line`
std::string TirReplace(const std::string& key, const std::string& line) {
  std::string s = kTirText;
  const auto at = s.find("\n" + key + " ");
  EXPECT_NE(at, std::string::npos) << key;
  const auto end = s.find('\n', at + 1);
  return s.replace(at + 1, end - at - 1, line);
}

// 1-based line of kTirText that starts with `key`
int TirLineOf(const std::string& key) {
  const std::string s = kTirText;
  const auto at = s.find("\n" + key + " ");
  return 2 + static_cast<int>(std::count(s.begin(), s.begin() + static_cast<long>(at), '\n'));
}

TEST(TirFile, ErrorsNameFileLineAndKey) {
  const InputError units = TirError("units.tir", TirReplace("LENGTH", "LENGTH = 'mm'"));
  EXPECT_EQ(units.context().line, TirLineOf("LENGTH"));
  EXPECT_NE(std::string(units.what()).find("LENGTH"), std::string::npos) << units.what();
  EXPECT_NE(std::string(units.what()).find("not SI"), std::string::npos) << units.what();
  const InputError force = TirError("force.tir", TirReplace("FORCE", "FORCE = 'kN'"));
  EXPECT_EQ(force.context().line, TirLineOf("FORCE"));

  const InputError malformed = TirError("malformed.tir", TirReplace("PCX1", "PCX1 1.6"));
  EXPECT_EQ(malformed.context().line, TirLineOf("PCX1"));
  EXPECT_NE(std::string(malformed.what()).find("PCX1 1.6"), std::string::npos) << malformed.what();

  const InputError nan = TirError("not_number.tir", TirReplace("PKX1", "PKX1 = 2O.5"));
  EXPECT_EQ(nan.context().line, TirLineOf("PKX1"));
  EXPECT_NE(std::string(nan.what()).find("PKX1"), std::string::npos) << nan.what();

  const InputError missing = TirError("missing.tir", TirReplace("FNOMIN", "$ no nominal load"));
  EXPECT_NE(std::string(missing.what()).find("FNOMIN"), std::string::npos) << missing.what();

  const InputError duplicate = TirError("duplicate.tir", std::string(kTirText) + "PDY1 = 0.6\n");
  EXPECT_EQ(duplicate.context().line, TirLineOf("QDZ1") + 1);
  EXPECT_NE(std::string(duplicate.what()).find("PDY1"), std::string::npos) << duplicate.what();
  EXPECT_NE(std::string(duplicate.what()).find("line " + std::to_string(TirLineOf("PDY1"))), std::string::npos)
      << duplicate.what();

  const InputError sign = TirError("sign.tir", TirReplace("PKY1", "PKY1 = 12"));
  EXPECT_EQ(sign.context().line, TirLineOf("PKY1"));
  EXPECT_NE(std::string(sign.what()).find("negative"), std::string::npos) << sign.what();

  const InputError quote = TirError("quote.tir", TirReplace("TYRESIDE", "TYRESIDE = 'LEFT"));
  EXPECT_EQ(quote.context().line, TirLineOf("TYRESIDE"));
}

}  // namespace tir_file_test
}  // namespace flexmb::vehicle
