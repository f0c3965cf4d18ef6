#pragma once
/// \file stress_recovery.h
/// Stress histories of a flexible body recovered after a run from its
/// stress modes (reduction/reduced_body.h StressTable) and its modal
/// coordinates (durability/modal_history.h), in batches: the components of
/// a block of elements at all instants are one matrix product
/// W^T (T x n) times the block's rows of the stress modes transposed.
///
/// Recovery points: shells "bottom", "middle", "top" (middle = the mean of
/// the two surfaces, the membrane stress), solids "centroid" or, from the
/// solid_node table, their corner nodes "n1" ... (the points the stress
/// modes hold), beams the stress points of their sections at
/// both ends (the beam_fibre table, "end_a_p1" ...: a uniaxial normal
/// stress sxx, so von Mises |sxx|, principal stresses sxx and 0). The beam
/// table of section forces is not a stress table.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "flexmb/reduction/reduced_body.h"

namespace flexmb::durability {

/// A scalar of a point's stress state.
enum class StressMeasure {
  kVonMises,         ///< von Mises stress (>= 0)
  kSignedVonMises,   ///< von Mises with the sign of the largest-magnitude principal stress
  kMaxPrincipal,     ///< largest principal stress (shells: in-plane)
  kMinPrincipal,     ///< smallest principal stress (shells: in-plane)
  kMaxAbsPrincipal,  ///< the principal stress of largest magnitude, with its sign
};

/// Parses "von_mises", "signed_von_mises", "max_principal",
/// "min_principal", "max_abs_principal"; throws InputError naming the
/// value and the valid names otherwise.
StressMeasure ParseStressMeasure(const std::string& name);
/// The name ParseStressMeasure accepts.
const char* StressMeasureName(StressMeasure m);

/// All measures of one stress state [Pa].
struct PointStress {
  double von_mises = 0, signed_von_mises = 0, max_principal = 0, min_principal = 0, max_abs_principal = 0;
  /// The value of measure m.
  double Get(StressMeasure m) const;
};

/// Measures of a plane stress state (sxx, syy, sxy) (shell components;
/// principal stresses in plane).
PointStress PlaneStressMeasures(double sxx, double syy, double sxy);
/// Measures of a 3-D stress state (sxx, syy, szz, sxy, syz, szx).
PointStress SolidStressMeasures(const double* s);

/// All measures of one recovery point over the instants [Pa] (arrays of
/// Instants() entries; resized on first use, then reused).
struct PointHistory {
  Eigen::ArrayXd von_mises, signed_von_mises, max_principal, min_principal, max_abs_principal;
  /// The array of measure m.
  const Eigen::ArrayXd& Get(StressMeasure m) const;
};

/// Measures of a uniaxial stress sxx (beam fibres).
PointStress UniaxialStressMeasures(double sxx);

/// Batched recovery of one shell, solid or beam-fibre table; see the file
/// comment.
class StressRecovery {
 public:
  /// `table` (shell, solid or beam_fibre, must outlive this) and modal
  /// coordinates W (n x T, column r at instant r). Throws InputError naming
  /// the table for a beam table (section forces) or when W has not
  /// table.modes.cols() rows.
  StressRecovery(const reduction::StressTable& table, const Eigen::MatrixXd& W);

  /// Elements of the table.
  int Elements() const { return static_cast<int>(table_.elements.size()); }
  /// Recovery points per element (shells 3, solids and beam fibres the
  /// table's locations).
  int Points() const { return shell_ ? 3 : table_.Locations(); }
  /// Instants T.
  int Instants() const { return static_cast<int>(wt_.rows()); }
  /// Name of point p ("bottom", "middle", "top", or the table's location
  /// name: "centroid", "n1" ..., "end_a_p1" ...).
  const char* PointName(int p) const;
  /// True for a shell table.
  bool shell() const { return shell_; }

  /// Recovers the components of elements [k0, k0 + count) (positions in
  /// table.elements) at all instants; the previous block is discarded.
  void Recover(int k0, int count);
  /// The measures of point p of element k (of the last Recover) at instant r.
  PointStress At(int k, int p, int r) const;
  /// Every measure at point p of element k (of the last Recover) at all
  /// instants into h (shells: array expressions over the instants).
  void Histories(int k, int p, PointHistory& h) const;
  /// History of measure m at point p of element k (of the last Recover)
  /// into out[0 .. Instants()).
  void History(int k, int p, StressMeasure m, double* out) const;
  /// History of component c (table.components; shells at "middle": the
  /// mean of bottom and top) at point p of element k into out.
  void ComponentHistory(int k, int p, int c, double* out) const;

 private:
  const double* Column(int k, int l, int c) const;

  const reduction::StressTable& table_;
  bool shell_ = false;
  bool uniaxial_ = false;
  mutable Eigen::ArrayXd sxx_, syy_, sxy_, c_, r_;  // scratch of Histories
  Eigen::MatrixXd wt_;      // T x n
  Eigen::MatrixXd values_;  // T x (count * locations * components)
  int k0_ = 0, count_ = 0;
};

}  // namespace flexmb::durability
