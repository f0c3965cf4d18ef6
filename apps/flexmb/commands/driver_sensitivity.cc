#include "apps/flexmb/commands/driver_sensitivity.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "flexmb/common/error.h"
#include "flexmb/common/json_text.h"
#include "flexmb/vehicle/lane_change_course.h"

namespace flexmb::vehicle {

DriverVariation ParseDriverVariation(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--vary '" + text + "': expected KEY=V1,V2,... (e.g. reaction_delay=0,0.1,0.2)");
  DriverVariation v;
  v.key = text.substr(0, eq);
  DriverData probe;
  SetDriverSetting(probe, v.key, 0.0);  // an unknown key names the valid ones
  const std::string list = text.substr(eq + 1);
  size_t at = 0;
  while (at <= list.size()) {
    const size_t comma = std::min(list.find(',', at), list.size());
    const std::string item = list.substr(at, comma - at);
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || errno != 0 || !std::isfinite(x))
      throw InputError("--vary '" + text + "': '" + item + "' is not a number");
    v.values.push_back(x);
    at = comma + 1;
  }
  return v;
}

std::string DriverSensitivityJson(const DriverSensitivityOptions& opt, const DriverSensitivityResult& r) {
  std::string j = "{\n";
  j += "  \"file\": " + io::JsonString(opt.base.file) + ",\n";
  j += "  \"frame\": " + io::JsonString(r.frame) + ",\n";
  j += "  \"low_kmh\": " + io::JsonNumber(opt.low) + ",\n  \"high_kmh\": " + io::JsonNumber(opt.high) +
       ",\n  \"tolerance_kmh\": " + io::JsonNumber(opt.tol) + ",\n";
  j += "  \"base_max_pass_speed_kmh\": " + io::JsonNumber(r.base_kmh) + ",\n";
  j += std::string("  \"base_low_passed\": ") + (r.base_low_passed ? "true" : "false") + ",\n";
  j += "  \"min_max_pass_speed_kmh\": " + io::JsonNumber(r.min_kmh) + ",\n";
  j += "  \"max_max_pass_speed_kmh\": " + io::JsonNumber(r.max_kmh) + ",\n";
  j += "  \"driver_spread_kmh\": " + io::JsonNumber(r.max_kmh - r.min_kmh) + ",\n";
  j += "  \"settings\": [";
  for (size_t k = 0; k < r.rows.size(); ++k) {
    const DriverSensitivityRow& row = r.rows[k];
    j += std::string(k ? "," : "") + "\n    {\"key\": " + io::JsonString(row.key) + ", \"value\": " +
         io::JsonNumber(row.value) + ", \"file_value\": " + io::JsonNumber(row.file_value) +
         ", \"max_pass_speed_kmh\": " + io::JsonNumber(row.max_pass_kmh) +
         ", \"low_passed\": " + (row.low_passed ? "true" : "false") + "}";
  }
  j += "\n  ]\n}\n";
  return j;
}

DriverSensitivityResult RunDriverSensitivity(const DriverSensitivityOptions& opt) {
  if (!(opt.low > 0) || !(opt.high > opt.low) || !(opt.tol > 0))
    throw InputError("driver-sensitivity: need 0 < low < high and tol > 0");
  if (opt.vary.empty()) throw InputError("driver-sensitivity: nothing to vary (give --vary KEY=V1,V2,...)");
  const TruckFileSettings file = LoadTruckFileSettings(opt.base.file);
  // every value checked by the driver before the first run
  const LaneChangeCourse course(LaneChangeCourseData{});
  for (const DriverVariation& v : opt.vary) {
    if (v.values.empty()) throw InputError("driver-sensitivity: no values for '" + v.key + "'");
    for (double x : v.values) {
      DriverData d = file.driver;
      SetDriverSetting(d, v.key, x);
      try {
        Driver check(d, course, 10.0);
      } catch (const InputError& e) {
        throw InputError("driver-sensitivity: " + v.key + " = " + io::JsonNumber(x) + ": " + e.what());
      }
    }
  }
  LaneChangeOptions base = opt.base;
  base.out_dir.clear();
  base.driver_settings.clear();
  if (!base.frame_body && base.frame.value_or(file.frame) == "elastic")
    base.frame_body = ReduceTruckFrame(file.truck, LaneChangeFrameReduction(base.file));

  DriverSensitivityResult r;
  r.frame = base.frame.value_or(file.frame);
  if (opt.info) std::fprintf(opt.info, "the file's driver:\n");
  r.base_kmh = MaxPassSpeed(base, opt.low, opt.high, opt.tol, opt.info, &r.base_low_passed);
  r.min_kmh = r.max_kmh = r.base_kmh;
  for (const DriverVariation& v : opt.vary)
    for (double x : v.values) {
      DriverSensitivityRow row;
      row.key = v.key;
      row.value = x;
      row.file_value = GetDriverSetting(file.driver, v.key);
      LaneChangeOptions o = base;
      o.driver_settings = {{v.key, x}};
      if (opt.info) std::fprintf(opt.info, "%s = %g:\n", v.key.c_str(), x);
      row.max_pass_kmh = MaxPassSpeed(o, opt.low, opt.high, opt.tol, opt.info, &row.low_passed);
      r.min_kmh = std::min(r.min_kmh, row.max_pass_kmh);
      r.max_kmh = std::max(r.max_kmh, row.max_pass_kmh);
      r.rows.push_back(row);
    }

  if (opt.info) {
    std::fprintf(opt.info, "\nhighest passing entry speed (bisection to %g km/h in [%g, %g]):\n", opt.tol, opt.low,
                 opt.high);
    std::fprintf(opt.info, "  %-26s %10s %14s %10s\n", "setting", "value", "speed [km/h]", "change");
    std::fprintf(opt.info, "  %-26s %10s %14.2f %10s\n", "the file's driver", "", r.base_kmh, "");
    for (const DriverSensitivityRow& row : r.rows)
      std::fprintf(opt.info, "  %-26s %10g %14.2f %+10.2f%s\n", row.key.c_str(), row.value, row.max_pass_kmh,
                   row.max_pass_kmh - r.base_kmh, row.low_passed ? "" : "  (fails even at the lowest speed)");
    std::fprintf(opt.info, "the driver settings move the highest passing speed between %.2f and %.2f km/h (%.2f km/h)\n",
                 r.min_kmh, r.max_kmh, r.max_kmh - r.min_kmh);
  }
  if (!opt.out_dir.empty()) {
    std::filesystem::create_directories(opt.out_dir);
    const std::string csv_path = (std::filesystem::path(opt.out_dir) / "sensitivity.csv").string();
    std::FILE* csv = std::fopen(csv_path.c_str(), "w");
    if (!csv) throw InputError("cannot open the results file for writing", {csv_path, 0, ""});
    std::fprintf(csv, "key,value,file_value,max_pass_speed_kmh,low_passed,change_kmh\n");
    for (const DriverSensitivityRow& row : r.rows)
      std::fprintf(csv, "%s,%.15g,%.15g,%.15g,%d,%.15g\n", row.key.c_str(), row.value, row.file_value,
                   row.max_pass_kmh, row.low_passed ? 1 : 0, row.max_pass_kmh - r.base_kmh);
    std::fclose(csv);
    const std::string json_path = (std::filesystem::path(opt.out_dir) / "summary.json").string();
    std::FILE* js = std::fopen(json_path.c_str(), "w");
    if (!js) throw InputError("cannot open the summary file for writing", {json_path, 0, ""});
    std::fputs(DriverSensitivityJson(opt, r).c_str(), js);
    std::fclose(js);
  }
  return r;
}

}  // namespace flexmb::vehicle
