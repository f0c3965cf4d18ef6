#pragma once
/// \file petsc_interior_solver.h
/// Steps 2 to 4 of the Craig-Bampton reduction over MPI (`flexmb reduce
/// --backend petsc` under mpirun): K_ii factorized by MUMPS through PETSc,
/// the static modes as one multiple-right-hand-side solve on that factor,
/// the fixed-interface modes by SLEPc's Krylov-Schur with shift-and-invert
/// at 0 on the same factor. Rank 0 holds the FE model and runs the serial
/// steps (assembly, reduced matrices, invariants, stress modes, body file);
/// it hands the interior blocks to PETSc row by row (each rank receives the
/// rows it owns) and gets Psi and Phi back. The factor, the largest object
/// of a reduction, is spread over the ranks. docs/design.md, "Distributed
/// reduction", says what is and is not distributed.
///
/// Built only with FLEXMB_PETSC (CMake option; needs Debian's petsc-dev,
/// slepc-dev and openmpi).

#include "flexmb/reduction/craig_bampton.h"

namespace flexmb::reduction::petsc {

/// PETSc and SLEPc (and so MPI) started for the life of the object, on
/// MPI_COMM_WORLD. One per process; the error handler is set so that PETSc
/// errors come back as codes (turned into NumericalError) instead of
/// aborting.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

/// Settings of the distributed steps.
struct PetscSolverOptions {
  /// Relative residual tolerance of the SLEPc eigen solve. The reduced
  /// frequencies err by its square, the spanned space by about itself.
  double eigen_tolerance = 1e-12;
};

/// The ReductionOptions::interior_solver of rank 0. Every call is a
/// collective step: the other ranks must be in ServeInteriorSolves().
/// Throws NumericalError if MUMPS finds K_ii singular or SLEPc does not
/// converge (the caller then names the DOF by its own factorization).
InteriorSolver MakePetscInteriorSolver(const PetscSolverOptions& options = {});

/// The ranks other than 0: take part in every solve rank 0 starts, until
/// rank 0 calls ReleaseWorkers(). Returns 0, or 1 after a PETSc error
/// (which rank 0 also sees and reports).
int ServeInteriorSolves();

/// Rank 0: ends ServeInteriorSolves() on the other ranks. Call it on every
/// way out of the command (WorkerRelease does).
void ReleaseWorkers();

/// Calls ReleaseWorkers() when it goes out of scope (rank 0 only).
class WorkerRelease {
 public:
  explicit WorkerRelease(bool active) : active_(active) {}
  ~WorkerRelease() {
    if (active_) ReleaseWorkers();
  }
  WorkerRelease(const WorkerRelease&) = delete;
  WorkerRelease& operator=(const WorkerRelease&) = delete;

 private:
  bool active_;
};

}  // namespace flexmb::reduction::petsc
