#pragma once
/// \file fe_commands.h
/// The "flexmb fe" command group as library calls: "fe modes" (natural
/// frequencies of a part's full FE model), "fe info" (what a model file
/// holds: counts, mass, bounding box) and "fe export" (the exchange set
/// M_CCS.hb, K_CCS.hb, geometry.vtk, dof_map.txt). Each command loads the
/// model with LoadFeModel (a mesh file, an FE model file or an exchange-set
/// directory), writes its report to a stream and returns the process exit
/// code (0). Faults are thrown: InputError for bad files, options, node ids
/// or sets, NumericalError for a failing solve (e.g. a mechanism with zero
/// mass); their context names the model file when the fault has no file of
/// its own, and DOF are named by node id. Nothing is written to the stream
/// before the command has succeeded, so that with --json the stream holds
/// exactly one JSON object or nothing. Documented in docs/cli.md.

#include <ostream>
#include <string>

namespace flexmb::io {

/// Options of "fe modes".
struct FeModesOptions {
  std::string model_path;  ///< mesh file, FE model file (.yaml) or exchange-set directory
  /// Nodes to clamp (all 6 DOF) in addition to the model's own constraints:
  /// comma-separated node ids or a node set name; empty: none.
  std::string fix;
  int count = 10;          ///< number of modes (>= 1)
  bool json = false;       ///< one JSON object instead of the table
  bool lumped = false;     ///< lumped instead of consistent element mass
  /// Spectral shift sigma [rad^2/s^2], < 0; 0 = automatic (fe::ModalOptions).
  double shift = 0.0;
};

/// "fe modes": loads the model, fixes the --fix nodes, assembles, and
/// solves the lowest `count` modes. Writes a table (mode, frequency [Hz])
/// with the model's DOF, mass and centre of mass, or with `json` one object:
/// file, nodes, elements, dofs (free DOF), fixed_nodes, mass_form,
/// frequencies_hz, mass_kg, center_of_mass_m [3], inertia_kg_m2 (3x3, about
/// the centre of mass, basic axes), timings_s {read, assemble, solve}. Mass
/// properties are those of the unconstrained model (fixed and dependent
/// nodes included; an exchange set holds only the DOF it was written with).
/// A free model lists its six rigid-body modes first, near 0 Hz.
int FeModes(const FeModesOptions& options, std::ostream& out);

/// Options of "fe info".
struct FeInfoOptions {
  std::string model_path;  ///< mesh file, FE model file (.yaml) or exchange-set directory
  bool json = false;       ///< one JSON object instead of text
};

/// "fe info": counts of nodes, elements by type, materials, sections, node
/// and element sets (with sizes), rigid links, point masses and
/// single-point constraints; the bounding box of the nodes [m]; for imported
/// matrices their size and stored non-zeros. Total mass, centre of mass and
/// inertia come from the unconstrained assembled (or imported) mass matrix;
/// if the mesh cannot be assembled (e.g. a gmsh mesh without sections) they
/// are reported as unavailable with the reason, and the command still
/// succeeds. JSON keys: file, nodes, elements {type: count}, materials,
/// sections {shell, beam, solid}, node_sets {name: size}, element_sets,
/// rigid_links, linear_constraints (dependent DOF), point_masses, springs, constraints, bounding_box_m {min, max},
/// matrices (imported only: {dofs, k_nonzeros, m_nonzeros}), mass_kg,
/// center_of_mass_m, inertia_kg_m2 (null with mass_error when unavailable).
int FeInfo(const FeInfoOptions& options, std::ostream& out);

/// Options of "fe export".
struct FeExportOptions {
  std::string model_path;  ///< mesh file, FE model file (.yaml) or exchange-set directory
  std::string hb_dir;      ///< output directory of the exchange set (created if missing)
  std::string fix;         ///< as FeModesOptions::fix
  /// Interface nodes (ids or a node set): if given, the Craig-Bampton modes
  /// for them are written too (modes.mtx, body_file/modes_file.h).
  std::string interface;
  int modes = 10;          ///< fixed-interface normal modes in modes.mtx (with `interface`)
};

/// "fe export": assembles the model (consistent mass, the model's
/// constraints and the --fix nodes removed) and writes the exchange set to
/// `hb_dir` (io::WriteExchangeSet); with an interface also the static and
/// fixed-interface normal modes (modes.mtx); prints the files written with
/// matrix size and non-zeros.
int FeExport(const FeExportOptions& options, std::ostream& out);

}  // namespace flexmb::io
