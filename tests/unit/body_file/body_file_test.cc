// The flexible body file (body_file/body_file.h): write and read back bit for bit
// (every field of ReducedBody: a synthetic body with every kind of mesh
// entity and awkward values, a body reduced from a plate, an empty body),
// atomic writing, and the errors for damaged files made with the HDF5 API
// (missing file, not HDF5, truncated, wrong format name or version, missing
// or misshapen dataset, non-finite value, index out of range).

#include "flexmb/body_file/body_file.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/stress_modes.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"
#include "tests/unit/reduction/reduction_test_models.h"

namespace flexmb::io {
namespace {

namespace fs = std::filesystem;
using reduction::Mat3;
using reduction::MatX;
using reduction::ReducedBody;
using reduction::StressTable;
using testing::ExpectContains;
using testing::InputErrorOf;
using testing::ScratchPath;

// ---- bitwise comparison of every field ----

::testing::AssertionResult SameBits(const double* a, const double* b, size_t n) {
  for (size_t k = 0; k < n; ++k) {
    if (std::memcmp(a + k, b + k, sizeof(double)) != 0) {
      return ::testing::AssertionFailure() << "entry " << k << ": " << a[k] << " vs " << b[k];
    }
  }
  return ::testing::AssertionSuccess();
}

void ExpectSame(const MatX& a, const MatX& b, const std::string& what) {
  ASSERT_EQ(a.rows(), b.rows()) << what;
  ASSERT_EQ(a.cols(), b.cols()) << what;
  EXPECT_TRUE(SameBits(a.data(), b.data(), a.size())) << what;
}

void ExpectSame(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_TRUE(SameBits(a.data(), b.data(), a.size())) << what;
}

void ExpectSame(const Mat3& a, const Mat3& b, const std::string& what) {
  EXPECT_TRUE(SameBits(a.data(), b.data(), 9)) << what;
}

void ExpectSame(double a, double b, const std::string& what) { EXPECT_TRUE(SameBits(&a, &b, 1)) << what; }

void ExpectSame(const std::vector<Mat3>& a, const std::vector<Mat3>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) ExpectSame(a[i], b[i], what + "[" + std::to_string(i) + "]");
}

void ExpectBitIdenticalMesh(const fe::Mesh& a, const fe::Mesh& b) {
  EXPECT_EQ(a.source, b.source);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (size_t k = 0; k < a.nodes.size(); ++k) {
    EXPECT_EQ(a.nodes[k].id, b.nodes[k].id);
    EXPECT_TRUE(SameBits(a.nodes[k].x.data(), b.nodes[k].x.data(), 3)) << "node " << a.nodes[k].id;
    EXPECT_EQ(b.NodeIndex(a.nodes[k].id), static_cast<int>(k));
  }
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (size_t k = 0; k < a.elements.size(); ++k) {
    const fe::Element &x = a.elements[k], &y = b.elements[k];
    const std::string what = "element " + std::to_string(x.id);
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.type, y.type) << what;
    EXPECT_EQ(x.property, y.property) << what;
    EXPECT_EQ(x.nodes, y.nodes) << what;
    EXPECT_TRUE(SameBits(x.orientation.data(), y.orientation.data(), 3)) << what;
    EXPECT_TRUE(SameBits(x.offset_a.data(), y.offset_a.data(), 3)) << what;
    EXPECT_TRUE(SameBits(x.offset_b.data(), y.offset_b.data(), 3)) << what;
    ExpectSame(x.shell_offset, y.shell_offset, what);
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (size_t k = 0; k < a.materials.size(); ++k) {
    const fe::Material &x = a.materials[k], &y = b.materials[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.name, y.name);
    for (auto [p, q] : {std::pair{x.E, y.E}, {x.nu, y.nu}, {x.G, y.G}, {x.rho, y.rho}}) ExpectSame(p, q, x.name);
  }
  ASSERT_EQ(a.shell_sections.size(), b.shell_sections.size());
  for (size_t k = 0; k < a.shell_sections.size(); ++k) {
    const fe::ShellSection &x = a.shell_sections[k], &y = b.shell_sections[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.material, y.material);
    ExpectSame(x.thickness, y.thickness, "shell thickness");
    ExpectSame(x.nsm, y.nsm, "shell nsm");
  }
  ASSERT_EQ(a.beam_sections.size(), b.beam_sections.size());
  for (size_t k = 0; k < a.beam_sections.size(); ++k) {
    const fe::BeamSection &x = a.beam_sections[k], &y = b.beam_sections[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.material, y.material);
    const double xa[] = {x.A, x.Iy, x.Iz, x.Iyz, x.J, x.ky, x.kz, x.nsm};
    const double ya[] = {y.A, y.Iy, y.Iz, y.Iyz, y.J, y.ky, y.kz, y.nsm};
    EXPECT_TRUE(SameBits(xa, ya, 8)) << "beam section " << x.id;
  }
  ASSERT_EQ(a.solid_sections.size(), b.solid_sections.size());
  for (size_t k = 0; k < a.solid_sections.size(); ++k) {
    EXPECT_EQ(a.solid_sections[k].id, b.solid_sections[k].id);
    EXPECT_EQ(a.solid_sections[k].material, b.solid_sections[k].material);
  }
  ASSERT_EQ(a.point_masses.size(), b.point_masses.size());
  for (size_t k = 0; k < a.point_masses.size(); ++k) {
    const fe::PointMass &x = a.point_masses[k], &y = b.point_masses[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.node, y.node);
    ExpectSame(x.mass, y.mass, "point mass");
    EXPECT_TRUE(SameBits(x.offset.data(), y.offset.data(), 3));
    ExpectSame(x.inertia, y.inertia, "point mass inertia");
    EXPECT_EQ(x.general, y.general);
    EXPECT_TRUE(SameBits(x.matrix.data(), y.matrix.data(), 36));
  }
  ASSERT_EQ(a.springs.size(), b.springs.size());
  for (size_t k = 0; k < a.springs.size(); ++k) {
    const fe::ScalarSpring &x = a.springs[k], &y = b.springs[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.node_a, y.node_a);
    EXPECT_EQ(x.component_a, y.component_a);
    EXPECT_EQ(x.node_b, y.node_b);
    EXPECT_EQ(x.component_b, y.component_b);
    ExpectSame(x.k, y.k, "spring stiffness");
    EXPECT_EQ(x.directional, y.directional);
    EXPECT_TRUE(SameBits(x.coef_a.data(), y.coef_a.data(), 6));
    EXPECT_TRUE(SameBits(x.coef_b.data(), y.coef_b.data(), 6));
  }
  ASSERT_EQ(a.rigid_links.size(), b.rigid_links.size());
  for (size_t k = 0; k < a.rigid_links.size(); ++k) {
    EXPECT_EQ(a.rigid_links[k].id, b.rigid_links[k].id);
    EXPECT_EQ(a.rigid_links[k].independent, b.rigid_links[k].independent);
    EXPECT_EQ(a.rigid_links[k].dependent, b.rigid_links[k].dependent);
    EXPECT_EQ(a.rigid_links[k].dofs, b.rigid_links[k].dofs);
  }
  ASSERT_EQ(a.constraints.size(), b.constraints.size());
  for (size_t k = 0; k < a.constraints.size(); ++k) {
    EXPECT_EQ(a.constraints[k].node, b.constraints[k].node);
    EXPECT_EQ(a.constraints[k].dofs, b.constraints[k].dofs);
  }
  EXPECT_EQ(a.node_sets, b.node_sets);
  EXPECT_EQ(a.element_sets, b.element_sets);
}

void ExpectSameTable(const StressTable& a, const StressTable& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.components, b.components) << a.name;
  EXPECT_EQ(a.locations, b.locations) << a.name;
  EXPECT_EQ(a.elements, b.elements) << a.name;
  ExpectSame(a.axes, b.axes, a.name + " axes");
  ExpectSame(a.modes, b.modes, a.name + " modes");
}

void ExpectSameBody(const ReducedBody& a, const ReducedBody& b) {
  ExpectBitIdenticalMesh(a.mesh, b.mesh);
  EXPECT_EQ(a.interface_nodes, b.interface_nodes);
  ExpectSame(a.modes, b.modes, "modes");
  ExpectSame(a.frequencies_hz, b.frequencies_hz, "frequencies_hz");
  ExpectSame(a.mass, b.mass, "mass");
  ExpectSame(a.stiffness, b.stiffness, "stiffness");
  ExpectSame(a.damping, b.damping, "damping");
  const reduction::InertiaInvariants &u = a.invariants, &v = b.invariants;
  EXPECT_EQ(u.n, v.n);
  ExpectSame(u.mvv, v.mvv, "mvv");
  ExpectSame(u.mvo0, v.mvo0, "mvo0");
  ExpectSame(u.mvo1, v.mvo1, "mvo1");
  ExpectSame(u.mvw, v.mvw, "mvw");
  ExpectSame(u.moo0, v.moo0, "moo0");
  ExpectSame(u.moo1, v.moo1, "moo1");
  ExpectSame(u.moo2, v.moo2, "moo2");
  ExpectSame(u.mow0, v.mow0, "mow0");
  ASSERT_EQ(u.mow1.size(), v.mow1.size());
  for (size_t i = 0; i < u.mow1.size(); ++i) ExpectSame(u.mow1[i], v.mow1[i], "mow1[" + std::to_string(i) + "]");
  ExpectSame(u.mww, v.mww, "mww");
  ExpectSameTable(a.stress.shell, b.stress.shell);
  ExpectSameTable(a.stress.beam, b.stress.beam);
  ExpectSameTable(a.stress.solid, b.stress.solid);
  EXPECT_EQ(a.units, b.units);
  EXPECT_EQ(a.provenance, b.provenance);
  EXPECT_EQ(a.static_modes, b.static_modes);
  EXPECT_EQ(a.normal_modes, b.normal_modes);
  EXPECT_EQ(a.rigid_modes_removed, b.rigid_modes_removed);
}

// ---- bodies ----

// reproducible doubles of every magnitude, with the awkward ones mixed in
struct Values {
  uint64_t state = 12345;
  int count = 0;
  double operator()() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = static_cast<double>(state >> 11) / 9007199254740992.0;  // [0, 1)
    switch (++count % 11) {
      case 3: return -0.0;
      case 5: return 4.9406564584124654e-324 * (1 + (state >> 60));  // subnormal
      case 7: return -1.7976931348623157e308 * u;
      case 9: return 1e-300 * u;
      default: return (u - 0.5) * std::pow(10.0, static_cast<int>(state >> 59) - 8);
    }
  }
  Mat3 M3() {
    Mat3 m;
    for (int k = 0; k < 9; ++k) m.data()[k] = (*this)();
    return m;
  }
  MatX M(Eigen::Index r, Eigen::Index c) {
    MatX m(r, c);
    for (Eigen::Index k = 0; k < m.size(); ++k) m.data()[k] = (*this)();
    return m;
  }
  fe::Vec3 V3() { return fe::Vec3((*this)(), (*this)(), (*this)()); }
};

StressTable Table(Values& val, const std::string& name, std::vector<std::string> components,
                  std::vector<std::string> locations, std::vector<int> elements, int n) {
  StressTable t;
  t.name = name;
  t.components = std::move(components);
  t.locations = std::move(locations);
  t.elements = std::move(elements);
  for (size_t k = 0; k < t.elements.size(); ++k) t.axes.push_back(val.M3());
  t.modes = val.M(static_cast<Eigen::Index>(t.elements.size()) * t.Locations() * t.Components(), n);
  return t;
}

// a body with every kind of mesh entity and every field set (not a
// physical body: the values only have to come back bit for bit)
ReducedBody EveryField() {
  Values val;
  ReducedBody b;
  fe::Mesh& m = b.mesh;
  m.source = "models/frame ü.bdf";
  for (int k = 0; k < 14; ++k) {
    fe::Node nd;
    nd.id = 1000 + 7 * k;
    nd.x = val.V3();
    m.nodes.push_back(nd);
  }
  m.IndexNodes();
  for (int k = 0; k < 3; ++k) {
    fe::Material mat;
    mat.id = 10 + k;
    mat.name = k == 0 ? "" : k == 1 ? "steel \"S355\"" : "alu/6061.T6";
    mat.E = val();
    mat.nu = val();
    mat.G = val();
    mat.rho = val();
    m.materials.push_back(mat);
  }
  m.shell_sections.push_back({5, 0, val(), val(), {}});
  m.shell_sections.push_back({6, -1, val(), val(), {}});
  m.beam_sections.push_back({7, 1, val(), val(), val(), val(), val(), val(), val(), val(), {}});
  m.solid_sections.push_back({8, 2, {}});
  m.solid_sections.push_back({9, 1, {}});
  auto element = [&](int id, fe::ElementType type, int property, std::vector<int> nodes) {
    fe::Element e;
    e.id = id;
    e.type = type;
    e.property = property;
    e.nodes = std::move(nodes);
    e.orientation = val.V3();
    e.offset_a = val.V3();
    e.offset_b = val.V3();
    e.shell_offset = val();
    m.elements.push_back(e);
  };
  element(1, fe::ElementType::kQuad4, 0, {0, 1, 2, 3});
  element(2, fe::ElementType::kTria3, 1, {3, 2, 4});
  element(30, fe::ElementType::kBeam2, 0, {4, 5});
  element(4, fe::ElementType::kTet4, 0, {5, 6, 7, 8});
  element(5, fe::ElementType::kTet10, 1, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  element(6, fe::ElementType::kHex8, 0, {6, 7, 8, 9, 10, 11, 12, 13});
  element(7, fe::ElementType::kQuad4, -1, {10, 11, 12, 13});
  m.point_masses.push_back({3, 4, val(), val.V3(), val.M3(), {}});
  m.point_masses.push_back({4, 13, val(), val.V3(), val.M3(), {}});
  {
    // a general 6 x 6 nodal mass matrix (CONM1)
    fe::PointMass general;
    general.id = 5;
    general.node = 2;
    general.general = true;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) general.matrix(i, j) = val();
    m.point_masses.push_back(general);
  }
  m.springs.push_back({21, 3, 2, 7, 4, val(), false, {}, {}, {}});
  m.springs.push_back({22, 5, 5, -1, 0, val(), false, {}, {}, {}});
  {
    // a directional spring (CELAS in a CD system, CBUSH)
    fe::ScalarSpring d;
    d.id = 23;
    d.node_a = 4;
    d.node_b = 6;
    d.k = val();
    d.directional = true;
    for (int c = 0; c < 6; ++c) d.coef_a[c] = val(), d.coef_b[c] = val();
    m.springs.push_back(d);
  }
  m.rigid_links.push_back({11, 0, {12, 13}, 0b111111, {}});
  m.rigid_links.push_back({12, 5, {}, 0b000111, {}});
  m.rigid_links.push_back({13, 6, {9}, 0b101000, {}});
  m.constraints.push_back({1, 0b111111, {}});
  m.constraints.push_back({13, 0b000100, {}});
  m.node_sets["SET1_1"] = {0, 1, 2};
  m.node_sets["ASET"] = {};
  m.node_sets["a/b.c with blanks"] = {13, 0, 13};
  m.element_sets["flexmb_shell_section_1"] = {0, 6};
  m.element_sets["EALL"] = {0, 1, 2, 3, 4, 5, 6};

  const int nn = static_cast<int>(m.nodes.size()), n = 3;
  b.interface_nodes = {13, 0, 5};
  b.modes = val.M(6 * nn, n);
  b.frequencies_hz = val.M(n, 1);
  b.mass = val.M(n, n);
  b.stiffness = val.M(n, n);
  b.damping = val.M(n, n);
  reduction::InertiaInvariants& v = b.invariants;
  v.n = n;
  v.mvv = val.M3();
  v.mvo0 = val.M3();
  v.moo0 = val.M3();
  for (int i = 0; i < n; ++i) {
    v.mvo1.push_back(val.M3());
    v.moo1.push_back(val.M3());
    v.mow1.push_back(val.M(3, n));
  }
  for (int i = 0; i < n * n; ++i) v.moo2.push_back(val.M3());
  v.mvw = val.M(3, n);
  v.mow0 = val.M(3, n);
  v.mww = val.M(n, n);
  b.stress.shell = Table(val, "shell", {"sxx", "syy", "sxy"}, {"bottom", "top"}, {0, 1, 6}, n);
  b.stress.beam = Table(val, "beam", {"N", "Vy", "Vz", "T", "My", "Mz"}, {"end_a", "end_b"}, {2}, n);
  b.stress.solid = Table(val, "solid", {"sxx", "syy", "szz", "sxy", "syz", "szx"}, {"centroid"}, {3, 4, 5}, n);
  b.units = "mm, t, s, N, MPa";
  b.provenance = {{"source", m.source}, {"empty", ""}, {"options", "--modes 10 --keep 3"}, {"source", "again"}};
  b.static_modes = 18;
  b.normal_modes = 10;
  b.rigid_modes_removed = 6;
  return b;
}

// a free plate reduced by Craig-Bampton, with its stress modes
ReducedBody ReducedPlate() {
  fe::FeModel model;
  const std::vector<int> grid = reduction::testing::AddPlate(model.mesh, 6, 4, 0.6, 0.4, 0.004);
  model.mesh.node_sets["corners"] = {grid[0], grid[6]};
  reduction::ReductionOptions options;
  options.interface_nodes = {grid[0], grid[6]};
  options.normal_modes = 5;
  options.rayleigh_alpha = 0.5;
  options.rayleigh_beta = 1e-4;
  ReducedBody body = reduction::ReduceCraigBampton(model, options);
  // stress tables of all three families (shells filled, beams and solids 0 x n)
  body.stress = reduction::ComputeStressModes(model.mesh, body.modes);
  return body;
}

// ---- editing files with the HDF5 API ----

class H5File {
 public:
  explicit H5File(const std::string& path) : id_(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)) {
    EXPECT_GE(id_, 0) << path;
  }
  ~H5File() { H5Fclose(id_); }
  hid_t id() const { return id_; }

 private:
  hid_t id_;
};

void SetIntAttribute(const std::string& path, const char* object, const char* name, int value) {
  H5File f(path);
  const hid_t a = H5Aopen_by_name(f.id(), object, name, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(a, 0);
  EXPECT_GE(H5Awrite(a, H5T_NATIVE_INT, &value), 0);
  H5Aclose(a);
}

// replaces the root attribute "format" by a fixed-length string
void SetFormat(const std::string& path, const std::string& value) {
  H5File f(path);
  ASSERT_GE(H5Adelete(f.id(), "format"), 0);
  const hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, value.size());
  const hid_t s = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate2(f.id(), "format", t, s, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(H5Awrite(a, t, value.data()), 0);
  H5Aclose(a);
  H5Sclose(s);
  H5Tclose(t);
}

void DeleteLink(const std::string& path, const char* name) {
  H5File f(path);
  EXPECT_GE(H5Ldelete(f.id(), name, H5P_DEFAULT), 0) << name;
}

// replaces a dataset by doubles of the given shape
void ReplaceDoubles(const std::string& path, const char* name, const std::vector<hsize_t>& dims,
                    const std::vector<double>& values) {
  H5File f(path);
  ASSERT_GE(H5Ldelete(f.id(), name, H5P_DEFAULT), 0) << name;
  const hid_t s = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t d = H5Dcreate2(f.id(), name, H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(d);
  H5Sclose(s);
}

// overwrites entry k of an existing dataset of doubles (or integers) in place
template <class T>
void PokeValue(const std::string& path, const char* name, hsize_t k, T value) {
  H5File f(path);
  const hid_t d = H5Dopen2(f.id(), name, H5P_DEFAULT);
  ASSERT_GE(d, 0) << name;
  const hid_t s = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(s);
  std::vector<hsize_t> dims(rank), at(rank);
  H5Sget_simple_extent_dims(s, dims.data(), nullptr);
  for (int r = rank - 1; r >= 0; --r) {
    at[r] = k % dims[r];
    k /= dims[r];
  }
  EXPECT_GE(H5Sselect_elements(s, H5S_SELECT_SET, 1, at.data()), 0);
  const hsize_t one = 1;
  const hid_t mem = H5Screate_simple(1, &one, nullptr);
  const hid_t type = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT;
  EXPECT_GE(H5Dwrite(d, type, mem, s, H5P_DEFAULT, &value), 0);
  H5Sclose(mem);
  H5Sclose(s);
  H5Dclose(d);
}

// a fresh copy of the synthetic body's file under `name`
std::string GoodFile(const std::string& name) {
  const std::string path = ScratchPath(name);
  WriteBody(EveryField(), path);
  return path;
}

// ---- tests ----

TEST(BodyFile, RoundTripOfEveryFieldIsBitForBit) {
  const ReducedBody body = EveryField();
  const std::string path = ScratchPath("every_field.h5");
  WriteBody(body, path);
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  const ReducedBody back = ReadBody(path);
  ExpectSameBody(body, back);
  // the origin of mesh entities is not stored: they name the body file
  EXPECT_EQ(back.mesh.elements[2].origin.file, path);
  EXPECT_EQ(back.mesh.nodes[0].origin.file, path);
  // writing what was read gives the same body again
  const std::string again = ScratchPath("every_field_again.h5");
  WriteBody(back, again);
  ExpectSameBody(body, ReadBody(again));
}

TEST(BodyFile, RoundTripOfAReducedPlate) {
  const ReducedBody body = ReducedPlate();
  ASSERT_EQ(body.modes.cols(), 11);
  ASSERT_EQ(body.stress.shell.elements.size(), 24u);
  ASSERT_EQ(body.stress.solid.modes.cols(), 11);
  ASSERT_EQ(body.invariants.n, 11);
  const std::string path = ScratchPath("plate.h5");
  std::ofstream(path) << "an older file that is replaced";
  WriteBody(body, path);
  ExpectSameBody(body, ReadBody(path));
  EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST(BodyFile, RoundTripOfABodyWithoutModesOrElements) {
  ReducedBody body;
  fe::Node nd;
  nd.id = 1;
  body.mesh.nodes.push_back(nd);
  body.mesh.IndexNodes();
  body.modes.resize(6, 0);
  body.mass.resize(0, 0);
  body.stiffness.resize(0, 0);
  body.damping.resize(0, 0);
  body.invariants.mvw.resize(3, 0);
  body.invariants.mow0.resize(3, 0);
  body.invariants.mww.resize(0, 0);
  body.invariants.mvv = 2.0 * Mat3::Identity();
  for (StressTable* t : {&body.stress.shell, &body.stress.beam, &body.stress.solid}) t->modes.resize(0, 0);
  const std::string path = ScratchPath("empty.h5");
  WriteBody(body, path);
  const ReducedBody back = ReadBody(path);
  ExpectBitIdenticalMesh(body.mesh, back.mesh);
  EXPECT_EQ(back.modes.rows(), 6);
  EXPECT_EQ(back.modes.cols(), 0);
  ExpectSame(back.invariants.mvv, body.invariants.mvv, "mvv");
  EXPECT_TRUE(back.provenance.empty());
  // a table never filled (0 x 0) reads back as 0 x n
  EXPECT_EQ(back.stress.shell.modes.rows(), 0);
}

TEST(BodyFile, WriteRefusesAnInconsistentBodyAndLeavesNoFile) {
  const std::string path = ScratchPath("inconsistent.h5");
  std::error_code ec;
  fs::remove(path, ec);
  ReducedBody body = EveryField();
  body.invariants.n = 2;
  ExpectContains(InputErrorOf([&] { WriteBody(body, path); }), {path, "invariants", "are for 2 modes"}, "n");
  body = EveryField();
  body.stress.beam.modes(1, 2) = std::numeric_limits<double>::quiet_NaN();
  ExpectContains(InputErrorOf([&] { WriteBody(body, path); }), {path, "stress table 'beam' modes", "non-finite"},
                 "NaN");
  body = EveryField();
  body.damping.resize(3, 2);
  ExpectContains(InputErrorOf([&] { WriteBody(body, path); }), {path, "damping", "is 3 x 2, expected 3 x 3"},
                 "damping");
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  // an existing body file is left as it was
  const std::string good = GoodFile("kept.h5");
  const auto size = fs::file_size(good);
  ExpectContains(InputErrorOf([&] { WriteBody(body, good); }), {good}, "kept");
  EXPECT_EQ(fs::file_size(good), size);
  ExpectSameBody(EveryField(), ReadBody(good));
  // a directory that does not exist: the temporary file is named
  const std::string nowhere = ScratchPath("no/such/dir/body.h5");
  ExpectContains(InputErrorOf([&] { WriteBody(EveryField(), nowhere); }), {nowhere + ".tmp", "cannot create"},
                 "dir");
}

TEST(BodyFile, MissingUnreadableAndForeignFiles) {
  const std::string missing = ScratchPath("missing.h5");
  ExpectContains(InputErrorOf([&] { ReadBody(missing); }), {missing, "does not exist"}, "missing");
  const std::string text = testing::WriteScratch("text.h5", "this is not HDF5\n");
  ExpectContains(InputErrorOf([&] { ReadBody(text); }), {text, "not an HDF5 file"}, "text");
  ExpectContains(InputErrorOf([&] { ReadBody(testing::ScratchDir().string()); }), {"not a regular file"}, "dir");

  // truncated: the first half of a good file
  const std::string good = GoodFile("to_truncate.h5");
  const std::string bytes = testing::ReadText(good);
  const std::string half = testing::WriteScratch("truncated.h5", bytes.substr(0, bytes.size() / 2));
  ExpectContains(InputErrorOf([&] { ReadBody(half); }), {half, "truncated"}, "truncated");

  // an HDF5 file that is not a body file
  const std::string other = ScratchPath("other.h5");
  const hid_t f = H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(f);
  ExpectContains(InputErrorOf([&] { ReadBody(other); }), {other, "attribute format", "not a flexmb body file"},
                 "other");
  const std::string renamed = GoodFile("renamed.h5");
  SetFormat(renamed, "flexmb-mesh");
  ExpectContains(InputErrorOf([&] { ReadBody(renamed); }), {renamed, "'flexmb-mesh'", "not a flexmb body file"},
                 "format");
}

TEST(BodyFile, WrongVersion) {
  const std::string newer = GoodFile("newer.h5");
  SetIntAttribute(newer, "/", "version", reduction::ReducedBody::kFormatVersion + 1);
  ExpectContains(InputErrorOf([&] { ReadBody(newer); }),
                 {newer, "attribute version", "version " + std::to_string(reduction::ReducedBody::kFormatVersion + 1),
                  "newer", "update flexmb"},
                 "newer");
  const std::string older = GoodFile("older.h5");
  SetIntAttribute(older, "/", "version", reduction::ReducedBody::kFormatVersion - 1);
  ExpectContains(InputErrorOf([&] { ReadBody(older); }), {older, "attribute version", "older", "reduce the body again"},
                 "older");
}

TEST(BodyFile, MissingOrMisshapenDatasets) {
  const std::string no_moo2 = GoodFile("no_moo2.h5");
  DeleteLink(no_moo2, "/invariants/moo2");
  ExpectContains(InputErrorOf([&] { ReadBody(no_moo2); }), {no_moo2 + ": dataset /invariants/moo2: is missing"},
                 "moo2");
  const std::string no_group = GoodFile("no_group.h5");
  DeleteLink(no_group, "/stress");
  ExpectContains(InputErrorOf([&] { ReadBody(no_group); }), {no_group, "/stress/shell", "missing"}, "stress");
  const std::string no_count = GoodFile("no_count.h5");
  {
    H5File f(no_count);
    EXPECT_GE(H5Adelete_by_name(f.id(), "/counts", "modes", H5P_DEFAULT), 0);
  }
  ExpectContains(InputErrorOf([&] { ReadBody(no_count); }), {no_count, "attribute modes of /counts", "missing"},
                 "count");

  // the reduced mass 3 x 4 instead of 3 x 3
  const std::string wide = GoodFile("wide.h5");
  ReplaceDoubles(wide, "/reduced/mass", {3, 4}, std::vector<double>(12, 1.0));
  ExpectContains(InputErrorOf([&] { ReadBody(wide); }),
                 {wide + ": dataset /reduced/mass: has shape [3, 4], expected [3, 3]"}, "mass");
  // mode shapes of one node too few
  const std::string short_modes = GoodFile("short_modes.h5");
  ReplaceDoubles(short_modes, "/modes/shapes", {3, 13, 6}, std::vector<double>(3 * 13 * 6, 0.0));
  ExpectContains(InputErrorOf([&] { ReadBody(short_modes); }),
                 {short_modes, "dataset /modes/shapes", "[3, 13, 6], expected [3, 14, 6]"}, "shapes");
  // integers where doubles belong
  const std::string ints = GoodFile("ints.h5");
  DeleteLink(ints, "/modes/frequencies_hz");
  {
    H5File f(ints);
    const hsize_t n = 3;
    const int v[3] = {1, 2, 3};
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    const hid_t d =
        H5Dcreate2(f.id(), "/modes/frequencies_hz", H5T_STD_I32LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v);
    H5Dclose(d);
    H5Sclose(s);
  }
  ExpectContains(InputErrorOf([&] { ReadBody(ints); }), {ints, "dataset /modes/frequencies_hz", "floating-point"},
                 "ints");
}

TEST(BodyFile, BadValues) {
  const std::string nan = GoodFile("nan.h5");
  PokeValue(nan, "/invariants/mow1", 7, std::numeric_limits<double>::quiet_NaN());
  ExpectContains(InputErrorOf([&] { ReadBody(nan); }), {nan, "dataset /invariants/mow1", "non-finite", "index 7"},
                 "nan");
  const std::string inf = GoodFile("inf.h5");
  PokeValue(inf, "/mesh/nodes/coordinates", 4, std::numeric_limits<double>::infinity());
  ExpectContains(InputErrorOf([&] { ReadBody(inf); }), {inf, "dataset /mesh/nodes/coordinates", "non-finite"}, "inf");
  const std::string node = GoodFile("node.h5");
  PokeValue(node, "/mesh/elements/node_indices", 5, 14);
  ExpectContains(InputErrorOf([&] { ReadBody(node); }),
                 {node, "dataset /mesh/elements/node_indices", "entry 5 is 14", "node index"}, "node");
  const std::string section = GoodFile("section.h5");
  PokeValue(section, "/mesh/elements/properties", 2, 1);
  ExpectContains(InputErrorOf([&] { ReadBody(section); }),
                 {section, "dataset /mesh/elements/properties", "element 30", "section index 1"}, "section");
  const std::string ids = GoodFile("ids.h5");
  PokeValue(ids, "/interface/node_ids", 1, 1007);
  ExpectContains(InputErrorOf([&] { ReadBody(ids); }), {ids, "dataset /interface/node_ids", "node 1007"}, "ids");
  const std::string offsets = GoodFile("offsets.h5");
  PokeValue(offsets, "/mesh/elements/node_offsets", 2, 8);
  ExpectContains(InputErrorOf([&] { ReadBody(offsets); }),
                 {offsets, "dataset /mesh/elements/node_offsets", "element 2 (entry 1): 4 nodes, a tria3 has 3"},
                 "offsets");
  const std::string stress = GoodFile("stress.h5");
  PokeValue(stress, "/stress/solid/elements", 0, 7);
  ExpectContains(InputErrorOf([&] { ReadBody(stress); }), {stress, "dataset /stress/solid/elements", "entry 0 is 7"},
                 "stress");
}

}  // namespace
}  // namespace flexmb::io
