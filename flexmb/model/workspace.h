#pragma once
/// \file workspace.h
/// Caches and scratch of the computation: everything derived from a State.
/// Sized once (solver::InitWorkspace); the step loop allocates nothing.

#include <Eigen/SparseCore>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/forces/force_element.h"
#include "flexmb/joints/joint.h"
#include "flexmb/kinematics/marker.h"

namespace flexmb {

using SparseMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Workspace of a model; see the file comment.
struct Workspace {
  std::vector<MarkerState> markers;  ///< per marker
  std::vector<JointEval> joints;     ///< per joint
  std::vector<ForceEval> forces;     ///< per force element
  std::vector<MatX> mass;            ///< per body: mass matrix block (nv_b x nv_b)
  std::vector<MatX> dQdq, dQdv;      ///< per body: own force derivatives
  /// Per body: true if the body declared a block pattern (Body::BlockPattern);
  /// then only its entries of mass, dQdq, dQdv are zeroed, used and copied.
  std::vector<char> body_sparse;
  /// One pattern entry of S in a sparse body's diagonal block: its position
  /// in S.valuePtr(), its row i and column j in the body's block and the
  /// index i + j nv_b of the same entry in the body's dense blocks (mass,
  /// dQdq, dQdv).
  struct BlockEntry {
    int s, i, j, lin;
  };
  /// Per body: the entries of a sparse body's block, column by column (empty
  /// for dense bodies), found once so that the step loop does not search S.
  std::vector<std::vector<BlockEntry>> body_entries;
  /// Per sparse body: its mass block on those entries (compressed columns,
  /// values in the order of body_entries), for the mass product of every
  /// Newton iteration; refreshed whenever the mass block is.
  std::vector<SparseMat> body_mass;
  /// Per marker: (first, count) of the body's velocity columns its Jacobian
  /// can touch (Body::MarkerColumns), in the body's own indices.
  std::vector<std::pair<int, int>> marker_cols;
  VecX Q;                            ///< generalized applied + inertial-velocity forces (nv)
  VecX vdot;                         ///< accelerations of the last solved step (nv)

  /// Constraint rows: row_of_eq[offset + k] is the active row of equation k
  /// of a joint, or -1 if the equation was removed as redundant.
  std::vector<int> row_of_eq;
  int n_active = 0;                  ///< number of active constraint rows
  /// Per joint: 1 once the simulator has released it (Joint::release_time);
  /// its rows then read lambda = 0 and have no B entries.
  std::vector<char> joint_released;
  VecX phi, phi_t;                   ///< active constraint values and time derivatives
  SparseMat B;                       ///< constraint Jacobian (n_active x nv), fixed pattern

  /// Iteration matrix [[A, B^T], [B, 0]] (nv + n_active square), fixed pattern.
  SparseMat S;

  /// Positions in S.valuePtr() (and B.valuePtr()) of the blocks the assembly
  /// writes, found once by InitWorkspace so that AssembleIterationMatrix and
  /// EvaluateConstraints copy into S and B without searching the pattern.
  /// A block's entry is the position of its first row in each of its columns
  /// (the pattern holds whole blocks, so a column's rows are consecutive).
  std::vector<int> slots;
  /// Per body: offset in `slots` of the nv column starts of its diagonal
  /// block (dense bodies; -1 for sparse bodies and bodies without velocities).
  std::vector<int> body_slots;
  /// Per force element k with n markers (ForceElement::NumMarkers), n^2
  /// entries from force_slot_begin[k]: offset in `slots` of the column
  /// starts of the coupling block of its markers (a, b) at n a + b, rows
  /// marker a's columns, columns marker b's columns (-1 if empty).
  std::vector<int> force_slots;
  std::vector<int> force_slot_begin;  ///< per force element, see force_slots
  /// Per joint, 5 entries: the 4 coupling offsets of its two markers as
  /// force_slots (2 a + b), then the
  /// offset in `slots` of its constraint rows: for each active equation and
  /// each of its markers with columns (count c), the c positions in S of the
  /// B row, the position in S of the first entry of the B^T column, and the
  /// c positions in B of the B row.
  std::vector<int> joint_slots;

  // scratch
  std::vector<const MarkerState*> force_markers;  ///< marker states of one force element
  Mat12 H;        ///< geometric stiffness of one joint
  MatX G, GtK;    ///< scratch for marker Jacobian products
  MatX twist_dq;  ///< scratch: d(J v)/dx of one marker (6 x nv)
  VecX rhs;       ///< right-hand side / solution (nv + n_active)
};

}  // namespace flexmb
