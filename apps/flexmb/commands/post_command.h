#pragma once
/// \file post_command.h
/// "flexmb post DIR --body NAME": stresses and fatigue of one flexible body
/// of a run, recovered from the run's modal coordinates
/// (flexmb/durability/): element extremes, hot spots, damage, element and
/// node histories, a ParaView file. docs/cli.md describes the options and
/// files.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace flexmb::commands {

/// Options of "flexmb post".
struct PostOptions {
  std::string run_dir;                 ///< run folder holding modal_coordinates.bin
  std::string body;                    ///< flexible body name
  std::string out_dir;                 ///< output folder ("" = RUN_DIR/post_BODY)
  int top = 10;                        ///< hot spots listed
  std::string measure = "max_abs_principal";  ///< counted stress measure
  std::string sn;                      ///< S-N preset, e.g. "en1993-71" ("" = none)
  std::string sn_file;                 ///< S-N table CSV ("" = none)
  std::vector<double> sn_basquin;      ///< S_ref [Pa], N_ref, m1 [, N_knee, m2 [, N_cut]]
  std::string mean_stress = "none";    ///< none, goodman, fkm
  double ultimate = 0.0;               ///< Goodman S_u [Pa]
  double sensitivity = 0.0;            ///< FKM M
  std::optional<double> distance_km;   ///< distance covered by the run [km]: damage per 1000 km, life in km
  std::vector<int> elements;           ///< element ids: stress histories to CSV
  std::vector<int> nodes;              ///< node ids: elastic displacement histories to CSV
  bool json = false;                   ///< print a JSON object instead of text
};

/// Runs "flexmb post"; writes the files, prints the report to `out` and
/// returns 0. Throws InputError for a folder without modal coordinates, an
/// unknown body, element or node, bad S-N data or options.
int Post(const PostOptions& options, std::ostream& out);

}  // namespace flexmb::commands
