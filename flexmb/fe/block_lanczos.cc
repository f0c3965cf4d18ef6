#include "flexmb/fe/block_lanczos.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/shift_invert.h"

namespace flexmb::fe {

namespace {

using Mat = Eigen::MatrixXd;

Mat RandomBlock(Eigen::Index n, Eigen::Index p, std::mt19937_64& gen) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mat v(n, p);
  for (Eigen::Index j = 0; j < p; ++j)
    for (Eigen::Index i = 0; i < n; ++i) v(i, j) = u(gen);
  return v;
}

// w -= Q Q^T w, twice (classical Gram-Schmidt with reorthogonalization);
// returns the coefficients Q^T w_in
Mat Project(const Mat& q, Eigen::Index k, Mat& w) {
  if (k == 0) return Mat::Zero(0, w.cols());
  const auto qk = q.leftCols(k);
  Mat c = qk.transpose() * w;
  w.noalias() -= qk * c;
  const Mat c2 = qk.transpose() * w;
  w.noalias() -= qk * c2;
  return c + c2;
}

// w (orthogonal to the first k columns of q) = V R with V orthonormal and
// orthogonal to them too; rank-deficient directions of w (R rows ~ 0) get
// random orthonormal replacements. Returns R, leaves V in w.
Mat Orthonormalize(Mat& w, const Mat& q, Eigen::Index k, std::mt19937_64& gen) {
  const Eigen::Index n = w.rows(), p = w.cols();
  // Cholesky QR twice (BLAS 3) when w is well conditioned
  {
    Mat v = w;
    Mat r = Mat::Identity(p, p);
    bool ok = true;
    for (int pass = 0; pass < 2 && ok; ++pass) {
      Mat g(p, p);
      g.setZero();
      g.selfadjointView<Eigen::Lower>().rankUpdate(v.transpose());
      Eigen::LLT<Mat> llt(g);
      if (llt.info() != Eigen::Success) {
        ok = false;
        break;
      }
      const Mat rt = llt.matrixU();
      const Eigen::VectorXd d = rt.diagonal().cwiseAbs();
      if (!(d.minCoeff() > 1e-6 * d.maxCoeff())) {
        ok = false;
        break;
      }
      rt.triangularView<Eigen::Upper>().solveInPlace<Eigen::OnTheRight>(v);
      r = rt * r;
    }
    if (ok) {
      w = std::move(v);
      return r;
    }
  }
  // rank-revealing Householder QR otherwise
  Eigen::ColPivHouseholderQR<Mat> qr(w);
  const Mat rp = qr.matrixR().topRows(p).triangularView<Eigen::Upper>();
  Mat r = rp * qr.colsPermutation().transpose();
  Mat v = qr.householderQ() * Mat::Identity(n, p);
  const double rmax = rp.diagonal().cwiseAbs().maxCoeff();
  Eigen::Index rank = 0;
  while (rank < p && std::abs(rp(rank, rank)) > 1e-10 * rmax) ++rank;
  if (rank < p) {
    r.bottomRows(p - rank).setZero();
    Mat extra = RandomBlock(n, p - rank, gen);
    for (int pass = 0; pass < 2; ++pass) {
      Project(q, k, extra);
      const auto vr = v.leftCols(rank);
      extra.noalias() -= vr * (vr.transpose() * extra);
    }
    Eigen::HouseholderQR<Mat> eq(extra);
    v.rightCols(p - rank) = eq.householderQ() * Mat::Identity(n, p - rank);
  }
  w = std::move(v);
  return r;
}

}  // namespace

ModalResult SolveModesBlockLanczos(const SparseMat& K, const SparseMat& M, const SparseCholesky& factor,
                                   double shift, const BlockLanczosOptions& options, const std::string& what) {
  CheckModalRequest(K, M, factor, shift, options.count, options.tolerance, what);
  const Eigen::Index n = K.rows();
  const int nev = options.count;

  const Eigen::Index p = std::min<Eigen::Index>(
      n, options.block_size > 0 ? options.block_size : std::clamp(nev / 2 + 4, 6, 16));
  const Eigen::Index kmax = std::min<Eigen::Index>(
      n, options.max_basis > 0 ? std::max<Eigen::Index>(options.max_basis, nev + 3 * p) : nev + 10 * p);
  const ShiftInvertOperator op(M, factor);
  std::mt19937_64 gen(20240611);

  Mat q(n, kmax);   // orthonormal basis, first k columns used
  Mat t = Mat::Zero(kmax, kmax);   // Q^T C Q
  Mat v = RandomBlock(n, p, gen);
  Orthonormalize(v, q, 0, gen);
  q.leftCols(p) = v;
  Eigen::Index k = p;   // basis size
  Eigen::Index b = p;   // size of the newest block
  Eigen::SelfAdjointEigenSolver<Mat> ritz;
  int restarts = 0;
  while (true) {
    // next block of the Krylov space, coefficients against the whole basis
    Mat w = op.Apply(q.middleCols(k - b, b));
    const Mat c = Project(q, k, w);
    t.block(0, k - b, k, b) = c;
    t.block(k - b, 0, b, k) = c.transpose();
    const Mat tk = t.topLeftCorner(k, k);
    ritz.compute(0.5 * (tk + tk.transpose()));
    const Eigen::VectorXd& theta = ritz.eigenvalues();   // ascending: the wanted are the last nev
    const Eigen::Index wanted = std::min<Eigen::Index>(nev, k);
    const Mat r = k < n ? Orthonormalize(w, q, k, gen) : Mat::Zero(b, b);

    // residual ||C y - theta y|| = ||R (last rows of the Ritz vector)||
    const double scale = std::max(std::abs(theta[k - 1]), std::numeric_limits<double>::min());
    bool converged = wanted == nev;
    for (Eigen::Index i = k - wanted; i < k && converged; ++i) {
      const double res = (r * ritz.eigenvectors().col(i).tail(b)).norm();
      const double tol = options.tolerance * std::max(std::abs(theta[i]), 1e-12 * scale);
      if (!(res <= tol)) converged = false;
    }
    if (converged || k == n) {
      if (wanted < nev) throw NumericalError(what + ": the Krylov space ended before " + std::to_string(nev) + " modes");
      const Mat phi = op.Recover(q.leftCols(k) * ritz.eigenvectors().rightCols(nev));
      return RayleighRitzModes(K, M, theta.tail(nev), phi, what);
    }

    // thick restart: keep the best Ritz vectors, then continue with w
    Eigen::Index add = std::min<Eigen::Index>(b, n - k);
    if (k + add > kmax) {
      if (++restarts > options.max_restarts) {
        throw NumericalError(what + ": block Lanczos did not converge to " + std::to_string(nev) + " modes in " +
                             std::to_string(options.max_restarts) + " restarts");
      }
      const Eigen::Index keep = std::min<Eigen::Index>(kmax - 2 * p, nev + p);
      const Mat y = q.leftCols(k) * ritz.eigenvectors().rightCols(keep);
      q.leftCols(keep) = y;
      t.setZero();
      t.topLeftCorner(keep, keep).diagonal() = theta.tail(keep);
      k = keep;
      add = std::min<Eigen::Index>(b, n - k);
    }
    q.middleCols(k, add) = w.leftCols(add);
    k += add;
    b = add;
  }
}

}  // namespace flexmb::fe
