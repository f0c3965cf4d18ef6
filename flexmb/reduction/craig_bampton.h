#pragma once
/// \file craig_bampton.h
/// Craig-Bampton reduction of a linear FE model (THEORY section 2): static
/// modes of the interface DOF by one sparse Cholesky factorization of K_ii
/// (CHOLMOD), fixed-interface normal modes by shift-invert Lanczos on the
/// same factor (block Lanczos, fe/block_lanczos.h; Spectra as fallback),
/// orthonormalization by the reduced eigenproblem, removal of
/// the rigid-body modes of a free body (detected against the geometric
/// rigid-body vectors), optional truncation.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb::reduction {

/// Options of the reduction.
struct ReductionOptions {
  /// Node indices; every free DOF their motion depends on is a boundary DOF
  /// (a node's own DOF; for a node made dependent by a rigid link, the
  /// independent node's DOF it follows). Listed twice counts once.
  std::vector<int> interface_nodes;
  int normal_modes = 10;              ///< fixed-interface normal modes (0 = Guyan)
  double cutoff_hz = 0.0;             ///< if > 0: all fixed-interface modes below it instead
  int keep = -1;                      ///< keep the lowest N flexible modes (-1 = all)
  std::vector<int> fixed_nodes;       ///< nodes clamped in the body (single-point constraints)
  fe::MassForm mass_form = fe::MassForm::kConsistent;
  /// Damping: Rayleigh D = alpha M + beta K (reduced), or per-mode ratios
  /// zeta (the last value repeats for higher modes); ratios win if given.
  double rayleigh_alpha = 0.0, rayleigh_beta = 0.0;
  std::vector<double> damping_ratios;
  /// Eigen solver of the fixed-interface modes on the K_ii factor: block
  /// shift-invert Lanczos (default; fe/block_lanczos.h, Spectra as its
  /// fallback) or Spectra alone (the baseline of bench/reduce.cc).
  enum class EigenSolver { kBlockLanczos, kSpectra };
  EigenSolver eigen_solver = EigenSolver::kBlockLanczos;
  /// Relative residual to which the fixed-interface modes are solved; 0:
  /// the solver's default (block Lanczos 1e-6, which leaves the reduced
  /// frequencies exact to about 1e-12 and the modes to about 1e-6 over the
  /// relative gap; the PETSc solver 1e-12). A smaller value makes the modes
  /// and invariants of two solvers agree to about it.
  double eigen_tolerance = 0.0;
  /// Also compute the geometric stiffness of the centrifugal load cases
  /// (reduction/geometric_stiffness.h), held at `fixed_nodes` or, without
  /// them, at the interface nodes. Every element type (beams, shells,
  /// solids); not for imported matrices (InputError).
  bool geometric_stiffening = false;
  /// Also compute the geometric stiffness of the body's own deformation
  /// (reduction/deformation_stiffness.h: one n x n matrix per mode, the
  /// P-delta of the forces at the interface nodes). Every element type;
  /// not for imported matrices (InputError).
  bool deformation_stiffening = false;
  /// Also add the acceleration modes (static correction modes): the
  /// interior's static response, interface held, to the inertial loads of
  /// the six rigid-body accelerations (M r), M-orthonormalized against the
  /// normal modes. With them the body's deformation under its own weight or
  /// any uniform acceleration is in the basis exactly, however few normal
  /// modes are kept (distributed mass away from the interface nodes: a
  /// platform's deck, a boom's own weight). Not with imported modes or the
  /// PETSc backend (InputError).
  bool acceleration_modes = false;
  /// Also store the stress modes of solids at their corner nodes
  /// (StressModes::solid_node: 6 rows per corner, up to 8 per element, so
  /// the body file grows by about that factor for the solid part).
  bool solid_corner_stress = false;
};

/// Wall time of each step [s]. The static and the normal modes are computed
/// side by side on two threads when the machine has two cores or more, so
/// their sum may exceed the time they took together.
struct ReductionTimings {
  double assemble = 0, factorize = 0, static_modes = 0, normal_modes = 0, orthonormalize = 0,
         invariants = 0, stress_modes = 0, stiffening = 0;
};

/// Reduces `model` and fills a ReducedBody (modes, frequencies, reduced
/// matrices, invariants, stress modes, provenance). Throws InputError for
/// bad options (interface node missing, more modes than interior DOF) and
/// NumericalError naming the DOF where K_ii is singular (a mechanism inside
/// the body).
ReducedBody ReduceCraigBampton(const fe::FeModel& model, const ReductionOptions& options,
                               ReductionTimings* timings = nullptr);

struct CraigBamptonBasis;

/// The options as ReduceCraigBampton uses them: checked (InputError for a
/// negative mode count, cut-off or damping, a bad keep or eigen tolerance)
/// and with interface nodes listed twice counted once.
ReductionOptions PrepareReductionOptions(const fe::Mesh& mesh, const ReductionOptions& options);

/// The assembly of a reduction: the mass form, the fixed nodes clamped,
/// the interface nodes kept independent (an RBE3 reference node).
fe::AssemblyOptions ReductionAssemblyOptions(const ReductionOptions& options);

/// The steps of ReduceBasis done elsewhere when the model is spread over
/// processes (reduction/petsc/petsc_reduction.h): each process holds a
/// share of the assembled matrices and of the basis rows.
struct DistributedSteps {
  /// H y for reduced coordinates y (m x k): n_free x k in the free
  /// numbering on the root process, an empty matrix on the others.
  std::function<Eigen::MatrixXd(const Eigen::MatrixXd& y)> expand;
  /// The inertia invariants of the body's modes (given on the root, empty
  /// on the others) with the modal mass H^T M H (on every process),
  /// complete on the root.
  std::function<InertiaInvariants(const MatX& modes, const MatX& modal_mass)> invariants;
  /// The stress modes of the body's modes (called after `invariants`),
  /// complete on the root.
  std::function<StressModes(const MatX& modes)> stress;
  /// This process writes the body: the mode matrix is formed here only.
  bool root = true;
};

/// The steps of ReduceCraigBampton after the basis, on a basis computed
/// here (BuildCraigBamptonBasis) or imported (body_file/modes_file.h BasisOfModes):
/// orthonormalization, rigid-body removal, truncation (options.keep),
/// invariants, stress modes, damping and provenance. `assembled` is `model`
/// assembled as the basis was; options.interface_nodes are recorded as the
/// body's interface nodes. Fills the orthonormalize, invariants and
/// stress_modes timings.
/// With `steps`, the basis holds no rows of Psi and Phi here and
/// `assembled` is this process's share: H y and the invariants come from
/// `steps`, and only the root process returns a complete body.
ReducedBody ReduceBasis(const fe::FeModel& model, const fe::AssembledModel& assembled, const CraigBamptonBasis& basis,
                        const ReductionOptions& options, ReductionTimings* timings = nullptr,
                        const DistributedSteps* steps = nullptr);

}  // namespace flexmb::reduction
