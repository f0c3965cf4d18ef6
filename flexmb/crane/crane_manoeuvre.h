#pragma once
/// \file crane_manoeuvre.h
/// The crane keys of a crane file's manoeuvres (docs/crane-file.md,
/// "Manoeuvres"): `hoist` and `slew` moves, `luff` moves, `release_time`,
/// and `crane` (values of the crane map replaced for this manoeuvre).

#include <yaml-cpp/yaml.h>

#include <string>

#include "flexmb/crane/crane_data.h"
#include "flexmb/crane/crane_geometry.h"

namespace flexmb::crane {

/// The crane of the selected manoeuvre: its data, its placement at t = 0
/// and its drive functions (muparser expressions in t): the cylinder length
/// [m], the drum angle [rad], the slew angle [rad].
struct CraneSetup {
  CraneData data;
  BoomPoints boom;  ///< the boom's foot, head and eye in its axes
  CraneGeometry geometry;
  std::string luffing, hoist, slew;
};

/// Reads root["crane"] and checks the crane keys of every entry of
/// root["manoeuvres"] against the crane it makes (`folder`: the model
/// file's folder; g [m/s^2]); removes them from the entries, leaving the
/// model-file keys (a release time becomes `joints: {grab: ...}`), and
/// returns the setup of the manoeuvre `requested` (empty: the file's
/// `manoeuvre`; none: the crane at rest).
CraneSetup SelectCraneManoeuvre(YAML::Node& root, const std::string& requested, const std::string& folder, double g,
                                YamlContext& ctx);

}  // namespace flexmb::crane
