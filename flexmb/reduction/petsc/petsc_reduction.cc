#include "flexmb/reduction/petsc/petsc_reduction.h"

#include <petscksp.h>
#include <slepceps.h>

#include <Eigen/Dense>
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/reduction/craig_bampton_basis.h"
#include "flexmb/reduction/inertia_invariants.h"
#include "flexmb/reduction/rigid_modes.h"
#include "flexmb/reduction/stress_modes.h"

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

// Owns a PETSc object and destroys it at the end of the scope.
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Owned {
  T obj = nullptr;
  Owned() = default;
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  ~Owned() {
    if (obj != nullptr) Destroy(&obj);
  }
  T* operator&() { return &obj; }
  operator T() const { return obj; }
};
using OwnedMat = Owned<Mat, MatDestroy>;
using OwnedKsp = Owned<KSP, KSPDestroy>;
using OwnedEps = Owned<EPS, EPSDestroy>;
using OwnedVec = Owned<Vec, VecDestroy>;

// Column-major n x k block of this process's rows.
using Block = Eigen::MatrixXd;

int Rank() {
  int r = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  return r;
}
int Size() {
  int s = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &s);
  return s;
}

// Sums a dense matrix over the processes, the result on all of them.
void SumAll(Eigen::MatrixXd& a) {
  for (Eigen::Index done = 0; done < a.size();) {  // in pieces whose count fits an int
    const int count = static_cast<int>(std::min<Eigen::Index>(a.size() - done, INT_MAX));
    MPI_Allreduce(MPI_IN_PLACE, a.data() + done, count, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    done += count;
  }
}

// Runs `step` on every process; if it throws on any, every process throws
// the error of the lowest process that failed (its kind and message), so
// that none is left waiting in a collective call. `step` must not itself
// make collective calls that a failing process could skip.
template <class F>
auto Agreed(F&& step) -> decltype(step()) {
  int kind = 0;  // 0 ok, 1 input error, 2 other error
  std::string message;
  decltype(step()) out{};
  try {
    out = step();
  } catch (const InputError& e) {
    kind = 1;
    message = e.what();
  } catch (const std::exception& e) {
    kind = 2;
    message = e.what();
  }
  const int rank = Rank();
  int first = kind != 0 ? rank : INT_MAX;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  if (first == INT_MAX) return out;
  int length = static_cast<int>(message.size());
  MPI_Bcast(&kind, 1, MPI_INT, first, PETSC_COMM_WORLD);
  MPI_Bcast(&length, 1, MPI_INT, first, PETSC_COMM_WORLD);
  message.resize(static_cast<size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, first, PETSC_COMM_WORLD);
  if (kind == 1) throw InputError(message);
  throw NumericalError(message);
}
// Sums a dense matrix over the processes into rank 0's (column by column,
// so that no count exceeds an int).
template <class M>
void SumOnRoot(M& a) {
  const bool root = Rank() == 0;
  for (Eigen::Index j = 0; j < a.cols(); ++j) {
    if (a.rows() == 0) break;
    MPI_Reduce(root ? MPI_IN_PLACE : a.col(j).data(), a.col(j).data(), static_cast<int>(a.rows()), MPI_DOUBLE, MPI_SUM,
               0, PETSC_COMM_WORLD);
  }
}
double SumAll(double v) {
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return v;
}

// Interior rows [begin[r], begin[r + 1]) belong to rank r, as
// PetscSplitOwnership splits them.
std::vector<PetscInt> RowSplit(int n, int size) {
  std::vector<PetscInt> begin(static_cast<size_t>(size) + 1, 0);
  for (int r = 0; r < size; ++r) begin[r + 1] = begin[r] + n / size + (r < n % size ? 1 : 0);
  return begin;
}

// The block (element, point mass, spring) shares: an element to the process
// that owns its first node (nodes split into contiguous ranges like the
// rows), point masses and springs to rank 0 (the invariants need the point
// masses in one share: inertia_invariants.h).
std::vector<char> BlockShare(const fe::Mesh& mesh, int rank, int size) {
  const size_t ne = mesh.elements.size();
  const size_t nb = ne + mesh.point_masses.size() + mesh.springs.size();
  std::vector<char> mine(nb, rank == 0 ? 1 : 0);
  const int64_t nn = static_cast<int64_t>(std::max<size_t>(mesh.nodes.size(), 1));
  for (size_t e = 0; e < ne; ++e) {
    const fe::Element& el = mesh.elements[e];
    const int64_t first = el.nodes.empty() ? 0 : el.nodes[0];
    mine[e] = static_cast<int>(first * size / nn) == rank ? 1 : 0;
  }
  return mine;
}

// One entry of the interior rows: column >= 0 an interior DOF, < 0 the
// boundary DOF -1 - column.
struct Entry {
  int row, col;
  double k, m;
};

// This process's interior rows after the exchange, summed over the shares:
// CSR of K_ii and M_ii (interior columns, global numbering) and of K_ib and
// M_ib (boundary columns).
struct LocalRows {
  PetscInt begin = 0, rows = 0;
  std::vector<PetscInt> ii_ptr, ii_col, ib_ptr, ib_col;
  std::vector<double> ii_k, ii_m, ib_k, ib_m;
};

// Sends every entry of this process's share to the process owning its row
// and sums what arrives; the boundary x boundary block is summed into kbb
// and mbb (complete on every process).
LocalRows ExchangeEntries(const fe::AssembledModel& a, const InterfaceSplit& split, const std::vector<PetscInt>& begin,
                          Eigen::MatrixXd& kbb, Eigen::MatrixXd& mbb) {
  const int rank = Rank(), size = Size();
  const int nb = static_cast<int>(split.boundary.size());
  if (a.K.nonZeros() != a.M.nonZeros() || a.K.outerSize() != a.M.outerSize()) {
    throw NumericalError("K and M of the share do not have one pattern", kWhere);
  }
  auto owner = [&](int li) {
    return static_cast<int>(std::upper_bound(begin.begin(), begin.end(), static_cast<PetscInt>(li)) - begin.begin()) -
           1;
  };
  std::vector<std::vector<Entry>> out(static_cast<size_t>(size));
  kbb.setZero(nb, nb);
  mbb.setZero(nb, nb);
  for (int j = 0; j < a.K.outerSize(); ++j) {
    const int lj = split.local[j];
    const bool bj = split.is_b[j] != 0;
    fe::SparseMat::InnerIterator ik(a.K, j), im(a.M, j);
    for (; ik; ++ik, ++im) {
      const int i = static_cast<int>(ik.row()), li = split.local[i];
      if (split.is_b[i]) {
        if (bj) {
          kbb(li, lj) += ik.value();
          mbb(li, lj) += im.value();
        }
        continue;  // the b x i entries are the transposed i x b ones
      }
      out[static_cast<size_t>(owner(li))].push_back({li, bj ? -1 - lj : lj, ik.value(), im.value()});
    }
  }
  SumAll(kbb);
  SumAll(mbb);
  // entries to the other processes (none to itself: its own stay here)
  // byte counts of MPI are ints: every process checks its own and all agree before exchanging
  std::vector<int> send(size), recv(size), sdisp(size, 0), rdisp(size, 0);
  int64_t stotal = 0;
  for (int r = 0; r < size; ++r) {
    const int64_t bytes = r == rank ? 0 : static_cast<int64_t>(out[static_cast<size_t>(r)].size() * sizeof(Entry));
    send[r] = static_cast<int>(std::min<int64_t>(bytes, INT_MAX));
    stotal += bytes;
  }
  int too_many = stotal > INT_MAX ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &too_many, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  if (too_many) throw NumericalError("more than 2 GB of matrix entries to exchange at once: run on more processes", kWhere);
  MPI_Alltoall(send.data(), 1, MPI_INT, recv.data(), 1, MPI_INT, PETSC_COMM_WORLD);
  std::vector<char> sbuf;
  int64_t rtotal = 0;
  stotal = 0;
  for (int r = 0; r < size; ++r) {
    sdisp[r] = static_cast<int>(stotal);
    rdisp[r] = static_cast<int>(rtotal);
    stotal += send[r];
    rtotal += recv[r];
  }
  too_many = rtotal > INT_MAX ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &too_many, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  if (too_many) throw NumericalError("more than 2 GB of matrix entries to receive at once: run on more processes", kWhere);
  sbuf.resize(static_cast<size_t>(stotal));
  for (int r = 0; r < size; ++r) {
    if (send[r] > 0) std::memcpy(sbuf.data() + sdisp[r], out[static_cast<size_t>(r)].data(), send[r]);
    if (r != rank) std::vector<Entry>().swap(out[static_cast<size_t>(r)]);
  }
  std::vector<Entry> mine = std::move(out[static_cast<size_t>(rank)]);
  const size_t own = mine.size();
  mine.resize(own + static_cast<size_t>(rtotal) / sizeof(Entry));
  MPI_Alltoallv(sbuf.data(), send.data(), sdisp.data(), MPI_BYTE, reinterpret_cast<char*>(mine.data() + own),
                recv.data(), rdisp.data(), MPI_BYTE, PETSC_COMM_WORLD);
  std::vector<char>().swap(sbuf);
  std::sort(mine.begin(), mine.end(),
            [](const Entry& x, const Entry& y) { return x.row != y.row ? x.row < y.row : x.col < y.col; });

  LocalRows l;
  l.begin = begin[rank];
  l.rows = begin[rank + 1] - begin[rank];
  l.ii_ptr.assign(static_cast<size_t>(l.rows) + 1, 0);
  l.ib_ptr.assign(static_cast<size_t>(l.rows) + 1, 0);
  for (size_t p = 0; p < mine.size();) {
    const Entry& e = mine[p];
    double k = 0.0, m = 0.0;
    size_t q = p;
    for (; q < mine.size() && mine[q].row == e.row && mine[q].col == e.col; ++q) {
      k += mine[q].k;
      m += mine[q].m;
    }
    const PetscInt r = e.row - l.begin;
    if (e.col >= 0) {
      l.ii_col.push_back(e.col);
      l.ii_k.push_back(k);
      l.ii_m.push_back(m);
      ++l.ii_ptr[static_cast<size_t>(r) + 1];
    } else {
      l.ib_col.push_back(-1 - e.col);
      l.ib_k.push_back(k);
      l.ib_m.push_back(m);
      ++l.ib_ptr[static_cast<size_t>(r) + 1];
    }
    p = q;
  }
  for (PetscInt r = 0; r < l.rows; ++r) {
    l.ii_ptr[static_cast<size_t>(r) + 1] += l.ii_ptr[static_cast<size_t>(r)];
    l.ib_ptr[static_cast<size_t>(r) + 1] += l.ib_ptr[static_cast<size_t>(r)];
  }
  return l;
}

// The diagonal of K and M at this process's interior rows (row r: column
// begin + r), and on rank 0 also at the boundary: the ratios of
// StiffnessScale, whose median is taken on rank 0 and broadcast.
double DistributedStiffnessScale(const LocalRows& l, const Eigen::MatrixXd& kbb, const Eigen::MatrixXd& mbb) {
  std::vector<double> ratio;
  for (PetscInt r = 0; r < l.rows; ++r) {
    for (PetscInt p = l.ii_ptr[r]; p < l.ii_ptr[r + 1]; ++p) {
      if (l.ii_col[p] != l.begin + r) continue;
      if (l.ii_k[p] > 0.0 && l.ii_m[p] > 0.0) ratio.push_back(l.ii_k[p] / l.ii_m[p]);
    }
  }
  if (Rank() == 0) {
    for (Eigen::Index b = 0; b < kbb.rows(); ++b)
      if (kbb(b, b) > 0.0 && mbb(b, b) > 0.0) ratio.push_back(kbb(b, b) / mbb(b, b));
  }
  const int size = Size();
  int count = static_cast<int>(ratio.size());
  std::vector<int> counts(size), disp(size, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, PETSC_COMM_WORLD);
  std::vector<double> all;
  if (Rank() == 0) {
    for (int r = 1; r < size; ++r) disp[r] = disp[r - 1] + counts[r - 1];
    all.resize(static_cast<size_t>(disp[size - 1] + counts[size - 1]));
  }
  MPI_Gatherv(ratio.data(), count, MPI_DOUBLE, all.data(), counts.data(), disp.data(), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  double scale = 1.0;
  if (Rank() == 0 && !all.empty()) {
    auto mid = all.begin() + static_cast<std::ptrdiff_t>(all.size() / 2);
    std::nth_element(all.begin(), mid, all.end());
    scale = *mid;
  }
  MPI_Bcast(&scale, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  return scale;
}

// The rigid-body vectors r at the boundary and at this process's rows, if
// the body is free (K r = 0): then the static solve's round-off along them
// is removed from Psi (RemoveRigidRoundOff of the serial path).
struct RigidVectors {
  bool free = false;
  Eigen::MatrixXd rb, ri;  // n_b x 6, this process's interior rows x 6
};
RigidVectors FreeBodyRigidVectors(const fe::Mesh& mesh, const fe::AssembledModel& a, const InterfaceSplit& split,
                                  const LocalRows& l, const Eigen::MatrixXd& kbb) {
  RigidVectors out;
  const int nb = static_cast<int>(split.boundary.size());
  if (nb == 0) return out;
  fe::Vec3 origin = fe::Vec3::Zero();
  for (const fe::Node& node : mesh.nodes) origin += node.x;
  origin /= static_cast<double>(std::max<size_t>(mesh.nodes.size(), 1));
  const Eigen::MatrixXd r = RigidBodyVectors(mesh, a.dofs, origin);
  Eigen::MatrixXd rb(nb, 6);
  for (int j = 0; j < nb; ++j) rb.row(j) = r.row(split.boundary[j]);
  auto ri = [&](PetscInt li) { return r.row(split.interior[static_cast<size_t>(li)]); };
  // |K r|^2 and |K|_F^2 of the whole matrix, from the interior rows and the boundary block
  double kr2 = 0.0, k2 = 0.0;
  Eigen::MatrixXd kbi_ri = Eigen::MatrixXd::Zero(nb, 6);
  for (PetscInt row = 0; row < l.rows; ++row) {
    Eigen::Matrix<double, 1, 6> v = Eigen::Matrix<double, 1, 6>::Zero();
    for (PetscInt p = l.ii_ptr[row]; p < l.ii_ptr[row + 1]; ++p) {
      v += l.ii_k[p] * ri(l.ii_col[p]);
      k2 += l.ii_k[p] * l.ii_k[p];
    }
    for (PetscInt p = l.ib_ptr[row]; p < l.ib_ptr[row + 1]; ++p) {
      v += l.ib_k[p] * rb.row(l.ib_col[p]);
      kbi_ri.row(l.ib_col[p]) += l.ib_k[p] * ri(l.begin + row);
      k2 += 2.0 * l.ib_k[p] * l.ib_k[p];
    }
    kr2 += v.squaredNorm();
  }
  SumAll(kbi_ri);
  kr2 = SumAll(kr2) + (kbi_ri + kbb * rb).squaredNorm();
  k2 = SumAll(k2) + kbb.squaredNorm();
  if (std::sqrt(kr2) > 1e-10 * std::sqrt(k2) * r.norm()) return out;
  out.free = true;
  out.rb = rb;
  out.ri.resize(l.rows, 6);
  for (PetscInt row = 0; row < l.rows; ++row) out.ri.row(row) = ri(l.begin + row);
  return out;
}


// A distributed dense matrix over this process's rows of `local` (copied).
void DenseOf(const Block& local, int n_rows, Mat* out) {
  FLEXMB_PETSC(MatCreateDense(PETSC_COMM_WORLD, static_cast<PetscInt>(local.rows()), PETSC_DECIDE, n_rows,
                              static_cast<PetscInt>(local.cols()), nullptr, out));
  PetscScalar* a = nullptr;
  PetscInt lda = 0;
  FLEXMB_PETSC(MatDenseGetLDA(*out, &lda));
  FLEXMB_PETSC(MatDenseGetArrayWrite(*out, &a));
  for (Eigen::Index j = 0; j < local.cols(); ++j) std::copy_n(local.col(j).data(), local.rows(), a + j * lda);
  FLEXMB_PETSC(MatDenseRestoreArrayWrite(*out, &a));
}

// This process's rows of a distributed dense matrix.
Block LocalBlock(Mat x) {
  PetscInt rows = 0, cols = 0, lda = 0;
  FLEXMB_PETSC(MatGetLocalSize(x, &rows, nullptr));
  FLEXMB_PETSC(MatGetSize(x, nullptr, &cols));
  FLEXMB_PETSC(MatDenseGetLDA(x, &lda));
  const PetscScalar* a = nullptr;
  FLEXMB_PETSC(MatDenseGetArrayRead(x, &a));
  Block out(rows, cols);
  for (PetscInt j = 0; j < cols; ++j) std::copy_n(a + j * lda, rows, out.col(j).data());
  FLEXMB_PETSC(MatDenseRestoreArrayRead(x, &a));
  return out;
}

// A^T (S B) summed over the processes, for the rows of A and B here and the
// distributed sparse S: the interior part of H^T M H and Phi^T K Phi.
Eigen::MatrixXd ProjectedProduct(Mat s, const Block& a, const Block& b, int n_rows) {
  if (a.cols() == 0 || b.cols() == 0) return Eigen::MatrixXd::Zero(a.cols(), b.cols());
  OwnedMat bd, w;
  DenseOf(b, n_rows, &bd);
  FLEXMB_PETSC(MatMatMult(s, bd, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &w));
  Eigen::MatrixXd out = a.transpose() * LocalBlock(w);
  SumAll(out);
  return out;
}

// sum over this process's rows i of C_ib(i, :)^T A(i, :), summed over the
// processes: K_bi Psi and M_bi H_i from the local boundary columns.
Eigen::MatrixXd BoundaryProduct(const LocalRows& l, const std::vector<double>& c, int nb, const Block& a) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(nb, a.cols());
  for (PetscInt row = 0; row < l.rows; ++row) {
    for (PetscInt p = l.ib_ptr[row]; p < l.ib_ptr[row + 1]; ++p) out.row(l.ib_col[p]) += c[p] * a.row(row);
  }
  SumAll(out);
  return out;
}

// The `count` lowest eigenpairs of K_ii phi = lambda M_ii phi by SLEPc's
// Krylov-Schur with shift-and-invert at 0 on `ksp` (K_ii's factor):
// this process's rows of the M-normalized modes, frequencies on all.
fe::ModalResult SolveModes(Mat k, Mat m, KSP ksp, int count, double tolerance) {
  fe::ModalResult out;
  PetscInt rows = 0;
  FLEXMB_PETSC(MatGetLocalSize(k, &rows, nullptr));
  out.modes.resize(rows, count);
  out.frequencies_hz.resize(count);
  if (count == 0) return out;
  OwnedEps eps;
  FLEXMB_PETSC(EPSCreate(PETSC_COMM_WORLD, &eps));
  FLEXMB_PETSC(EPSSetOperators(eps, k, m));
  FLEXMB_PETSC(EPSSetProblemType(eps, EPS_GHEP));
  FLEXMB_PETSC(EPSSetType(eps, EPSKRYLOVSCHUR));
  FLEXMB_PETSC(EPSSetDimensions(eps, count, PETSC_DEFAULT, PETSC_DEFAULT));
  FLEXMB_PETSC(EPSSetTolerances(eps, tolerance, PETSC_DEFAULT));
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
  if (converged < count) {
    throw NumericalError("SLEPc found " + std::to_string(converged) + " of the " + std::to_string(count) +
                             " fixed-interface modes asked",
                         kWhere);
  }
  OwnedVec v, mv;
  FLEXMB_PETSC(MatCreateVecs(k, &v, &mv));
  std::vector<std::pair<double, int>> order;
  Block modes(rows, count);
  for (int j = 0; j < count; ++j) {
    PetscScalar lambda = 0.0, vmv = 0.0;
    FLEXMB_PETSC(EPSGetEigenpair(eps, j, &lambda, nullptr, v, nullptr));
    FLEXMB_PETSC(MatMult(m, v, mv));
    FLEXMB_PETSC(VecDot(v, mv, &vmv));
    if (!(vmv > 0.0)) throw NumericalError("SLEPc returned a fixed-interface mode without mass", kWhere);
    const PetscScalar* va = nullptr;
    FLEXMB_PETSC(VecGetArrayRead(v, &va));
    modes.col(j) = Eigen::Map<const Eigen::VectorXd>(va, rows) / std::sqrt(vmv);
    FLEXMB_PETSC(VecRestoreArrayRead(v, &va));
    order.emplace_back(lambda, j);
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });  // ascending
  for (int j = 0; j < count; ++j) {
    const double lambda = order[static_cast<size_t>(j)].first;
    out.modes.col(j) = modes.col(order[static_cast<size_t>(j)].second);
    out.frequencies_hz[j] = std::copysign(std::sqrt(std::abs(lambda)), lambda) / (2.0 * M_PI);
  }
  return out;
}

// Every array of the invariants in one vector, or back (to sum them).
void Flatten(InertiaInvariants& v, std::vector<double>& flat, bool gather) {
  size_t pos = 0;
  auto one = [&](double* data, Eigen::Index count) {
    if (gather) {
      flat.insert(flat.end(), data, data + count);
    } else {
      std::copy_n(flat.data() + pos, count, data);
    }
    pos += static_cast<size_t>(count);
  };
  auto mats3 = [&](std::vector<Mat3>& list) {
    for (Mat3& m : list) one(m.data(), 9);
  };
  one(v.mvv.data(), 9);
  one(v.mvo0.data(), 9);
  mats3(v.mvo1);
  one(v.mvw.data(), v.mvw.size());
  one(v.moo0.data(), 9);
  mats3(v.moo1);
  mats3(v.moo2);
  one(v.mow0.data(), v.mow0.size());
  for (MatX& m : v.mow1) one(m.data(), m.size());
  one(v.mww.data(), v.mww.size());
}

}  // namespace

MpiSession::MpiSession() {
  Check(SlepcInitialize(nullptr, nullptr, nullptr, nullptr), "SlepcInitialize");
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  rank_ = Rank();
  size_ = Size();
}

MpiSession::~MpiSession() { SlepcFinalize(); }

ReducedBody ReduceCraigBamptonPetsc(const fe::FeModel& model, const ReductionOptions& options_in,
                                    ReductionTimings* timings) {
  const fe::Mesh& mesh = model.mesh;
  const ReductionOptions options = PrepareReductionOptions(mesh, options_in);
  const ErrorContext where{mesh.source, 0, "distributed reduction (--backend petsc)"};
  if (model.imported) {
    throw InputError("imported matrices have no elements to share out among the processes: reduce them without "
                     "--backend petsc",
                     where);
  }
  if (options.acceleration_modes)
    throw InputError("the acceleration modes are not distributed yet: reduce without --backend petsc", where);
  if (options.geometric_stiffening || options.deformation_stiffening) {
    throw InputError("the stiffening options are not distributed yet: reduce without --backend petsc", where);
  }
  ReductionTimings local_timings;
  ReductionTimings& t = timings != nullptr ? *timings : local_timings;
  t = ReductionTimings{};
  const int rank = Rank(), size = Size();

  // 1. this process's share of the elements, the DOF split, the rows it owns
  double t0 = MPI_Wtime();
  fe::AssemblyOptions assembly = ReductionAssemblyOptions(options);
  assembly.block_subset = BlockShare(mesh, rank, size);
  // an element's errors now arise on its process only: agreed on by all
  const fe::AssembledModel a = Agreed([&] { return fe::BuildMatrices(model, assembly); });
  const InterfaceSplit split = SplitInterface(mesh, a, options);
  const int nb = static_cast<int>(split.boundary.size());
  const int ni = static_cast<int>(split.interior.size());
  const std::vector<PetscInt> begin = RowSplit(ni, size);
  Eigen::MatrixXd kbb, mbb;
  LocalRows l = ExchangeEntries(a, split, begin, kbb, mbb);
  CraigBamptonBasis basis;
  basis.boundary = split.boundary;
  basis.interior = split.interior;
  basis.stiffness_scale = DistributedStiffnessScale(l, kbb, mbb);
  OwnedMat k, m;
  FLEXMB_PETSC(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, l.rows, l.rows, ni, ni, l.ii_ptr.data(), l.ii_col.data(),
                                         l.ii_k.data(), &k));
  FLEXMB_PETSC(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, l.rows, l.rows, ni, ni, l.ii_ptr.data(), l.ii_col.data(),
                                         l.ii_m.data(), &m));
  FLEXMB_PETSC(MatSetOption(k, MAT_SYMMETRIC, PETSC_TRUE));
  FLEXMB_PETSC(MatSetOption(m, MAT_SYMMETRIC, PETSC_TRUE));
  if (split.normal_modes > 0) {
    double m_max = 0.0;
    for (PetscInt r = 0; r < l.rows; ++r)
      for (PetscInt p = l.ii_ptr[r]; p < l.ii_ptr[r + 1]; ++p)
        if (l.ii_col[p] == l.begin + r) m_max = std::max(m_max, l.ii_m[p]);
    MPI_Allreduce(MPI_IN_PLACE, &m_max, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
    RequireInteriorMass(m_max, mesh.source);
  }
  const RigidVectors rigid = FreeBodyRigidVectors(mesh, a, split, l, kbb);
  // the interior block lives on in k and m (PETSc copied it)
  for (auto* v : {&l.ii_col}) std::vector<PetscInt>().swap(*v);
  for (auto* v : {&l.ii_k, &l.ii_m}) std::vector<double>().swap(*v);
  t.assemble = MPI_Wtime() - t0;

  // 2. K_ii = L D L^T by MUMPS (symmetric indefinite, SYM = 2, with null
  // pivot detection): negative or zero pivots are a mechanism in the body
  t0 = MPI_Wtime();
  OwnedKsp ksp;
  FLEXMB_PETSC(KSPCreate(PETSC_COMM_WORLD, &ksp));
  FLEXMB_PETSC(KSPSetOperators(ksp, k, k));
  FLEXMB_PETSC(KSPSetType(ksp, KSPPREONLY));
  PC pc = nullptr;
  FLEXMB_PETSC(KSPGetPC(ksp, &pc));
  FLEXMB_PETSC(PCSetType(pc, PCCHOLESKY));
  FLEXMB_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  FLEXMB_PETSC(KSPSetFromOptions(ksp));  // MUMPS settings from PETSC_OPTIONS, e.g. -mat_mumps_icntl_14
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
    const std::string what = reason != PC_NOERROR ? std::string(PCFailedReasons[reason])
                                                   : std::to_string(negative) + " negative and " +
                                                         std::to_string(null) + " zero pivots";
    throw NumericalError("K_ii (the stiffness with the " + std::to_string(options.interface_nodes.size()) +
                             " interface nodes held" +
                             (options.fixed_nodes.empty() ? "" : " and the fixed nodes clamped") +
                             ") is not positive definite (MUMPS: " + what +
                             "): a mechanism, a DOF without stiffness, or a negative stiffness; the reduction without "
                             "--backend petsc names the node",
                         {mesh.source, 0, "Craig-Bampton reduction"});
  }
  t.factorize = MPI_Wtime() - t0;

  // 3. static modes: K_ii Psi = -K_ib, all columns in one MatMatSolve
  t0 = MPI_Wtime();
  Block psi(l.rows, nb);
  if (nb > 0) {
    Block rhs = Block::Zero(l.rows, nb);
    for (PetscInt row = 0; row < l.rows; ++row)
      for (PetscInt p = l.ib_ptr[row]; p < l.ib_ptr[row + 1]; ++p) rhs(row, l.ib_col[p]) = -l.ib_k[p];
    OwnedMat b, x;
    DenseOf(rhs, ni, &b);
    FLEXMB_PETSC(MatCreateDense(PETSC_COMM_WORLD, l.rows, PETSC_DECIDE, ni, nb, nullptr, &x));
    FLEXMB_PETSC(MatMatSolve(factor, b, x));
    psi = LocalBlock(x);
    if (rigid.free) ProjectRigidMotions(rigid.rb, rigid.ri, psi);
  }
  t.static_modes = MPI_Wtime() - t0;

  // 4. fixed-interface normal modes on the same factor, up to the cut-off
  t0 = MPI_Wtime();
  const double tolerance = options.eigen_tolerance > 0.0 ? options.eigen_tolerance : 1e-12;
  auto solve = [&](int c) { return SolveModes(k, m, ksp, c, tolerance); };
  fe::ModalResult modes = split.normal_modes > 0 ? SolveUpToCutoff(split.normal_modes, ni, options.cutoff_hz, solve)
                                                 : solve(0);
  const Block& phi = modes.modes;
  const int nf = static_cast<int>(phi.cols());
  basis.fixed_interface_hz = modes.frequencies_hz;
  t.normal_modes = MPI_Wtime() - t0;

  // 5. reduced matrices, coordinates (u_b, eta), summed over the processes
  t0 = MPI_Wtime();
  const int mm = nb + nf;
  Block hi(l.rows, mm);
  hi.leftCols(nb) = psi;
  hi.rightCols(nf) = phi;
  {
    Eigen::MatrixXd out = ProjectedProduct(m, hi, hi, ni);
    const Eigen::MatrixXd mbi_h = BoundaryProduct(l, l.ib_m, nb, hi);
    out.topRows(nb) += mbi_h;
    out.leftCols(nb) += mbi_h.transpose();
    out.topLeftCorner(nb, nb) += mbb;
    basis.mass = 0.5 * (out + out.transpose());
  }
  {
    basis.stiffness = Eigen::MatrixXd::Zero(mm, mm);
    const Eigen::MatrixXd kbi_psi = BoundaryProduct(l, l.ib_k, nb, psi);
    basis.stiffness.topLeftCorner(nb, nb) = kbb + 0.5 * (kbi_psi + kbi_psi.transpose());
    if (nf > 0) {
      const Eigen::MatrixXd kff = ProjectedProduct(k, phi, phi, ni);
      basis.stiffness.bottomRightCorner(nf, nf) = 0.5 * (kff + kff.transpose());
    }
  }
  // every process decides on rank 0's bits (rigid modes, keep, the sizes gathered in expand)
  MPI_Bcast(basis.mass.data(), static_cast<int>(basis.mass.size()), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  MPI_Bcast(basis.stiffness.data(), static_cast<int>(basis.stiffness.size()), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  // no rows of Psi and Phi in the basis itself: only their counts
  basis.psi.resize(0, nb);
  basis.phi.resize(0, nf);
  t.orthonormalize = MPI_Wtime() - t0;

  // 6. the serial steps on the reduced matrices; H y and the invariants here
  DistributedSteps steps;
  steps.root = rank == 0;
  steps.expand = [&](const Eigen::MatrixXd& y) {
    const int cols = static_cast<int>(y.cols());
    // this process's rows of H_i y, row-major, gathered on rank 0
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> part = hi * y;
    std::vector<int> counts(size), disp(size);
    for (int r = 0; r < size; ++r) {
      const int64_t c = static_cast<int64_t>(begin[r + 1] - begin[r]) * cols, d = int64_t{begin[r]} * cols;
      if (d + c > INT_MAX) throw NumericalError("the mode matrix is too large to gather at once", kWhere);
      counts[r] = static_cast<int>(c);
      disp[r] = static_cast<int>(d);
    }
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> all;
    if (rank == 0) all.resize(ni, cols);
    MPI_Gatherv(part.data(), counts[rank], MPI_DOUBLE, all.data(), counts.data(), disp.data(), MPI_DOUBLE, 0,
                PETSC_COMM_WORLD);
    Eigen::MatrixXd u;
    if (rank != 0) return u;
    u.resize(nb + ni, cols);
    for (int j = 0; j < nb; ++j) u.row(basis.boundary[j]) = y.row(j);
    for (int i = 0; i < ni; ++i) u.row(basis.interior[i]) = all.row(i);
    return u;
  };
  // every process needs the modes of its share's nodes: the whole matrix,
  // broadcast column by column for the invariants and kept for the stress modes
  MatX modes_here;
  steps.invariants = [&](const MatX& root_modes, const MatX& modal_mass) {
    Eigen::Index rows = root_modes.rows(), cols = root_modes.cols();
    MPI_Bcast(&rows, sizeof rows, MPI_BYTE, 0, PETSC_COMM_WORLD);
    MPI_Bcast(&cols, sizeof cols, MPI_BYTE, 0, PETSC_COMM_WORLD);
    if (rank != 0) modes_here.resize(rows, cols);
    const MatX& m_all = rank == 0 ? root_modes : modes_here;
    for (Eigen::Index j = 0; j < cols; ++j)
      MPI_Bcast(const_cast<double*>(m_all.col(j).data()), static_cast<int>(rows), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
    const MatX& modes_here_ref = m_all;
    // mww is the modal mass, as on one process (every process is handed it, so the sum is not)
    InertiaInvariants inv = ComputeInertiaInvariants(mesh, a, modes_here_ref, &modal_mass, rank == 0);
    std::vector<double> flat;
    Flatten(inv, flat, true);
    if (flat.size() > static_cast<size_t>(INT_MAX)) throw NumericalError("too many invariants to sum", kWhere);
    MPI_Reduce(rank == 0 ? MPI_IN_PLACE : flat.data(), flat.data(), static_cast<int>(flat.size()), MPI_DOUBLE, MPI_SUM,
               0, PETSC_COMM_WORLD);
    Flatten(inv, flat, false);
    inv.mww = 0.5 * (modal_mass + modal_mass.transpose());
    return inv;
  };
  steps.stress = [&](const MatX& root_modes) {
    // this process's elements; the others' rows and axes are zero, so the sum is the whole
    const std::vector<char> elements(assembly.block_subset.begin(),
                                     assembly.block_subset.begin() + static_cast<std::ptrdiff_t>(mesh.elements.size()));
    StressModes stress =
        ComputeStressModes(mesh, rank == 0 ? root_modes : modes_here, options.solid_corner_stress, &elements);
    for (StressTable* t : {&stress.shell, &stress.beam, &stress.solid, &stress.beam_fibre, &stress.solid_node}) {
      SumOnRoot(t->modes);
      Eigen::MatrixXd axes(9, static_cast<Eigen::Index>(t->axes.size()));  // one column per element
      for (size_t e = 0; e < t->axes.size(); ++e)
        axes.col(static_cast<Eigen::Index>(e)) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(t->axes[e].data());
      SumAll(axes);
      for (size_t e = 0; e < t->axes.size(); ++e)
        t->axes[e] = Eigen::Map<const Mat3>(axes.col(static_cast<Eigen::Index>(e)).data());
    }
    return stress;
  };
  return ReduceBasis(model, a, basis, options, &t, &steps);
}

}  // namespace flexmb::reduction::petsc
