#pragma once
/// \file exchange_set.h
/// The seed's exchange set between the FE package and the multibody code: a
/// directory with M_CCS.hb and K_CCS.hb (Harwell-Boeing, compressed column,
/// real symmetric assembled), geometry.vtk (legacy VTK) and dof_map.txt (the
/// node and component of every matrix row; docs/formats.md).

#include <string>

#include "flexmb/fe/fe_model.h"

namespace flexmb::io {

/// Writes the free-DOF matrices of `model` and the mesh geometry to `dir`
/// (created if missing). Files are written to a temporary name and renamed.
void WriteExchangeSet(const fe::Mesh& mesh, const fe::AssembledModel& model, const std::string& dir);

/// Reads an exchange set directory back into an imported FeModel.
fe::FeModel ReadExchangeSet(const std::string& dir);

}  // namespace flexmb::io
