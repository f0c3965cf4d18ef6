#include "flexmb/results/vtk_animation.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <sstream>

#include "flexmb/ancf/ancf_cable3d_body.h"
#include "flexmb/ancf/ancf_hoist_rope_body.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/fe/mesh.h"
#include "flexmb/math/rotation.h"
#include "flexmb/model/model.h"
#include "tests/unit/bodies/flexible_test_bodies.h"
#include "tests/unit/results/vtu_test_reader.h"

namespace flexmb {
namespace {

constexpr const char* kDebianPython = "/usr/bin/python3";

// a rigid body of 1 kg, inertia 0.01 kg m^2 about each axis, at the pose
// (p_WB, R_WB)
RigidBodyData VtkAnimUnitBody(const Vec3& p_WB, const Mat3& R_WB) {
  RigidBodyData d;
  d.mass = 1.0;
  d.inertia_C = 0.01 * Mat3::Identity();
  d.p_WB = p_WB;
  d.R_WB = R_WB;
  return d;
}

// a model with an unshaped ground, one body of the given shape at a general
// pose and one body without a shape
std::unique_ptr<Model> ShapedModel(const Shape& shape, const Vec3& p_WB, const Mat3& R_WB) {
  auto m = std::make_unique<Model>();
  RigidBodyData d = VtkAnimUnitBody(p_WB, R_WB);
  auto b = std::make_unique<RigidBody>("shaped", d);
  b->shape = shape;
  m->AddBody(std::move(b));
  d.p_WB = Vec3(5, 5, 5);
  m->AddBody(std::make_unique<RigidBody>("plain", d));
  m->Finalize();
  return m;
}

Shape BoxShape() {
  Shape s;
  s.type = Shape::Type::kBox;
  s.size = Vec3(0.4, 0.2, 0.1);
  s.p_BS = Vec3(0.1, 0.0, -0.05);
  s.R_BS = FromRollPitchYaw(Vec3(0.0, 0.0, std::numbers::pi / 2));
  return s;
}

// runs python and returns its standard output
std::string Python(const std::string& script, const std::string& arg) {
  const std::string cmd = std::string(kDebianPython) + " -c '" + script + "' '" + arg + "'";
  std::FILE* p = popen(cmd.c_str(), "r");
  if (!p) return "";
  std::string out;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof(buf), p)) > 0) out.append(buf, n);
  const int rc = pclose(p);
  return rc == 0 ? out : "python failed";
}

// parses a .vtu as XML and prints: points, connectivity, offsets, types,
// body_id, displacement, von_mises, each as "count values..." on one line,
// after the piece sizes; binary arrays are decoded with base64 and struct
// (floats printed with repr, which reads back to the same double)
const char* kReadVtu = R"(
import sys, base64, struct, xml.etree.ElementTree as E
r = E.parse(sys.argv[1]).getroot()
assert r.get("type") == "UnstructuredGrid"
head = {"UInt32": "<I", "UInt64": "<Q"}[r.get("header_type", "UInt32")]
code = {"Float64": "d", "Float32": "f", "Int32": "i", "Int64": "q", "UInt8": "B"}
def values(a):
  if a.get("format") == "ascii":
    return (a.text or "").split()
  assert a.get("format") == "binary" and r.get("byte_order") == "LittleEndian"
  raw = base64.b64decode("".join((a.text or "").split()))
  h = struct.calcsize(head)
  n = struct.unpack(head, raw[:h])[0]
  assert n == len(raw) - h
  c = code[a.get("type")]
  return [repr(x) for x in struct.unpack("<%d%s" % (n // struct.calcsize(c), c), raw[h:])]
p = r.find("UnstructuredGrid/Piece")
print(p.get("NumberOfPoints"), p.get("NumberOfCells"))
cells = {a.get("Name"): values(a) for a in p.find("Cells").findall("DataArray")}
bid = [a for a in p.find("CellData").findall("DataArray") if a.get("Name") == "body_id"][0]
disp = [a for a in p.find("PointData").findall("DataArray") if a.get("Name") == "displacement"][0]
vm = [a for a in p.find("CellData").findall("DataArray") if a.get("Name") == "von_mises"][0]
for x in (values(p.find("Points/DataArray")), cells["connectivity"], cells["offsets"], cells["types"], values(bid), values(disp), values(vm)):
  print(len(x), " ".join(x))
)";

// parses a .pvd and prints "count" then "timestep file" per data set
const char* kReadPvd = R"(
import sys, xml.etree.ElementTree as E
r = E.parse(sys.argv[1]).getroot()
assert r.get("type") == "Collection"
d = r.findall("Collection/DataSet")
print(len(d))
for x in d: print(x.get("timestep"), x.get("file"))
)";

struct Vtu {
  int n_points = -1, n_cells = -1;
  std::vector<double> points;
  std::vector<int> connectivity, offsets, types, body_id;
  std::vector<double> displacement, von_mises;
};

Vtu ReadVtu(const std::string& path) {
  std::istringstream in(Python(kReadVtu, path));
  Vtu v;
  in >> v.n_points >> v.n_cells;
  auto read = [&](auto& vec) {
    int n = 0;
    in >> n;
    vec.resize(n);
    for (auto& x : vec) in >> x;
  };
  read(v.points);
  read(v.connectivity);
  read(v.offsets);
  read(v.types);
  read(v.body_id);
  read(v.displacement);
  read(v.von_mises);
  return v;
}

class VtkAnimation : public ::testing::Test {
 protected:
  void SetUp() override {
    if (access(kDebianPython, X_OK) != 0) GTEST_SKIP() << "no " << kDebianPython << " to parse the XML";
    dir_ = std::filesystem::temp_directory_path() / ("flexmb_vtk_test_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(VtkAnimation, BoxFramesAndCollection) {
  const Vec3 p_WB(1, 2, 3);
  const Mat3 R_WB = FromRollPitchYaw(Vec3(0.3, -0.2, 0.5));
  const Shape shape = BoxShape();
  auto model = ShapedModel(shape, p_WB, R_WB);
  VtkAnimationWriter w(dir_.string(), *model);
  State s = model->InitialState();
  w.WriteFrame(s);

  // the collection is complete after the first frame
  EXPECT_EQ(Python(kReadPvd, w.pvd_path()), "1\n0 frames/frame_00000.vtu\n");

  // second frame: the body moved by (0, 0, 1)
  s.t = 0.5;
  s.q.segment<3>(model->bodies[1]->q_offset) += Vec3(0, 0, 1);
  w.WriteFrame(s);
  EXPECT_EQ(Python(kReadPvd, w.pvd_path()),
            "2\n0 frames/frame_00000.vtu\n0.5 frames/frame_00001.vtu\n");

  // corners of the box in its shape frame, base counter-clockwise about +z
  const Vec3 h = 0.5 * shape.size;
  const Vec3 corners[8] = {{-h.x(), -h.y(), -h.z()}, {h.x(), -h.y(), -h.z()}, {h.x(), h.y(), -h.z()},
                           {-h.x(), h.y(), -h.z()},  {-h.x(), -h.y(), h.z()}, {h.x(), -h.y(), h.z()},
                           {h.x(), h.y(), h.z()},    {-h.x(), h.y(), h.z()}};
  for (int f = 0; f < 2; ++f) {
    const Vtu v = ReadVtu(w.FramePath(f));
    // one hexahedron of the shaped body; the unshaped body is skipped
    ASSERT_EQ(v.n_points, 8);
    ASSERT_EQ(v.n_cells, 1);
    ASSERT_EQ(v.points.size(), 24u);
    EXPECT_EQ(v.connectivity, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(v.offsets, std::vector<int>{8});
    EXPECT_EQ(v.types, std::vector<int>{12});
    EXPECT_EQ(v.body_id, std::vector<int>{1});
    for (int k = 0; k < 8; ++k) {
      const Vec3 expected = p_WB + Vec3(0, 0, f) + R_WB * (shape.p_BS + shape.R_BS * corners[k]);
      const Vec3 got(v.points[3 * k], v.points[3 * k + 1], v.points[3 * k + 2]);
      EXPECT_LT((got - expected).norm(), 1e-9) << "frame " << f << " corner " << k;
    }
  }
}

TEST_F(VtkAnimation, MeshShapeMovesWithItsBody) {
  const Vec3 p_WB(1, -2, 0.5);
  const Mat3 R_WB = FromRollPitchYaw(Vec3(0.2, 0.1, -0.4));
  auto model = ShapedModel(Shape{}, p_WB, R_WB);
  // a quadrilateral and a triangle of an FE mesh, in the body's frame
  fe::Mesh mesh;
  const Vec3 x[5] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.2}, {2, 0, 0}};
  for (int k = 0; k < 5; ++k) mesh.nodes.push_back(fe::Node{k + 1, x[k], {}});
  fe::Element quad, tria;
  quad.type = fe::ElementType::kQuad4;
  quad.nodes = {0, 1, 2, 3};
  tria.type = fe::ElementType::kTria3;
  tria.nodes = {1, 4, 2};
  mesh.elements = {quad, tria};
  VtkAnimationWriter w(dir_.string(), *model);
  w.AddShapeMesh(MakeMeshShape(1, mesh));
  w.WriteFrame(model->InitialState());
  const Vtu v = ReadVtu(w.FramePath(0));
  ASSERT_EQ(v.n_points, 5);
  ASSERT_EQ(v.points.size(), 15u);
  EXPECT_EQ(v.connectivity, (std::vector<int>{0, 1, 2, 3, 1, 4, 2}));
  EXPECT_EQ(v.types, (std::vector<int>{9, 5}));
  EXPECT_EQ(v.body_id, (std::vector<int>{1, 1}));
  EXPECT_EQ(v.von_mises, (std::vector<double>{0, 0}));
  for (int k = 0; k < 5; ++k) {
    const Vec3 expected = p_WB + R_WB * x[k];
    EXPECT_LT((Vec3(v.points[3 * k], v.points[3 * k + 1], v.points[3 * k + 2]) - expected).norm(), 1e-9);
  }
  // only before the first frame, and only valid meshes
  EXPECT_THROW(w.AddShapeMesh(MakeMeshShape(1, mesh)), InputError);
  VtkAnimationWriter w2((dir_ / "b").string(), *model);
  ShapeMesh bad = MakeMeshShape(1, mesh);
  bad.connectivity[2] = 7;
  EXPECT_THROW(w2.AddShapeMesh(bad), InputError);
  EXPECT_THROW(w2.AddShapeMesh(MakeMeshShape(9, mesh)), InputError);
}

TEST_F(VtkAnimation, NoShapesGiveValidEmptyFrames) {
  Shape none;
  auto model = ShapedModel(none, Vec3::Zero(), Mat3::Identity());
  VtkAnimationWriter w(dir_.string(), *model);
  EXPECT_EQ(Python(kReadPvd, w.pvd_path()), "0\n");
  w.WriteFrame(model->InitialState());
  const Vtu v = ReadVtu(w.FramePath(0));
  EXPECT_EQ(v.n_points, 0);
  EXPECT_EQ(v.n_cells, 0);
  EXPECT_TRUE(v.connectivity.empty());
}

TEST_F(VtkAnimation, FlexibleBodyMeshAtRhoPlusScaledModes) {
  // the free bent bar (7 nodes, 6 beams) at a general pose with a known
  // modal state: node k at r + R (rho_k + s H_k^t w), displacement H_k^t w
  const auto reduced = testing::FreeBentBar(3, 3);
  const int n = reduced->invariants.n;
  FlexibleBodyData d;
  d.reduced = reduced;
  d.p_WB = Vec3(1, -2, 0.5);
  d.R_WB = FromRollPitchYaw(Vec3(0.3, -0.2, 0.5));
  d.w0 = 1e-3 * VecX::LinSpaced(n, 1.0, -2.0);
  Model model;
  model.AddBody(std::make_unique<FlexibleBody>("bar", d));
  model.output.deformation_scale = 40.0;
  model.Finalize();
  VtkAnimationWriter w(dir_.string(), model);
  w.WriteFrame(model.InitialState());
  EXPECT_EQ(Python(kReadPvd, w.pvd_path()), "1\n0 frames/frame_00000.vtu\n");
  const Vtu v = ReadVtu(w.FramePath(0));
  const int nodes = static_cast<int>(reduced->mesh.nodes.size());
  ASSERT_EQ(v.n_points, nodes);
  ASSERT_EQ(v.n_cells, 6);
  ASSERT_EQ(v.points.size(), 3u * nodes);
  ASSERT_EQ(v.displacement.size(), 3u * nodes);
  EXPECT_EQ(v.types, std::vector<int>(6, 3));
  EXPECT_EQ(v.connectivity, (std::vector<int>{0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6}));
  EXPECT_EQ(v.body_id, std::vector<int>(6, 1));
  EXPECT_EQ(v.von_mises, std::vector<double>(6, 0.0));  // beams: none
  double largest = 0.0;
  for (int k = 0; k < nodes; ++k) {
    const Vec3 u = reduced->modes.middleRows(6 * k, 3) * d.w0;
    const Vec3 p = d.p_WB + d.R_WB * (reduced->mesh.nodes[k].x + 40.0 * u);
    const Vec3 got(v.points[3 * k], v.points[3 * k + 1], v.points[3 * k + 2]);
    const Vec3 disp(v.displacement[3 * k], v.displacement[3 * k + 1], v.displacement[3 * k + 2]);
    EXPECT_LT((got - p).norm(), 1e-9) << "node " << k;
    EXPECT_LT((disp - u).norm(), 1e-9 * u.norm() + 1e-15) << "node " << k;
    largest = std::max(largest, 40.0 * u.norm());
  }
  EXPECT_GT(largest, 1e-3);  // the deformation is visible in the positions
}

// the written arrays equal the writer's in-memory arrays: exactly for the
// binary encoding, to the printed digits for ASCII
void VtkExpectFileHasArrays(const std::string& path, const VtkFrameArrays& a, bool exact) {
  const Vtu v = ReadVtu(path);
  auto same = [&](const std::vector<double>& got, const std::vector<double>& want, const char* what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (size_t k = 0; k < got.size(); ++k) {
      if (exact)
        EXPECT_EQ(got[k], want[k]) << what << " " << k;
      else
        EXPECT_NEAR(got[k], want[k], 1e-9 * std::max(1.0, std::abs(want[k]))) << what << " " << k;
    }
  };
  auto ints = [](const auto& x) { return std::vector<int>(x.begin(), x.end()); };
  EXPECT_EQ(v.n_points, static_cast<int>(a.points.size() / 3));
  EXPECT_EQ(v.n_cells, static_cast<int>(a.types.size()));
  same(v.points, a.points, "points");
  same(v.displacement, a.displacement, "displacement");
  same(v.von_mises, a.von_mises, "von_mises");
  EXPECT_EQ(v.connectivity, ints(a.connectivity));
  EXPECT_EQ(v.offsets, ints(a.offsets));
  EXPECT_EQ(v.types, ints(a.types));
  EXPECT_EQ(v.body_id, ints(a.body_id));
  // the tests' own C++ decoder (tests/unit/results/vtu_test_reader.h) agrees
  std::string format;
  const std::vector<double> pts = vtu_test::VtuTestArray(path, "Points", &format);
  EXPECT_EQ(format, exact ? "binary" : "ascii");
  same(pts, a.points, "points (C++ reader)");
  same(vtu_test::VtuTestArray(path, "von_mises"), a.von_mises, "von_mises (C++ reader)");
  same(vtu_test::VtuTestArray(path, "displacement"), a.displacement, "displacement (C++ reader)");
  const std::vector<double> types = vtu_test::VtuTestArray(path, "types");
  EXPECT_EQ(ints(types), ints(a.types));
}

// the flexible bar (non-zero displacement and irrational coordinates) and a
// boxed body and a cylinder, at general poses
TEST_F(VtkAnimation, BinaryAndAsciiFramesHoldTheWrittenArrays) {
  const auto reduced = testing::FreeBentBar(3, 3);
  FlexibleBodyData d;
  d.reduced = reduced;
  d.p_WB = Vec3(1, -2, 0.5);
  d.R_WB = FromRollPitchYaw(Vec3(0.3, -0.2, 0.5));
  d.w0 = 1e-3 * VecX::LinSpaced(reduced->invariants.n, 1.0, -2.0);
  Model model;
  model.AddBody(std::make_unique<FlexibleBody>("bar", d));
  auto box = std::make_unique<RigidBody>(
      "box", VtkAnimUnitBody(Vec3(0.1, 0.7, -0.3), FromRollPitchYaw(Vec3(0.1, 0.9, -0.4))));
  box->shape = BoxShape();
  model.AddBody(std::move(box));
  model.output.deformation_scale = 7.0;
  model.Finalize();
  Shape cyl;
  cyl.type = Shape::Type::kCylinder;
  cyl.size = Vec3(0.3, 1.1, 0.0);
  cyl.p_BS = Vec3(0.2, 0.1, 0.0);
  for (VtkEncoding e : {VtkEncoding::kBinary, VtkEncoding::kAscii}) {
    const bool binary = e == VtkEncoding::kBinary;
    VtkAnimationWriter w((dir_ / (binary ? "bin" : "txt")).string(), model, e);
    EXPECT_EQ(w.encoding(), e);
    w.AddShapeMesh(MakeShapeMesh(cyl, 2, "cylinder", 7));
    State s = model.InitialState();
    s.t = 0.1 / 3.0;
    w.WriteFrame(s);
    const VtkFrameArrays& a = w.last_frame();
    // box 8 + cylinder 2 (7 + 1) + bar nodes; 1 + 7 + 6 cells
    const size_t nodes = reduced->mesh.nodes.size();
    ASSERT_EQ(a.points.size(), 3 * (8 + 16 + nodes));
    ASSERT_EQ(a.types.size(), 14u);
    EXPECT_GT(*std::max_element(a.displacement.begin(), a.displacement.end()), 0.0);
    VtkExpectFileHasArrays(w.FramePath(0), a, binary);
    // the bar's last node at r + R (rho + s u) (the writer's arrays are right)
    const Vec3 u = reduced->modes.middleRows(6 * (nodes - 1), 3) * d.w0;
    const Vec3 p = d.p_WB + d.R_WB * (reduced->mesh.nodes.back().x + 7.0 * u);
    EXPECT_LT((Vec3(a.points[a.points.size() - 3], a.points[a.points.size() - 2], a.points.back()) - p).norm(),
              1e-12);
    EXPECT_EQ(Python(kReadPvd, w.pvd_path()), "1\n0.0333333333333333 frames/frame_00000.vtu\n");
  }
  // binary is smaller than ASCII
  EXPECT_LT(std::filesystem::file_size(dir_ / "bin" / "frames" / "frame_00000.vtu"),
            std::filesystem::file_size(dir_ / "txt" / "frames" / "frame_00000.vtu"));
}

TEST_F(VtkAnimation, LinkIsALineBetweenItsMarkers) {
  const Vec3 p_WB(1, 2, 3);
  const Mat3 R_WB = FromRollPitchYaw(Vec3(0.3, -0.2, 0.5));
  auto model = std::make_unique<Model>();
  RigidBodyData d = VtkAnimUnitBody(p_WB, R_WB);
  d.c_B = Vec3(0.2, 0, 0);
  model->AddBody(std::make_unique<RigidBody>("a", d));
  const int mi = model->AddMarker(1, "end", Vec3(0.5, -0.1, 0.2), Mat3::Identity());
  const int mj = model->AddMarker(0, "fixed", Vec3(-1, 4, 0.5), Mat3::Identity());
  model->Finalize();
  VtkAnimationWriter w(dir_.string(), *model);
  w.AddLink(mi, mj);
  EXPECT_THROW(w.AddLink(mi, 99), InputError);
  w.WriteFrame(model->InitialState());
  EXPECT_THROW(w.AddLink(mi, mj), InputError);
  const Vtu v = ReadVtu(w.FramePath(0));
  ASSERT_EQ(v.n_points, 2);
  ASSERT_EQ(v.n_cells, 1);
  EXPECT_EQ(v.types, std::vector<int>{3});
  EXPECT_EQ(v.body_id, std::vector<int>{1});
  EXPECT_EQ(v.connectivity, (std::vector<int>{0, 1}));
  // marker positions in the user's body frame moved by the body's pose
  EXPECT_LT((Vec3(v.points[0], v.points[1], v.points[2]) - (p_WB + R_WB * Vec3(0.5, -0.1, 0.2))).norm(), 1e-12);
  EXPECT_LT((Vec3(v.points[3], v.points[4], v.points[5]) - Vec3(-1, 4, 0.5)).norm(), 1e-12);
}

TEST_F(VtkAnimation, AncfLinesArePolylinesThroughTheirCentreLines) {
  // a cable and a hoisting rope, bent and stretched: 4 points per element
  auto model = std::make_unique<Model>();
  ancf::AncfCable3dData c;
  c.length = 2.0;
  c.elements = 3;
  c.section.E = 1e9, c.section.A = 1e-4, c.section.I = 1e-10, c.section.rho = 7800;
  c.start_W = Vec3(1, 0, 2);
  c.direction_W = Vec3(1, 1, 0);
  const int bc = model->AddBody(std::make_unique<ancf::AncfCable3dBody>("cable", c));
  ancf::HoistRopeData r;
  r.free_length = 6.0;
  r.stored_length = 10.0;
  r.elements = 2;
  r.section = c.section;
  r.drum_radius = 0.3;
  const int br = model->AddBody(std::make_unique<ancf::AncfHoistRopeBody>("rope", r));
  model->Finalize();
  State s = model->InitialState();
  for (int j = 0; j < s.q.size(); ++j) s.q(j) += 0.05 * std::sin(1.7 * j);
  VtkAnimationWriter w(dir_.string(), *model);
  w.WriteFrame(s);
  const Vtu v = ReadVtu(w.FramePath(0));
  ASSERT_EQ(v.n_cells, 2);
  ASSERT_EQ(v.n_points, 13 + 9);
  EXPECT_EQ(v.types, (std::vector<int>{4, 4}));
  EXPECT_EQ(v.body_id, (std::vector<int>{bc, br}));
  EXPECT_EQ(v.offsets, (std::vector<int>{13, 22}));
  const auto& cable = dynamic_cast<const ancf::AncfCable3dBody&>(*model->bodies[bc]);
  const auto& rope = dynamic_cast<const ancf::AncfHoistRopeBody&>(*model->bodies[br]);
  const double* qc = s.q.data() + cable.q_offset;
  const double* qr = s.q.data() + rope.q_offset;
  for (int k = 0; k < 13; ++k) {
    EXPECT_EQ(v.connectivity[k], k);
    const Vec3 p(v.points[3 * k], v.points[3 * k + 1], v.points[3 * k + 2]);
    EXPECT_LT((p - cable.PositionAt(qc, k * 2.0 / 12)).norm(), 1e-12) << k;
  }
  // the rope's points: every 4th at a node, the ends at the hook and the sheave
  const auto node = [&](int n) { return Vec3(qr[6 * n], qr[6 * n + 1], qr[6 * n + 2]); };
  for (int n = 0; n <= 2; ++n) {
    const int k = 13 + 4 * n;
    EXPECT_LT((Vec3(v.points[3 * k], v.points[3 * k + 1], v.points[3 * k + 2]) - node(n)).norm(), 1e-12) << n;
  }
  const int mid = 13 + 6;  // eta = 1.5: the material point half-way along element 1
  const double L = rope.FreeLength(qr);
  EXPECT_LT((Vec3(v.points[3 * mid], v.points[3 * mid + 1], v.points[3 * mid + 2]) -
             rope.MaterialPoint(qr, 0.5 * L / 2.0)).norm(),
            1e-12);
}

// signed volume of the tetrahedron (a, b, c, d)
double TetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

TEST(ShapeMesh, BoxHexahedronIsPositivelyOriented) {
  auto model = ShapedModel(BoxShape(), Vec3::Zero(), Mat3::Identity());
  const ShapeMesh m = MakeShapeMesh(*model, 1);
  ASSERT_EQ(m.points_B.size(), 8u);
  ASSERT_EQ(m.cell_types, std::vector<unsigned char>{12});
  const auto& p = m.points_B;
  // vtk hexahedron: the base (0,1,2,3) has its normal towards (4,5,6,7);
  // the volume of the six tetrahedra of the corner-0 fan is the box volume
  const int c[8] = {m.connectivity[0], m.connectivity[1], m.connectivity[2], m.connectivity[3],
                    m.connectivity[4], m.connectivity[5], m.connectivity[6], m.connectivity[7]};
  EXPECT_GT(TetVolume(p[c[0]], p[c[1]], p[c[3]], p[c[4]]), 0.0);
  const double vol = TetVolume(p[c[0]], p[c[1]], p[c[2]], p[c[6]]) +
                     TetVolume(p[c[0]], p[c[2]], p[c[3]], p[c[6]]) +
                     TetVolume(p[c[0]], p[c[3]], p[c[7]], p[c[6]]) +
                     TetVolume(p[c[0]], p[c[7]], p[c[4]], p[c[6]]) +
                     TetVolume(p[c[0]], p[c[4]], p[c[5]], p[c[6]]) +
                     TetVolume(p[c[0]], p[c[5]], p[c[1]], p[c[6]]);
  EXPECT_NEAR(vol, 0.4 * 0.2 * 0.1, 1e-15);
}

TEST(ShapeMesh, CylinderWedgesFillThePolygonalPrism) {
  Shape s;
  s.type = Shape::Type::kCylinder;
  s.size = Vec3(0.3, 1.2, 0.0);
  s.p_BS = Vec3(0.5, -0.2, 0.1);
  s.R_BS = FromRollPitchYaw(Vec3(0.4, 0.7, -0.3));
  auto model = ShapedModel(s, Vec3::Zero(), Mat3::Identity());
  const int n = 16;
  const ShapeMesh m = MakeShapeMesh(*model, 1, n);
  ASSERT_EQ(m.points_B.size(), static_cast<size_t>(2 * n + 2));
  ASSERT_EQ(m.cell_types.size(), static_cast<size_t>(n));
  const Vec3 axis = s.R_BS.col(2);
  double volume = 0.0;
  for (int c = 0; c < n; ++c) {
    EXPECT_EQ(m.cell_types[c], 13);
    ASSERT_EQ(m.cell_sizes[c], 6);
    const int* w = &m.connectivity[6 * c];
    const Vec3 &p0 = m.points_B[w[0]], &p1 = m.points_B[w[1]], &p2 = m.points_B[w[2]];
    const Vec3& p3 = m.points_B[w[3]];
    // vtk wedge: the normal of the base (0,1,2) points away from (3,4,5)
    const Vec3 normal = (p1 - p0).cross(p2 - p0);
    EXPECT_LT(normal.dot(p3 - p0), 0.0);
    // each top vertex is its base vertex moved by the length along the axis
    for (int k = 0; k < 3; ++k)
      EXPECT_LT((m.points_B[w[k + 3]] - m.points_B[w[k]] - s.size.y() * axis).norm(), 1e-14);
    volume += 0.5 * normal.norm() * s.size.y();
  }
  // every vertex is on the axis or on the rim
  for (const Vec3& p : m.points_B) {
    const Vec3 d = p - s.p_BS;
    const double radial = (d - d.dot(axis) * axis).norm();
    EXPECT_TRUE(radial < 1e-14 || std::abs(radial - s.size.x()) < 1e-14);
    EXPECT_NEAR(std::abs(d.dot(axis)), 0.5 * s.size.y(), 1e-14);
  }
  // regular n-gon area n/2 r^2 sin(2 pi/n) times the length
  const double r = s.size.x();
  EXPECT_NEAR(volume, 0.5 * n * r * r * std::sin(2 * std::numbers::pi / n) * s.size.y(), 1e-13);
}

TEST(ShapeMesh, SphereIsAClosedOutwardSurface) {
  Shape s;
  s.type = Shape::Type::kSphere;
  s.size = Vec3(0.25, 0, 0);
  s.p_BS = Vec3(0.1, 0.2, 0.3);
  auto model = ShapedModel(s, Vec3::Zero(), Mat3::Identity());
  const ShapeMesh m = MakeShapeMesh(*model, 1, 24);
  for (const Vec3& p : m.points_B) EXPECT_NEAR((p - s.p_BS).norm(), 0.25, 1e-14);
  // each directed edge once and its reverse once: closed and consistently oriented
  std::map<std::pair<int, int>, int> edges;
  double volume = 0.0;
  for (size_t c = 0; c < m.cell_types.size(); ++c) {
    ASSERT_EQ(m.cell_types[c], 5);
    const int* t = &m.connectivity[3 * c];
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
    volume += TetVolume(s.p_BS, m.points_B[t[0]], m.points_B[t[1]], m.points_B[t[2]]);
  }
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u);
  }
  // Euler characteristic of a sphere: V - E + F = 2
  const long V = static_cast<long>(m.points_B.size()), E = static_cast<long>(edges.size()) / 2,
             F = static_cast<long>(m.cell_types.size());
  EXPECT_EQ(V - E + F, 2);
  // outward normals: positive enclosed volume, a little below the sphere's
  const double sphere = 4.0 / 3.0 * std::numbers::pi * std::pow(0.25, 3);
  EXPECT_GT(volume, 0.9 * sphere);
  EXPECT_LT(volume, sphere);
}

TEST(ShapeMesh, NoShapeGivesNoCells) {
  auto model = ShapedModel(Shape{}, Vec3::Zero(), Mat3::Identity());
  const ShapeMesh m = MakeShapeMesh(*model, 1);
  EXPECT_TRUE(m.points_B.empty());
  EXPECT_TRUE(m.cell_types.empty());
}

}  // namespace
}  // namespace flexmb
