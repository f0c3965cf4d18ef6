#include "flexmb/results/vtk_animation.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numbers>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/model/model.h"
#include "flexmb/model/state.h"
#include "flexmb/reduction/stress_modes.h"

namespace flexmb {
namespace {

constexpr unsigned char kLine = 3, kPolyLine = 4, kTriangle = 5, kHexahedron = 12, kWedge = 13;

// an FE element as a VTK cell, its nodes in VTK order (fe/element_traits.h)
template <class Cells>
void AddElementCell(Cells& m, const fe::Element& e) {
  const fe::ElementTraits& t = fe::Traits(e.type);
  m.cell_types.push_back(static_cast<unsigned char>(t.vtk_code));
  m.cell_sizes.push_back(static_cast<int>(e.nodes.size()));
  const size_t first = m.connectivity.size();
  m.connectivity.resize(first + e.nodes.size());
  for (size_t k = 0; k < e.nodes.size(); ++k)
    m.connectivity[first + fe::FormatNode(t.vtk_order, static_cast<int>(k))] = e.nodes[k];
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
  return MakeShapeMesh(b.shape, body, "body '" + b.name() + "'", segments);
}

ShapeMesh MakeShapeMesh(const Shape& s, int body, const std::string& what, int segments) {
  ShapeMesh m;
  m.body = body;
  if (s.type == Shape::Type::kNone) return m;
  const ErrorContext ctx{"", 0, what};
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
    AddElementCell(m, e);
  }
  return m;
}

VtkAnimationWriter::VtkAnimationWriter(const std::string& dir, const Model& model, VtkEncoding encoding)
    : model_(model), dir_(dir), pvd_((std::filesystem::path(dir) / "anim.pvd").string()), encoding_(encoding) {
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
      AddElementCell(m, el);
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
  // ANCF lines and ropes: a polyline through the centre line
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    const int n = model.bodies[b]->CentreLinePoints();
    if (n < 2) continue;
    lines_.push_back(b);
    n_points_ += n;
    n_cells_ += 1;
    n_conn_ += n;
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

void VtkAnimationWriter::AddLink(int marker_i, int marker_j) {
  const ErrorContext ctx{pvd_, 0, "animation link"};
  if (frames() > 0) throw InputError("a link cannot be added after the first frame", ctx);
  const int n = static_cast<int>(model_.markers.size());
  for (int k : {marker_i, marker_j})
    if (k < 0 || k >= n) throw InputError("marker index " + std::to_string(k) + " out of range", ctx);
  links_.emplace_back(marker_i, marker_j);
  n_points_ += 2;
  n_cells_ += 1;
  n_conn_ += 2;
}

void VtkAnimationWriter::FillArrays(const State& state) {
  VtkFrameArrays& a = arrays_;
  a.points.clear();
  a.connectivity.clear();
  a.offsets.clear();
  a.types.clear();
  a.displacement.clear();
  a.body_id.clear();
  a.von_mises.clear();
  a.points.reserve(3 * static_cast<size_t>(n_points_));
  a.displacement.reserve(3 * static_cast<size_t>(n_points_));
  a.connectivity.reserve(static_cast<size_t>(n_conn_));
  a.offsets.reserve(static_cast<size_t>(n_cells_));
  a.types.reserve(static_cast<size_t>(n_cells_));
  a.body_id.reserve(static_cast<size_t>(n_cells_));
  a.von_mises.reserve(static_cast<size_t>(n_cells_));
  auto point = [&](const Vec3& p) { a.points.insert(a.points.end(), {p.x(), p.y(), p.z()}); };
  std::int32_t base = 0, offset = 0;
  auto cells = [&](const std::vector<int>& conn, const std::vector<int>& sizes,
                   const std::vector<unsigned char>& types, int body, std::int32_t points) {
    for (int v : conn) a.connectivity.push_back(base + v);
    for (int size : sizes) a.offsets.push_back(offset += size);
    a.types.insert(a.types.end(), types.begin(), types.end());
    a.body_id.insert(a.body_id.end(), types.size(), body);
    base += points;
  };

  // shape vertices moved by each body's current frame pose
  for (const ShapeMesh& m : meshes_) {
    const Body& b = *model_.bodies[m.body];
    Vec3 p_WB;
    Mat3 R_WB;
    b.BodyFramePose(state.q.data() + b.q_offset, p_WB, R_WB);
    for (const Vec3& p_B : m.points_B) point(p_WB + R_WB * p_B);
    cells(m.connectivity, m.cell_sizes, m.cell_types, m.body, static_cast<std::int32_t>(m.points_B.size()));
    a.displacement.insert(a.displacement.end(), 3 * m.points_B.size(), 0.0);
    a.von_mises.insert(a.von_mises.end(), m.cell_types.size(), 0.0);
  }
  // links: a line between the marker origins
  for (const auto& link : links_) {
    for (int k : {link.first, link.second}) {
      const Marker& mk = model_.markers[static_cast<size_t>(k)];
      const Body& b = *model_.bodies[mk.body];
      b.EvaluateMarker(state.q.data() + b.q_offset, state.v.data() + b.v_offset, mk, marker_state_);
      point(marker_state_.p_WM);
    }
    a.connectivity.insert(a.connectivity.end(), {base, base + 1});
    a.offsets.push_back(offset += 2);
    a.types.push_back(kLine);
    a.body_id.push_back(model_.markers[static_cast<size_t>(link.first)].body);
    base += 2;
    a.displacement.insert(a.displacement.end(), 6, 0.0);
    a.von_mises.push_back(0.0);
  }
  // centre lines: one polyline each
  for (int body : lines_) {
    const Body& b = *model_.bodies[body];
    const int n = b.CentreLinePoints();
    for (int k = 0; k < n; ++k) {
      point(b.CentreLinePoint(state.q.data() + b.q_offset, k));
      a.connectivity.push_back(base + k);
    }
    a.offsets.push_back(offset += n);
    a.types.push_back(kPolyLine);
    a.body_id.push_back(body);
    base += n;
    a.displacement.insert(a.displacement.end(), 3 * static_cast<size_t>(n), 0.0);
    a.von_mises.push_back(0.0);
  }
  // flexible bodies: nodes at r + R (rho + s u), displacement u in body axes
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
      const Vec3 u = m.u.segment<3>(6 * static_cast<Eigen::Index>(k));
      point(p_WB + R_WB * (nodes[k].x + scale * u));
      a.displacement.insert(a.displacement.end(), {u.x(), u.y(), u.z()});
    }
    cells(m.connectivity, m.cell_sizes, m.cell_types, m.body, static_cast<std::int32_t>(nodes.size()));
    a.von_mises.insert(a.von_mises.end(), m.von_mises.begin(), m.von_mises.end());
  }
}

namespace {

constexpr char kVtkBase64Digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// appends the base64 code of n bytes at p to out; `carry` holds 0-2 bytes
// left from the previous call, flushed with padding when `last`
void VtkBase64Append(const unsigned char* p, size_t n, unsigned char carry[3], int& carried, bool last,
                     std::string& out) {
  auto emit = [&](const unsigned char b[3], int count) {
    const unsigned v = (unsigned(b[0]) << 16) | (unsigned(count > 1 ? b[1] : 0) << 8) | unsigned(count > 2 ? b[2] : 0);
    out.push_back(kVtkBase64Digits[(v >> 18) & 63]);
    out.push_back(kVtkBase64Digits[(v >> 12) & 63]);
    out.push_back(count > 1 ? kVtkBase64Digits[(v >> 6) & 63] : '=');
    out.push_back(count > 2 ? kVtkBase64Digits[v & 63] : '=');
  };
  size_t i = 0;
  while (carried > 0 && carried < 3 && i < n) carry[carried++] = p[i++];
  if (carried == 3) {
    emit(carry, 3);
    carried = 0;
  }
  for (; i + 3 <= n; i += 3) emit(p + i, 3);
  while (i < n) carry[carried++] = p[i++];
  if (last && carried > 0) {
    emit(carry, carried);
    carried = 0;
  }
}

const char* VtkByteOrder() {
  return std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
}

}  // namespace

template <class T>
void VtkAnimationWriter::WriteArray(std::FILE* f, const char* type, const char* name, int components,
                                    const std::vector<T>& values, const char* ascii_format) {
  std::fprintf(f, "        <DataArray type=\"%s\"", type);
  if (name) std::fprintf(f, " Name=\"%s\"", name);
  if (components > 1) std::fprintf(f, " NumberOfComponents=\"%d\"", components);
  text_.clear();
  if (encoding_ == VtkEncoding::kBinary) {
    std::fprintf(f, " format=\"binary\">\n          ");
    const std::uint64_t bytes = values.size() * sizeof(T);
    text_.reserve(4 * ((bytes + sizeof(bytes)) / 3 + 1));
    unsigned char carry[3];
    int carried = 0;
    VtkBase64Append(reinterpret_cast<const unsigned char*>(&bytes), sizeof(bytes), carry, carried, false, text_);
    VtkBase64Append(reinterpret_cast<const unsigned char*>(values.data()), bytes, carry, carried, true, text_);
    text_.push_back('\n');
  } else {
    std::fprintf(f, " format=\"ascii\">\n");
    char buf[96];
    for (size_t k = 0; k < values.size(); k += static_cast<size_t>(components)) {
      text_ += "         ";
      for (int c = 0; c < components && k + static_cast<size_t>(c) < values.size(); ++c) {
        const int n = std::snprintf(buf, sizeof(buf), ascii_format, values[k + static_cast<size_t>(c)]);
        text_.push_back(' ');
        text_.append(buf, static_cast<size_t>(n));
      }
      text_.push_back('\n');
    }
  }
  std::fwrite(text_.data(), 1, text_.size(), f);
  std::fprintf(f, "        </DataArray>\n");
}

void VtkAnimationWriter::WriteFrame(const State& state) {
  FillArrays(state);
  const VtkFrameArrays& a = arrays_;
  const std::string path = FramePath(frames());
  std::FILE* f = OpenOrThrow(path);
  std::fprintf(f,
               "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"%s\" header_type=\"UInt64\">\n"
               "  <UnstructuredGrid>\n"
               "    <FieldData>\n"
               "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
               "format=\"ascii\">%.17g</DataArray>\n"
               "    </FieldData>\n"
               "    <Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n",
               VtkByteOrder(), state.t, n_points_, n_cells_);
  std::fprintf(f, "      <Points>\n");
  WriteArray(f, "Float64", nullptr, 3, a.points, "%.10g");
  std::fprintf(f, "      </Points>\n      <Cells>\n");
  WriteArray(f, "Int32", "connectivity", 1, a.connectivity, "%d");
  WriteArray(f, "Int32", "offsets", 1, a.offsets, "%d");
  WriteArray(f, "UInt8", "types", 1, a.types, "%d");
  std::fprintf(f, "      </Cells>\n      <PointData Vectors=\"displacement\">\n");
  WriteArray(f, "Float64", "displacement", 3, a.displacement, "%.10g");
  std::fprintf(f, "      </PointData>\n      <CellData Scalars=\"body_id\">\n");
  WriteArray(f, "Int32", "body_id", 1, a.body_id, "%d");
  WriteArray(f, "Float64", "von_mises", 1, a.von_mises, "%.8g");
  std::fprintf(f, "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) throw InputError("error writing animation frame", {path, 0, ""});
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
