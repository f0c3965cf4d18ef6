#include "flexmb/reduction/petsc/petsc_interior_solver.h"

#include <petscksp.h>
#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

#include "flexmb/common/error.h"

namespace flexmb::reduction::petsc {

namespace {

const ErrorContext kWhere{"", 0, "distributed reduction (PETSc)"};

// A PETSc or SLEPc call that failed: NumericalError with PETSc's message.
void Check(PetscErrorCode code, const char* call) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw NumericalError(std::string(call) + " failed: " + (text != nullptr ? text : "unknown PETSc error"), kWhere);
}
#define FLEXMB_PETSC(call) Check((call), #call)

// What rank 0 broadcasts before each collective step.
enum Command : int { kSolve = 1, kDone = 2 };
struct Header {
  int command = kDone;
  int ni = 0, nb = 0, count = 0;
  double eigen_tolerance = 1e-12;
};

// Rows [begin[r], begin[r + 1]) of an n-row matrix belong to rank r, as
// PetscSplitOwnership would split them.
std::vector<PetscInt> RowSplit(int n, int size) {
  std::vector<PetscInt> begin(static_cast<size_t>(size) + 1, 0);
  for (int r = 0; r < size; ++r) begin[r + 1] = begin[r] + n / size + (r < n % size ? 1 : 0);
  return begin;
}

// MPI counts and displacements in units of `per_row` values per row.
struct Layout {
  std::vector<int> count, offset;
};
Layout RowLayout(const std::vector<PetscInt>& begin, int64_t per_row) {
  const size_t size = begin.size() - 1;
  Layout l{std::vector<int>(size), std::vector<int>(size)};
  int64_t offset = 0;
  for (size_t r = 0; r < size; ++r) {
    const int64_t c = (begin[r + 1] - begin[r]) * per_row;
    if (offset + c > INT32_MAX) throw NumericalError("a block of more than 2^31 values to scatter", kWhere);
    l.count[r] = static_cast<int>(c);
    l.offset[r] = static_cast<int>(offset);
    offset += c;
  }
  return l;
}

// Owns a PETSc object and destroys it at the end of the scope.
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T obj = nullptr;
  ~Owned() {
    if (obj != nullptr) Destroy(&obj);
  }
  T* operator&() { return &obj; }
  operator T() const { return obj; }
};
using OwnedMat = Owned<Mat, MatDestroy>;
using OwnedVec = Owned<Vec, VecDestroy>;
using OwnedKsp = Owned<KSP, KSPDestroy>;
using OwnedEps = Owned<EPS, EPSDestroy>;

// The distributed symmetric matrix of rank 0's CSC matrix `a` (n x n, both
// triangles stored: column j is row j): every rank receives the rows it
// owns and builds its part of an MPIAIJ matrix from them.
void ScatterSymmetric(const fe::SparseMat* a, int n, const std::vector<PetscInt>& begin, int rank, Mat* out) {
  const int size = static_cast<int>(begin.size()) - 1;
  const PetscInt b = begin[rank], e = begin[rank + 1], rows = e - b;
  // row pointers (rank 0's absolute ones, rebased here) and then the entries
  std::vector<int> nnz_count(size), nnz_offset(size), ptr_count(size), ptr_offset(size);
  if (rank == 0) {
    const int* outer = a->outerIndexPtr();
    for (int r = 0; r < size; ++r) {
      nnz_offset[r] = outer[begin[r]];
      nnz_count[r] = outer[begin[r + 1]] - outer[begin[r]];
      ptr_offset[r] = static_cast<int>(begin[r]);
      ptr_count[r] = static_cast<int>(begin[r + 1] - begin[r]) + 1;
    }
  }
  std::vector<int> ptr(static_cast<size_t>(rows) + 1);
  MPI_Scatterv(rank == 0 ? a->outerIndexPtr() : nullptr, ptr_count.data(), ptr_offset.data(), MPI_INT, ptr.data(),
               static_cast<int>(rows) + 1, MPI_INT, 0, PETSC_COMM_WORLD);
  const int nnz = ptr[rows] - ptr[0];
  std::vector<PetscInt> idx(static_cast<size_t>(nnz)), row_ptr(static_cast<size_t>(rows) + 1);
  std::vector<PetscScalar> val(static_cast<size_t>(nnz));
  static_assert(sizeof(PetscInt) == sizeof(int), "PETSc with 32-bit indices");
  MPI_Scatterv(rank == 0 ? a->innerIndexPtr() : nullptr, nnz_count.data(), nnz_offset.data(), MPI_INT, idx.data(), nnz,
               MPI_INT, 0, PETSC_COMM_WORLD);
  MPI_Scatterv(rank == 0 ? a->valuePtr() : nullptr, nnz_count.data(), nnz_offset.data(), MPI_DOUBLE, val.data(), nnz,
               MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  for (PetscInt k = 0; k <= rows; ++k) row_ptr[k] = ptr[k] - ptr[0];
  FLEXMB_PETSC(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, rows, rows, n, n, row_ptr.data(), idx.data(), val.data(),
                                         out));
  FLEXMB_PETSC(MatSetOption(*out, MAT_SYMMETRIC, PETSC_TRUE));
}

// The steps every rank runs for one solve. Rank 0 passes the blocks and
// receives the solution; the others pass null.
bool SolveDistributed(const Header& h, const fe::SparseMat* k_ii, const fe::SparseMat* k_ib,
                      const fe::SparseMat* m_ii, InteriorSolution* solution,
                      std::string* failure) {
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const std::vector<PetscInt> begin = RowSplit(h.ni, size);
  const PetscInt rows = begin[rank + 1] - begin[rank];

  double t0 = MPI_Wtime();
  OwnedMat k, m;
  ScatterSymmetric(k_ii, h.ni, begin, rank, &k);
  if (h.count > 0) ScatterSymmetric(m_ii, h.ni, begin, rank, &m);

  // K_ii = L D L^T by MUMPS, through a KSP that applies it once (preonly)
  OwnedKsp ksp;
  FLEXMB_PETSC(KSPCreate(PETSC_COMM_WORLD, &ksp));
  FLEXMB_PETSC(KSPSetOperators(ksp, k, k));
  FLEXMB_PETSC(KSPSetType(ksp, KSPPREONLY));
  PC pc = nullptr;
  FLEXMB_PETSC(KSPGetPC(ksp, &pc));
  FLEXMB_PETSC(PCSetType(pc, PCCHOLESKY));
  FLEXMB_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  FLEXMB_PETSC(KSPSetFromOptions(ksp));  // MUMPS settings from PETSC_OPTIONS, e.g. -mat_mumps_icntl_14
  // symmetric indefinite L D L^T (MUMPS SYM = 2), not the positive definite
  // variant: it counts negative pivots (INFOG(12)) and, with null pivot
  // detection (ICNTL(24)), zero ones (INFOG(28)), so that a mechanism in
  // the body is found here instead of as zero-frequency modes later
  Mat factor = nullptr;
  FLEXMB_PETSC(PCFactorSetUpMatSolverType(pc));
  FLEXMB_PETSC(PCFactorGetMatrix(pc, &factor));
  FLEXMB_PETSC(MatMumpsSetIcntl(factor, 24, 1));
  FLEXMB_PETSC(KSPSetUp(ksp));
  PCFailedReason reason = PC_NOERROR;
  FLEXMB_PETSC(PCGetFailedReason(pc, &reason));
  PetscInt negative = 0, null = 0;
  if (reason == PC_NOERROR) {
    FLEXMB_PETSC(MatMumpsGetInfog(factor, 12, &negative));
    FLEXMB_PETSC(MatMumpsGetInfog(factor, 28, &null));
  }
  if (reason != PC_NOERROR || negative > 0 || null > 0) {
    *failure = "MUMPS: K_ii is not positive definite (" +
               (reason != PC_NOERROR ? std::string(PCFailedReasons[reason])
                                     : std::to_string(negative) + " negative and " + std::to_string(null) +
                                           " zero pivots") +
               ")";
    return false;
  }

  if (rank == 0) solution->factorize_s = MPI_Wtime() - t0;
  t0 = MPI_Wtime();

  // static modes: K_ii Psi = -K_ib, all columns in one MatMatSolve
  if (h.nb > 0) {
    const Layout l = RowLayout(begin, h.nb);
    std::vector<double> packed;  // rank r's rows, column-major, one after the other
    if (rank == 0) {
      packed.assign(static_cast<size_t>(h.ni) * static_cast<size_t>(h.nb), 0.0);
      std::vector<int> owner(static_cast<size_t>(h.ni));
      for (int r = 0; r < size; ++r) std::fill(owner.begin() + begin[r], owner.begin() + begin[r + 1], r);
      for (int j = 0; j < h.nb; ++j) {
        for (fe::SparseMat::InnerIterator it(*k_ib, j); it; ++it) {
          const int i = static_cast<int>(it.row()), r = owner[static_cast<size_t>(i)];
          const PetscInt local_rows = begin[r + 1] - begin[r];
          packed[static_cast<size_t>(l.offset[r] + (i - begin[r]) + j * local_rows)] = -it.value();
        }
      }
    }
    std::vector<double> local(static_cast<size_t>(rows) * static_cast<size_t>(h.nb));
    MPI_Scatterv(packed.data(), l.count.data(), l.offset.data(), MPI_DOUBLE, local.data(), l.count[rank], MPI_DOUBLE,
                 0, PETSC_COMM_WORLD);
    OwnedMat rhs, x;
    FLEXMB_PETSC(MatCreateDense(PETSC_COMM_WORLD, rows, PETSC_DECIDE, h.ni, h.nb, local.data(), &rhs));
    FLEXMB_PETSC(MatCreateDense(PETSC_COMM_WORLD, rows, PETSC_DECIDE, h.ni, h.nb, nullptr, &x));
    FLEXMB_PETSC(MatMatSolve(factor, rhs, x));
    const PetscScalar* xa = nullptr;
    PetscInt lda = 0;
    FLEXMB_PETSC(MatDenseGetLDA(x, &lda));
    FLEXMB_PETSC(MatDenseGetArrayRead(x, &xa));
    for (int j = 0; j < h.nb; ++j) std::copy_n(xa + j * lda, rows, local.begin() + j * rows);
    FLEXMB_PETSC(MatDenseRestoreArrayRead(x, &xa));
    MPI_Gatherv(local.data(), l.count[rank], MPI_DOUBLE, packed.data(), l.count.data(), l.offset.data(), MPI_DOUBLE,
                0, PETSC_COMM_WORLD);
    if (rank == 0) {
      solution->psi.resize(h.ni, h.nb);
      for (int r = 0; r < size; ++r) {
        const PetscInt lr = begin[r + 1] - begin[r];
        for (int j = 0; j < h.nb; ++j) {
          for (PetscInt i = 0; i < lr; ++i) solution->psi(begin[r] + i, j) = packed[l.offset[r] + i + j * lr];
        }
      }
    }
  } else if (rank == 0) {
    solution->psi.resize(h.ni, 0);
  }

  // fixed-interface modes: K_ii phi = lambda M_ii phi, shift-and-invert at 0 on the same factor
  if (rank == 0) solution->static_modes_s = MPI_Wtime() - t0;
  t0 = MPI_Wtime();
  if (rank == 0) {
    solution->phi.resize(h.ni, h.count);
    solution->frequencies_hz.resize(h.count);
  }
  if (h.count == 0) return true;
  OwnedEps eps;
  FLEXMB_PETSC(EPSCreate(PETSC_COMM_WORLD, &eps));
  FLEXMB_PETSC(EPSSetOperators(eps, k, m));
  FLEXMB_PETSC(EPSSetProblemType(eps, EPS_GHEP));
  FLEXMB_PETSC(EPSSetType(eps, EPSKRYLOVSCHUR));
  FLEXMB_PETSC(EPSSetDimensions(eps, h.count, PETSC_DEFAULT, PETSC_DEFAULT));
  FLEXMB_PETSC(EPSSetTolerances(eps, h.eigen_tolerance, PETSC_DEFAULT));
  FLEXMB_PETSC(EPSSetTarget(eps, 0.0));
  FLEXMB_PETSC(EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE));
  ST st = nullptr;
  FLEXMB_PETSC(EPSGetST(eps, &st));
  FLEXMB_PETSC(STSetType(st, STSINVERT));
  // the shift is 0, so the operator to invert is K_ii itself: the KSP that
  // holds its factor serves (PETSc does not refactorize an unchanged matrix)
  FLEXMB_PETSC(STSetKSP(st, ksp));
  FLEXMB_PETSC(EPSSetFromOptions(eps));
  FLEXMB_PETSC(EPSSolve(eps));
  PetscInt converged = 0;
  FLEXMB_PETSC(EPSGetConverged(eps, &converged));
  if (converged < h.count) {
    *failure = "SLEPc found " + std::to_string(converged) + " of the " + std::to_string(h.count) +
               " fixed-interface modes asked";
    return false;
  }
  OwnedVec v, mv;
  FLEXMB_PETSC(MatCreateVecs(k, &v, &mv));
  const Layout l = RowLayout(begin, 1);
  std::vector<double> column(rank == 0 ? static_cast<size_t>(h.ni) : 0);
  std::vector<std::pair<double, int>> order;
  for (int j = 0; j < h.count; ++j) {
    PetscScalar lambda = 0.0;
    FLEXMB_PETSC(EPSGetEigenpair(eps, j, &lambda, nullptr, v, nullptr));
    // M-normalized here whatever SLEPc's normalization
    PetscScalar vmv = 0.0;
    FLEXMB_PETSC(MatMult(m, v, mv));
    FLEXMB_PETSC(VecDot(v, mv, &vmv));
    if (!(vmv > 0.0)) {
      *failure = "SLEPc returned a mode of zero mass";
      return false;
    }
    FLEXMB_PETSC(VecScale(v, 1.0 / std::sqrt(vmv)));
    const PetscScalar* va = nullptr;
    FLEXMB_PETSC(VecGetArrayRead(v, &va));
    MPI_Gatherv(va, l.count[rank], MPI_DOUBLE, column.data(), l.count.data(), l.offset.data(), MPI_DOUBLE, 0,
                PETSC_COMM_WORLD);
    FLEXMB_PETSC(VecRestoreArrayRead(v, &va));
    if (rank == 0) {
      solution->phi.col(j) = Eigen::Map<const Eigen::VectorXd>(column.data(), h.ni);
      solution->frequencies_hz[j] = std::copysign(std::sqrt(std::abs(lambda)), lambda) / (2.0 * M_PI);
    }
  }
  if (rank == 0) {
    // ascending, as the built-in solver delivers them
    std::vector<int> idx(static_cast<size_t>(h.count));
    std::iota(idx.begin(), idx.end(), 0);
    std::stable_sort(idx.begin(), idx.end(),
                     [&](int a, int b) { return solution->frequencies_hz[a] < solution->frequencies_hz[b]; });
    const Eigen::MatrixXd phi = solution->phi;
    const Eigen::VectorXd hz = solution->frequencies_hz;
    for (int j = 0; j < h.count; ++j) {
      solution->phi.col(j) = phi.col(idx[static_cast<size_t>(j)]);
      solution->frequencies_hz[j] = hz[idx[static_cast<size_t>(j)]];
    }
    solution->normal_modes_s = MPI_Wtime() - t0;
  }
  return true;
}

}  // namespace

MpiSession::MpiSession(int* argc, char*** argv) {
  // options for PETSc come from PETSC_OPTIONS, not the command line (which is flexmb's)
  (void)argc;
  (void)argv;
  Check(SlepcInitialize(nullptr, nullptr, nullptr, nullptr), "SlepcInitialize");
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { SlepcFinalize(); }

InteriorSolver MakePetscInteriorSolver(const PetscSolverOptions& options) {
  return [options](const fe::SparseMat& k_ii, const fe::SparseMat& k_ib, const fe::SparseMat& m_ii, int count) {
    Header h;
    h.command = kSolve;
    h.ni = static_cast<int>(k_ii.rows());
    h.nb = static_cast<int>(k_ib.cols());
    h.count = count;
    h.eigen_tolerance = options.eigen_tolerance;
    MPI_Bcast(&h, sizeof h, MPI_BYTE, 0, PETSC_COMM_WORLD);
    InteriorSolution solution;
    std::string failure;
    if (!SolveDistributed(h, &k_ii, &k_ib, &m_ii, &solution, &failure)) throw NumericalError(failure, kWhere);
    return solution;
  };
}

int ServeInteriorSolves() {
  int status = 0;
  for (;;) {
    Header h;
    MPI_Bcast(&h, sizeof h, MPI_BYTE, 0, PETSC_COMM_WORLD);
    if (h.command != kSolve) return status;
    std::string failure;
    try {
      SolveDistributed(h, nullptr, nullptr, nullptr, nullptr, &failure);
    } catch (const Error& e) {
      // rank 0 meets the same collective failure and reports it
      std::cerr << "flexmb (rank " << PetscGlobalRank << "): " << e.what() << "\n";
      status = 1;
    }
  }
}

void ReleaseWorkers() {
  Header h;
  h.command = kDone;
  MPI_Bcast(&h, sizeof h, MPI_BYTE, 0, PETSC_COMM_WORLD);
}

}  // namespace flexmb::reduction::petsc
