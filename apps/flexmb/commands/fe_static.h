#pragma once
/// \file fe_static.h
/// "flexmb fe static": the linear static solution K u = f of a part's full
/// FE model under gravity and nodal forces and moments, the check an FE
/// package's linear static step (Nastran SOL 101, CalculiX *STATIC) gives,
/// and the reference against which a reduced body or a beam model of the
/// part is judged (examples/crane/methods.py). Loads as the other "fe"
/// commands (fe_commands.h); documented in docs/cli.md.

#include <ostream>
#include <string>
#include <vector>

namespace flexmb::io {

/// Options of "fe static".
struct FeStaticOptions {
  std::string model_path;  ///< mesh file or FE model file (.yaml); not imported matrices
  std::string fix;         ///< as FeModesOptions::fix: nodes clamped in all 6 DOF
  /// Supports of single components "ID:COMPONENTS" (Nastran component digits
  /// 1-6 in basic axes, e.g. "1:12346" a pin about y), as an SPC1 would add.
  std::vector<std::string> supports;
  /// Gravity [m/s^2] as "gx,gy,gz" in the model's basic axes; empty: none.
  std::string gravity;
  /// Nodal loads "ID:fx,fy,fz" or "ID:fx,fy,fz,mx,my,mz" [N, N m], basic axes.
  std::vector<std::string> forces;
  /// Nodes whose displacement and rotation are reported (ids or a node set);
  /// empty: the loaded nodes.
  std::string nodes;
  bool json = false;  ///< one JSON object instead of the table
  /// Second-order (P-delta) solution: (K + K_G) u = f with the element
  /// geometric stiffness K_G of the linear solution's stresses
  /// (reduction/geometric_stiffness.h), as an FE package's linear buckling
  /// prestress or differential stiffness; the reference for a reduced body
  /// with `--deformation-stiffening`.
  bool second_order = false;
};

/// "fe static": assembles K (the model's constraints, rigid links, the
/// --support components and the --fix nodes applied) and the consistent mass (for the weight), solves
/// K u = T^T f by sparse Cholesky and reports, for each reported node, the
/// displacement [m] and rotation [rad] in basic axes, the largest
/// translation over all nodes and where, the applied load's resultant [N]
/// and the strain energy 1/2 u.f [J]. With `second_order` the solution is
/// that of (K + K_G) u = f (FeStaticOptions::second_order). JSON keys: file,
/// dofs, fixed_nodes, second_order, gravity_m_s2, load_resultant_n, nodes [{id, displacement_m,
/// rotation_rad}], max_displacement_m, max_displacement_node,
/// strain_energy_j, timings_s. Throws InputError for a bad option (naming
/// it), a support component outside 1-6, a load on a missing node or on a component the node does not have
/// (a moment on a solid's node); NumericalError for a model that is a
/// mechanism under the supports, naming the first singular DOF by node id.
int FeStatic(const FeStaticOptions& options, std::ostream& out);

}  // namespace flexmb::io
