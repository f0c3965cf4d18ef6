#pragma once
/// \file tir_file.h
/// Reader of Magic Formula tire property files (`.tir`, the TYDEX / MF-Tyre
/// format of MF 5.2 / PAC2002 and MF 6.1: `[SECTION]` headers, `KEY = value`
/// lines, `$` or `!` comments, quoted strings) into the simplified tire model's
/// TireData (tire.h). The mapping of each key, with the MF equation it comes
/// from, is documented in docs/model-file.md, section "tire".

#include <string>
#include <vector>

#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {

/// What a `.tir` file gives: the tire data and the keys the simplified model
/// cannot represent.
struct TirFile {
  TireData data;  ///< mapped coefficients (count 1; unmapped members keep their defaults)
  /// Keys present in the file with a numeric value other than their neutral
  /// one (1 for the scaling factors [SCALING_COEFFICIENTS] and for RCX1,
  /// RCY1, QCZ1; 2 for PKY4; 0 otherwise) that the simplified model does not
  /// use, in file order; a table section (e.g. [SHAPE]) appears as "[NAME]".
  std::vector<std::string> ignored;
};

/// Reads the `.tir` file at `path`. Throws InputError naming the file, the
/// line and the key for an unreadable file, a malformed line, a non-number
/// where a number is needed, a duplicate key, a unit in [UNITS] that is not
/// SI (meter, newton, radian, kg, second, pascal), a missing required key
/// (UNLOADED_RADIUS, FNOMIN, VERTICAL_STIFFNESS, PCX1, PDX1, PKX1, PCY1,
/// PDY1, PKY1), a positive PKY1 (flexmb follows the ISO sign convention of
/// the TYDEX files, where PKY1 < 0) or a coefficient the Tire rejects.
TirFile ReadTirFile(const std::string& path);

/// True when `path` ends in ".tir" (any case).
bool IsTirPath(const std::string& path);

}  // namespace flexmb::vehicle
