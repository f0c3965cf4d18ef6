#include "flexmb/fe_io/format_registry.h"

#include <algorithm>

#include "flexmb/common/error.h"
#include "flexmb/common/text.h"
#include "flexmb/fe_io/abaqus/abaqus_matrix.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/calculix_matrices.h"
#include "flexmb/fe_io/gmsh_reader.h"
#include "flexmb/fe_io/harwell_boeing.h"
#include "flexmb/fe_io/matrix_market.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "flexmb/fe_io/vtk_mesh.h"

namespace flexmb::io {
namespace {

fe::SparseMat HarwellBoeingMatrixOf(const std::string& path, const std::string&, int) {
  return ReadHarwellBoeing(path).A;
}

// .mtx: Matrix Market, or Abaqus's coordinate format when the banner is
// missing and the first entry line is "ROW COLUMN VALUE"; Abaqus's labelled
// format names its rows itself and is read only as a K and M pair
fe::SparseMat MatrixMarketMatrixOf(const std::string& path, const std::string& what, int n) {
  if (IsAbaqusLabelledMatrixFile(path))
    throw InputError("is in Abaqus's labelled format (FORMAT=MATRIX INPUT, rows named by node and DOF), which is "
                     "read only as a stiffness and mass pair of imported matrices (docs/formats.md)",
                     {path, 0, what});
  if (!IsAbaqusCoordinateMatrixFile(path)) return ReadMatrixMarket(path).A;
  // equations after the last stored entry (no stiffness, no mass) come back
  // when the DOF map says how many there are
  fe::SparseMat a = ReadAbaqusCoordinateMatrix(path);
  if (n > a.rows()) a.conservativeResize(n, n);
  return a;
}

fe::SparseMat CalculixMatrixOf(const std::string& path, const std::string& what, int n_dof) {
  if (n_dof <= 0) throw InputError("a CalculiX matrix needs its job.dof file", {path, 0, what});
  return ReadCalculixMatrix(path, n_dof);
}

fe::Mesh NastranMeshOf(const std::string& path) { return ReadNastran(path); }
fe::Mesh AbaqusMeshOf(const std::string& path) { return ReadAbaqus(path); }
fe::Mesh GmshMeshOf(const std::string& path) { return ReadGmsh(path); }
fe::Mesh VtkMeshOf(const std::string& path) { return ReadVtk(path); }

std::string FormatList(bool mesh) {
  std::string list;
  for (const FeFileFormat& f : FeFileFormats()) {
    if (mesh ? !f.read_mesh : !f.read_matrix) continue;
    std::string exts;
    for (const std::string& e : f.extensions) exts += (exts.empty() ? "" : ", ") + e;
    list += (list.empty() ? "" : ", ") + exts + " (" + f.name + ")";
  }
  return list;
}

const FeFileFormat* Find(const std::string& path, bool mesh) {
  const std::string ext = LowerExtension(path);
  for (const FeFileFormat& f : FeFileFormats()) {
    if (mesh ? !f.read_mesh : !f.read_matrix) continue;
    if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end()) return &f;
  }
  return nullptr;
}

}  // namespace

const std::vector<FeFileFormat>& FeFileFormats() {
  static const std::vector<FeFileFormat> formats = {
      {"Nastran", {".bdf", ".nas", ".dat", ".blk", ".bulk"}, NastranMeshOf, nullptr},
      {"Abaqus/CalculiX", {".inp"}, AbaqusMeshOf, nullptr},
      {"gmsh", {".msh"}, GmshMeshOf, nullptr},
      {"legacy VTK", {".vtk"}, VtkMeshOf, nullptr},
      {"Harwell-Boeing", {".hb", ".rb", ".rsa", ".rua", ".psa", ".hbf"}, nullptr, HarwellBoeingMatrixOf},
      {"Matrix Market", {".mtx"}, nullptr, MatrixMarketMatrixOf},
      {"CalculiX matrix", {".sti", ".mas"}, nullptr, CalculixMatrixOf},
  };
  return formats;
}

const FeFileFormat* FindMeshFormat(const std::string& path) { return Find(path, true); }
const FeFileFormat* FindMatrixFormat(const std::string& path) { return Find(path, false); }
std::string MeshFormatList() { return FormatList(true); }
std::string MatrixFormatList() { return FormatList(false); }

}  // namespace flexmb::io
