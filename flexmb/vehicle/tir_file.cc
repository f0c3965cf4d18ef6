// Reader of Magic Formula `.tir` tire property files into TireData; the key
// mapping is documented in docs/model-file.md ("tire", "Tire property files").

#include "flexmb/vehicle/tir_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "flexmb/common/error.h"
#include "flexmb/common/text.h"

namespace flexmb::vehicle {
namespace {

// one `KEY = value` entry of a .tir file
struct TirEntry {
  int line = 0;
  std::string section;  // upper case, without brackets
  std::string text;     // the value as written, quotes removed
  bool quoted = false;
  bool is_number = false;
  double number = 0.0;
};

std::string TirTrim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r\f\v");
  if (b == std::string_view::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\f\v");
  return std::string(s.substr(b, e - b + 1));
}

std::string TirUpper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// the line without its `$` or `!` comment (a comment character inside quotes stays)
std::string TirStripComment(const std::string& line) {
  char quote = 0;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '$' || c == '!') {
      return line.substr(0, k);
    }
  }
  return line;
}

// a whole-string C number (1.0E+05, -0.1, +3, .5); false otherwise
bool TirParseNumber(const std::string& s, double* value) {
  std::string_view v(s);
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  if (v.empty()) return false;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), *value);
  return r.ec == std::errc() && r.ptr == v.data() + v.size() && std::isfinite(*value);
}

// a table row: numbers separated by blanks
bool TirIsNumberRow(const std::string& s) {
  std::istringstream in(s);
  std::string token;
  double x = 0.0;
  while (in >> token)
    if (!TirParseNumber(token, &x)) return false;
  return true;
}

bool TirIsKey(const std::string& k) {
  if (k.empty() || !(std::isalpha(static_cast<unsigned char>(k[0])) || k[0] == '_')) return false;
  return std::all_of(k.begin(), k.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

[[noreturn]] void TirFail(const std::string& path, int line, const std::string& key, const std::string& message) {
  throw InputError(message, {path, line, key.empty() ? "tire property file" : "key " + key});
}

// accepted SI spellings (lower case) per [UNITS] key
bool TirUnitIsSi(const std::string& key, const std::string& unit) {
  static const std::map<std::string, std::set<std::string>> kTirSiUnits = {
      {"LENGTH", {"meter", "metre", "meters", "metres", "m"}},
      {"FORCE", {"newton", "newtons", "n"}},
      {"ANGLE", {"radian", "radians", "rad"}},
      {"MASS", {"kg", "kilogram", "kilograms"}},
      {"TIME", {"second", "seconds", "s", "sec"}},
      {"PRESSURE", {"pascal", "pa"}}};
  const auto it = kTirSiUnits.find(key);
  if (it == kTirSiUnits.end()) return false;
  std::string u = unit;
  for (char& c : u) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return it->second.count(u) > 0;
}

// value of a coefficient the simplified model does not use that leaves the MF
// equations as the simplified ones (scaling factors 1, shape factors 1, ...)
double TirNeutralValue(const std::string& key, const std::string& section) {
  if (section == "SCALING_COEFFICIENTS") return 1.0;
  if (key == "RCX1" || key == "RCY1" || key == "QCZ1") return 1.0;
  if (key == "PKY4") return 2.0;
  return 0.0;
}

// the parsed file
class TirReader {
 public:
  explicit TirReader(std::string path) : path_(std::move(path)) {}

  void Parse() {
    std::ifstream in(path_);
    if (!in) TirFail(path_, 0, "", "cannot open the tire property file");
    std::string raw, section;
    bool in_table = false;
    int line = 0;
    while (std::getline(in, raw)) {
      ++line;
      const std::string s = TirTrim(TirStripComment(raw));
      if (s.empty()) continue;
      if (s.front() == '[') {
        if (s.back() != ']' || s.size() < 3) TirFail(path_, line, "", "malformed section header '" + s + "'");
        section = TirUpper(TirTrim(std::string_view(s).substr(1, s.size() - 2)));
        in_table = false;
        continue;
      }
      const auto eq = s.find('=');
      if (eq == std::string::npos) {
        // a table (e.g. [SHAPE]: an optional {radial width} header, rows of numbers)
        if (!(s.front() == '{' && s.back() == '}') && !TirIsNumberRow(s))
          TirFail(path_, line, "", "malformed line '" + s + "' (expected KEY = value)");
        if (!in_table) order_.push_back("[" + section + "]");
        in_table = true;
        continue;
      }
      const std::string key = TirUpper(TirTrim(std::string_view(s).substr(0, eq)));
      const std::string value = TirTrim(std::string_view(s).substr(eq + 1));
      if (!TirIsKey(key)) TirFail(path_, line, "", "malformed key in line '" + s + "'");
      if (value.empty()) TirFail(path_, line, key, "no value after '='");
      TirEntry e;
      e.line = line;
      e.section = section;
      if (value.front() == '\'' || value.front() == '"') {
        if (value.size() < 2 || value.back() != value.front())
          TirFail(path_, line, key, "unterminated quoted string " + value);
        e.text = value.substr(1, value.size() - 2);
        e.quoted = true;
      } else {
        e.text = value;
        e.is_number = TirParseNumber(value, &e.number);
      }
      // [UNITS] keys have their own names (MF 6.1 files have MASS in [UNITS] and [INERTIA])
      auto& entries = section == "UNITS" ? units_ : entries_;
      if (const auto it = entries.find(key); it != entries.end())
        TirFail(path_, line, key, "duplicate key (first on line " + std::to_string(it->second.line) + ")");
      entries.emplace(key, e);
      if (section != "UNITS") {
        order_.push_back(key);
      } else if (!TirUnitIsSi(key, e.text)) {
        TirFail(path_, line, key,
                "unit '" + e.text + "' is not SI (meter, newton, radian, kg, second, pascal); convert the file");
      }
    }
    if (const TirEntry* t = Find("FILE_TYPE"); t && TirUpper(t->text) != "TIR")
      TirFail(path_, t->line, "FILE_TYPE", "FILE_TYPE is '" + t->text + "', expected 'tir'");
  }

  const TirEntry* Find(const std::string& key) const {
    const auto it = entries_.find(key);
    return it == entries_.end() ? nullptr : &it->second;
  }

  // the number of `key`, marking it used; InputError when missing or not a number
  double Required(const std::string& key) {
    const TirEntry* e = Find(key);
    if (!e) TirFail(path_, 0, key, "missing required key " + key);
    return Number(key, *e);
  }

  // the number of `key`, or `fallback` when the file has none
  double Optional(const std::string& key, double fallback) {
    const TirEntry* e = Find(key);
    return e ? Number(key, *e) : fallback;
  }

  int LineOf(const std::string& key) const {
    const TirEntry* e = Find(key);
    return e ? e->line : 0;
  }

  // unused keys with non-neutral numeric values (and table sections), in file order
  std::vector<std::string> Ignored() const {
    std::vector<std::string> out;
    for (const std::string& key : order_) {
      if (key.front() == '[') {
        out.push_back(key);
        continue;
      }
      const TirEntry& e = entries_.at(key);
      if (used_.count(key) || e.section == "MDI_HEADER" || !e.is_number) continue;
      if (e.number != TirNeutralValue(key, e.section)) out.push_back(key);
    }
    return out;
  }

  const std::string& path() const { return path_; }

 private:
  double Number(const std::string& key, const TirEntry& e) {
    if (!e.is_number) TirFail(path_, e.line, key, "expected a number, got '" + e.text + "'");
    used_.insert(key);
    return e.number;
  }

  std::string path_;
  std::map<std::string, TirEntry> entries_;
  std::map<std::string, TirEntry> units_;
  std::vector<std::string> order_;
  std::set<std::string> used_;
};

}  // namespace

bool IsTirPath(const std::string& path) { return LowerExtension(path) == ".tir"; }

TirFile ReadTirFile(const std::string& path) {
  TirReader r(path);
  r.Parse();
  TirFile out;
  TireData& d = out.data;
  // required: size, load, vertical stiffness, pure-slip peak, shape and stiffness
  d.unloaded_radius = r.Required("UNLOADED_RADIUS");
  d.nominal_load = r.Required("FNOMIN");
  d.vertical_stiffness = r.Required("VERTICAL_STIFFNESS");
  d.pcx1 = r.Required("PCX1");
  d.pdx1 = r.Required("PDX1");
  d.pkx1 = r.Required("PKX1");
  d.pcy1 = r.Required("PCY1");
  d.pdy1 = r.Required("PDY1");
  const double pky1 = r.Required("PKY1");
  if (!(pky1 < 0))
    TirFail(path, r.LineOf("PKY1"), "PKY1",
            "PKY1 must be negative (the ISO sign convention of TYDEX files, Ky = PKY1 Fz0 ... < 0); "
            "a positive PKY1 means another sign convention, which the reader does not guess");
  // TireData::pky1 is the magnitude: Tire applies Fy0 = -MF(alpha) with alpha = atan(Vsy / V)
  d.pky1 = -pky1;
  d.vertical_damping = r.Optional("VERTICAL_DAMPING", d.vertical_damping);
  // MF: mu = PDX1 + PDX2 dfz; Tire: mu = pdx1 (1 + pdx2 dfz). The force's
  // direction comes from the sign of K (By = Ky / (Cy Dy)), so a negative
  // PDY1 (MF-Tyre 5.0 files) gives the same force as |PDY1|
  if (!(d.pdx1 != 0)) TirFail(path, r.LineOf("PDX1"), "PDX1", "PDX1 must not be zero");
  if (!(d.pdy1 != 0)) TirFail(path, r.LineOf("PDY1"), "PDY1", "PDY1 must not be zero");
  if (r.Find("PDX2")) d.pdx2 = r.Optional("PDX2", 0.0) / d.pdx1;
  if (r.Find("PDY2")) d.pdy2 = r.Optional("PDY2", 0.0) / d.pdy1;
  d.pdx1 = std::abs(d.pdx1);
  d.pdy1 = std::abs(d.pdy1);
  d.pex1 = r.Optional("PEX1", d.pex1);
  d.pey1 = r.Optional("PEY1", d.pey1);
  d.pky2 = r.Optional("PKY2", d.pky2);
  d.rbx1 = r.Optional("RBX1", d.rbx1);
  d.rby1 = r.Optional("RBY1", d.rby1);
  d.rolling_resistance = r.Optional("QSY1", d.rolling_resistance);
  // MF trail at Fz0 and zero camber: Dt = QDZ1 R0, Bt = QBZ1
  if (r.Find("QDZ1")) d.trail = r.Optional("QDZ1", 0.0) * d.unloaded_radius;
  d.trail_decay = r.Optional("QBZ1", d.trail_decay);
  // relaxation lengths at Fz0 (MF 5.2): sigma_alpha = PTY1 sin(2 atan(1 / PTY2)) R0, sigma_kappa = PTX1 R0
  if (r.Find("PTY1") && r.Optional("PTY1", 0.0) != 0) {
    const double pty1 = r.Optional("PTY1", 0.0);
    if (!r.Find("PTY2")) TirFail(path, r.LineOf("PTY1"), "PTY2", "PTY1 needs PTY2 (missing)");
    const double pty2 = r.Optional("PTY2", 0.0);
    if (!(pty2 != 0)) TirFail(path, r.LineOf("PTY2"), "PTY2", "PTY2 must not be zero");
    d.relaxation_length = pty1 * std::sin(2.0 * std::atan(1.0 / pty2)) * d.unloaded_radius;
  }
  if (r.Find("PTX1")) d.longitudinal_relaxation_length = r.Optional("PTX1", 0.0) * d.unloaded_radius;
  out.ignored = r.Ignored();
  try {
    Tire("check", d, 1.0);
  } catch (const InputError& e) {
    throw InputError("the mapped tire data are invalid: " + e.message(), {path, 0, "tire property file"});
  }
  return out;
}

}  // namespace flexmb::vehicle
