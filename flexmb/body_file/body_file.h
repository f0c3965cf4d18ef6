#pragma once
/// \file body_file.h
/// The flexible body file: one self-describing, versioned HDF5 file holding
/// a reduction::ReducedBody whole (the FE mesh with its properties, the
/// interface nodes, mode shapes, reduced mass, stiffness and damping,
/// frequencies, inertia invariants, stress modes, units, provenance and
/// counts). The layout is documented in docs/formats.md, section "Flexible
/// body file (.h5)".

#include <string>

#include "flexmb/reduction/reduced_body.h"

namespace flexmb::io {

/// The value of the root attribute "format" of a body file.
inline constexpr const char* kBodyFileFormat = "flexmb-body";

/// Writes `body` to `path` (HDF5). The file is written to `path`.tmp and
/// renamed when complete, so a crash never leaves a half-written body file.
/// Every dataset carries an HDF5 Fletcher32 checksum and all metadata
/// HDF5's own checksums, so that ReadBody detects a changed byte.
/// Every floating-point value is stored as a 64-bit IEEE double, so
/// ReadBody gives the body back bit for bit (except the `origin` of mesh
/// entities, which is not stored). Throws InputError naming the path and
/// the field for an inconsistent body (e.g. invariants for another number
/// of modes, an index out of range) or an I/O failure.
void WriteBody(const reduction::ReducedBody& body, const std::string& path);

/// Reads a body file written by WriteBody. Throws InputError naming the
/// file and the dataset or attribute for a missing file, a file that is not
/// HDF5, another format name, a format version other than
/// ReducedBody::kFormatVersion, a missing dataset or attribute, a dataset of
/// the wrong type or shape, an index out of range or a non-finite value, and
/// for a dataset whose checksum does not match its data (a changed byte).
/// A file of an older writer without checksums is read with one warning
/// (LogWarning) naming the file. Mesh entities get `origin.file` = `path` (the line is 0).
reduction::ReducedBody ReadBody(const std::string& path);

}  // namespace flexmb::io
