#pragma once
/// \file nastran_writer.h
/// Writes an FE model as Nastran bulk data, so that a model flexmb generates
/// (the truck's ladder frame) reaches the user and the reduction the way a
/// user's own model does: as a deck their FE package and ReadNastran read.

#include <string>
#include <vector>

#include "flexmb/fe/mesh.h"

namespace flexmb::io {

/// What WriteNastranBulk writes besides the mesh.
struct NastranDeckExtras {
  std::vector<std::string> comments;  ///< written as `$` lines after the header
  /// Node indices written as ASET1 (component 123456): the interface of a
  /// Craig-Bampton reduction (`flexmb reduce DECK --interface ASET`).
  std::vector<int> interface_nodes;
};

/// Writes `mesh` to `path` as Nastran bulk data (BEGIN BULK ... ENDDATA):
/// GRID (basic coordinates), MAT1,
/// PSHELL (with NSM), CQUAD4 and CTRIA3 (with ZOFFS), RBE2 (element ids
/// after the largest element id), the node sets as SET1 (numbered from 1 in
/// name order, each named in a comment) and `extras`. Materials and
/// properties keep their ids when these are positive and unique, else are
/// numbered from 1. Throws InputError, naming the entity, for anything the
/// writer cannot carry without changing the model: beams, solids, point
/// masses, springs, linear constraints, SPCs, a node or element id <= 0, or a
/// file that cannot be written. Reals are in large field (16 characters, the
/// most a Nastran field holds): the shortest text that reads back to the
/// same double where it fits (short decimals such as -6.76 read back bit for
/// bit), else 10 significant digits.
void WriteNastranBulk(const fe::Mesh& mesh, const std::string& path, const NastranDeckExtras& extras = {});

}  // namespace flexmb::io
