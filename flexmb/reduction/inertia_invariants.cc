#include "flexmb/reduction/inertia_invariants.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/point_mass.h"
#include "flexmb/math/rotation.h"
#include "flexmb/reduction/parallel_rows.h"

namespace flexmb::reduction {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Index = Eigen::Index;
using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstRows = Eigen::Map<const RowMat, 0, Eigen::OuterStride<>>;

// nodes per slab of the dense products
constexpr Index kSlab = 256;

// one component of `len` consecutive nodes of a row-major matrix with
// `per_node` rows per node, from node k0, columns [col0, col0 + cols)
ConstRows NodeRows(const RowMat& m, int per_node, Index k0, Index len, int c, Index col0, Index cols) {
  return ConstRows(m.data() + (per_node * k0 + c) * m.cols() + col0, len, cols,
                   Eigen::OuterStride<>(per_node * m.cols()));
}

// M_full as 6 x 6 node blocks, column node by column node: column l holds
// (row node k, M_kl) for every node k that M_full couples with l; rows and
// columns of inactive DOF are zero
struct NodeBlocks {
  std::vector<int> ptr;   // nodes + 1
  std::vector<int> row;   // row node of each block
  std::vector<Mat6> block;
};

NodeBlocks BuildNodeBlocks(const fe::Mesh& mesh, const fe::AssembledModel& a, const ErrorContext& where) {
  const fe::DofMap& dm = a.dofs;
  const int nn = static_cast<int>(mesh.nodes.size());
  const int nf = dm.n_full;
  if (static_cast<int>(dm.full.size()) != nn) {
    throw InputError("the assembled model has " + std::to_string(dm.full.size()) + " nodes, the mesh " +
                         std::to_string(nn),
                     where);
  }
  if (a.M_full.rows() != nf || a.M_full.cols() != nf) {
    throw InputError("the full mass matrix is " + std::to_string(a.M_full.rows()) + " x " +
                         std::to_string(a.M_full.cols()) + ", expected " + std::to_string(nf) + " square (n_full)",
                     where);
  }
  std::vector<int> node_of(static_cast<size_t>(nf), -1), comp_of(static_cast<size_t>(nf), -1);
  for (int k = 0; k < nn; ++k) {
    for (int c = 0; c < 6; ++c) {
      const int f = dm.full[static_cast<size_t>(k)][static_cast<size_t>(c)];
      if (f < 0) continue;
      if (f >= nf || node_of[static_cast<size_t>(f)] >= 0) {
        throw InputError("the DOF map gives full DOF " + std::to_string(f) + " twice or out of range (node " +
                             std::to_string(mesh.nodes[static_cast<size_t>(k)].id) + ")",
                         where);
      }
      node_of[static_cast<size_t>(f)] = k;
      comp_of[static_cast<size_t>(f)] = c;
    }
  }
  NodeBlocks b;
  b.ptr.assign(static_cast<size_t>(nn) + 1, 0);
  std::vector<int> pos(static_cast<size_t>(nn), -1);
  for (int l = 0; l < nn; ++l) {
    const int start = static_cast<int>(b.row.size());
    for (int c = 0; c < 6; ++c) {
      const int g = dm.full[static_cast<size_t>(l)][static_cast<size_t>(c)];
      if (g < 0) continue;
      for (fe::SparseMat::InnerIterator it(a.M_full, g); it; ++it) {
        const int k = node_of[static_cast<size_t>(it.row())];
        if (k < 0) {
          throw InputError("the full mass matrix has an entry on full DOF " + std::to_string(it.row()) +
                               ", which belongs to no node",
                           where);
        }
        if (pos[static_cast<size_t>(k)] < start) {
          pos[static_cast<size_t>(k)] = static_cast<int>(b.row.size());
          b.row.push_back(k);
          b.block.push_back(Mat6::Zero());
        }
        b.block[static_cast<size_t>(pos[static_cast<size_t>(k)])](comp_of[static_cast<size_t>(it.row())], c) =
            it.value();
      }
    }
    b.ptr[static_cast<size_t>(l) + 1] = static_cast<int>(b.row.size());
  }
  return b;
}

// Offset point masses as points of their own (docs/design.md, "Inertia of
// the nodes' rotations"): a point mass m with offset e at node k moves with
// u_k + theta_k x e, so it is a translational point at rho_k + e with the
// mode rows H_k^t - S(e) H_k^r, for which the node-by-node kinetic energy is
// exact; only its rotary inertia J stays on node k. Its block in M_full
// (mass, offset coupling and J) is taken out of node k's diagonal block, J
// put back there, and the point appended to `positions`, `b` and `hr` as a
// node with the block diag(m I, 0). The constant and modal-mass invariants
// do not change (the same kinetic energy to first order); the terms linear
// and quadratic in w gain the offset's rotation.
void AddOffsetPointMasses(const fe::Mesh& mesh, NodeBlocks& b, std::vector<Vec3>& positions, RowMat& hr) {
  std::vector<const fe::PointMass*> offset;
  for (const fe::PointMass& pm : mesh.point_masses)
    if (!pm.general && pm.mass > 0.0 && pm.offset.squaredNorm() > 0.0) offset.push_back(&pm);
  if (offset.empty()) return;
  const Index nn = static_cast<Index>(positions.size());
  RowMat h(hr.rows() + 6 * static_cast<Index>(offset.size()), hr.cols());
  h.topRows(hr.rows()) = hr;
  Index added = 0;
  for (const fe::PointMass* pp : offset) {
    const fe::PointMass& pm = *pp;
    const int k = pm.node;
    // node k's diagonal block: without the point mass, with its rotary inertia
    fe::PointMass rotary = pm;
    rotary.mass = 0.0;
    rotary.offset.setZero();
    fe::PointMass point = pm;
    point.offset.setZero();
    point.inertia.setZero();
    bool found = false;
    for (int q = b.ptr[static_cast<size_t>(k)]; q < b.ptr[static_cast<size_t>(k) + 1]; ++q) {
      if (b.row[static_cast<size_t>(q)] != k) continue;
      b.block[static_cast<size_t>(q)] += fe::PointMassMatrix(rotary) - fe::PointMassMatrix(pm);
      found = true;
    }
    if (!found) continue;  // no mass at the node's DOF: nothing to move
    const Index r = 6 * (nn + added);
    const Index rk = 6 * static_cast<Index>(k);
    h.middleRows(r, 3) = hr.middleRows(rk, 3) - Skew(pm.offset) * hr.middleRows(rk + 3, 3);
    h.middleRows(r + 3, 3).setZero();
    positions.push_back(positions[static_cast<size_t>(k)] + pm.offset);
    b.row.push_back(static_cast<int>(nn + added));
    b.block.push_back(fe::PointMassMatrix(point));
    b.ptr.push_back(static_cast<int>(b.row.size()));
    ++added;
  }
  hr = h.topRows(6 * static_cast<Index>(positions.size()));
}

// sum_k S(h_k,i) Y_k, row a, column b, from q(e n + i, c w + b) =
// sum_k h_k,i[e] Y_k(c, b): (S(h) Y)(a, b) = h[a+1] Y(a+2, b) - h[a+2] Y(a+1, b)
double CrossSum(const MatX& q, int n, int w, int i, int a, int b) {
  const int e1 = (a + 1) % 3, e2 = (a + 2) % 3;
  return q(e1 * n + i, e2 * w + b) - q(e2 * n + i, e1 * w + b);
}

// sums over one thread's range of nodes of the products with Omega1 and H
struct Partial {
  MatX moo2;                 // Omega1^T M Omega1, 3n x 3n, (a n + i, b n + j), upper triangle
  std::array<MatX, 3> mow1;  // Omega1^T M H, row a of mow1[i] at (i, j)
  MatX mww;                  // H^T M H, n x n, upper triangle
};

}  // namespace

InertiaInvariants ComputeInertiaInvariants(const fe::Mesh& mesh, const fe::AssembledModel& model,
                                           const MatX& modes, const MatX* modal_mass, bool offset_point_masses) {
  const ErrorContext where{mesh.source, 0, "inertia invariants"};
  const int nn_mesh = static_cast<int>(mesh.nodes.size());
  if (modes.rows() != 6 * static_cast<Index>(nn_mesh)) {
    throw InputError("the mode matrix has " + std::to_string(modes.rows()) + " rows, expected 6 per node (" +
                         std::to_string(6 * static_cast<Index>(nn_mesh)) + ")",
                     where);
  }
  const int n = static_cast<int>(modes.cols());
  if (modal_mass != nullptr && (modal_mass->rows() != n || modal_mass->cols() != n)) {
    throw InputError("the modal mass is " + std::to_string(modal_mass->rows()) + " x " +
                         std::to_string(modal_mass->cols()) + ", expected " + std::to_string(n) + " square",
                     where);
  }
  NodeBlocks b = BuildNodeBlocks(mesh, model, where);
  std::vector<Vec3> positions;
  positions.reserve(static_cast<size_t>(nn_mesh));
  for (const fe::Node& node : mesh.nodes) positions.push_back(node.x);
  RowMat hr = modes;  // row-major: the six rows of a node are contiguous
  if (offset_point_masses) AddOffsetPointMasses(mesh, b, positions, hr);
  const int nn = static_cast<int>(positions.size());
  auto rho = [&](int k) -> const Vec3& { return positions[static_cast<size_t>(k)]; };

  InertiaInvariants inv;
  inv.n = n;

  // y6 = M_full [E, Omega0] node by node (6 N x 6): the mass times the rigid
  // columns of L, A0_l = [[I, -S(rho_l)], [0, I]]
  RowMat y6 = RowMat::Zero(6 * static_cast<Index>(nn), 6);
  for (int l = 0; l < nn; ++l) {
    Mat6 a0 = Mat6::Identity();
    a0.block<3, 3>(0, 3) = -Skew(rho(l));
    for (int p = b.ptr[static_cast<size_t>(l)]; p < b.ptr[static_cast<size_t>(l) + 1]; ++p) {
      y6.block<6, 6>(6 * static_cast<Index>(b.row[static_cast<size_t>(p)]), 0).noalias() +=
          b.block[static_cast<size_t>(p)] * a0;
    }
  }
  Mat3 mvv = Mat3::Zero(), mvo0 = Mat3::Zero(), moo0 = Mat3::Zero();
  for (int k = 0; k < nn; ++k) {
    const auto yt = y6.block<3, 6>(6 * static_cast<Index>(k), 0);
    const auto yr = y6.block<3, 6>(6 * static_cast<Index>(k) + 3, 0);
    mvv += yt.leftCols<3>();
    mvo0 += yt.rightCols<3>();
    // Omega0_k^T = [S(rho_k), I]
    moo0.noalias() += Skew(rho(k)) * yt.rightCols<3>();
    moo0 += yr.rightCols<3>();
  }
  inv.mvv = 0.5 * (mvv + mvv.transpose());
  inv.mvo0 = mvo0;
  inv.moo0 = 0.5 * (moo0 + moo0.transpose());
  inv.mvw = y6.leftCols(3).transpose() * hr;
  inv.mow0 = y6.rightCols(3).transpose() * hr;
  if (n == 0) {
    inv.mww.resize(0, 0);
    return inv;
  }
  const int n3 = 3 * n;

  // terms linear in w with a rigid column: Omega1_i^T M_full [E, Omega0] =
  // sum_k S(h_k,i) y6_k (translational rows), from
  // q(e n + i, 6 c + b) = sum_k h_k,i[e] y6(6 k + c, b)
  {
    MatX q(n3, 18);
    for (int e = 0; e < 3; ++e) {
      for (int c = 0; c < 3; ++c) {
        q.block(e * n, 6 * c, n, 6).noalias() =
            NodeRows(hr, 6, 0, nn, e, 0, n).transpose() * NodeRows(y6, 6, 0, nn, c, 0, 6);
      }
    }
    inv.mvo1.assign(static_cast<size_t>(n), Mat3::Zero());
    inv.moo1.assign(static_cast<size_t>(n), Mat3::Zero());
    for (int i = 0; i < n; ++i) {
      Mat3 zv, zo;
      for (int a = 0; a < 3; ++a) {
        for (int c = 0; c < 3; ++c) {
          zv(a, c) = CrossSum(q, n, 6, i, a, c);
          zo(a, c) = CrossSum(q, n, 6, i, a, 3 + c);
        }
      }
      inv.mvo1[static_cast<size_t>(i)] = zv.transpose();
      inv.moo1[static_cast<size_t>(i)] = zo + zo.transpose();
    }
  }

  // Omega1_i (translational rows only) holds e_a x h_k,i in column a at node
  // k: -h[a+2] in row a+1, h[a+1] in row a+2. Slab by slab of nodes: g = M_full
  // H (all six rows of a node when mww is formed here, else the
  // translational ones) and w = M_tt Omega1 on the slab's rows (gathered:
  // M_kl = M_lk^T), then the products with H and Omega1 restricted to
  // Omega1's non-zero rows
  std::array<Mat3, 3> skew_e;
  for (int a = 0; a < 3; ++a) skew_e[static_cast<size_t>(a)] = Skew(Vec3::Unit(a));
  const bool form_mww = modal_mass == nullptr;
  const int gn = form_mww ? 6 : 3;   // rows of g per node
  const int ranges = ParallelRanges(nn, 2 * kSlab);
  std::vector<Partial> partial(static_cast<size_t>(ranges));
  ParallelRows(nn, ranges, [&](int r, Index begin, Index end) {
    Partial& acc = partial[static_cast<size_t>(r)];
    acc.moo2.setZero(n3, n3);
    for (MatX& m : acc.mow1) m.setZero(n, n);
    acc.mww.setZero(n, n);
    const Index cap = std::min(kSlab, end - begin);
    RowMat g(gn * cap, n), w(3 * cap, n3);
    for (Index s0 = begin; s0 < end; s0 += kSlab) {
      const Index len = std::min(kSlab, end - s0);
      g.topRows(gn * len).setZero();
      w.topRows(3 * len).setZero();
      for (Index k = s0; k < s0 + len; ++k) {
        auto gk = g.middleRows(gn * (k - s0), gn);
        auto wk = w.middleRows(3 * (k - s0), 3);
        for (int p = b.ptr[static_cast<size_t>(k)]; p < b.ptr[static_cast<size_t>(k) + 1]; ++p) {
          const Mat6& m = b.block[static_cast<size_t>(p)];   // M_lk
          const Index l6 = 6 * static_cast<Index>(b.row[static_cast<size_t>(p)]);
          if (form_mww) {
            gk.noalias() += m.transpose() * hr.middleRows(l6, 6);
          } else {
            gk.noalias() += m.leftCols<3>().transpose() * hr.middleRows(l6, 6);
          }
          const Mat3 tkl = m.topLeftCorner<3, 3>().transpose();
          for (int a = 0; a < 3; ++a) {
            // T_kl (e_a x h_l) = T_kl S(e_a) h_l
            const Mat3 c = tkl * skew_e[static_cast<size_t>(a)];
            wk.middleCols(a * n, n).noalias() += c * hr.middleRows(l6, 3);
          }
        }
      }
      if (form_mww) {
        acc.mww.triangularView<Eigen::Upper>() += hr.middleRows(6 * s0, 6 * len).transpose() * g.topRows(6 * len);
      }
      for (int a = 0; a < 3; ++a) {
        const int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        const ConstRows x1 = NodeRows(hr, 6, s0, len, a1, 0, n), x2 = NodeRows(hr, 6, s0, len, a2, 0, n);
        MatX& ow = acc.mow1[static_cast<size_t>(a)];
        ow.noalias() += x1.transpose() * NodeRows(g, gn, 0, len, a2, 0, n);
        ow.noalias() -= x2.transpose() * NodeRows(g, gn, 0, len, a1, 0, n);
        for (int c = a; c < 3; ++c) {
          const ConstRows w1 = NodeRows(w, 3, 0, len, a1, c * n, n), w2 = NodeRows(w, 3, 0, len, a2, c * n, n);
          auto oo = acc.moo2.block(a * n, c * n, n, n);
          if (c == a) {
            oo.triangularView<Eigen::Upper>() += x1.transpose() * w2;
            oo.triangularView<Eigen::Upper>() -= x2.transpose() * w1;
          } else {
            oo.noalias() += x1.transpose() * w2;
            oo.noalias() -= x2.transpose() * w1;
          }
        }
      }
    }
  });
  MatX moo2_upper = partial[0].moo2, mww_upper = partial[0].mww;
  std::array<MatX, 3> mow1 = partial[0].mow1;
  for (size_t r = 1; r < partial.size(); ++r) {
    moo2_upper += partial[r].moo2;
    mww_upper += partial[r].mww;
    for (int a = 0; a < 3; ++a) mow1[static_cast<size_t>(a)] += partial[r].mow1[static_cast<size_t>(a)];
  }
  const MatX moo2 = moo2_upper.selfadjointView<Eigen::Upper>();
  if (form_mww) {
    inv.mww = mww_upper.selfadjointView<Eigen::Upper>();
  } else {
    inv.mww = 0.5 * (*modal_mass + modal_mass->transpose());
  }
  inv.mow1.assign(static_cast<size_t>(n), MatX(3, n));
  for (int i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) inv.mow1[static_cast<size_t>(i)].row(a) = mow1[static_cast<size_t>(a)].row(i);
  }
  inv.moo2.assign(static_cast<size_t>(n) * static_cast<size_t>(n), Mat3::Zero());
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      Mat3& m = inv.moo2[static_cast<size_t>(i) * static_cast<size_t>(n) + static_cast<size_t>(j)];
      for (int a = 0; a < 3; ++a) {
        for (int c = 0; c < 3; ++c) m(a, c) = moo2(a * n + i, c * n + j);
      }
    }
  }
  return inv;
}

void MassMatrix(const InertiaInvariants& inv, const Eigen::Ref<const VecX>& w, Eigen::Ref<MatX> out) {
  const int n = inv.n;
  const size_t un = static_cast<size_t>(n);
  if (inv.mvo1.size() != un || inv.moo1.size() != un || inv.mow1.size() != un || inv.moo2.size() != un * un ||
      inv.mvw.rows() != 3 || inv.mvw.cols() != n || inv.mow0.rows() != 3 || inv.mow0.cols() != n ||
      inv.mww.rows() != n || inv.mww.cols() != n ||
      std::any_of(inv.mow1.begin(), inv.mow1.end(), [n](const MatX& m) { return m.rows() != 3 || m.cols() != n; })) {
    throw InputError("mass matrix from inertia invariants: the invariants are inconsistent with n = " +
                     std::to_string(n));
  }
  if (w.size() != n || out.rows() != 6 + n || out.cols() != 6 + n) {
    throw InputError("mass matrix from inertia invariants: " + std::to_string(n) +
                     " modal coordinates expect w of size " + std::to_string(n) + " and a " + std::to_string(6 + n) +
                     " square output, got " + std::to_string(w.size()) + " and " + std::to_string(out.rows()) +
                     " x " + std::to_string(out.cols()));
  }
  Mat3 mvo = inv.mvo0, moo = inv.moo0;
  for (int i = 0; i < n; ++i) {
    mvo += w[i] * inv.mvo1[static_cast<size_t>(i)];
    moo += w[i] * inv.moo1[static_cast<size_t>(i)];
    Mat3 s = Mat3::Zero();
    const Mat3* row = inv.moo2.data() + static_cast<size_t>(i) * static_cast<size_t>(n);
    for (int j = 0; j < n; ++j) s += w[j] * row[j];
    moo += w[i] * s;
  }
  out.block<3, 3>(0, 0) = inv.mvv;
  out.block<3, 3>(0, 3) = mvo;
  out.block<3, 3>(3, 0) = mvo.transpose();
  out.block<3, 3>(3, 3) = 0.5 * (moo + moo.transpose());
  if (n == 0) return;
  out.block(0, 6, 3, n) = inv.mvw;
  auto ow = out.block(3, 6, 3, n);
  ow = inv.mow0;
  for (int i = 0; i < n; ++i) ow += w[i] * inv.mow1[static_cast<size_t>(i)];
  out.block(6, 0, n, 3) = inv.mvw.transpose();
  out.block(6, 3, n, 3) = ow.transpose();
  out.block(6, 6, n, n) = inv.mww;
}

MatX MassMatrix(const InertiaInvariants& inv, const Eigen::Ref<const VecX>& w) {
  MatX out(6 + inv.n, 6 + inv.n);
  MassMatrix(inv, w, out);
  return out;
}

}  // namespace flexmb::reduction
