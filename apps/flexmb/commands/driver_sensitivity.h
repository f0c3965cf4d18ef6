#pragma once
/// \file driver_sensitivity.h
/// `flexmb truck driver-sensitivity`: how much of the lane change's result
/// is the truck and how much the driver. The highest passing entry speed
/// (MaxPassSpeed, bisection) with the file's driver, then with each varied
/// driver setting (one at a time, the others as in the file) at each of its
/// values; the spread of these speeds is what the driver model moves.

#include <cstdio>
#include <string>
#include <vector>

#include "apps/flexmb/commands/lane_change.h"

namespace flexmb::vehicle {

/// One driver setting and the values it takes (the file's units).
struct DriverVariation {
  std::string key;              ///< a numeric key of the driver section (SetDriverSetting)
  std::vector<double> values;   ///< values tried
};

/// What a sensitivity study should do.
struct DriverSensitivityOptions {
  LaneChangeOptions base;       ///< the file, the frame (out_dir, speed and driver_settings unused)
  std::vector<DriverVariation> vary;  ///< settings varied one at a time
  double low = 20.0;            ///< lowest entry speed tried [km/h]
  double high = 90.0;           ///< highest entry speed tried [km/h]
  double tol = 1.0;             ///< bisection tolerance [km/h]
  std::string out_dir;          ///< sensitivity.csv and summary.json; empty: write nothing
  std::FILE* info = nullptr;    ///< the table and the trials (nullptr: silent)
};

/// The highest passing speed with one setting changed.
struct DriverSensitivityRow {
  std::string key;
  double value = 0.0;           ///< the setting's value (file units)
  double file_value = 0.0;      ///< its value in the file
  double max_pass_kmh = 0.0;    ///< highest passing entry speed [km/h]; `low` when even low fails
  bool low_passed = false;      ///< the test passed at `low`
};

/// Outcome of the study.
struct DriverSensitivityResult {
  double base_kmh = 0.0;        ///< highest passing speed with the file's driver [km/h]
  bool base_low_passed = false;
  std::vector<DriverSensitivityRow> rows;  ///< per setting and value, in the order given
  double min_kmh = 0.0, max_kmh = 0.0;     ///< over the base and all rows [km/h]
  std::string frame;            ///< "rigid" or "elastic": the frame the study ran with
};

/// Runs the study: one bisection per value (each trial stops at the first
/// corridor exit or lift-off; an elastic frame is reduced once). Throws
/// InputError for an unknown key, no values, a bad speed range, or a value
/// the driver rejects (before any run).
DriverSensitivityResult RunDriverSensitivity(const DriverSensitivityOptions& options);

/// The study as JSON text (summary.json): the options' file, range and
/// tolerance, the base speed, the range of all speeds and each row.
std::string DriverSensitivityJson(const DriverSensitivityOptions& options, const DriverSensitivityResult& result);

/// Parses a --vary option "KEY=V1,V2,..." (numbers); throws InputError.
DriverVariation ParseDriverVariation(const std::string& text);

}  // namespace flexmb::vehicle
