#pragma once
/// \file petsc_reduction.h
/// The Craig-Bampton reduction over MPI (`flexmb reduce --backend petsc`
/// under mpirun), every process running the same steps on its share:
/// the elements assembled by the process that owns their first node
/// (fe::AssemblyOptions::block_subset), the matrix rows of the interior DOF
/// split into contiguous ranges, one per process, the entries sent to the
/// process owning their row; K_ii factorized by MUMPS through PETSc, the
/// static modes as one multiple-right-hand-side solve on that factor, the
/// fixed-interface modes by SLEPc's Krylov-Schur with shift-and-invert at 0
/// on the same factor; the reduced matrices and the inertia invariants
/// summed over the processes. The root process (rank 0) gathers the
/// body's mode matrix, computes the stress modes and writes the body file.
/// docs/design.md, "Distributed reduction", says what each process holds.
///
/// Built only with FLEXMB_PETSC (CMake option; needs Debian's petsc-dev,
/// slepc-dev and openmpi).

#include "flexmb/fe/fe_model.h"
#include "flexmb/reduction/craig_bampton.h"

namespace flexmb::reduction::petsc {

/// PETSc and SLEPc (and so MPI) started for the life of the object, on
/// MPI_COMM_WORLD. One per process; PETSc's error handler is set so that
/// its errors come back as codes (turned into NumericalError) instead of
/// aborting. PETSc options come from the PETSC_OPTIONS environment
/// variable, not the command line.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

/// ReduceCraigBampton over the processes of MPI_COMM_WORLD (a collective
/// call: every process passes the same model and options). Returns the
/// complete body on rank 0 and a partial one (no modes, stress modes or
/// complete invariants) on the others. Relative residual of the eigen
/// solve: options.eigen_tolerance, 1e-12 if 0. Throws as
/// ReduceCraigBampton, on every process alike: InputError for bad options,
/// for imported matrices (no elements to share out) and for the
/// stiffening options (not distributed); NumericalError if MUMPS finds
/// negative or zero pivots in K_ii (a mechanism) or SLEPc does not
/// converge.
ReducedBody ReduceCraigBamptonPetsc(const fe::FeModel& model, const ReductionOptions& options,
                                    ReductionTimings* timings = nullptr);

}  // namespace flexmb::reduction::petsc
