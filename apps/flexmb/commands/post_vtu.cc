#include "post_vtu.h"

#include <cstdio>

#include "flexmb/common/error.h"
#include "flexmb/results/vtk_animation.h"

namespace flexmb::commands {

PostElementData::PostElementData(int n)
    : has(n, 0), max_vm(n, 0.0), vm_instant(n, 0), vm_point(n, 0), vm_point_name(n), min_svm(n, 0.0),
      max_svm(n, 0.0), max_p1(n, 0.0), min_p3(n, 0.0), range(n, 0.0), damage(n, 0.0) {}

void PostElementData::Set(int e, const durability::ElementResults& r, int k, const durability::StressRecovery& rec) {
  has[e] = 1;
  max_vm[e] = r.max_von_mises[k];
  vm_instant[e] = r.max_von_mises_instant[k];
  vm_point[e] = r.max_von_mises_point[k];
  vm_point_name[e] = rec.PointName(vm_point[e]);
  min_svm[e] = r.min_signed_von_mises[k];
  max_svm[e] = r.max_signed_von_mises[k];
  max_p1[e] = r.max_principal[k];
  min_p3[e] = r.min_principal[k];
  range[e] = r.range[k];
  damage[e] = r.damage[k];
}

void WritePostVtu(const std::string& path, const fe::Mesh& mesh, const PostElementData& d, double factor) {
  const ShapeMesh cells = MakeMeshShape(0, mesh);
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw InputError("cannot write the ParaView file", {path, 0, ""});
  std::fprintf(f,
               "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
               "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n",
               cells.points_B.size(), cells.cell_types.size());
  std::fprintf(f, "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const Vec3& p : cells.points_B) std::fprintf(f, "%.10g %.10g %.10g\n", p(0), p(1), p(2));
  std::fprintf(f, "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
  for (int v : cells.connectivity) std::fprintf(f, "%d\n", v);
  std::fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
  int end = 0;
  for (int s : cells.cell_sizes) std::fprintf(f, "%d\n", end += s);
  std::fprintf(f, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (unsigned char t : cells.cell_types) std::fprintf(f, "%d\n", t);
  std::fprintf(f, "</DataArray>\n</Cells>\n<CellData Scalars=\"damage\">\n");
  std::fprintf(f, "<DataArray type=\"Int32\" Name=\"element_id\" format=\"ascii\">\n");
  for (const fe::Element& e : mesh.elements) std::fprintf(f, "%d\n", e.id);
  std::fprintf(f, "</DataArray>\n<DataArray type=\"Int32\" Name=\"has_stress\" format=\"ascii\">\n");
  for (int h : d.has) std::fprintf(f, "%d\n", h);
  std::fprintf(f, "</DataArray>\n");
  const auto array = [f](const char* name, const std::vector<double>& v, double scale) {
    std::fprintf(f, "<DataArray type=\"Float64\" Name=\"%s\" format=\"ascii\">\n", name);
    for (double x : v) std::fprintf(f, "%.9g\n", x * scale);
    std::fprintf(f, "</DataArray>\n");
  };
  array("max_von_mises", d.max_vm, 1.0);
  array("min_signed_von_mises", d.min_svm, 1.0);
  array("max_signed_von_mises", d.max_svm, 1.0);
  array("max_principal", d.max_p1, 1.0);
  array("min_principal", d.min_p3, 1.0);
  array("range", d.range, 1.0);
  array("damage", d.damage, 1.0);
  if (factor > 0) array("damage_per_1000km", d.damage, factor);
  std::fprintf(f, "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) throw InputError("cannot write the ParaView file", {path, 0, ""});
}

}  // namespace flexmb::commands
