// Body files that cannot be corrupted silently (body_file/body_file.h, hdf5_file.h):
// every dataset with values is written with HDF5's Fletcher32 checksum
// filter; a byte flipped in the data of a dataset (several datasets, several
// positions in each, found with H5Dget_chunk_info) is an InputError naming
// the file and the dataset; a byte flipped anywhere in the file either gives
// an InputError (naming the dataset when the byte is in its data) or leaves
// the body read back bit for bit, and leaves nothing open; a file of an
// older writer (datasets without checksums) is read with one warning.

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/body_file/body_file.h"
#include "tests/unit/fe_io/mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using reduction::Mat3;
using reduction::MatX;
using reduction::ReducedBody;
using testing::ExpectContains;
using testing::InputErrorOf;
using testing::ReadText;
using testing::ScratchPath;
using testing::WriteScratch;

// a small consistent body: 4 nodes, 2 modes, values without pattern
ReducedBody ChecksumBody() {
  ReducedBody b;
  for (int k = 0; k < 4; ++k) {
    fe::Node nd;
    nd.id = 100 + 7 * k;
    nd.x = fe::Vec3(0.1 * k, std::sin(k + 1.0), -0.3 * k * k);
    b.mesh.nodes.push_back(nd);
  }
  b.mesh.IndexNodes();
  const int n = 2;
  auto fill = [](MatX& m, int rows, int cols, double seed) {
    m.resize(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) m(i, j) = std::sin(seed + 1.37 * i + 0.71 * j);
  };
  fill(b.modes, 24, n, 0.3);
  b.frequencies_hz = Eigen::Vector2d(12.5, 40.25);
  b.mass = MatX::Identity(n, n);
  b.stiffness = MatX::Zero(n, n);
  b.stiffness.diagonal() << 6168.5, 63955.1;
  b.damping = 1e-3 * b.stiffness;
  b.interface_nodes = {0, 3};
  b.static_modes = 1;
  b.normal_modes = 1;
  b.provenance = {{"source", "checksum test"}, {"method", "none"}};
  reduction::InertiaInvariants& v = b.invariants;
  v.n = n;
  v.mvv = 3.0 * Mat3::Identity();
  v.mvo0 << 0, 0.2, -0.1, -0.2, 0, 0.4, 0.1, -0.4, 0;
  v.moo0 = Mat3::Identity() * 0.7;
  v.mvo1.assign(n, 0.5 * Mat3::Identity());
  v.moo1.assign(n, 0.25 * Mat3::Identity());
  v.moo2.assign(n * n, 0.125 * Mat3::Identity());
  fill(v.mvw, 3, n, 1.1);
  fill(v.mow0, 3, n, 2.2);
  v.mow1.resize(n);
  for (int i = 0; i < n; ++i) fill(v.mow1[i], 3, n, 3.3 + i);
  v.mww = MatX::Identity(n, n);
  b.stress.shell.name = "shell";
  b.stress.shell.components = {"sxx", "syy", "sxy"};
  b.stress.shell.locations = {"top", "bottom"};
  for (reduction::StressTable* t : {&b.stress.shell, &b.stress.beam, &b.stress.solid}) t->modes.resize(0, n);
  return b;
}

bool SameBytes(const MatX& a, const MatX& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

// every stored field of the checksum body read back unchanged
bool SameBody(const ReducedBody& a, const ReducedBody& b) {
  if (a.mesh.nodes.size() != b.mesh.nodes.size()) return false;
  for (size_t k = 0; k < a.mesh.nodes.size(); ++k) {
    if (a.mesh.nodes[k].id != b.mesh.nodes[k].id) return false;
    if (std::memcmp(a.mesh.nodes[k].x.data(), b.mesh.nodes[k].x.data(), 3 * sizeof(double)) != 0) return false;
  }
  const reduction::InertiaInvariants &u = a.invariants, &w = b.invariants;
  bool same = SameBytes(a.modes, b.modes) && SameBytes(a.mass, b.mass) && SameBytes(a.stiffness, b.stiffness) &&
              SameBytes(a.damping, b.damping) && SameBytes(u.mvw, w.mvw) && SameBytes(u.mow0, w.mow0) &&
              SameBytes(u.mww, w.mww) && SameBytes(u.mvv, w.mvv) && SameBytes(u.mvo0, w.mvo0) &&
              SameBytes(u.moo0, w.moo0) && SameBytes(a.frequencies_hz, b.frequencies_hz);
  for (size_t i = 0; same && i < u.mow1.size(); ++i) same = SameBytes(u.mow1[i], w.mow1[i]);
  for (size_t i = 0; same && i < u.moo2.size(); ++i) same = SameBytes(u.moo2[i], w.moo2[i]);
  return same && a.interface_nodes == b.interface_nodes && a.units == b.units && a.provenance == b.provenance &&
         a.stress.shell.components == b.stress.shell.components &&
         a.stress.shell.locations == b.stress.shell.locations && a.static_modes == b.static_modes;
}

// names of all datasets of the file
std::vector<std::string> DatasetNames(hid_t file) {
  std::vector<std::string> names;
  H5Ovisit(
      file, H5_INDEX_NAME, H5_ITER_NATIVE,
      [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
        if (info->type == H5O_TYPE_DATASET)
          static_cast<std::vector<std::string>*>(data)->push_back(std::string("/") + name);
        return 0;
      },
      &names);
  return names;
}

// file offset and size of the first chunk of a dataset (size 0 if none)
std::pair<haddr_t, hsize_t> FirstChunk(const std::string& path, const std::string& name) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  hsize_t offset[8] = {};
  unsigned mask = 0;
  haddr_t addr = 0;
  hsize_t size = 0;
  const hid_t s = H5Dget_space(d);
  if (H5Dget_chunk_info(d, s, 0, offset, &mask, &addr, &size) < 0) size = 0;
  H5Sclose(s);
  H5Dclose(d);
  H5Fclose(f);
  return {addr, size};
}

// the bytes with byte k flipped (all 8 bits)
std::string Flipped(std::string bytes, size_t k) {
  bytes[k] = static_cast<char>(~static_cast<unsigned char>(bytes[k]));
  return bytes;
}

TEST(BodyFileChecksum, EveryDatasetWithValuesHasAChecksum) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // probing for the filter pushes errors
  const std::string path = ScratchPath("checksum_all.h5");
  WriteBody(ChecksumBody(), path);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  int with_values = 0;
  for (const std::string& name : DatasetNames(f)) {
    const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
    const hid_t s = H5Dget_space(d);
    const hid_t dcpl = H5Dget_create_plist(d);
    const bool fletcher =
        H5Pget_filter_by_id2(dcpl, H5Z_FILTER_FLETCHER32, nullptr, nullptr, nullptr, 0, nullptr, nullptr) >= 0;
    H5Eclear2(H5E_DEFAULT);
    if (H5Sget_simple_extent_npoints(s) > 0) {
      ++with_values;
      EXPECT_TRUE(fletcher) << name;
      // strings are fixed-length (a variable-length string's bytes would sit
      // in the global heap, outside the checksum)
      const hid_t t = H5Dget_type(d);
      if (H5Tget_class(t) == H5T_STRING) EXPECT_LE(H5Tis_variable_str(t), 0) << name;
      H5Tclose(t);
    }
    H5Pclose(dcpl);
    H5Sclose(s);
    H5Dclose(d);
  }
  H5Fclose(f);
  EXPECT_GE(with_values, 20);
  // and the body reads back bit for bit, without a warning
  testing::WarningCapture warnings;
  EXPECT_TRUE(SameBody(ChecksumBody(), ReadBody(path)));
  EXPECT_TRUE(warnings.messages.empty());
}

TEST(BodyFileChecksum, AFlippedByteInTheDataOfADatasetIsAnErrorNamingIt) {
  const std::string good = ScratchPath("checksum_good.h5");
  WriteBody(ChecksumBody(), good);
  const std::string bytes = ReadText(good);
  int cases = 0;
  for (const char* name : {"/modes/shapes", "/reduced/stiffness", "/mesh/nodes/coordinates", "/interface/nodes",
                           "/invariants/mow1", "/stress/shell/components"}) {
    const std::pair<haddr_t, hsize_t> chunk = FirstChunk(good, name);
    const haddr_t addr = chunk.first;
    const hsize_t size = chunk.second;
    ASSERT_GT(size, 4u) << name;
    ASSERT_LE(addr + size, bytes.size()) << name;
    // first byte, middle, last byte of the values, and the stored checksum
    for (const hsize_t at : {hsize_t{0}, (size - 4) / 2, size - 5, size - 1}) {
      const std::string path = WriteScratch("checksum_flip.h5", Flipped(bytes, addr + at));
      ExpectContains(InputErrorOf([&] { ReadBody(path); }),
                     {path + ": dataset " + std::string(name) + ": checksum mismatch"},
                     std::string(name) + " +" + std::to_string(at));
      ++cases;
    }
  }
  EXPECT_EQ(cases, 24);
}

TEST(BodyFileChecksum, AFlippedByteAnywhereIsAnErrorOrChangesNothing) {
  const ReducedBody body = ChecksumBody();
  const std::string good = ScratchPath("checksum_sweep_good.h5");
  WriteBody(body, good);
  const std::string bytes = ReadText(good);
  ASSERT_GT(bytes.size(), 1000u);
  // the byte ranges of the datasets' data (one chunk each in this body)
  struct Range {
    std::string name;
    haddr_t begin, end;
  };
  std::vector<Range> data;
  {
    const hid_t f = H5Fopen(good.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const std::vector<std::string> names = DatasetNames(f);
    H5Fclose(f);
    for (const std::string& name : names) {
      const std::pair<haddr_t, hsize_t> chunk = FirstChunk(good, name);
      if (chunk.second > 0) data.push_back({name, chunk.first, chunk.first + chunk.second});
    }
  }
  // about 80 positions spread over the whole file, and one in the data of
  // every dataset (a third into it)
  std::vector<size_t> positions;
  for (size_t k = 0; k < bytes.size(); k += bytes.size() / 80 + 1) positions.push_back(k);
  for (const Range& r : data) positions.push_back(r.begin + (r.end - r.begin) / 3);
  int in_data = 0, errors = 0, unchanged = 0;
  for (const size_t k : positions) {
    const std::string path = WriteScratch("checksum_sweep.h5", Flipped(bytes, k));
    const Range* hit = nullptr;
    for (const Range& r : data)
      if (k >= r.begin && k < r.end) hit = &r;
    testing::WarningCapture quiet;
    try {
      const ReducedBody back = ReadBody(path);
      EXPECT_TRUE(SameBody(body, back)) << "byte " << k << " of " << bytes.size() << " changed the body silently";
      EXPECT_EQ(hit, nullptr) << "byte " << k << " in the data of " << hit->name << " went unnoticed";
      ++unchanged;
    } catch (const InputError& e) {
      // a flip in a dataset's data names the dataset; elsewhere, the file
      const std::string want = hit ? path + ": dataset " + hit->name + ": checksum mismatch" : path;
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
      ++errors;
    }
    in_data += hit != nullptr;
    // nothing of the damaged file stays open
    EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0) << "byte " << k;
  }
  EXPECT_GE(data.size(), 20u);
  EXPECT_GE(in_data, static_cast<int>(data.size()));
  std::printf("%d flips: %d in dataset data, %d errors, %d read back unchanged\n", errors + unchanged, in_data,
              errors, unchanged);
}

TEST(BodyFileChecksum, AnOlderFileWithoutChecksumsIsReadWithOneWarning) {
  const std::string path = ScratchPath("checksum_old.h5");
  WriteBody(ChecksumBody(), path);
  {
    // rewrite two datasets the way older writers stored them: contiguous,
    // no filter
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    for (const char* name : {"/reduced/mass", "/reduced/stiffness"}) {
      const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
      double v[4];
      ASSERT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v), 0);
      H5Dclose(d);
      ASSERT_GE(H5Ldelete(f, name, H5P_DEFAULT), 0);
      const hsize_t dims[2] = {2, 2};
      const hid_t s = H5Screate_simple(2, dims, nullptr);
      const hid_t nd = H5Dcreate2(f, name, H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      EXPECT_GE(H5Dwrite(nd, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v), 0);
      H5Dclose(nd);
      H5Sclose(s);
    }
    H5Fclose(f);
  }
  testing::WarningCapture warnings;
  EXPECT_TRUE(SameBody(ChecksumBody(), ReadBody(path)));
  ASSERT_EQ(warnings.messages.size(), 1u);
  ExpectContains(warnings.messages[0], {path, "without checksums", "2 datasets", "/reduced/mass"}, "old file");
}

}  // namespace
}  // namespace flexmb::io
