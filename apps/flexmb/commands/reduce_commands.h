#pragma once
/// \file reduce_commands.h
/// The "flexmb reduce" and "flexmb body info" commands as library calls:
/// "reduce" turns a part's FE model into a flexible body file by
/// Craig-Bampton (reduction::ReduceCraigBampton, io::WriteBody); "body info"
/// summarizes a body file (io::ReadBody). Like fe_commands.h, each command
/// writes its report to a stream and returns the process exit code (0);
/// faults are thrown (InputError for bad files, options, node ids or sets;
/// NumericalError for a failing reduction, e.g. a mechanism inside the
/// body), their context naming the model or body file; nothing is written
/// to the stream before the command has succeeded, so that with --json it
/// holds exactly one JSON object or nothing. Documented in docs/cli.md.

#include <functional>
#include <ostream>
#include <string>

#include "flexmb/reduction/craig_bampton.h"

namespace flexmb::io {

/// Options of "reduce".
struct ReduceOptions {
  std::string model_path;  ///< mesh file, FE model file (.yaml) or exchange-set directory
  /// Interface nodes: comma-separated node ids or a node set name (required).
  std::string interface;
  /// Fixed-interface normal modes (0 = Guyan); -1 = not given (then
  /// `cutoff_hz` must be).
  int modes = -1;
  double cutoff_hz = 0.0;  ///< > 0: all fixed-interface modes below this frequency [Hz] instead of `modes`
  int keep = -1;           ///< keep the lowest N flexible modes (-1 = all)
  std::string fix;         ///< nodes to clamp (ids or a set), as FeModesOptions::fix; empty: none
  /// The body's floating frame: "mean" (the mean axes; "tisserand" and
  /// "buckens" name the same frame, see docs/design.md "The floating frame")
  /// or "node:ID" (attached to node ID: the node is clamped in the
  /// reduction, as by `fix`, and is an interface node). Empty: mean axes
  /// without `fix`, attached to the fixed nodes with it.
  std::string frame;
  std::string rayleigh;    ///< Rayleigh damping "ALPHA,BETA" (D = alpha M + beta K); empty: none
  /// Modal damping ratios "Z" or "Z1,Z2,..." (the last one repeats for
  /// higher modes); empty: none. Not together with `rayleigh`.
  std::string damping_ratio;
  /// A modes file (body_file/modes_file.h) whose static and normal modes replace
  /// the computed basis; its rows follow the model's free DOF (the exchange
  /// set it was written with). Then `interface`, `modes`, `cutoff_hz` and
  /// `fix` must not be given. Empty: compute the basis.
  std::string modes_file;
  /// Also compute the centrifugal geometric stiffness (beams, shells and
  /// solids; reduction/geometric_stiffness.h).
  bool geometric_stiffening = false;
  /// Also compute the geometric stiffness of the body's own deformation
  /// (reduction/deformation_stiffness.h).
  bool deformation_stiffening = false;
  /// Also add the acceleration (static correction) modes
  /// (ReductionOptions::acceleration_modes).
  bool acceleration_modes = false;
  /// Also store solid stress modes at the corner nodes (the solid_node
  /// table: stresses at nodes for `flexmb post`; a larger body file).
  bool solid_corner_stress = false;
  /// Unit system of the FE model, recorded in the body file (a key of
  /// KnownUnitSystems, body_file/unit_system.h; default SI). A model file uses
  /// only SI body files; the others are refused when loaded.
  std::string units = "SI";
  std::string output;      ///< body file to write (.h5), required
  bool json = false;       ///< one JSON object instead of text
  /// Relative residual of the fixed-interface modes (ReductionOptions::
  /// eigen_tolerance); 0: the solver's default.
  double eigen_tolerance = 0.0;
  /// The reduction itself, e.g. reduction::petsc::ReduceCraigBamptonPetsc
  /// on every process of an MPI job; empty: reduction::ReduceCraigBampton.
  std::function<reduction::ReducedBody(const fe::FeModel&, const reduction::ReductionOptions&,
                                       reduction::ReductionTimings*)>
      reducer;
  /// Names the solver in the report and the body's provenance.
  std::string backend = "CHOLMOD and block Lanczos (this process)";
  /// This process writes the body file and the report (false on the other
  /// processes of an MPI job).
  bool root = true;
};

/// "reduce": loads the model, resolves the interface and --fix nodes,
/// reduces (ReduceCraigBampton) and writes the body file. Reports the
/// counts, the flexible free-free frequencies (rigid-body modes removed,
/// ascending), mass and centre of mass, and the wall time of each step;
/// with `json` one object with keys file, output, nodes, elements,
/// interface_nodes, fixed_nodes, free_dofs, static_modes, normal_modes,
/// rigid_modes_removed, flexible_modes, frequencies_hz, mass_kg,
/// center_of_mass_m, timings_s {read, assemble, factorize, static_modes,
/// normal_modes, orthonormalize, invariants, stress_modes, write, total}.
int Reduce(const ReduceOptions& options, std::ostream& out);

/// Options of "body info".
struct BodyInfoOptions {
  std::string body_path;  ///< body file (.h5)
  bool json = false;      ///< one JSON object instead of text
};

/// "body info": counts (nodes, elements, interface nodes, modes), mass,
/// centre of mass and inertia about it (from the inertia invariants: mvv,
/// mvo0, moo0), the flexible frequencies, the stress tables and the
/// provenance. JSON keys: file, format_version, units, nodes, elements,
/// interface_nodes (ids), static_modes, normal_modes, rigid_modes_removed,
/// flexible_modes, frequencies_hz, mass_kg, center_of_mass_m,
/// inertia_kg_m2 (null when the body has no mass), stress {shell, beam,
/// solid: {elements, locations, components}}, provenance {key: value}.
int BodyInfo(const BodyInfoOptions& options, std::ostream& out);

}  // namespace flexmb::io
