#include "flexmb/io/vtk_animation.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numbers>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/model/model.h"
#include "flexmb/reduction/stress_modes.h"

namespace flexmb {
namespace {

constexpr unsigned char kLine = 3, kTriangle = 5, kQuad = 9, kTetra = 10, kHexahedron = 12, kWedge = 13,
                        kQuadraticTetra = 24;

// vtk cell type of an FE element (node orders of Nastran and VTK agree)
unsigned char CellType(fe::ElementType t) {
  switch (t) {
    case fe::ElementType::kQuad4: return kQuad;
    case fe::ElementType::kTria3: return kTriangle;
    case fe::ElementType::kBeam2: return kLine;
    case fe::ElementType::kTet4: return kTetra;
    case fe::ElementType::kTet10: return kQuadraticTetra;
    case fe::ElementType::kHex8: return kHexahedron;
  }
  return 0;
}
constexpr const char* kPvdTail = "  </Collection>\n</VTKFile>\n";

std::FILE* OpenOrThrow(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f)
    throw InputError("cannot open animation file for writing: " + std::string(std::strerror(errno)),
                     {path, 0, ""});
  return f;
}

void AddCell(ShapeMesh& m, unsigned char type, std::initializer_list<int> ids) {
  m.cell_types.push_back(type);
  m.cell_sizes.push_back(static_cast<int>(ids.size()));
  m.connectivity.insert(m.connectivity.end(), ids);
}

// box with edge lengths a: one hexahedron, base (0-3) counter-clockwise about +z
void Box(ShapeMesh& m, const Vec3& a) {
  const Vec3 h = 0.5 * a;
  for (double z : {-h.z(), h.z()}) {
    m.points_B.emplace_back(-h.x(), -h.y(), z);
    m.points_B.emplace_back(h.x(), -h.y(), z);
    m.points_B.emplace_back(h.x(), h.y(), z);
    m.points_B.emplace_back(-h.x(), h.y(), z);
  }
  AddCell(m, kHexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
}

// cylinder of radius r and length l along z: a fan of n wedges around the axis
void Cylinder(ShapeMesh& m, double r, double l, int n) {
  m.points_B.emplace_back(0, 0, -0.5 * l);
  m.points_B.emplace_back(0, 0, 0.5 * l);
  for (double z : {-0.5 * l, 0.5 * l})
    for (int k = 0; k < n; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / n;
      m.points_B.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
  // vtk wedge: the base (0,1,2) has its normal pointing away from (3,4,5)
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    AddCell(m, kWedge, {0, 2 + k1, 2 + k, 1, 2 + n + k1, 2 + n + k});
  }
}

// sphere of radius r: latitude-longitude triangulation, outward normals
void Sphere(ShapeMesh& m, double r, int slices) {
  const int stacks = std::max(2, slices / 2);
  m.points_B.emplace_back(0, 0, r);
  for (int i = 1; i < stacks; ++i) {
    const double theta = std::numbers::pi * i / stacks;
    for (int k = 0; k < slices; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / slices;
      m.points_B.emplace_back(r * std::sin(theta) * std::cos(phi),
                              r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
    }
  }
  m.points_B.emplace_back(0, 0, -r);
  const int south = static_cast<int>(m.points_B.size()) - 1;
  auto ring = [&](int i, int k) { return 1 + (i - 1) * slices + (k % slices); };
  for (int k = 0; k < slices; ++k) {
    AddCell(m, kTriangle, {0, ring(1, k), ring(1, k + 1)});
    for (int i = 1; i + 1 < stacks; ++i) {
      AddCell(m, kTriangle, {ring(i, k), ring(i + 1, k), ring(i + 1, k + 1)});
      AddCell(m, kTriangle, {ring(i, k), ring(i + 1, k + 1), ring(i, k + 1)});
    }
    AddCell(m, kTriangle, {ring(stacks - 1, k), south, ring(stacks - 1, k + 1)});
  }
}

}  // namespace

ShapeMesh MakeShapeMesh(const Model& model, int body, int segments) {
  const Body& b = *model.bodies[body];
  const Shape& s = b.shape;
  ShapeMesh m;
  m.body = body;
  if (s.type == Shape::Type::kNone) return m;
  const ErrorContext ctx{"", 0, "body '" + b.name() + "'"};
  auto positive = [&](double x, const char* what) {
    if (!(x > 0) || !std::isfinite(x))
      throw InputError(std::string("shape ") + what + " must be positive", ctx);
  };
  switch (s.type) {
    case Shape::Type::kBox:
      positive(s.size.x(), "size x");
      positive(s.size.y(), "size y");
      positive(s.size.z(), "size z");
      Box(m, s.size);
      break;
    case Shape::Type::kCylinder:
      positive(s.size.x(), "radius");
      positive(s.size.y(), "length");
      Cylinder(m, s.size.x(), s.size.y(), std::max(3, segments));
      break;
    case Shape::Type::kSphere:
      positive(s.size.x(), "radius");
      Sphere(m, s.size.x(), std::max(4, segments));
      break;
    case Shape::Type::kNone:
      break;
  }
  // from the shape frame to the user's body frame
  for (Vec3& p : m.points_B) p = s.p_BS + s.R_BS * p;
  return m;
}

ShapeMesh MakeMeshShape(int body, const fe::Mesh& mesh) {
  ShapeMesh m;
  m.body = body;
  m.points_B.reserve(mesh.nodes.size());
  for (const fe::Node& n : mesh.nodes) m.points_B.push_back(n.x);
  for (const fe::Element& e : mesh.elements) {
    m.cell_types.push_back(CellType(e.type));
    m.cell_sizes.push_back(static_cast<int>(e.nodes.size()));
    m.connectivity.insert(m.connectivity.end(), e.nodes.begin(), e.nodes.end());
  }
  return m;
}

VtkAnimationWriter::VtkAnimationWriter(const std::string& dir, const Model& model)
    : model_(model), dir_(dir), pvd_((std::filesystem::path(dir) / "anim.pvd").string()) {
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(dir) / "frames", ec);
  if (ec)
    throw InputError("cannot create animation directory: " + ec.message(), {dir + "/frames", 0, ""});
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    ShapeMesh m = MakeShapeMesh(model, b);
    if (m.points_B.empty()) continue;
    n_points_ += static_cast<int>(m.points_B.size());
    n_cells_ += static_cast<int>(m.cell_types.size());
    n_conn_ += static_cast<int>(m.connectivity.size());
    meshes_.push_back(std::move(m));
  }
  // flexible bodies: their FE meshes
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    const auto* flex = dynamic_cast<const FlexibleBody*>(model.bodies[b].get());
    if (!flex) continue;
    const reduction::ReducedBody& r = flex->reduced();
    FlexMesh m;
    m.body = b;
    m.flexible = flex;
    m.cell_of_element.assign(r.mesh.elements.size(), -1);
    for (size_t e = 0; e < r.mesh.elements.size(); ++e) {
      const fe::Element& el = r.mesh.elements[e];
      m.cell_of_element[e] = static_cast<int>(m.cell_types.size());
      m.cell_types.push_back(CellType(el.type));
      m.cell_sizes.push_back(static_cast<int>(el.nodes.size()));
      m.connectivity.insert(m.connectivity.end(), el.nodes.begin(), el.nodes.end());
    }
    m.u.setZero(r.modes.rows());
    m.stress[0].setZero(r.stress.shell.modes.rows());
    m.stress[1].setZero(r.stress.solid.modes.rows());
    m.von_mises.assign(m.cell_types.size(), 0.0);
    n_points_ += static_cast<int>(r.mesh.nodes.size());
    n_cells_ += static_cast<int>(m.cell_types.size());
    n_conn_ += static_cast<int>(m.connectivity.size());
    flex_.push_back(std::move(m));
  }
  // the collection, empty until the first frame
  pvd_file_ = OpenOrThrow(pvd_);
  std::fprintf(pvd_file_, "<?xml version=\"1.0\"?>\n"
                          "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                          "  <Collection>\n");
  pvd_tail_ = std::ftell(pvd_file_);
  std::fprintf(pvd_file_, "%s", kPvdTail);
  std::fflush(pvd_file_);
}

VtkAnimationWriter::~VtkAnimationWriter() {
  if (pvd_file_) std::fclose(pvd_file_);
}

void VtkAnimationWriter::AddShapeMesh(ShapeMesh mesh) {
  const ErrorContext ctx{pvd_, 0, "animation mesh"};
  if (frames() > 0) throw InputError("a mesh cannot be added after the first frame", ctx);
  if (mesh.body < 0 || mesh.body >= static_cast<int>(model_.bodies.size()))
    throw InputError("body index " + std::to_string(mesh.body) + " out of range", ctx);
  if (mesh.cell_sizes.size() != mesh.cell_types.size())
    throw InputError("cell sizes and types differ in number", ctx);
  size_t conn = 0;
  for (int size : mesh.cell_sizes) {
    if (size <= 0) throw InputError("cell without vertices", ctx);
    conn += static_cast<size_t>(size);
  }
  if (conn != mesh.connectivity.size()) throw InputError("connectivity does not match the cell sizes", ctx);
  const int n = static_cast<int>(mesh.points_B.size());
  for (int v : mesh.connectivity)
    if (v < 0 || v >= n) throw InputError("vertex index " + std::to_string(v) + " out of range", ctx);
  if (mesh.points_B.empty()) return;
  n_points_ += n;
  n_cells_ += static_cast<int>(mesh.cell_types.size());
  n_conn_ += static_cast<int>(mesh.connectivity.size());
  meshes_.push_back(std::move(mesh));
}

std::string VtkAnimationWriter::FramePath(int i) const {
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%05d.vtu", i);
  return (std::filesystem::path(dir_) / "frames" / name).string();
}

void VtkAnimationWriter::UpdateFlexMesh(FlexMesh& m, const double* w) {
  const reduction::ReducedBody& r = m.flexible->reduced();
  const int n = m.flexible->modes();
  const Eigen::Map<const VecX> wv(w, n);
  m.u.noalias() = r.modes * wv;
  const reduction::StressTable* tables[2] = {&r.stress.shell, &r.stress.solid};
  for (int t = 0; t < 2; ++t) {
    const reduction::StressTable& table = *tables[t];
    if (table.elements.empty() || table.modes.cols() != n) continue;
    reduction::ElementVonMises(table, wv, m.stress[t], m.element_von_mises[t]);
    for (size_t k = 0; k < table.elements.size(); ++k)
      m.von_mises[m.cell_of_element[table.elements[k]]] = m.element_von_mises[t](static_cast<Eigen::Index>(k));
  }
}

void VtkAnimationWriter::WriteFrame(const State& state) {
  const std::string path = FramePath(frames());
  std::FILE* f = OpenOrThrow(path);
  std::fprintf(f,
               "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "  <UnstructuredGrid>\n"
               "    <FieldData>\n"
               "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
               "format=\"ascii\">%.15g</DataArray>\n"
               "    </FieldData>\n"
               "    <Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n",
               state.t, n_points_, n_cells_);

  // points: shape vertices moved by each body's current frame pose
  std::fprintf(f,
               "      <Points>\n"
               "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const ShapeMesh& m : meshes_) {
    const Body& b = *model_.bodies[m.body];
    Vec3 p_WB;
    Mat3 R_WB;
    b.BodyFramePose(state.q.data() + b.q_offset, p_WB, R_WB);
    for (const Vec3& p_B : m.points_B) {
      const Vec3 p_W = p_WB + R_WB * p_B;
      std::fprintf(f, "          %.10g %.10g %.10g\n", p_W.x(), p_W.y(), p_W.z());
    }
  }
  const double scale = model_.output.deformation_scale;
  for (FlexMesh& m : flex_) {
    const Body& b = *model_.bodies[m.body];
    const double* q = state.q.data() + b.q_offset;
    UpdateFlexMesh(m, q + 7);
    Vec3 p_WB;
    Mat3 R_WB;
    b.BodyFramePose(q, p_WB, R_WB);
    const auto& nodes = m.flexible->reduced().mesh.nodes;
    for (size_t k = 0; k < nodes.size(); ++k) {
      const Vec3 p_W = p_WB + R_WB * (nodes[k].x + scale * m.u.segment<3>(6 * k));
      std::fprintf(f, "          %.10g %.10g %.10g\n", p_W.x(), p_W.y(), p_W.z());
    }
  }
  std::fprintf(f, "        </DataArray>\n      </Points>\n      <Cells>\n");

  // connectivity with global vertex numbers, then offsets and types
  std::fprintf(f, "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
  int base = 0;
  for (const ShapeMesh& m : meshes_) {
    size_t c = 0;
    for (int size : m.cell_sizes) {
      std::fprintf(f, "         ");
      for (int k = 0; k < size; ++k) std::fprintf(f, " %d", base + m.connectivity[c++]);
      std::fputc('\n', f);
    }
    base += static_cast<int>(m.points_B.size());
  }
  for (const FlexMesh& m : flex_) {
    size_t c = 0;
    for (int size : m.cell_sizes) {
      std::fprintf(f, "         ");
      for (int k = 0; k < size; ++k) std::fprintf(f, " %d", base + m.connectivity[c++]);
      std::fputc('\n', f);
    }
    base += static_cast<int>(m.u.size() / 6);
  }
  std::fprintf(f, "        </DataArray>\n"
                  "        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
  int offset = 0;
  for (const ShapeMesh& m : meshes_)
    for (int size : m.cell_sizes) std::fprintf(f, "          %d\n", offset += size);
  for (const FlexMesh& m : flex_)
    for (int size : m.cell_sizes) std::fprintf(f, "          %d\n", offset += size);
  std::fprintf(f, "        </DataArray>\n"
                  "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (const ShapeMesh& m : meshes_)
    for (unsigned char t : m.cell_types) std::fprintf(f, "          %d\n", t);
  for (const FlexMesh& m : flex_)
    for (unsigned char t : m.cell_types) std::fprintf(f, "          %d\n", t);
  std::fprintf(f, "        </DataArray>\n      </Cells>\n");

  // point data: elastic displacement of flexible bodies' nodes (body axes)
  std::fprintf(f, "      <PointData Vectors=\"displacement\">\n"
                  "        <DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" "
                  "format=\"ascii\">\n");
  for (const ShapeMesh& m : meshes_)
    for (size_t k = 0; k < m.points_B.size(); ++k) std::fprintf(f, "          0 0 0\n");
  for (const FlexMesh& m : flex_)
    for (Eigen::Index k = 0; k < m.u.size(); k += 6)
      std::fprintf(f, "          %.10g %.10g %.10g\n", m.u(k), m.u(k + 1), m.u(k + 2));
  std::fprintf(f, "        </DataArray>\n      </PointData>\n");

  // cell data: the body index, von Mises stress
  std::fprintf(f, "      <CellData Scalars=\"body_id\">\n"
                  "        <DataArray type=\"Int32\" Name=\"body_id\" format=\"ascii\">\n");
  for (const ShapeMesh& m : meshes_)
    for (size_t c = 0; c < m.cell_types.size(); ++c) std::fprintf(f, "          %d\n", m.body);
  for (const FlexMesh& m : flex_)
    for (size_t c = 0; c < m.cell_types.size(); ++c) std::fprintf(f, "          %d\n", m.body);
  std::fprintf(f, "        </DataArray>\n"
                  "        <DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n");
  for (const ShapeMesh& m : meshes_)
    for (size_t c = 0; c < m.cell_types.size(); ++c) std::fprintf(f, "          0\n");
  for (const FlexMesh& m : flex_)
    for (double vm : m.von_mises) std::fprintf(f, "          %.8g\n", vm);
  std::fprintf(f, "        </DataArray>\n      </CellData>\n"
                  "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  const bool ok = std::ferror(f) == 0;
  std::fclose(f);
  if (!ok) throw InputError("error writing animation frame", {path, 0, ""});
  times_.push_back(state.t);
  AppendToPvd(state.t);
}

void VtkAnimationWriter::AppendToPvd(double t) {
  // overwrite the closing tags with the new entry and close again
  const int i = frames() - 1;
  if (std::fseek(pvd_file_, pvd_tail_, SEEK_SET) != 0)
    throw InputError("cannot seek in the animation collection", {pvd_, 0, ""});
  std::fprintf(pvd_file_, "    <DataSet timestep=\"%.15g\" group=\"\" part=\"0\" file=\"frames/frame_%05d.vtu\"/>\n",
               t, i);
  pvd_tail_ = std::ftell(pvd_file_);
  std::fprintf(pvd_file_, "%s", kPvdTail);
  if (std::fflush(pvd_file_) != 0 || std::ferror(pvd_file_))
    throw InputError("error writing the animation collection", {pvd_, 0, ""});
}

}  // namespace flexmb
