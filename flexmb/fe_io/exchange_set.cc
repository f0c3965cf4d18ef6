#include "flexmb/fe_io/exchange_set.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/dof_map.h"
#include "flexmb/fe_io/harwell_boeing.h"
#include "flexmb/fe_io/imported_matrices.h"
#include "flexmb/fe_io/vtk_mesh.h"

namespace flexmb::io {

namespace {

namespace fs = std::filesystem;

constexpr const char* kStiffness = "K_CCS.hb";
constexpr const char* kMass = "M_CCS.hb";
constexpr const char* kGeometry = "geometry.vtk";
constexpr const char* kDofMap = "dof_map.txt";

}  // namespace

void WriteExchangeSet(const fe::Mesh& mesh, const fe::AssembledModel& model, const std::string& dir) {
  const int n = model.dofs.n_free;
  if (model.K.rows() != n || model.K.cols() != n || model.M.rows() != n || model.M.cols() != n) {
    throw InputError("K is " + std::to_string(model.K.rows()) + " x " + std::to_string(model.K.cols()) + ", M " +
                         std::to_string(model.M.rows()) + " x " + std::to_string(model.M.cols()) + ", but the model has " +
                         std::to_string(n) + " free DOF",
                     {dir, 0, "exchange set"});
  }
  std::vector<DofMapRow> rows;
  try {
    rows = FreeDofRows(mesh, model.dofs);
  } catch (const InputError& e) {
    throw InputError(e.message(), {dir, 0, "exchange set"});
  }

  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError("cannot create the directory: " + (ec ? ec.message() : std::string("not a directory")),
                     {dir, 0, "exchange set"});
  }

  // every file to a temporary name first, then all renamed
  const std::string suffix = ".tmp" + std::to_string(getpid());
  const std::vector<std::string> names = {kStiffness, kMass, kGeometry, kDofMap};
  std::vector<std::pair<std::string, std::string>> moves;
  for (const std::string& name : names) {
    const std::string final_path = (fs::path(dir) / name).string();
    moves.emplace_back((fs::path(dir) / ("." + name + suffix)).string(), final_path);
  }
  auto cleanup = [&] {
    for (const auto& m : moves) std::remove(m.first.c_str());
  };
  try {
    HarwellBoeingWriteOptions k;
    k.title = "flexmb stiffness matrix (free DOF, " + std::to_string(n) + " rows; rows in dof_map.txt)";
    k.key = "K_CCS";
    WriteHarwellBoeing(model.K, moves[0].first, k);
    HarwellBoeingWriteOptions m;
    m.title = "flexmb mass matrix (free DOF, " + std::to_string(n) + " rows; rows in dof_map.txt)";
    m.key = "M_CCS";
    WriteHarwellBoeing(model.M, moves[1].first, m);
    WriteVtk(mesh, moves[2].first);
    WriteDofMap(rows, moves[3].first);
  } catch (...) {
    cleanup();
    throw;
  }
  for (const auto& [tmp, final_path] : moves) {
    fs::rename(tmp, final_path, ec);
    if (ec) {
      cleanup();
      throw InputError("cannot rename " + tmp + ": " + ec.message(), {final_path, 0, "exchange set"});
    }
  }
}

fe::FeModel ReadExchangeSet(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError("exchange set directory does not exist", {dir, 0, "exchange set"});
  ImportedMatricesSpec spec;
  spec.stiffness = (fs::path(dir) / kStiffness).string();
  spec.mass = (fs::path(dir) / kMass).string();
  spec.dof_map = (fs::path(dir) / kDofMap).string();
  spec.geometry = (fs::path(dir) / kGeometry).string();
  for (const std::string* f : {&spec.stiffness, &spec.mass, &spec.dof_map, &spec.geometry}) {
    if (!fs::exists(*f, ec)) throw InputError("file of the exchange set is missing", {*f, 0, "exchange set"});
  }
  return ReadImportedMatrices(spec);
}

}  // namespace flexmb::io
