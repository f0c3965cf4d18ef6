#pragma once
/// \file calculix_matrices.h
/// The matrices CalculiX (ccx 2.x) writes for a *FREQUENCY step with
/// SOLVER=MATRIXSTORAGE (ccx source matrixstorage.c): job.sti (stiffness)
/// and job.mas (mass), one "ROW COLUMN VALUE" line per stored entry of one
/// triangle (ccx prints ROW <= COLUMN, 14 significant digits, all diagonal
/// entries first), rows and columns 1-based over the equations left after
/// single-point constraints; and job.dof, one "NODE.DIRECTION" line per
/// equation (direction 1..3 = ux uy uz). Described in docs/formats.md.

#include <string>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/dof_map.h"

namespace flexmb::io {

/// Reads job.dof: row r (0-based) is line r+1 "NODE.DIRECTION". Throws
/// InputError naming the file and line for a malformed line, a node id <= 0
/// or a direction outside 1..6 (0, a temperature, is not structural).
MatrixRowMap ReadCalculixDofs(const std::string& path);

/// Reads job.sti or job.mas as an n x n symmetric matrix: each stored entry
/// is mirrored. Entries may be in either triangle but each position once.
/// Throws InputError naming the file, line and entry for a malformed line,
/// an index outside 1..n, a non-finite value, or a position given twice
/// (A(i,j) and A(j,i) count as the same position).
fe::SparseMat ReadCalculixMatrix(const std::string& path, int n);

/// K, M and the DOF rows of a CalculiX matrix storage run.
struct CalculixMatrices {
  fe::SparseMat K, M;    ///< full symmetric storage, rows as in `dofs`
  MatrixRowMap dofs;     ///< node id and direction of every row (from job.dof)
};

/// Reads JOB.sti, JOB.mas and JOB.dof, where `job` is the job name with its
/// directory and without extension (as given to ccx -i).
CalculixMatrices ReadCalculixMatrixStorage(const std::string& job);

}  // namespace flexmb::io
