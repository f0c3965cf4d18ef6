#pragma once
/// \file abaqus_writer.h
/// Writes an fe::Mesh as an Abaqus / CalculiX input deck (.inp), for
/// side-by-side runs with CalculiX. Included by abaqus_reader.h.

#include <string>

#include "flexmb/fe/mesh.h"

namespace flexmb::io {

/// Writes `mesh` as a flat input deck that CalculiX 2.20 and ReadAbaqus
/// accept: nodes, elements (quad4 -> S4, tria3 -> S3, hex8 -> C3D8I, tet4
/// -> C3D4, tet10 -> C3D10, beam2 -> B31, or B33 without shear
/// flexibility, rod2 -> T3D2 with its area in a *SOLID SECTION; a rod's
/// torsion constant J is dropped with a warning), the mesh's node and element sets, materials, one section
/// per run of elements sharing a section (element sets named
/// flexmb_<family>_section_<n>), point masses (MASS / ROTARYI elements),
/// rigid links (*RIGID BODY, or *COUPLING / *KINEMATIC for a partial
/// component mask), single-point constraints (*BOUNDARY); no step. Numbers
/// are written with 17 significant digits, so ReadAbaqus(WriteAbaqus(m))
/// reproduces m's nodes, elements, sections and materials exactly (up to
/// ids and names as described at ReadAbaqus). Throws InputError naming the
/// entity for what a deck cannot carry: a shear modulus that is not
/// E / (2 (1 + nu)), non-structural mass, beam end offsets, point-mass
/// offsets, unequal beam shear factors ky, kz where one is zero; or if the
/// file cannot be written.
void WriteAbaqus(const fe::Mesh& mesh, const std::string& path);

}  // namespace flexmb::io
