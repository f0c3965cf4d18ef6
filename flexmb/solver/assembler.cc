#include "flexmb/solver/assembler.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "flexmb/common/error.h"

namespace flexmb {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

void PatternBlock(Triplets& t, int r0, int nr, int c0, int nc) {
  for (int j = 0; j < nc; ++j)
    for (int i = 0; i < nr; ++i) t.emplace_back(r0 + i, c0 + j, 0.0);
}

/// Adds scale * blk to the entries of S's value array `val` whose column
/// starts (position of the block's first row in each column) are `starts`.
template <typename Block>
void AddBlockAtSlots(double* val, const int* starts, const Block& blk, double scale) {
  const int nr = static_cast<int>(blk.rows()), ncol = static_cast<int>(blk.cols());
  for (int j = 0; j < ncol; ++j) {
    double* v = val + starts[j];
    for (int i = 0; i < nr; ++i) v[i] += scale * blk(i, j);
  }
}

/// Position in the value array of the pattern entry (r, c) of a compressed
/// matrix; throws NumericalError if the pattern lacks it.
int SlotPatternPosition(const SparseMat& A, int r, int c) {
  const int* inner = A.innerIndexPtr();
  const int* end = inner + A.outerIndexPtr()[c + 1];
  const int* p = std::lower_bound(inner + A.outerIndexPtr()[c], end, r);
  if (p == end || *p != r)
    throw NumericalError("assembler: entry (" + std::to_string(r) + ", " + std::to_string(c) +
                         ") missing from the sparse pattern");
  return static_cast<int>(p - inner);
}

/// Appends to `out` the positions of the entries (r0, c0 + j), j < nc.
void AppendSlotColumnStarts(const SparseMat& A, int r0, int c0, int nc, std::vector<int>& out) {
  for (int j = 0; j < nc; ++j) out.push_back(SlotPatternPosition(A, r0, c0 + j));
}

/// Calls f(k, i, j) for every pattern entry of S in the diagonal block of
/// rows and columns off..off+n-1: k indexes S's value array, (i, j) are the
/// row and column in the block.
template <typename F>
void ForBlockEntries(const SparseMat& S, int off, int n, F&& f) {
  const int* outer = S.outerIndexPtr();
  const int* inner = S.innerIndexPtr();
  for (int j = 0; j < n; ++j) {
    const int* end = inner + outer[off + j + 1];
    for (const int* p = std::lower_bound(inner + outer[off + j], end, off); p != end && *p < off + n; ++p)
      f(static_cast<int>(p - inner), *p - off, j);
  }
}

/// Indices of the bodies a joint or force element couples (marker bodies).
int BodyOf(const Model& m, int marker) { return marker < 0 ? 0 : m.markers[marker].body; }

/// Column range (first, count) of a marker's Jacobian; ca.second == 0 for
/// markers on bodies without velocities.
using Cols = std::pair<int, int>;

/// Adds scale * Ja^T K6 Rb at the marker column ranges (a, b) of the top-left
/// of S, where Rb (6 x nv_b) is marker b's twist Jacobian or its twist
/// tangent; only the columns ca of Ja and cb of Rb can be non-zero.
/// `starts` are the block's column starts in S (Workspace::force_slots,
/// joint_slots).
template <typename Right>
void AddCoupling(SparseMat& S, const int* starts, const MarkerState& ma, const Cols& ca, const Cols& cb,
                 const Right& Rb, const Eigen::Ref<const Eigen::Matrix<double, 6, 6>>& K6, double scale,
                 MatX& tmp, MatX& blk) {
  if (ca.second == 0 || cb.second == 0 || scale == 0.0) return;
  if (ca.second == 6 && cb.second == 6) {
    // rigid-body markers: fixed-size products (no dynamic-size loops)
    const Eigen::Matrix<double, 6, 6> t6 = K6 * Rb.template block<6, 6>(0, cb.first);
    const Eigen::Matrix<double, 6, 6> b6 = ma.J.template block<6, 6>(0, ca.first).transpose() * t6;
    AddBlockAtSlots(S.valuePtr(), starts, b6, scale);
    return;
  }
  auto t = tmp.topLeftCorner(6, cb.second);
  auto b = blk.topLeftCorner(ca.second, cb.second);
  t.noalias() = K6 * Rb.middleCols(cb.first, cb.second);
  b.noalias() = ma.J.middleCols(ca.first, ca.second).transpose() * t;
  AddBlockAtSlots(S.valuePtr(), starts, b, scale);
}

/// Block (a, b) of a force element's wrench tangent (K or C, fixed 12 x 12
/// for two markers or 6 n x 6 n), without a copy.
using ForceBlock = Eigen::Ref<const Eigen::Matrix<double, 6, 6>, 0, Eigen::OuterStride<>>;
template <typename Tangent>
ForceBlock ForceTangentBlock(const Tangent& T, int a, int b) {
  return T.template block<6, 6>(6 * a, 6 * b);
}

/// Checks Body::BlockPattern's contract for the sparse body k: its mass
/// block at the initial state and its force derivatives there, at rest
/// velocities and at a perturbed velocity, are zero outside the declared
/// pattern (the assembler would drop such entries silently). Needs ws.S.
void CheckBodyPattern(const Model& model, const State& s0, Workspace& ws, int k) {
  const Body& b = *model.bodies[k];
  const int n = b.nv();
  Eigen::Matrix<char, Eigen::Dynamic, Eigen::Dynamic> in = Eigen::Matrix<char, Eigen::Dynamic, Eigen::Dynamic>::Zero(n, n);
  ForBlockEntries(ws.S, b.v_offset, n, [&in](int, int i, int j) { in(i, j) = 1; });
  const double* q = s0.q.data() + b.q_offset;
  VecX Q = VecX::Zero(n);
  const auto check = [&](const MatX& blk, const char* what) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (!in(i, j) && blk(i, j) != 0.0)
          throw InputError(std::string("the body writes entry (") + std::to_string(i) + ", " + std::to_string(j) +
                               ") of its " + what + " outside its declared block pattern (Body::BlockPattern)",
                           {"", 0, "body '" + b.name() + "'"});
  };
  check(ws.mass[k], "mass matrix");
  for (int pass = 0; pass < 2; ++pass) {
    VecX v = s0.v.segment(b.v_offset, n);
    if (pass == 1)
      for (int i = 0; i < n; ++i) v(i) += 0.1 * (1 + i % 3);
    ws.dQdq[k].setZero();
    ws.dQdv[k].setZero();
    b.AddForces(q, v.data(), model.gravity_W, Q, ws.dQdq[k], ws.dQdv[k]);
    check(ws.dQdq[k], "force derivative dQ/dq");
    check(ws.dQdv[k], "force derivative dQ/dv");
  }
  ws.dQdq[k].setZero();
  ws.dQdv[k].setZero();
}

/// Fills the position tables of ws (Workspace::slots and the offsets into
/// it) from the patterns of ws.S and ws.B, in the order the assembly uses.
void BuildAssemblySlots(const Model& model, Workspace& ws) {
  const int nv = model.nv;
  ws.slots.clear();
  ws.body_slots.assign(model.bodies.size(), -1);
  for (size_t k = 0; k < model.bodies.size(); ++k) {
    const Body& b = *model.bodies[k];
    if (b.nv() == 0 || ws.body_sparse[k]) continue;
    ws.body_slots[k] = static_cast<int>(ws.slots.size());
    AppendSlotColumnStarts(ws.S, b.v_offset, b.v_offset, b.nv(), ws.slots);
  }
  // coupling blocks of markers (a, b) of an element with markers mk[0..nm)
  const auto pairs = [&](const int* mk, int nm, int* out) {
    for (int a = 0; a < nm; ++a)
      for (int b = 0; b < nm; ++b) {
        const Cols& ca = ws.marker_cols[mk[a]];
        const Cols& cb = ws.marker_cols[mk[b]];
        out[nm * a + b] = -1;
        if (ca.second == 0 || cb.second == 0) continue;
        out[nm * a + b] = static_cast<int>(ws.slots.size());
        AppendSlotColumnStarts(ws.S, ws.markers[mk[a]].v_offset + ca.first, ws.markers[mk[b]].v_offset + cb.first,
                           cb.second, ws.slots);
      }
  };
  ws.force_slot_begin.assign(model.forces.size(), 0);
  int n_force_slots = 0;
  for (size_t k = 0; k < model.forces.size(); ++k) {
    ws.force_slot_begin[k] = n_force_slots;
    n_force_slots += model.forces[k]->NumMarkers() * model.forces[k]->NumMarkers();
  }
  ws.force_slots.assign(n_force_slots, -1);
  std::vector<int> force_mk;
  for (size_t k = 0; k < model.forces.size(); ++k) {
    const ForceElement& f = *model.forces[k];
    force_mk.resize(f.NumMarkers());
    for (int a = 0; a < f.NumMarkers(); ++a) force_mk[a] = f.MarkerAt(a);
    pairs(force_mk.data(), f.NumMarkers(), &ws.force_slots[ws.force_slot_begin[k]]);
  }
  ws.joint_slots.assign(5 * model.joints.size(), -1);
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const Joint& j = *model.joints[k];
    const int mk[2] = {j.marker_i, j.marker_j};
    pairs(mk, 2, &ws.joint_slots[5 * k]);
    ws.joint_slots[5 * k + 4] = static_cast<int>(ws.slots.size());
    for (int q = 0; q < j.NumEquations(); ++q) {
      const int r = ws.row_of_eq[j.lambda_offset + q];
      if (r < 0) continue;
      for (int a = 0; a < 2; ++a) {
        const Cols& c = ws.marker_cols[mk[a]];
        if (c.second == 0) continue;
        const int c0 = ws.markers[mk[a]].v_offset + c.first;
        for (int i = 0; i < c.second; ++i) ws.slots.push_back(SlotPatternPosition(ws.S, nv + r, c0 + i));
        ws.slots.push_back(SlotPatternPosition(ws.S, c0, nv + r));
        for (int i = 0; i < c.second; ++i) ws.slots.push_back(SlotPatternPosition(ws.B, r, c0 + i));
      }
    }
    if (!std::isfinite(j.release_time)) continue;
    for (int q = 0; q < j.NumEquations(); ++q) {
      const int r = ws.row_of_eq[j.lambda_offset + q];
      if (r >= 0) ws.slots.push_back(SlotPatternPosition(ws.S, nv + r, nv + r));
    }
  }
}

/// Copies sparse body k's mass block (ws.mass[k]) onto its compressed copy.
void RefreshSparseMass(Workspace& ws, int k) {
  const double* M = ws.mass[k].data();
  double* val = ws.body_mass[k].valuePtr();
  const auto& entries = ws.body_entries[k];
  for (size_t p = 0; p < entries.size(); ++p) val[p] = M[entries[p].lin];
}

}  // namespace

void InitWorkspace(const Model& model, Workspace& ws, const std::vector<int>& removed) {
  const int nb = static_cast<int>(model.bodies.size());
  ws.markers.assign(model.markers.size(), MarkerState{});
  ws.marker_cols.assign(model.markers.size(), Cols{0, 0});
  for (size_t k = 0; k < model.markers.size(); ++k) {
    const Body& b = *model.bodies[model.markers[k].body];
    ws.markers[k].J.setZero(6, b.nv());
    ws.markers[k].nv = b.nv();
    ws.markers[k].v_offset = b.v_offset;
    if (b.nv() == 0) continue;
    const Cols c = b.MarkerColumns(model.markers[k]);
    if (c.first < 0 || c.second < 0 || c.first + c.second > b.nv())
      throw InputError("body reports marker columns " + std::to_string(c.first) + " + " +
                           std::to_string(c.second) + " outside its " + std::to_string(b.nv()) +
                           " velocities",
                       {"", 0, "marker '" + model.markers[k].name + "'"});
    ws.marker_cols[k] = c;
  }
  ws.joints.resize(model.joints.size());
  ws.joint_released.assign(model.joints.size(), 0);
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const int n = model.joints[k]->NumEquations();
    ws.joints[k].phi.setZero(n);
    ws.joints[k].phi_t.setZero(n);
    ws.joints[k].D.setZero(n, 12);
  }
  ws.forces.assign(model.forces.size(), ForceEval{});
  size_t max_markers = 2;
  for (size_t k = 0; k < model.forces.size(); ++k) {
    const int n = model.forces[k]->NumMarkers();
    max_markers = std::max(max_markers, static_cast<size_t>(n));
    if (n <= 2) continue;
    ws.forces[k].wrench_n.setZero(6 * n);
    ws.forces[k].K_n.setZero(6 * n, 6 * n);
    ws.forces[k].C_n.setZero(6 * n, 6 * n);
  }
  ws.force_markers.assign(max_markers, nullptr);
  ws.mass.resize(nb);
  ws.dQdq.resize(nb);
  ws.dQdv.resize(nb);
  ws.body_sparse.assign(nb, 0);
  int max_nv = 1;
  for (int k = 0; k < nb; ++k) {
    const int n = model.bodies[k]->nv();
    max_nv = std::max(max_nv, n);
    ws.mass[k].setZero(n, n);
    ws.dQdq[k].setZero(n, n);
    ws.dQdv[k].setZero(n, n);
  }
  const State s0 = model.InitialState();
  for (int k = 0; k < nb; ++k)
    if (model.bodies[k]->nv() > 0) model.bodies[k]->MassMatrix(s0.q.data() + model.bodies[k]->q_offset, ws.mass[k]);
  ws.Q.setZero(model.nv);
  ws.vdot.setZero(model.nv);
  ws.G.setZero(6, max_nv);
  ws.GtK.setZero(max_nv, max_nv);
  ws.twist_dq.setZero(6, max_nv);

  // active constraint rows
  ws.row_of_eq.assign(model.nc, 0);
  for (int e : removed) ws.row_of_eq.at(e) = -1;
  int row = 0;
  for (int e = 0; e < model.nc; ++e)
    if (ws.row_of_eq[e] >= 0) ws.row_of_eq[e] = row++;
  ws.n_active = row;
  ws.phi.setZero(row);
  ws.phi_t.setZero(row);

  // sparse patterns
  const int nv = model.nv;
  Triplets tb, ts;
  // body blocks: the declared pattern, or dense
  std::vector<std::pair<int, int>> entries;
  for (int k = 0; k < nb; ++k) {
    const Body& b = *model.bodies[k];
    entries.clear();
    if (b.nv() == 0 || !b.BlockPattern(entries)) {
      PatternBlock(ts, b.v_offset, b.nv(), b.v_offset, b.nv());
      continue;
    }
    ws.body_sparse[k] = 1;
    for (const auto& e : entries) {
      if (e.first < 0 || e.first >= b.nv() || e.second < 0 || e.second >= b.nv())
        throw InputError("block pattern entry (" + std::to_string(e.first) + ", " +
                             std::to_string(e.second) + ") outside the body's " +
                             std::to_string(b.nv()) + " velocities",
                         {"", 0, "body '" + b.name() + "'"});
      ts.emplace_back(b.v_offset + e.first, b.v_offset + e.second, 0.0);
    }
  }
  // marker couplings of force elements and joints: rows of marker a's
  // columns times marker b's columns (for a == b the wrench tangent)
  auto couple = [&](int ma, int mb) {
    const Body& A = *model.bodies[BodyOf(model, ma)];
    const Body& Bb = *model.bodies[BodyOf(model, mb)];
    const Cols& ca = ws.marker_cols[ma];
    const Cols& cb = ws.marker_cols[mb];
    PatternBlock(ts, A.v_offset + ca.first, ca.second, Bb.v_offset + cb.first, cb.second);
  };
  for (const auto& f : model.forces)
    for (int a = 0; a < f->NumMarkers(); ++a)
      for (int b = 0; b < f->NumMarkers(); ++b) couple(f->MarkerAt(a), f->MarkerAt(b));
  for (const auto& j : model.joints) {
    for (int a : {j->marker_i, j->marker_j})
      for (int b : {j->marker_i, j->marker_j}) couple(a, b);
    for (int k = 0; k < j->NumEquations(); ++k) {
      const int r = ws.row_of_eq[j->lambda_offset + k];
      if (r < 0) continue;
      // a joint that can be released holds its multipliers at zero then
      if (std::isfinite(j->release_time)) ts.emplace_back(nv + r, nv + r, 0.0);
      for (int mk : {j->marker_i, j->marker_j}) {
        const Body& b = *model.bodies[BodyOf(model, mk)];
        const Cols& c = ws.marker_cols[mk];
        PatternBlock(tb, r, 1, b.v_offset + c.first, c.second);
        PatternBlock(ts, nv + r, 1, b.v_offset + c.first, c.second);
        PatternBlock(ts, b.v_offset + c.first, c.second, nv + r, 1);
      }
    }
  }
  ws.B.resize(ws.n_active, nv);
  ws.B.setFromTriplets(tb.begin(), tb.end());
  ws.B.makeCompressed();
  ws.S.resize(nv + ws.n_active, nv + ws.n_active);
  ws.S.setFromTriplets(ts.begin(), ts.end());
  ws.S.makeCompressed();
  ws.rhs.setZero(nv + ws.n_active);
  BuildAssemblySlots(model, ws);
  ws.body_entries.assign(nb, {});
  ws.body_mass.assign(nb, SparseMat());
  for (int k = 0; k < nb; ++k) {
    if (!ws.body_sparse[k]) continue;
    const int n = model.bodies[k]->nv();
    auto& entries = ws.body_entries[k];
    ForBlockEntries(ws.S, model.bodies[k]->v_offset, n,
                    [&](int p, int i, int j) { entries.push_back({p, i, j, i + j * n}); });
    // the same entries as a compressed matrix (column by column, rows ascending: the same order)
    Triplets t;
    for (const Workspace::BlockEntry& e : entries) t.emplace_back(e.i, e.j, 1.0);
    ws.body_mass[k].resize(n, n);
    ws.body_mass[k].setFromTriplets(t.begin(), t.end());
    ws.body_mass[k].makeCompressed();
    RefreshSparseMass(ws, k);
    CheckBodyPattern(model, s0, ws, k);
  }
}

void EvaluateMarkers(const Model& model, const State& s, Workspace& ws) {
  for (size_t k = 0; k < model.markers.size(); ++k) {
    const Marker& m = model.markers[k];
    const Body& b = *model.bodies[m.body];
    b.EvaluateMarker(s.q.data() + b.q_offset, s.v.data() + b.v_offset, m, ws.markers[k]);
  }
}

void EvaluateConstraints(const Model& model, const State& s, Workspace& ws) {
  std::fill(ws.B.valuePtr(), ws.B.valuePtr() + ws.B.nonZeros(), 0.0);
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const Joint& j = *model.joints[k];
    JointEval& e = ws.joints[k];
    const MarkerState& mi = ws.markers[j.marker_i];
    const MarkerState& mj = ws.markers[j.marker_j];
    e.phi_t.setZero();
    const int n = j.NumEquations();
    if (ws.joint_released[k]) {
      // released: the equations become lambda = 0 (B rows stay zero)
      e.phi.setZero();
      e.D.setZero();
      for (int q = 0; q < n; ++q) {
        const int r = ws.row_of_eq[j.lambda_offset + q];
        if (r < 0) continue;
        ws.phi(r) = s.lambda(j.lambda_offset + q);
        ws.phi_t(r) = 0.0;
      }
      continue;
    }
    j.Evaluate(mi, mj, s.t, e);
    int count = 0;
    for (int q = 0; q < n; ++q) {
      const int r = ws.row_of_eq[j.lambda_offset + q];
      if (r < 0) continue;
      ws.phi(r) = e.phi(q);
      ws.phi_t(r) = e.phi_t(q);
      ++count;
    }
    if (count == 0) continue;
    // B rows of the active equations: D_i J_i and D_j J_j, at their
    // positions in B (Workspace::joint_slots)
    const MarkerState* m[2] = {&mi, &mj};
    const Cols* cols[2] = {&ws.marker_cols[j.marker_i], &ws.marker_cols[j.marker_j]};
    const int* pos = ws.slots.data() + ws.joint_slots[5 * k + 4];
    double* bval = ws.B.valuePtr();
    for (int q = 0; q < n; ++q) {
      if (ws.row_of_eq[j.lambda_offset + q] < 0) continue;
      for (int a = 0; a < 2; ++a) {
        const Cols& c = *cols[a];
        if (c.second == 0) continue;
        auto row = ws.G.topLeftCorner(1, c.second);
        row.noalias() = e.D.block(q, 6 * a, 1, 6) * m[a]->J.middleCols(c.first, c.second);
        pos += c.second + 1;
        for (int i = 0; i < c.second; ++i) bval[pos[i]] += 1.0 * row(0, i);
        pos += c.second;
      }
    }
  }
}

void EvaluateForces(const Model& model, const State& s, Workspace& ws, bool tangents) {
  ws.Q.setZero();
  for (size_t k = 0; k < model.bodies.size(); ++k) {
    const Body& b = *model.bodies[k];
    if (b.nv() == 0) continue;
    const double* q = s.q.data() + b.q_offset;
    if (!b.HasConstantMass()) {
      b.MassMatrix(q, ws.mass[k]);
      if (ws.body_sparse[k]) RefreshSparseMass(ws, static_cast<int>(k));
    }
    // without tangents a body that can skips its derivative blocks (left as
    // they are: the next evaluation with tangents zeroes them first)
    if (!tangents && b.AddForceVector(q, s.v.data() + b.v_offset, model.gravity_W, ws.Q.segment(b.v_offset, b.nv())))
      continue;
    if (ws.body_sparse[k]) {
      // the body writes only its pattern entries: zero just those
      double* dq = ws.dQdq[k].data();
      double* dv = ws.dQdv[k].data();
      for (const Workspace::BlockEntry& e : ws.body_entries[k]) {
        dq[e.lin] = 0.0;
        dv[e.lin] = 0.0;
      }
    } else {
      ws.dQdq[k].setZero();
      ws.dQdv[k].setZero();
    }
    b.AddForces(q, s.v.data() + b.v_offset, model.gravity_W, ws.Q.segment(b.v_offset, b.nv()),
                ws.dQdq[k], ws.dQdv[k]);
  }
  static const MarkerState kNoMarker{};
  for (size_t k = 0; k < model.forces.size(); ++k) {
    const ForceElement& f = *model.forces[k];
    ForceEval& e = ws.forces[k];
    const MarkerState& mi = ws.markers[f.marker_i];
    const MarkerState& mj = f.marker_j >= 0 ? ws.markers[f.marker_j] : kNoMarker;
    e.wrench.setZero();
    e.tangents = tangents;
    if (tangents) {
      e.K.setZero();
      e.C.setZero();
    }
    const int n = f.NumMarkers();
    if (n <= 2) {
      f.Evaluate(mi, mj, s.t, e);
    } else {
      for (int a = 0; a < n; ++a) ws.force_markers[a] = &ws.markers[f.MarkerAt(a)];
      e.wrench_n.setZero();
      if (tangents) {
        e.K_n.setZero();
        e.C_n.setZero();
      }
      f.EvaluateMarkers(ws.force_markers.data(), s.t, e);
    }
    for (int a = 0; a < n; ++a) {
      const Cols& ca = ws.marker_cols[f.MarkerAt(a)];
      if (ca.second == 0) continue;
      const MarkerState& ma = ws.markers[f.MarkerAt(a)];
      ws.Q.segment(ma.v_offset + ca.first, ca.second).noalias() +=
          ma.J.middleCols(ca.first, ca.second).transpose() * MarkerWrench(e, n, a);
    }
  }
}

void AddMassTangents(const Model& model, const State& s, const VecX& a, Workspace& ws) {
  for (size_t k = 0; k < model.bodies.size(); ++k) {
    const Body& b = *model.bodies[k];
    if (b.nv() == 0 || b.HasConstantMass()) continue;
    b.AddMassTangent(s.q.data() + b.q_offset, a.data() + b.v_offset, -1.0, ws.dQdq[k]);
  }
}

void AssembleIterationMatrix(const Model& model, const State& s, Workspace& ws,
                             const MatrixCoefficients& c) {
  SparseMat& S = ws.S;
  std::fill(S.valuePtr(), S.valuePtr() + S.nonZeros(), 0.0);
  // bodies: mass and own force derivatives
  for (size_t k = 0; k < model.bodies.size(); ++k) {
    const Body& b = *model.bodies[k];
    if (b.nv() == 0) continue;
    // only the pattern entries of the body block (all of them for dense bodies)
    const MatX& M = ws.mass[k];
    const MatX& Kv = ws.dQdv[k];
    const MatX& Kq = ws.dQdq[k];
    double* val = S.valuePtr();
    if (!ws.body_sparse[k]) {
      // dense block: each column's rows are consecutive entries
      const int n = b.nv();
      const int* starts = ws.slots.data() + ws.body_slots[k];
      for (int j = 0; j < n; ++j) {
        Eigen::Map<VecX> col(val + starts[j], n);
        col.noalias() += c.mass * M.col(j);
        if (c.damping != 0.0) col.noalias() -= c.damping * Kv.col(j);
        if (c.stiffness != 0.0) col.noalias() -= c.stiffness * Kq.col(j);
      }
      continue;
    }
    const double* m = M.data();
    const double* kv = Kv.data();
    const double* kq = Kq.data();
    for (const Workspace::BlockEntry& e : ws.body_entries[k]) {
      double v = c.mass * m[e.lin];
      if (c.damping != 0.0) v -= c.damping * kv[e.lin];
      if (c.stiffness != 0.0) v -= c.stiffness * kq[e.lin];
      val[e.s] += v;
    }
  }
  // force elements: -d(J^T w)/dq and -d(J^T w)/dv
  for (size_t k = 0; k < model.forces.size() && (c.damping != 0.0 || c.stiffness != 0.0); ++k) {
    const ForceElement& f = *model.forces[k];
    const ForceEval& e = ws.forces[k];
    const int nm = f.NumMarkers();
    const int* fs = &ws.force_slots[ws.force_slot_begin[k]];
    for (int a = 0; a < nm; ++a) {
      const int mka = f.MarkerAt(a);
      const MarkerState& ma = ws.markers[mka];
      const Cols& ca = ws.marker_cols[mka];
      const Marker& marker = model.markers[mka];
      const Body& body = *model.bodies[marker.body];
      if (ca.second > 0 && c.stiffness != 0.0) {
        // the body adds only to its marker's column range: zero and copy that
        auto full = ws.GtK.topLeftCorner(ma.nv, ma.nv);
        auto blk = full.block(ca.first, ca.first, ca.second, ca.second);
        blk.setZero();
        const Vec6 w = MarkerWrench(e, nm, a);
        body.AddMarkerWrenchTangent(s.q.data() + body.q_offset, marker, w, full);
        AddBlockAtSlots(S.valuePtr(), ws.slots.data() + fs[(nm + 1) * a], blk, -c.stiffness);
      }
      for (int b = 0; b < nm; ++b) {
        const int mkb = f.MarkerAt(b);
        const MarkerState& mb = ws.markers[mkb];
        const Cols& cb = ws.marker_cols[mkb];
        if (fs[nm * a + b] < 0) continue;
        const int* starts = ws.slots.data() + fs[nm * a + b];
        const ForceBlock Kab = nm <= 2 ? ForceTangentBlock(e.K, a, b) : ForceTangentBlock(e.K_n, a, b);
        const ForceBlock Cab = nm <= 2 ? ForceTangentBlock(e.C, a, b) : ForceTangentBlock(e.C_n, a, b);
        // zero blocks (springs without damping, dampers without stiffness)
        // would add only zeros: skipped
        if (!Kab.isZero(0.0)) AddCoupling(S, starts, ma, ca, cb, mb.J, Kab, -c.stiffness, ws.G, ws.GtK);
        if (Cab.isZero(0.0)) continue;
        AddCoupling(S, starts, ma, ca, cb, mb.J, Cab, -c.damping, ws.G, ws.GtK);
        if (mb.nv == 0 || c.stiffness == 0.0) continue;
        // dampers: the twist of marker b turns with its body at fixed v
        const Marker& markerb = model.markers[mkb];
        const Body& bb = *model.bodies[markerb.body];
        auto td = ws.twist_dq.leftCols(mb.nv);
        bb.MarkerTwistTangent(s.q.data() + bb.q_offset, s.v.data() + bb.v_offset, markerb, td);
        AddCoupling(S, starts, ma, ca, cb, td, Cab, -c.stiffness, ws.G, ws.GtK);
      }
    }
  }
  // joints: B, B^T and the geometric stiffness d(B^T lambda)/dq
  for (size_t k = 0; k < model.joints.size(); ++k) {
    const Joint& j = *model.joints[k];
    const JointEval& e = ws.joints[k];
    const MarkerState* m[2] = {&ws.markers[j.marker_i], &ws.markers[j.marker_j]};
    const Cols* cols[2] = {&ws.marker_cols[j.marker_i], &ws.marker_cols[j.marker_j]};
    const int n = j.NumEquations();
    double lam[16] = {0};
    bool any_lambda = false;
    const int* js = &ws.joint_slots[5 * k];
    // positions of the B rows and B^T columns (Workspace::joint_slots)
    const int* pos = ws.slots.data() + js[4];
    double* val = S.valuePtr();
    if (ws.joint_released[k]) {
      // rows lambda_q = 0, scaled as the integrator's multiplier update
      // (lambda += y / stiffness); the diagonal follows the B positions
      for (int q = 0; q < n; ++q) {
        if (ws.row_of_eq[j.lambda_offset + q] < 0) continue;
        for (int a = 0; a < 2; ++a)
          if (cols[a]->second > 0) pos += 2 * cols[a]->second + 1;
      }
      for (int q = 0; q < n; ++q)
        if (ws.row_of_eq[j.lambda_offset + q] >= 0) val[*pos++] += c.stiffness > 0.0 ? 1.0 / c.stiffness : 1.0;
      continue;
    }
    for (int q = 0; q < n; ++q) {
      if (ws.row_of_eq[j.lambda_offset + q] < 0) continue;
      lam[q] = s.lambda(j.lambda_offset + q);
      any_lambda |= lam[q] != 0.0;
      for (int a = 0; a < 2; ++a) {
        const Cols& cc = *cols[a];
        if (cc.second == 0) continue;
        auto row = ws.G.topLeftCorner(1, cc.second);
        row.noalias() = e.D.block(q, 6 * a, 1, 6) * m[a]->J.middleCols(cc.first, cc.second);
        for (int i = 0; i < cc.second; ++i) val[pos[i]] += 1.0 * row(0, i);
        double* col = val + pos[cc.second];
        for (int i = 0; i < cc.second; ++i) col[i] += 1.0 * row(0, i);
        pos += 2 * cc.second + 1;
      }
    }
    if (!c.geometric || c.stiffness == 0.0 || !any_lambda) continue;
    ws.H.setZero();
    j.AddGeometricStiffness(*m[0], *m[1], lam, ws.H);
    Vec12 w = Vec12::Zero();
    for (int q = 0; q < n; ++q) w += lam[q] * e.D.row(q).transpose();
    const int mk[2] = {j.marker_i, j.marker_j};
    for (int a = 0; a < 2; ++a) {
      const Cols& ca = *cols[a];
      if (ca.second == 0) continue;
      const Marker& marker = model.markers[mk[a]];
      const Body& body = *model.bodies[marker.body];
      auto full = ws.GtK.topLeftCorner(m[a]->nv, m[a]->nv);
      auto blk = full.block(ca.first, ca.first, ca.second, ca.second);
      blk.setZero();
      body.AddMarkerWrenchTangent(s.q.data() + body.q_offset, marker, w.segment<6>(6 * a), full);
      AddBlockAtSlots(val, ws.slots.data() + js[3 * a], blk, c.stiffness);
      for (int b = 0; b < 2; ++b)
        if (js[2 * a + b] >= 0)
          AddCoupling(S, ws.slots.data() + js[2 * a + b], *m[a], ca, *cols[b], m[b]->J,
                      ws.H.block<6, 6>(6 * a, 6 * b), c.stiffness, ws.G, ws.GtK);
    }
  }
}

void MassTimes(const Model& model, const Workspace& ws, const VecX& a, VecX& r) {
  for (size_t k = 0; k < model.bodies.size(); ++k) {
    const Body& b = *model.bodies[k];
    if (b.nv() == 0) continue;
    if (!ws.body_sparse[k]) {
      r.segment(b.v_offset, b.nv()).noalias() = ws.mass[k] * a.segment(b.v_offset, b.nv());
      continue;
    }
    // the pattern entries of the mass block only
    r.segment(b.v_offset, b.nv()).noalias() = ws.body_mass[k] * a.segment(b.v_offset, b.nv());
  }
}

void RetractAll(const Model& model, const VecX& q, const VecX& dx, VecX& q_out) {
  for (const auto& b : model.bodies)
    if (b->nv() > 0)
      b->Retract(q.data() + b->q_offset, dx.data() + b->v_offset, q_out.data() + b->q_offset);
}

void AddConstraintForces(const Model& model, const Workspace& ws, const VecX& lambda, VecX& r) {
  (void)model;
  r.noalias() += ws.B.transpose() * lambda;
}

std::string DescribeEquation(const Model& model, int eq) {
  for (const auto& j : model.joints)
    if (eq >= j->lambda_offset && eq < j->lambda_offset + j->NumEquations())
      return "joint '" + j->name() + "' (" + j->EquationName(eq - j->lambda_offset) + ")";
  return "equation " + std::to_string(eq);
}

}  // namespace flexmb
