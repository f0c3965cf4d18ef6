#pragma once
/// \file modes_file.h
/// The modes file of an exchange set (`modes.mtx`, docs/formats.md): the
/// static (constraint) and fixed-interface normal modes of a Craig-Bampton
/// basis as one dense Matrix Market array, rows in the order of the
/// exchange set's DOF map, columns the static modes (one per interface
/// DOF, named in the header by node id and component) followed by the
/// normal modes (named by their frequency). With K_CCS.hb, M_CCS.hb,
/// geometry.vtk and dof_map.txt it lets a body be built from a basis that
/// another FE package computed.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"
#include "flexmb/fe_io/dof_map.h"
#include "flexmb/reduction/craig_bampton_basis.h"

namespace flexmb::io {

/// File name of the modes file inside an exchange-set directory.
inline constexpr const char* kModesFileName = "modes.mtx";

/// Static and normal modes of a Craig-Bampton basis on the DOF of a DOF map.
struct ExchangeModes {
  /// The interface DOF of each static mode, in column order (node id and
  /// component 1..6; `line` is the header line that named it, 0 if made in
  /// code). Static mode k is the unit displacement of that DOF with the
  /// other interface DOF held.
  std::vector<DofMapRow> static_dofs;
  /// Frequencies of the fixed-interface normal modes [Hz], in column order.
  Eigen::VectorXd normal_frequencies_hz;
  /// rows x (static + normal): the static modes, then the normal modes
  /// (mass-normalized: Phi^T M Phi = I); row r is row r of the DOF map.
  Eigen::MatrixXd modes;

  /// Number of static modes (interface DOF).
  int StaticModes() const { return static_cast<int>(static_dofs.size()); }
  /// Number of normal modes.
  int NormalModes() const { return static_cast<int>(normal_frequencies_hz.size()); }
};

/// Writes the modes file (Matrix Market "array real general" with the
/// flexmb header naming every column, values column by column in their
/// shortest exact form, so that reading back is bit for bit), through a
/// temporary file that is renamed. Throws InputError naming the path for
/// inconsistent sizes, a non-finite value, a bad node id or component.
void WriteModesFile(const ExchangeModes& modes, const std::string& path);

/// Reads a modes file. Throws InputError naming the file, the line and the
/// entity for a missing or wrong banner, a missing "flexmb modes" version
/// line or another version, column headers that are missing, repeated, out
/// of order (static before normal) or do not add up to the columns of the
/// size line, a malformed or non-finite value (named by row and column),
/// or too few or too many values.
ExchangeModes ReadModesFile(const std::string& path);

/// Checks modes read from `path` against the DOF map `map` of the same
/// exchange set: as many rows as the map; every static DOF mapped, none
/// twice; static mode k equal to 1 at its own DOF and the static and normal
/// modes 0 at the other interface DOF (to 1e-6 of the column's largest
/// |value|). Throws InputError naming `path`, the column and the row (by
/// node id and component).
void CheckModesAgainstDofMap(const ExchangeModes& modes, const MatrixRowMap& map, const std::string& path);

/// Reads `dir`/modes.mtx and checks it against `dir`/dof_map.txt.
ExchangeModes ReadExchangeSetModes(const std::string& dir);

/// The modes of a Craig-Bampton basis (reduction/craig_bampton_basis.h) on
/// the free DOF of the assembled model it was built from, rows in the free
/// numbering, i.e. the order of the exchange set that WriteExchangeSet
/// writes for that model (FreeDofRows). Throws InputError as FreeDofRows.
ExchangeModes ModesOfBasis(const reduction::CraigBamptonBasis& basis, const fe::Mesh& mesh,
                           const fe::DofMap& dofs);

/// The Craig-Bampton basis of imported modes on the assembled model `model`
/// (`mesh` gives the node indices of the static DOF's node ids), ready for
/// the rest of the reduction (orthonormalization, rigid-body removal,
/// invariants, stress modes) in place of BuildCraigBamptonBasis: boundary =
/// the free DOF of the static modes (ascending, static columns reordered to
/// match), interior = the other free DOF, psi and phi = the interior rows of
/// the static and normal columns, fixed_interface_hz from the file, mass =
/// H^T M H, stiffness = H^T K H, stiffness_scale as BuildCraigBamptonBasis.
/// The rows of `modes` must be the free DOF of `model` in order: true for
/// the exchange set it came with read by ReadExchangeSet and assembled with
/// nothing fixed, and for ModesOfBasis. Throws InputError naming `path` for
/// a row count other than the free DOF, or a static DOF that is not a free
/// DOF of the model.
reduction::CraigBamptonBasis BasisOfModes(const ExchangeModes& modes, const fe::Mesh& mesh,
                                          const fe::AssembledModel& model, const std::string& path);

}  // namespace flexmb::io
