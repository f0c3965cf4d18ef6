#include "flexmb/reduction/craig_bampton_basis.h"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <exception>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/process_tuning.h"
#include "flexmb/fe/block_lanczos.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe/sparse_cholesky.h"
#include "flexmb/reduction/parallel_rows.h"
#include "flexmb/reduction/rigid_modes.h"

namespace flexmb::reduction {

namespace {

using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// the interior and boundary blocks of a symmetric free x free matrix
struct Blocks {
  fe::SparseMat ii;     // n_i x n_i
  fe::SparseMat ib;     // n_i x n_b
  Eigen::MatrixXd bb;   // n_b x n_b
};

Blocks SplitMatrix(const fe::SparseMat& a, const std::vector<int>& local, const std::vector<char>& is_b, int ni,
                   int nb) {
  Blocks out;
  out.bb = Eigen::MatrixXd::Zero(nb, nb);
  std::vector<int> ii_ptr(ni + 1, 0), ib_ptr(nb + 1, 0);
  for (int j = 0; j < a.outerSize(); ++j) {
    for (fe::SparseMat::InnerIterator it(a, j); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (is_b[i]) {
        if (is_b[j]) out.bb(local[i], local[j]) = it.value();
      } else if (is_b[j]) {
        ++ib_ptr[local[j] + 1];
      } else {
        ++ii_ptr[local[j] + 1];
      }
    }
  }
  for (int k = 0; k < ni; ++k) ii_ptr[k + 1] += ii_ptr[k];
  for (int k = 0; k < nb; ++k) ib_ptr[k + 1] += ib_ptr[k];
  out.ii.resize(ni, ni);
  out.ii.resizeNonZeros(ii_ptr[ni]);
  out.ib.resize(ni, nb);
  out.ib.resizeNonZeros(ib_ptr[nb]);
  std::copy(ii_ptr.begin(), ii_ptr.end(), out.ii.outerIndexPtr());
  std::copy(ib_ptr.begin(), ib_ptr.end(), out.ib.outerIndexPtr());
  // rows come in ascending free order, and local numbering keeps that order
  for (int j = 0; j < a.outerSize(); ++j) {
    fe::SparseMat& target = is_b[j] ? out.ib : out.ii;
    int p = target.outerIndexPtr()[local[j]];
    for (fe::SparseMat::InnerIterator it(a, j); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (is_b[i]) continue;
      target.innerIndexPtr()[p] = local[i];
      target.valuePtr()[p] = it.value();
      ++p;
    }
  }
  return out;
}

// A free body: K r = 0 for the rigid-body vectors r, so Psi r_b = r_i
// exactly; removes the static solve's round-off along these six directions
// from basis.psi, so that the basis holds the rigid motions exactly (and the
// flexible modes are M-orthogonal to them to round-off). Nothing for a body
// that is held (K r != 0) or has no boundary.
void RemoveRigidRoundOff(const fe::Mesh& mesh, const fe::AssembledModel& model, CraigBamptonBasis& basis) {
  const int nb = basis.static_modes(), ni = static_cast<int>(basis.interior.size());
  if (nb == 0) return;
  fe::Vec3 origin = fe::Vec3::Zero();
  for (const fe::Node& node : mesh.nodes) origin += node.x;
  origin /= static_cast<double>(std::max<size_t>(mesh.nodes.size(), 1));
  const Eigen::MatrixXd r = RigidBodyVectors(mesh, model.dofs, origin);
  const Eigen::MatrixXd kr = model.K * r;
  const double k_norm = Eigen::Map<const Eigen::VectorXd>(model.K.valuePtr(), model.K.nonZeros()).norm();
  if (kr.norm() > 1e-10 * k_norm * r.norm()) return;
  Eigen::MatrixXd rb(nb, 6), ri(ni, 6);
  for (int j = 0; j < nb; ++j) rb.row(j) = r.row(basis.boundary[j]);
  for (int j = 0; j < ni; ++j) ri.row(j) = r.row(basis.interior[j]);
  ProjectRigidMotions(rb, ri, basis.psi);
}

// Appends to basis.phi the acceleration modes: K_ii^-1 (M r)_i for the six
// rigid-body vectors r (about the nodes' centroid), each M_ii-orthogonalized
// against the columns before it (twice, classical Gram-Schmidt) and
// normalized; one already in their span (below 1e-4 of its norm) is left out.
void AppendAccelerationModes(const fe::Mesh& mesh, const fe::AssembledModel& model, const fe::SparseMat& k_ii,
                             const fe::SparseMat& m_ii, const fe::SparseCholesky& factor, CraigBamptonBasis& basis) {
  const int ni = static_cast<int>(basis.interior.size());
  fe::Vec3 origin = fe::Vec3::Zero();
  for (const fe::Node& node : mesh.nodes) origin += node.x;
  origin /= static_cast<double>(std::max<size_t>(mesh.nodes.size(), 1));
  // the inertial loads through the mass of every active DOF (T^T M_full
  // r_full): the mass that couples to clamped or constrained DOF loads the
  // interior too (T r_free is zero there)
  const Eigen::MatrixXd mr = model.M_full.rows() == model.dofs.n_full && model.T.rows() == model.dofs.n_full
                                 ? Eigen::MatrixXd(model.T.transpose() *
                                                   (model.M_full * RigidBodyVectorsFull(mesh, model.dofs, origin)))
                                 : Eigen::MatrixXd(model.M * RigidBodyVectors(mesh, model.dofs, origin));
  Eigen::MatrixXd load(ni, 6);
  for (int j = 0; j < ni; ++j) load.row(j) = mr.row(basis.interior[j]);
  const Eigen::MatrixXd a = factor.Solve(load);
  const int nf = static_cast<int>(basis.phi.cols());
  Eigen::MatrixXd phi(ni, nf + 6);
  phi.leftCols(nf) = basis.phi;
  std::vector<double> hz(basis.fixed_interface_hz.data(), basis.fixed_interface_hz.data() + nf);
  int n = nf;
  for (int c = 0; c < 6; ++c) {
    Eigen::VectorXd v = a.col(c);
    const double norm0 = std::sqrt(std::max(0.0, v.dot(m_ii * v)));
    if (!(norm0 > 0.0)) continue;  // no mass moves in this direction
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd mv = m_ii * v;
      v -= phi.leftCols(n) * (phi.leftCols(n).transpose() * mv);
    }
    const double norm = std::sqrt(std::max(0.0, v.dot(m_ii * v)));
    // nearly in the span already: normalizing the remainder would scale the
    // solve's round-off (about the model's condition times 1e-16) by 1 / ratio
    if (!(norm > 1e-4 * norm0)) continue;
    v /= norm;
    phi.col(n) = v;
    hz.push_back(std::sqrt(std::max(0.0, v.dot(k_ii * v))) / (2.0 * 3.14159265358979323846));
    ++n;
  }
  basis.phi = phi.leftCols(n);
  basis.fixed_interface_hz = Eigen::Map<const Eigen::VectorXd>(hz.data(), static_cast<Eigen::Index>(hz.size()));
  basis.acceleration_modes = n - nf;
}

}  // namespace

double StiffnessScale(const fe::SparseMat& k, const fe::SparseMat& m) {
  std::vector<double> ratio;
  ratio.reserve(static_cast<size_t>(k.rows()));
  const Eigen::VectorXd kd = k.diagonal(), md = m.diagonal();
  for (Eigen::Index i = 0; i < kd.size(); ++i) {
    if (kd[i] > 0.0 && md[i] > 0.0) ratio.push_back(kd[i] / md[i]);
  }
  if (ratio.empty()) return 1.0;
  auto mid = ratio.begin() + static_cast<std::ptrdiff_t>(ratio.size() / 2);
  std::nth_element(ratio.begin(), mid, ratio.end());
  return *mid;
}

Eigen::MatrixXd CraigBamptonBasis::Expand(const Eigen::MatrixXd& q) const {
  const int nb = static_cast<int>(boundary.size()), nf = normal_modes();
  if (q.rows() != nb + nf) throw InputError("Craig-Bampton basis: reduced coordinates of the wrong size");
  const Eigen::Index ni = static_cast<Eigen::Index>(interior.size());
  Eigen::MatrixXd u(boundary.size() + interior.size(), q.cols());
  if (q.cols() == 0) return u;  // no flexible modes (e.g. Guyan on one node): rows of empty blocks are UB
  for (int k = 0; k < nb; ++k) u.row(boundary[k]) = q.row(k);
  ParallelRows(ni, ParallelRanges(ni, 4096), [&](int, Eigen::Index b, Eigen::Index e) {
    Eigen::MatrixXd ui = psi.middleRows(b, e - b) * q.topRows(nb);
    if (nf > 0) ui.noalias() += phi.middleRows(b, e - b) * q.bottomRows(nf);
    for (Eigen::Index k = b; k < e; ++k) u.row(interior[k]) = ui.row(k - b);
  });
  return u;
}

void ProjectRigidMotions(const Eigen::MatrixXd& rb, const Eigen::MatrixXd& ri, Eigen::MatrixXd& psi) {
  const Eigen::MatrixXd g = rb.transpose() * rb;
  Eigen::LDLT<Eigen::MatrixXd> gl(g);
  if (gl.info() == Eigen::Success && gl.vectorD().minCoeff() > 1e-12 * gl.vectorD().maxCoeff()) {
    psi.noalias() += (ri - psi * rb) * gl.solve(rb.transpose());
  }
}

void RequireInteriorMass(double largest_diagonal, const std::string& source) {
  if (largest_diagonal > 0.0) return;
  throw NumericalError("the model has no mass at its interior DOF, so it has no fixed-interface modes: give its "
                       "materials a density (Nastran MAT1 RHO, Abaqus *DENSITY) or reduce with --modes 0 and "
                       "without --acceleration-modes",
                       {source, 0, "Craig-Bampton reduction"});
}

InterfaceSplit SplitInterface(const fe::Mesh& mesh, const fe::AssembledModel& model, const ReductionOptions& options) {
  const fe::DofMap& dm = model.dofs;
  const int nn = static_cast<int>(mesh.nodes.size());
  const int n = dm.n_free;
  auto node_name = [&](int node) { return "node " + std::to_string(mesh.nodes[node].id); };
  InterfaceSplit out;
  std::vector<char>& is_b = out.is_b;
  is_b.assign(static_cast<size_t>(n), 0);
  {
    const Eigen::SparseMatrix<double, Eigen::RowMajor, int> tr = model.T;
    for (int node : options.interface_nodes) {
      if (node < 0 || node >= nn) {
        throw InputError("interface node index " + std::to_string(node) + " does not exist (the mesh has " +
                             std::to_string(nn) + " nodes)",
                         {mesh.source, 0, "reduction options"});
      }
      bool active = false;
      for (int c = 0; c < 6; ++c) {
        const int f = dm.full[node][c];
        if (f < 0) continue;
        active = true;
        for (decltype(tr)::InnerIterator it(tr, f); it; ++it) is_b[it.col()] = 1;
      }
      if (!active) {
        const fe::Origin& o = mesh.nodes[node].origin;
        throw InputError("has no degrees of freedom: no element, mass or rigid link uses it",
                         {o.file.empty() ? mesh.source : o.file, o.line, "interface " + node_name(node)});
      }
    }
  }
  out.local.resize(static_cast<size_t>(n));
  for (int f = 0; f < n; ++f) {
    std::vector<int>& list = is_b[f] ? out.boundary : out.interior;
    out.local[f] = static_cast<int>(list.size());
    list.push_back(f);
  }
  const int ni = static_cast<int>(out.interior.size());
  if (ni == 0) throw InputError("Craig-Bampton reduction: every DOF is an interface DOF; nothing to reduce");
  const int count =
      options.cutoff_hz > 0.0 ? std::min(ni - 1, std::max(10, options.normal_modes)) : options.normal_modes;
  if (options.cutoff_hz <= 0.0 && count >= ni) {
    throw InputError(std::to_string(count) + " fixed-interface normal modes asked, but the body has only " +
                         std::to_string(ni) + " interior DOF (at most " + std::to_string(ni - 1) + ")",
                     {mesh.source, 0, "normal modes"});
  }
  out.normal_modes = count;
  return out;
}

CraigBamptonBasis BuildCraigBamptonBasis(const fe::Mesh& mesh, const fe::AssembledModel& model,
                                         const ReductionOptions& options, ReductionTimings* timings) {
  const fe::DofMap& dm = model.dofs;
  const int nn = static_cast<int>(mesh.nodes.size());
  const int n = dm.n_free;
  if (static_cast<int>(dm.free.size()) != nn || model.K.rows() != n || model.M.rows() != n ||
      model.T.cols() != n) {
    throw InputError("Craig-Bampton reduction: the assembled matrices do not belong to the mesh");
  }
  auto node_name = [&](int node) { return "node " + std::to_string(mesh.nodes[node].id); };
  ReductionTimings local_timings;
  ReductionTimings& t = timings != nullptr ? *timings : local_timings;
  auto t0 = Clock::now();

  // 1. boundary and interior; the number of normal modes, checked before any factorization
  InterfaceSplit split = SplitInterface(mesh, model, options);
  CraigBamptonBasis basis;
  basis.boundary = std::move(split.boundary);
  basis.interior = std::move(split.interior);
  const std::vector<char>& is_b = split.is_b;
  const std::vector<int>& local = split.local;
  const int nb = static_cast<int>(basis.boundary.size());
  const int ni = static_cast<int>(basis.interior.size());
  int count = split.normal_modes;

  // 2. K_ii factorization, named DOF on failure
  const Blocks k = SplitMatrix(model.K, local, is_b, ni, nb);
  const Blocks m = SplitMatrix(model.M, local, is_b, ni, nb);
  basis.stiffness_scale = StiffnessScale(model.K, model.M);
  std::vector<std::pair<int, int>> owner(n, {-1, -1});
  for (int node = 0; node < nn; ++node) {
    for (int c = 0; c < 6; ++c) {
      if (dm.free[node][c] >= 0) owner[dm.free[node][c]] = {node, c};
    }
  }
  auto describe = [&](int i) {
    const auto [node, c] = owner[basis.interior[i]];
    if (node < 0) return "interior DOF " + std::to_string(i);
    const fe::Origin& o = mesh.nodes[node].origin;
    const std::string where =
        o.file.empty() ? std::string() : " (" + o.file + (o.line > 0 ? ":" + std::to_string(o.line) : "") + ")";
    return node_name(node) + where + " component " + fe::kDofComponentNames[c];
  };
  // the eigen solvers need a mass: a deck written for statics often has none
  // (no density on its materials), which they would report only as a failed
  // decomposition
  if (count > 0 || options.acceleration_modes) {
    double m_max = 0.0;
    for (Eigen::Index i = 0; i < m.ii.rows(); ++i) m_max = std::max(m_max, m.ii.coeff(i, i));
    RequireInteriorMass(m_max, mesh.source);
  }
  fe::SparseCholesky factor;
  try {
    factor.Factorize(k.ii,
                     "K_ii (the stiffness with the " + std::to_string(options.interface_nodes.size()) +
                         " interface nodes held" + (options.fixed_nodes.empty() ? "" : " and the fixed nodes clamped") +
                         ")",
                     describe);
  } catch (const NumericalError& e) {
    const std::string hint =
        nb == 0 ? "; with no interface DOF the body must be held by fixed nodes or single-point constraints" : "";
    throw NumericalError(e.message() + hint, {mesh.source, 0, "Craig-Bampton reduction"});
  }
  t.factorize += Seconds(t0);

  // 3. static modes, all right-hand sides in one solve; 3 and 4 side by side
  // when there are cores for it: the static modes on a second thread while
  // this one runs the Lanczos iteration (both only read the factor; block
  // solves carry their own CHOLMOD workspace)
  auto static_modes = [&] {
    const auto ts = Clock::now();
    basis.psi = factor.Solve(-Eigen::MatrixXd(k.ib));
    RemoveRigidRoundOff(mesh, model, basis);
    t.static_modes += Seconds(ts);
  };
  std::exception_ptr static_error;
  std::thread static_thread;
  // two threads of ours, each in CHOLMOD's BLAS: one BLAS thread each
  std::optional<BlasThreadLimit> one_blas_thread;
  if (count > 0 && nb > 0 && ParallelRanges(2, 1) > 1) {
    one_blas_thread.emplace(1);
    static_thread = std::thread([&] {
      try {
        static_modes();
      } catch (...) {
        static_error = std::current_exception();
      }
    });
  } else {
    static_modes();
  }
  // joins the static thread on every way out of this function
  struct Joiner {
    std::thread& thread;
    ~Joiner() {
      if (thread.joinable()) thread.join();
    }
  } joiner{static_thread};

  // 4. fixed-interface normal modes on the same factor (shift 0: K_ii is positive definite)
  t0 = Clock::now();
  basis.phi.resize(ni, 0);
  basis.fixed_interface_hz.resize(0);
  if (count > 0) {
    // block shift-invert Lanczos (each pass over the factor serves a block of
    // vectors); Spectra if it does not converge. A relative residual of 1e-6
    // leaves the eigenvalues exact to about 1e-12 (the error is quadratic in
    // the residual) and the modes, which need only span the right space for
    // the reduction, accurate to 1e-6 over the relative gap: their effect on
    // the reduced frequencies is again quadratic, below 1e-11.
    auto solve = [&](int c) {
      if (options.eigen_solver == ReductionOptions::EigenSolver::kSpectra) {
        return fe::SolveModesFactorized(k.ii, m.ii, factor, 0.0, c, 1e-10, "fixed-interface modes");
      }
      fe::BlockLanczosOptions lanczos;
      lanczos.count = c;
      lanczos.tolerance = options.eigen_tolerance > 0.0 ? options.eigen_tolerance : 1e-6;
      try {
        return fe::SolveModesBlockLanczos(k.ii, m.ii, factor, 0.0, lanczos, "fixed-interface modes");
      } catch (const NumericalError&) {
        return fe::SolveModesFactorized(k.ii, m.ii, factor, 0.0, c, 1e-10, "fixed-interface modes");
      }
    };
    fe::ModalResult r = SolveUpToCutoff(count, ni, options.cutoff_hz, solve);
    basis.phi = std::move(r.modes);
    basis.fixed_interface_hz = std::move(r.frequencies_hz);
  }
  t.normal_modes += Seconds(t0);
  if (static_thread.joinable()) static_thread.join();
  one_blas_thread.reset();
  if (static_error) std::rethrow_exception(static_error);
  // 4b. acceleration modes on the same factor
  if (options.acceleration_modes) {
    t0 = Clock::now();
    AppendAccelerationModes(mesh, model, k.ii, m.ii, factor, basis);
    t.normal_modes += Seconds(t0);
  }

  // 5. reduced matrices, coordinates (u_b, eta)
  t0 = Clock::now();
  const int nf = static_cast<int>(basis.phi.cols());
  const int mm = nb + nf;
  const int ranges = ParallelRanges(ni, 4096);
  // H_i = [Psi Phi], row-major: the sparse product gathers its rows
  RowMat hi(ni, mm);
  ParallelRows(ni, ranges, [&](int, Eigen::Index b, Eigen::Index e) {
    hi.block(b, 0, e - b, nb) = basis.psi.middleRows(b, e - b);
    hi.block(b, nb, e - b, nf) = basis.phi.middleRows(b, e - b);
  });
  // H^T M H: each range forms its rows of W = M_ii H_i slab by slab (M_ii
  // symmetric: row r of W gathers column r of M_ii) and adds the upper
  // triangle of H_i(rows)^T W(rows)
  std::vector<Eigen::MatrixXd> partial(static_cast<size_t>(ranges));
  ParallelRows(ni, ranges, [&](int r, Eigen::Index b, Eigen::Index e) {
    constexpr Eigen::Index kSlab = 1024;
    RowMat w(std::min(kSlab, e - b), mm);
    Eigen::MatrixXd& sum = partial[static_cast<size_t>(r)];
    sum.setZero(mm, mm);
    for (Eigen::Index s0 = b; s0 < e; s0 += kSlab) {
      const Eigen::Index len = std::min(kSlab, e - s0);
      for (Eigen::Index row = s0; row < s0 + len; ++row) {
        auto wr = w.row(row - s0);
        wr.setZero();
        for (fe::SparseMat::InnerIterator it(m.ii, row); it; ++it) wr.noalias() += it.value() * hi.row(it.row());
      }
      sum.triangularView<Eigen::Upper>() += hi.middleRows(s0, len).transpose() * w.topRows(len);
    }
  });
  {
    // plus the boundary rows and columns: H = [[I, 0], [H_i]]
    Eigen::MatrixXd upper = partial[0];
    for (size_t r = 1; r < partial.size(); ++r) upper += partial[r];
    Eigen::MatrixXd out = upper.selfadjointView<Eigen::Upper>();
    const Eigen::MatrixXd mbi_h = Eigen::MatrixXd(m.ib.transpose() * hi);  // M_bi H_i, n_b x m
    out.topRows(nb) += mbi_h;
    out.leftCols(nb) += mbi_h.transpose();
    out.topLeftCorner(nb, nb) += m.bb;
    basis.mass = 0.5 * (out + out.transpose());
  }
  // H^T K H needs no product over the interior: K_ii Psi = -K_ib makes the
  // static block the Schur complement K_bb + K_bi Psi (the two Psi^T terms
  // cancel) and the coupling K_bi Phi + Psi^T K_ii Phi vanish exactly; the
  // normal block is Phi^T K_ii Phi (diag(omega^2) to the eigen solver's
  // residual, formed here to keep that residual's effect second order)
  {
    basis.stiffness = Eigen::MatrixXd::Zero(mm, mm);
    const Eigen::MatrixXd kbi_psi = Eigen::MatrixXd(k.ib.transpose() * basis.psi);
    basis.stiffness.topLeftCorner(nb, nb) = k.bb + 0.5 * (kbi_psi + kbi_psi.transpose());
    if (nf > 0) {
      const Eigen::MatrixXd k_phi = k.ii * basis.phi;
      const Eigen::MatrixXd kff = basis.phi.transpose() * k_phi;
      basis.stiffness.bottomRightCorner(nf, nf) = 0.5 * (kff + kff.transpose());
    }
  }
  t.orthonormalize += Seconds(t0);
  return basis;
}

}  // namespace flexmb::reduction
