#pragma once
/// \file nastran_reader.h
/// Nastran bulk data (the subset FE packages write for linear parts): GRID,
/// CORD2R, CQUAD4, CTRIA3, CBAR, CBEAM, PBAR, PBARL, PBEAM, PSHELL, PSOLID,
/// CTETRA, CHEXA, MAT1, RBE2, CONM2, SPC1, ASET1 and SET1 (as named node
/// sets); small, large and free field, continuation lines, comments, INCLUDE.

#include <string>

#include "flexmb/fe/mesh.h"

namespace flexmb::io {

/// Reads a bulk data file (.bdf, .nas, .dat; executive and case control
/// sections before BEGIN BULK are skipped). Throws InputError naming the
/// file, line and card on malformed or unsupported input.
fe::Mesh ReadNastran(const std::string& path);

}  // namespace flexmb::io
