#pragma once
/// \file abaqus_reader.h
/// Abaqus / CalculiX input decks (.inp): *NODE, *ELEMENT (S4, S4R, S3, B31,
/// C3D4, C3D10, C3D8 and their variants), *NSET, *ELSET (with GENERATE),
/// *MATERIAL / *ELASTIC / *DENSITY, *SHELL SECTION, *BEAM SECTION,
/// *SOLID SECTION, *BOUNDARY, *MASS, *RIGID BODY / *KINEMATIC coupling,
/// *DISTRIBUTING coupling, *EQUATION, *TIE, *INCLUDE; and, through abaqus_writer.h, the writer used for side-by-side
/// runs with CalculiX. The supported subset and its mapping to fe::Mesh are
/// documented in docs/formats.md, "Abaqus / CalculiX input".

#include <string>

#include "flexmb/fe/mesh.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"

namespace flexmb::io {

/// Reads an input deck. Keywords that do not describe the model (steps,
/// outputs) are skipped; unknown element types and malformed lines throw
/// InputError naming the file, line and entity. Model keywords that flexmb
/// does not use and that do not change the stiffness or mass (loads,
/// *ORIENTATION of isotropic materials) are listed in one warning
/// (flexmb::LogWarning); those that would change them are an error. C3D8
/// and C3D8R elements become flexmb's incompatible-mode (C3D8I-like)
/// hexahedron with a warning. Material and section
/// ids are their positions + 1 in the deck; set names keep the spelling of
/// their first definition and are matched case-insensitively.
fe::Mesh ReadAbaqus(const std::string& path);

}  // namespace flexmb::io
