#pragma once
/// \file unit_system.h
/// Unit systems of body files. A model file is SI throughout (m, kg, s, N,
/// Pa; docs/model-file.md); a body file records the units of the FE model
/// it was reduced from in its root attribute `units` (`flexmb reduce
/// --units`, default SI). flexmb does not scale body files: a body file in
/// another system (e.g. a Nastran model in mm, t, s reduced without
/// conversion) is refused when a model uses it, with a message naming the
/// file and both systems; a file without a recognized `units` attribute
/// (written by another tool) is accepted with a warning. Because a
/// forgotten `--units` still records SI, a plausibility check warns when the
/// body's numbers do not look like SI (material densities, mass per size,
/// size). docs/formats.md "Body file" lists the systems.

#include <string>
#include <vector>

#include "flexmb/reduction/reduced_body.h"

namespace flexmb::io {

/// A consistent unit system: its key for `--units`, the text recorded in a
/// body file, and the SI value of its units of length, mass and time.
struct UnitSystem {
  const char* key;          ///< e.g. "mm-t-s"
  const char* attribute;    ///< e.g. "mm-t-s (mm, t, s, N, MPa)"
  double length_m;          ///< one length unit in m
  double mass_kg;           ///< one mass unit in kg
  double time_s;            ///< one time unit in s
};

/// The known systems, SI first: SI (m, kg, s, N, Pa), mm-t-s (mm, t, s, N,
/// MPa), mm-kg-ms (mm, kg, ms, kN, GPa), mm-kg-s (mm, kg, s, mN, kPa),
/// mm-g-ms (mm, g, ms, N, MPa), cm-g-s (cm, g, s, dyn, Ba), in-lbf-s (in,
/// lbf s^2/in, s, lbf, psi).
const std::vector<UnitSystem>& KnownUnitSystems();

/// The SI system (KnownUnitSystems().front()).
const UnitSystem& SiUnits();

/// The system named by `text`: a key (case-insensitive; "si" too) or a
/// body-file attribute (its first word is the key). Null if none matches
/// (empty, "unknown", anything else).
const UnitSystem* FindUnitSystem(const std::string& text);

/// The system of a `--units` value; throws InputError listing the known
/// keys if it is none of them.
const UnitSystem& ParseUnitsOption(const std::string& key);

/// Warnings (possibly none) if the numbers of `body` do not look like SI:
/// a material density outside 1 .. 30000 kg/m^3, a mass per cube of the
/// largest extent below 1e-4 or above 1e5 kg/m^3, or a largest extent above
/// 1000 m. Each names `file` and the likely cause.
std::vector<std::string> UnitPlausibilityWarnings(const reduction::ReducedBody& body, const std::string& file);

/// Checks the units of the body file `file` (read into `body`) for a model
/// in SI: throws InputError naming the file, its system and SI if it is in
/// another known system; returns warnings (the caller logs them) if its
/// system is not recorded or not recognized, and the plausibility warnings.
std::vector<std::string> CheckBodyUnits(const reduction::ReducedBody& body, const std::string& file);

}  // namespace flexmb::io
