#include "flexmb/body_file/hdf5_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "flexmb/common/error.h"

namespace flexmb::io::hdf5 {

namespace {

namespace fs = std::filesystem;

// the innermost message of HDF5's current error stack (then cleared); empty
// if there is none
std::string Hdf5Reason() {
  std::string reason;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_DOWNWARD,
      [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
        if (e->desc != nullptr && e->desc[0] != '\0') *static_cast<std::string*>(data) = e->desc;
        return 0;
      },
      &reason);
  H5Eclear2(H5E_DEFAULT);
  return reason;
}

using Block3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

// largest chunk of a checksummed dataset [bytes]: whole small datasets are
// one chunk, large ones are split along their slowest dimensions
constexpr size_t kHdf5ChunkBytes = size_t{1} << 20;

// dataset creation properties: chunked with the Fletcher32 checksum filter
// (invalid handle for a dataset without values, which cannot be chunked)
Handle ChecksummedLayout(const Dims& dims, hid_t file_type) {
  size_t count = 1;
  for (hsize_t d : dims) count *= static_cast<size_t>(d);
  if (dims.empty() || count == 0) return Handle();
  Dims chunk = dims;
  size_t bytes = count * std::max<size_t>(1, H5Tget_size(file_type));
  for (size_t k = 0; k < chunk.size() && bytes > kHdf5ChunkBytes; ++k) {
    while (chunk[k] > 1 && bytes > kHdf5ChunkBytes) {
      const hsize_t half = (chunk[k] + 1) / 2;
      bytes = bytes / chunk[k] * half;
      chunk[k] = half;
    }
  }
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data());
  H5Pset_fletcher32(dcpl.get());
  return dcpl;
}

// whether the open dataset `d` carries the Fletcher32 checksum filter
bool HasChecksum(hid_t d) {
  Handle dcpl(H5Dget_create_plist(d), H5Pclose);
  if (!dcpl.ok()) return false;
  const int n = H5Pget_nfilters(dcpl.get());
  for (int k = 0; k < n; ++k) {
    unsigned flags = 0, config = 0;
    size_t nvalues = 0;
    if (H5Pget_filter2(dcpl.get(), static_cast<unsigned>(k), &flags, &nvalues, nullptr, 0, nullptr, &config) ==
        H5Z_FILTER_FLETCHER32)
      return true;
  }
  return false;
}

// fixed-length UTF-8 string type for strings of up to `longest` bytes: its
// values sit in the dataset's own (checksummed) data, unlike variable-length
// strings, which HDF5 keeps in an unchecked heap
Handle FixedStringType(size_t longest) {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.get(), longest + 1);
  H5Tset_strpad(t.get(), H5T_STR_NULLTERM);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  return t;
}

// the strings packed as fixed-length values of `size` bytes each
std::vector<char> PackStrings(const std::vector<std::string>& v, size_t size) {
  std::vector<char> buf(std::max<size_t>(1, v.size() * size), '\0');
  for (size_t k = 0; k < v.size(); ++k) std::copy(v[k].begin(), v[k].end(), buf.begin() + k * size);
  return buf;
}

size_t LongestString(const std::vector<std::string>& v) {
  size_t n = 0;
  for (const std::string& s : v) n = std::max(n, s.size());
  return n;
}

}  // namespace

Handle& Handle::operator=(Handle&& o) noexcept {
  if (this != &o) {
    Reset();
    id_ = o.id_;
    close_ = o.close_;
    o.id_ = -1;
  }
  return *this;
}

bool Handle::Close() {
  const herr_t r = id_ >= 0 && close_ != nullptr ? close_(id_) : 0;
  id_ = -1;
  return r >= 0;
}

void Handle::Reset() {
  if (id_ >= 0 && close_ != nullptr) close_(id_);
  id_ = -1;
}

QuietHdf5::QuietHdf5() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietHdf5::~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

std::string WithReason(const std::string& message) {
  const std::string reason = Hdf5Reason();
  return reason.empty() ? message : message + " (HDF5: " + reason + ")";
}

std::string DimsText(const Dims& d) {
  std::string s = "[";
  for (size_t k = 0; k < d.size(); ++k) s += (k ? ", " : "") + std::to_string(d[k]);
  return s + "]";
}

Handle StringType() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  return t;
}

std::vector<double> Blocks(const std::vector<Eigen::Matrix3d>& m) {
  std::vector<double> v(9 * m.size());
  for (size_t i = 0; i < m.size(); ++i) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) v[9 * i + 3 * r + c] = m[i](r, c);
    }
  }
  return v;
}

void WriteFileAtomically(const std::string& path, const std::string& what,
                         const std::function<void(Writer&)>& fill) {
  const std::string tmp = path + ".tmp";
  {
    Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    H5Pset_file_locking(fapl.get(), true, true);
    // file format of HDF5 1.8 and later: every metadata block carries a
    // checksum (HDF5 1.10 reads and writes it)
    H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST);
    Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
    if (!file.ok()) throw InputError(WithReason("cannot create the file"), {tmp, 0, what});
    try {
      Writer w(file.get(), path);
      fill(w);
    } catch (...) {
      file.Close();
      std::remove(tmp.c_str());
      throw;
    }
    if (!file.Close()) {
      std::remove(tmp.c_str());
      throw InputError(WithReason("cannot complete the file (disk full?)"), {tmp, 0, what});
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw InputError("cannot rename " + tmp + " to the " + what + ": " + ec.message(), {path, 0, what});
  }
}

Handle OpenFileForReading(const std::string& path, const std::string& what, const std::string& not_hdf5) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("does not exist", {path, 0, what});
  if (!fs::is_regular_file(path, ec)) throw InputError("is not a regular file", {path, 0, what});
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    H5Eclear2(H5E_DEFAULT);
    throw InputError(not_hdf5, {path, 0, what});
  }
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_file_locking(fapl.get(), true, true);
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
  if (!file.ok()) throw InputError(WithReason("cannot open the HDF5 file (truncated or damaged?)"), {path, 0, what});
  return file;
}

// ---------------------------------------------------------------- writing

void Writer::Fail(const std::string& what, const std::string& message) const {
  throw InputError(WithReason(message), {path_, 0, what});
}

void Writer::Group(const std::string& name) {
  Handle g(H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!g.ok()) Fail("group " + name, "cannot create the group");
}

void Writer::Data(const std::string& name, hid_t file_type, hid_t mem_type, const Dims& dims, const void* data) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  if (!space.ok()) Fail("dataset " + name, "cannot create the dataspace " + DimsText(dims));
  const Handle dcpl = ChecksummedLayout(dims, file_type);
  Handle d(H5Dcreate2(file_, name.c_str(), file_type, space.get(), H5P_DEFAULT,
                      dcpl.ok() ? dcpl.get() : H5P_DEFAULT, H5P_DEFAULT),
           H5Dclose);
  if (!d.ok()) Fail("dataset " + name, "cannot create the dataset");
  static const double dummy = 0.0;
  if (H5Dwrite(d.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data != nullptr ? data : &dummy) < 0) {
    Fail("dataset " + name, "cannot write the dataset");
  }
}

void Writer::Doubles(const std::string& name, const Dims& dims, const double* data) {
  Data(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, data);
}

void Writer::Ints(const std::string& name, const std::vector<int>& v) {
  Data(name, H5T_STD_I32LE, H5T_NATIVE_INT, {Size(v.size())}, v.data());
}

void Writer::Longs(const std::string& name, const std::vector<int64_t>& v) {
  Data(name, H5T_STD_I64LE, H5T_NATIVE_INT64, {Size(v.size())}, v.data());
}

void Writer::Matrix(const std::string& name, const Eigen::MatrixXd& m) {
  const RowMat r = m;
  Doubles(name, {Size(m.rows()), Size(m.cols())}, r.data());
}

void Writer::Strings(const std::string& name, const std::vector<std::string>& v, const Dims& dims) {
  const Handle t = FixedStringType(LongestString(v));
  const std::vector<char> buf = PackStrings(v, H5Tget_size(t.get()));
  Data(name, t.get(), t.get(), dims, buf.data());
}

void Writer::Attribute(const std::string& object, const std::string& name, hid_t file_type, hid_t mem_type,
                       const Dims& dims, const void* data) {
  const std::string what = "attribute " + name + " of " + object;
  Handle space(dims.empty() ? H5Screate(H5S_SCALAR)
                            : H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
               H5Sclose);
  if (!space.ok()) Fail(what, "cannot create the dataspace");
  Handle a(H5Acreate_by_name(file_, object.c_str(), name.c_str(), file_type, space.get(), H5P_DEFAULT,
                             H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose);
  if (!a.ok()) Fail(what, "cannot create the attribute");
  static const double dummy = 0.0;
  if (H5Awrite(a.get(), mem_type, data != nullptr ? data : &dummy) < 0) Fail(what, "cannot write the attribute");
}

void Writer::AttributeStrings(const std::string& object, const std::string& name, const std::vector<std::string>& v,
                              const Dims& dims) {
  const Handle t = FixedStringType(LongestString(v));
  const std::vector<char> buf = PackStrings(v, H5Tget_size(t.get()));
  Attribute(object, name, t.get(), t.get(), dims, buf.data());
}

void Writer::AttributeString(const std::string& object, const std::string& name, const std::string& value) {
  const Handle t = FixedStringType(value.size());
  const std::vector<char> buf = PackStrings({value}, H5Tget_size(t.get()));
  Attribute(object, name, t.get(), t.get(), {}, buf.data());
}

void Writer::AttributeInt(const std::string& object, const std::string& name, int value) {
  Attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, {}, &value);
}

// ---------------------------------------------------------------- reading

void Reader::Fail(const std::string& what, const std::string& message) const {
  throw InputError(message, {path_, 0, what});
}

bool Reader::Exists(const std::string& name) const {
  // H5Lexists wants the parents to exist
  size_t p = 0;
  while (p != std::string::npos) {
    p = name.find('/', p + 1);
    const std::string part = name.substr(0, p);
    if (H5Lexists(file_, part.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return true;
}

Handle Reader::Dataset(const std::string& name) const {
  if (!Exists(name)) Fail("dataset " + name, "is missing");
  Handle d(H5Dopen2(file_, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.ok()) Fail("dataset " + name, WithReason("cannot open the dataset"));
  return d;
}

Dims Reader::DimsOf(hid_t space) {
  const int rank = H5Sget_simple_extent_ndims(space);
  Dims d(rank > 0 ? rank : 0);
  if (rank > 0) H5Sget_simple_extent_dims(space, d.data(), nullptr);
  return d;
}

size_t Reader::Count(const Dims& dims) {
  size_t n = 1;
  for (hsize_t d : dims) n *= static_cast<size_t>(d);
  return n;
}

Handle Reader::Checked(const std::string& name, H5T_class_t cls, const Dims& dims) const {
  Handle d = Dataset(name);
  Handle t(H5Dget_type(d.get()), H5Tclose);
  const H5T_class_t c = H5Tget_class(t.get());
  if (c != cls) {
    const char* want = cls == H5T_FLOAT ? "floating-point" : cls == H5T_INTEGER ? "integer"
                       : cls == H5T_STRING                  ? "string"
                                                            : "enum";
    Fail("dataset " + name, std::string("has the wrong type: expected ") + want + " values");
  }
  Handle s(H5Dget_space(d.get()), H5Sclose);
  const Dims got = DimsOf(s.get());
  if (H5Sget_simple_extent_type(s.get()) != H5S_SIMPLE && !(dims.empty() && got.empty())) {
    Fail("dataset " + name, "has no simple dataspace");
  }
  if (got != dims) Fail("dataset " + name, "has shape " + DimsText(got) + ", expected " + DimsText(dims));
  return d;
}

size_t Reader::Length(const std::string& name) const {
  Handle d = Dataset(name);
  Handle s(H5Dget_space(d.get()), H5Sclose);
  const Dims got = DimsOf(s.get());
  if (got.size() != 1) Fail("dataset " + name, "has shape " + DimsText(got) + ", expected one dimension");
  return static_cast<size_t>(got[0]);
}

void Reader::NoteChecksum(const std::string& name, hid_t d) const {
  if (HasChecksum(d)) return;
  Handle s(H5Dget_space(d), H5Sclose);
  if (H5Sget_simple_extent_npoints(s.get()) > 0) unchecked_.push_back(name);
}

void Reader::FailedRead(const std::string& name, hid_t d, hid_t mem_type, void* out) const {
  const std::string reason = WithReason("cannot read the dataset (damaged or truncated file?)");
  if (HasChecksum(d)) {
    // read again without verification: if that works, the checksum is what failed
    Handle dxpl(H5Pcreate(H5P_DATASET_XFER), H5Pclose);
    H5Pset_edc_check(dxpl.get(), H5Z_DISABLE_EDC);
    const bool unverified = H5Dread(d, mem_type, H5S_ALL, H5S_ALL, dxpl.get(), out) >= 0;
    H5Eclear2(H5E_DEFAULT);
    if (unverified) {
      Fail("dataset " + name,
           "checksum mismatch (Fletcher32): the data of this dataset was changed after it was written (a damaged "
           "disk, copy or transfer); copy the file again or write it again");
    }
  }
  Fail("dataset " + name, reason);
}

void Reader::Read(const std::string& name, const Handle& d, hid_t mem_type, void* out) const {
  static double dummy;
  NoteChecksum(name, d.get());
  if (H5Dread(d.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out != nullptr ? out : &dummy) < 0) {
    FailedRead(name, d.get(), mem_type, out != nullptr ? out : &dummy);
  }
}

void Reader::DoublesInto(const std::string& name, const Dims& dims, double* out) const {
  const Handle d = Checked(name, H5T_FLOAT, dims);
  Read(name, d, H5T_NATIVE_DOUBLE, out);
  const size_t n = Count(dims);
  for (size_t k = 0; k < n; ++k) {
    if (!std::isfinite(out[k])) {
      Fail("dataset " + name, "holds a non-finite value (" + std::to_string(out[k]) + ") at flat index " +
                                  std::to_string(k));
    }
  }
}

std::vector<double> Reader::Doubles(const std::string& name, const Dims& dims) const {
  std::vector<double> v(Count(dims));
  DoublesInto(name, dims, v.data());
  return v;
}

Eigen::MatrixXd Reader::Matrix(const std::string& name, size_t rows, size_t cols) const {
  RowMat r(rows, cols);
  DoublesInto(name, {Size(rows), Size(cols)}, r.data());
  return r;
}

Eigen::Matrix3d Reader::Block(const std::string& name) const {
  const std::vector<double> v = Doubles(name, {3, 3});
  return Eigen::Map<const Block3>(v.data());
}

std::vector<Eigen::Matrix3d> Reader::Blocks(const std::string& name, const Dims& dims) const {
  const std::vector<double> v = Doubles(name, dims);
  std::vector<Eigen::Matrix3d> m(v.size() / 9);
  for (size_t i = 0; i < m.size(); ++i) m[i] = Eigen::Map<const Block3>(&v[9 * i]);
  return m;
}

std::vector<int> Reader::Ints(const std::string& name, size_t n) const {
  const Handle d = Checked(name, H5T_INTEGER, {Size(n)});
  std::vector<int> v(n);
  Read(name, d, H5T_NATIVE_INT, v.data());
  return v;
}

std::vector<int64_t> Reader::Offsets(const std::string& name, size_t n) const {
  const Handle d = Checked(name, H5T_INTEGER, {Size(n + 1)});
  std::vector<int64_t> v(n + 1);
  Read(name, d, H5T_NATIVE_INT64, v.data());
  if (v[0] != 0) Fail("dataset " + name, "must start with 0, starts with " + std::to_string(v[0]));
  for (size_t k = 1; k <= n; ++k) {
    if (v[k] < v[k - 1]) Fail("dataset " + name, "decreases at entry " + std::to_string(k));
  }
  return v;
}

std::vector<std::string> Reader::StringsOf(const std::string& what, hid_t type, hid_t space, bool attribute,
                                           hid_t obj) const {
  const size_t n = Count(DimsOf(space));
  std::vector<std::string> out(n);
  if (H5Tget_class(type) != H5T_STRING) Fail(what, "has the wrong type: expected strings");
  if (H5Tis_variable_str(type) > 0) {
    std::vector<char*> p(n + 1, nullptr);
    const Handle mem = StringType();
    const herr_t r = attribute ? H5Aread(obj, mem.get(), p.data())
                               : H5Dread(obj, mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data());
    if (r < 0) Fail(what, WithReason("cannot read the strings"));
    for (size_t k = 0; k < n; ++k) out[k] = p[k] != nullptr ? p[k] : "";
    H5Dvlen_reclaim(mem.get(), space, H5P_DEFAULT, p.data());
  } else {
    const size_t size = H5Tget_size(type);
    std::vector<char> buf(n * size + 1, '\0');
    Handle mem(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(mem.get(), size);
    H5Tset_cset(mem.get(), H5Tget_cset(type));
    const herr_t r = attribute ? H5Aread(obj, mem.get(), buf.data())
                               : H5Dread(obj, mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
    if (r < 0 && !attribute) FailedRead(what.substr(8), obj, mem.get(), buf.data());
    if (r < 0) Fail(what, WithReason("cannot read the strings"));
    for (size_t k = 0; k < n; ++k) {
      const char* s = buf.data() + k * size;
      size_t len = 0;
      while (len < size && s[len] != '\0') ++len;
      out[k] = std::string(s, len);
    }
  }
  return out;
}

std::vector<std::string> Reader::Strings(const std::string& name, size_t n) const {
  const Handle d = Dataset(name);
  Handle t(H5Dget_type(d.get()), H5Tclose);
  Handle s(H5Dget_space(d.get()), H5Sclose);
  const Dims got = DimsOf(s.get());
  if (got != Dims{Size(n)}) {
    Fail("dataset " + name, "has shape " + DimsText(got) + ", expected " + DimsText({Size(n)}));
  }
  NoteChecksum(name, d.get());
  return StringsOf("dataset " + name, t.get(), s.get(), false, d.get());
}

Handle Reader::Attribute(const std::string& object, const std::string& name) const {
  const std::string what = "attribute " + name + " of " + object;
  if (object != "/" && !Exists(object)) Fail("group " + object, "is missing");
  if (H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) Fail(what, "is missing");
  Handle a(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.ok()) Fail(what, WithReason("cannot open the attribute"));
  return a;
}

std::vector<std::string> Reader::AttributeStrings(const std::string& object, const std::string& name,
                                                  Dims* dims) const {
  const std::string what = "attribute " + name + " of " + object;
  const Handle a = Attribute(object, name);
  Handle t(H5Aget_type(a.get()), H5Tclose);
  Handle s(H5Aget_space(a.get()), H5Sclose);
  *dims = DimsOf(s.get());
  return StringsOf(what, t.get(), s.get(), true, a.get());
}

std::string Reader::AttributeString(const std::string& object, const std::string& name) const {
  Dims dims;
  const std::vector<std::string> v = AttributeStrings(object, name, &dims);
  if (!dims.empty() || v.size() != 1) Fail("attribute " + name + " of " + object, "must be one string");
  return v[0];
}

int Reader::AttributeInt(const std::string& object, const std::string& name) const {
  const std::string what = "attribute " + name + " of " + object;
  const Handle a = Attribute(object, name);
  Handle t(H5Aget_type(a.get()), H5Tclose);
  Handle s(H5Aget_space(a.get()), H5Sclose);
  if (H5Tget_class(t.get()) != H5T_INTEGER || H5Sget_simple_extent_npoints(s.get()) != 1) {
    Fail(what, "must be one integer");
  }
  long long v = 0;
  if (H5Aread(a.get(), H5T_NATIVE_LLONG, &v) < 0) Fail(what, WithReason("cannot read the attribute"));
  if (v < -2147483647LL || v > 2147483647LL) Fail(what, "is out of range: " + std::to_string(v));
  return static_cast<int>(v);
}

void Reader::InRange(const std::string& name, const std::vector<int>& v, int lo, int hi, const char* of) const {
  for (size_t k = 0; k < v.size(); ++k) {
    if (v[k] < lo || v[k] >= hi) {
      Fail("dataset " + name, "entry " + std::to_string(k) + " is " + std::to_string(v[k]) + ", not a valid " + of +
                                  " index (" + std::to_string(lo) + " to " + std::to_string(hi - 1) + ")");
    }
  }
}

}  // namespace flexmb::io::hdf5
