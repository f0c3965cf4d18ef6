#include "flexmb/body_file/unit_system.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "flexmb/common/error.h"

namespace flexmb::io {
namespace {

std::string UnitsLower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string UnitsKeyList() {
  std::string keys;
  for (const UnitSystem& u : KnownUnitSystems()) keys += (keys.empty() ? "" : ", ") + std::string(u.key);
  return keys;
}

}  // namespace

const std::vector<UnitSystem>& KnownUnitSystems() {
  static const std::vector<UnitSystem> systems = {
      {"SI", "SI (m, kg, s, N, Pa)", 1.0, 1.0, 1.0},
      {"mm-t-s", "mm-t-s (mm, t, s, N, MPa)", 1e-3, 1e3, 1.0},
      {"mm-kg-ms", "mm-kg-ms (mm, kg, ms, kN, GPa)", 1e-3, 1.0, 1e-3},
      {"mm-kg-s", "mm-kg-s (mm, kg, s, mN, kPa)", 1e-3, 1.0, 1.0},
      {"mm-g-ms", "mm-g-ms (mm, g, ms, N, MPa)", 1e-3, 1e-3, 1e-3},
      {"cm-g-s", "cm-g-s (cm, g, s, dyn, Ba)", 1e-2, 1e-3, 1.0},
      {"in-lbf-s", "in-lbf-s (in, lbf s^2/in, s, lbf, psi)", 0.0254, 4.4482216152605 / 0.0254, 1.0},
  };
  return systems;
}

const UnitSystem& SiUnits() { return KnownUnitSystems().front(); }

const UnitSystem* FindUnitSystem(const std::string& text) {
  std::istringstream in(text);
  std::string first;
  in >> first;
  first = UnitsLower(first);
  if (first.empty()) return nullptr;
  for (const UnitSystem& u : KnownUnitSystems()) {
    if (UnitsLower(u.key) == first) return &u;
  }
  return nullptr;
}

const UnitSystem& ParseUnitsOption(const std::string& key) {
  const UnitSystem* u = FindUnitSystem(key);
  if (u == nullptr || key.find(' ') != std::string::npos)
    throw InputError("unknown unit system '" + key + "' (known: " + UnitsKeyList() + ")", {"", 0, "--units"});
  return *u;
}

std::vector<std::string> UnitPlausibilityWarnings(const reduction::ReducedBody& body, const std::string& file) {
  std::vector<std::string> out;
  const std::string head = "body file '" + file + "' (units recorded: " +
                           (body.units.empty() ? std::string("none") : body.units) + "): ";
  const std::string hint =
      "; if the FE model is not in SI, convert it to SI before reducing (flexmb does not scale body files) "
      "or record its units with 'flexmb reduce --units'";
  for (const fe::Material& m : body.mesh.materials) {
    if (m.rho > 0.0 && (m.rho < 1.0 || m.rho > 3e4)) {
      std::ostringstream s;
      s << head << "material " << m.id << " has the density " << m.rho
        << ", implausible in kg/m^3 (steel 7850; mm-t-s gives 7.85e-9, mm-kg 7.85e-6)" << hint;
      out.push_back(s.str());
      break;
    }
  }
  if (!body.mesh.nodes.empty()) {
    fe::Vec3 lo = body.mesh.nodes.front().x, hi = lo;
    for (const fe::Node& n : body.mesh.nodes) {
      lo = lo.cwiseMin(n.x);
      hi = hi.cwiseMax(n.x);
    }
    const double size = (hi - lo).maxCoeff();
    const double mass = body.invariants.mvv(0, 0);
    if (size > 1e3) {
      std::ostringstream s;
      s << head << "the body is " << size << " long, implausible in m (lengths in mm?)" << hint;
      out.push_back(s.str());
    }
    if (size > 0.0 && mass > 0.0) {
      const double ratio = mass / (size * size * size);
      if (ratio < 1e-4 || ratio > 1e5) {
        std::ostringstream s;
        s << head << "its mass " << mass << " over the cube of its size " << size << " is " << ratio
          << ", implausible in kg/m^3 (a solid steel cube has 7850, slender SI bodies 0.01 to 100)" << hint;
        out.push_back(s.str());
      }
    }
  }
  return out;
}

std::vector<std::string> CheckBodyUnits(const reduction::ReducedBody& body, const std::string& file) {
  const UnitSystem* u = FindUnitSystem(body.units);
  std::vector<std::string> out;
  if (u == nullptr) {
    out.push_back("body file '" + file + "' does not record a known unit system (units: '" + body.units +
                  "'); it is used as SI (m, kg, s, N, Pa), the model's units");
  } else if (u != &SiUnits()) {
    throw InputError("body file '" + file + "' is in " + u->attribute + ", the model is in " + SiUnits().attribute +
                         ": convert the FE model to SI and reduce it again (flexmb does not scale body files)",
                     ErrorContext{});
  }
  const std::vector<std::string> more = UnitPlausibilityWarnings(body, file);
  out.insert(out.end(), more.begin(), more.end());
  return out;
}

}  // namespace flexmb::io
