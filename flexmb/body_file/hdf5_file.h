#pragma once
/// \file hdf5_file.h
/// Internal HDF5 layer of the flexmb file formats (used by body_file.cc):
/// RAII handles, silencing of HDF5's own error printing, atomic creation
/// and checked opening of files, and typed reading and writing of datasets
/// and attributes. Every value is stored little-endian (doubles as 64-bit
/// IEEE); reads check the type class and the shape. Every fault is thrown
/// as InputError whose context names the file and the dataset, attribute
/// or group ("dataset /modes/shapes"), with HDF5's innermost reason where
/// there is one. Files are written in HDF5's 1.8-and-later format (every
/// metadata block checksummed) and every dataset with values is chunked with
/// the Fletcher32 checksum filter; strings are stored fixed-length so that
/// the checksums cover them too. Reads verify the checksums and report a
/// mismatch naming the dataset. Not a public header: no stable API.

#include <hdf5.h>

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace flexmb::io::hdf5 {

class Writer;

/// Shape of a dataspace, slowest index first ({} for a scalar).
using Dims = std::vector<hsize_t>;
/// Row-major dynamic matrix: the memory layout of a [rows][cols] dataset.
using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Owns an HDF5 identifier and closes it with the matching H5?close
/// (given at construction) when destroyed. Move-only.
class Handle {
 public:
  Handle() = default;
  /// Takes `id` (may be negative: a failed call) closed by `close`.
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle& operator=(Handle&& o) noexcept;
  ~Handle() { Reset(); }
  /// The identifier (negative if none).
  hid_t get() const { return id_; }
  /// Whether the identifier is valid (>= 0).
  bool ok() const { return id_ >= 0; }
  /// Closes now; false if closing failed (for a file: data not flushed).
  bool Close();

 private:
  void Reset();
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

/// Silences HDF5's own printing of its error stack while alive (our
/// messages say what went wrong); the previous handler is restored after.
class QuietHdf5 {
 public:
  QuietHdf5();
  ~QuietHdf5();
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// `message` followed by " (HDF5: reason)" with the innermost message of
/// HDF5's current error stack (e.g. "truncated file: eof = 1024, ..."), if
/// there is one; the stack is cleared.
std::string WithReason(const std::string& message);

/// "[2, 3]".
std::string DimsText(const Dims& d);

/// A size as an HDF5 extent.
inline hsize_t Size(size_t n) { return static_cast<hsize_t>(n); }

/// Variable-length UTF-8 string type.
Handle StringType();

/// Row-major copies of 3 x 3 blocks: [i][r][c] (9 values a block).
std::vector<double> Blocks(const std::vector<Eigen::Matrix3d>& m);

/// Creates `path`.tmp (HDF5 with file locking), calls `fill` with a
/// Writer on it, closes it and renames it to `path`, so that a crash never
/// leaves a half-written file. `what` names the file kind in error contexts
/// ("body file"). On any fault the temporary file is removed and the fault
/// rethrown; creation, flush and rename failures throw InputError.
void WriteFileAtomically(const std::string& path, const std::string& what,
                         const std::function<void(Writer&)>& fill);

/// Opens `path` read-only with file locking. Throws InputError with context
/// (`path`, `what`) if it does not exist, is not a regular file, is not
/// HDF5 (`not_hdf5` is the message) or cannot be opened. Call with a
/// QuietHdf5 alive.
Handle OpenFileForReading(const std::string& path, const std::string& what, const std::string& not_hdf5);

/// Writes groups, datasets and attributes of an open file; absolute names
/// ("/mesh/nodes/ids"). Errors name `path` and the object.
class Writer {
 public:
  /// Writes into the open file `file`; `path` is named in errors.
  Writer(hid_t file, std::string path) : file_(file), path_(std::move(path)) {}

  /// Throws InputError(message + HDF5 reason) with context (path, `what`).
  [[noreturn]] void Fail(const std::string& what, const std::string& message) const;

  /// Creates the group `name`.
  void Group(const std::string& name);
  /// Creates and writes a dataset of shape `dims` from `data` (may be null
  /// for an empty dataset).
  void Data(const std::string& name, hid_t file_type, hid_t mem_type, const Dims& dims, const void* data);
  /// Doubles of shape `dims` (row-major).
  void Doubles(const std::string& name, const Dims& dims, const double* data);
  /// A one-dimensional dataset of doubles.
  void Doubles(const std::string& name, const std::vector<double>& v) { Doubles(name, {Size(v.size())}, v.data()); }
  /// A one-dimensional dataset of 32-bit integers.
  void Ints(const std::string& name, const std::vector<int>& v);
  /// A one-dimensional dataset of 64-bit integers.
  void Longs(const std::string& name, const std::vector<int64_t>& v);
  /// A matrix as [rows][cols], row-major.
  void Matrix(const std::string& name, const Eigen::MatrixXd& m);
  /// Variable-length strings of shape `dims`.
  void Strings(const std::string& name, const std::vector<std::string>& v, const Dims& dims);
  /// A one-dimensional dataset of strings.
  void Strings(const std::string& name, const std::vector<std::string>& v) { Strings(name, v, {Size(v.size())}); }

  /// Attribute `name` of the object `object` ("/" for the root), shape
  /// `dims` ({} for a scalar).
  void Attribute(const std::string& object, const std::string& name, hid_t file_type, hid_t mem_type,
                 const Dims& dims, const void* data);
  /// String attributes of shape `dims`.
  void AttributeStrings(const std::string& object, const std::string& name, const std::vector<std::string>& v,
                        const Dims& dims);
  /// A scalar string attribute.
  void AttributeString(const std::string& object, const std::string& name, const std::string& value);
  /// A scalar 32-bit integer attribute.
  void AttributeInt(const std::string& object, const std::string& name, int value);

 private:
  hid_t file_;
  std::string path_;
};

/// Reads and checks datasets and attributes of an open file; absolute names.
/// Every fault throws InputError with context (path, "dataset NAME" or
/// "attribute NAME of OBJECT").
class Reader {
 public:
  /// Reads from the open file `file`; `path` is named in errors.
  Reader(hid_t file, std::string path) : file_(file), path_(std::move(path)) {}

  /// Throws InputError(message) with context (path, `what`).
  [[noreturn]] void Fail(const std::string& what, const std::string& message) const;

  /// Every link of the absolute name exists.
  bool Exists(const std::string& name) const;
  /// Opens a dataset ("is missing" if it is not there).
  Handle Dataset(const std::string& name) const;
  /// Shape of a dataspace.
  static Dims DimsOf(hid_t space);
  /// Number of values of a shape.
  static size_t Count(const Dims& dims);
  /// Opens a dataset and checks its type class and shape.
  Handle Checked(const std::string& name, H5T_class_t cls, const Dims& dims) const;
  /// Length of a one-dimensional dataset.
  size_t Length(const std::string& name) const;
  /// Reads all of the open dataset `d` as `mem_type` into `out`, verifying
  /// its checksum (InputError "checksum mismatch" naming the dataset).
  void Read(const std::string& name, const Handle& d, hid_t mem_type, void* out) const;
  /// Names of the datasets with values read so far that carry no checksum
  /// (files of older writers).
  const std::vector<std::string>& unchecked() const { return unchecked_; }

  /// Doubles of the given shape into `out` (Count(dims) values), all finite.
  void DoublesInto(const std::string& name, const Dims& dims, double* out) const;
  /// Doubles of the given shape (row-major), all finite.
  std::vector<double> Doubles(const std::string& name, const Dims& dims) const;
  /// A [rows][cols] dataset as a matrix.
  Eigen::MatrixXd Matrix(const std::string& name, size_t rows, size_t cols) const;
  /// A [3][3] dataset.
  Eigen::Matrix3d Block(const std::string& name) const;
  /// A [..][3][3] dataset of shape `dims` as 3 x 3 blocks.
  std::vector<Eigen::Matrix3d> Blocks(const std::string& name, const Dims& dims) const;
  /// `n` integers.
  std::vector<int> Ints(const std::string& name, size_t n) const;
  /// Offsets of a packed list: n + 1 values from 0, non-decreasing.
  std::vector<int64_t> Offsets(const std::string& name, size_t n) const;
  /// `n` strings (fixed or variable length).
  std::vector<std::string> Strings(const std::string& name, size_t n) const;

  /// Opens attribute `name` of `object` ("is missing" if it is not there).
  Handle Attribute(const std::string& object, const std::string& name) const;
  /// A string attribute; its shape is returned in `dims` ({} for a scalar).
  std::vector<std::string> AttributeStrings(const std::string& object, const std::string& name, Dims* dims) const;
  /// A scalar string attribute.
  std::string AttributeString(const std::string& object, const std::string& name) const;
  /// A scalar integer attribute in the range of int.
  int AttributeInt(const std::string& object, const std::string& name) const;

  /// Every value of dataset `name` (already read into `v`) is in [lo, hi);
  /// `of` names what it indexes ("node").
  void InRange(const std::string& name, const std::vector<int>& v, int lo, int hi, const char* of) const;

 private:
  std::vector<std::string> StringsOf(const std::string& what, hid_t type, hid_t space, bool attribute,
                                     hid_t obj) const;
  // records the dataset in unchecked_ if it has values and no checksum
  void NoteChecksum(const std::string& name, hid_t d) const;
  // throws for a failed read of dataset `name`: a checksum mismatch if the
  // data reads without verification, else HDF5's reason
  [[noreturn]] void FailedRead(const std::string& name, hid_t d, hid_t mem_type, void* out) const;
  hid_t file_;
  std::string path_;
  mutable std::vector<std::string> unchecked_;
};

}  // namespace flexmb::io::hdf5
