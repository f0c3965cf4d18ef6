#pragma once
/// \file imported_matrices.h
/// FE models made of matrices another FE package wrote: stiffness and mass
/// in Harwell-Boeing (.hb, .rb, .rsa), Matrix Market (.mtx) or CalculiX
/// matrix storage (job.sti, job.mas, job.dof), a DOF map that names the node
/// and component of every row, and geometry (legacy VTK or any mesh file).
/// The DOF map format is documented in docs/formats.md.

#include <string>

#include "flexmb/fe/fe_model.h"

namespace flexmb::io {

/// Where the parts of an imported model are.
struct ImportedMatricesSpec {
  std::string stiffness;  ///< K file (.hb/.rb/.rsa, .mtx, or CalculiX .sti)
  std::string mass;       ///< M file (same formats, CalculiX .mas)
  std::string dof_map;    ///< DOF map file; empty: CalculiX job.dof, else 3 or 6 rows per geometry node in node order
  std::string geometry;   ///< node coordinates: .vtk or any mesh file
};

/// Reads and checks the matrices (square, same size, symmetric to round-off,
/// finite, every row mapped to an existing node) and builds an FeModel with
/// `imported` set. Throws InputError naming the file (and line or entry).
fe::FeModel ReadImportedMatrices(const ImportedMatricesSpec& spec);

}  // namespace flexmb::io
