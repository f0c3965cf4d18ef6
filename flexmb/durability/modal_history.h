#pragma once
/// \file modal_history.h
/// The modal coordinates of every floating-frame flexible body of a run,
/// kept in one compact binary file per run (DIR/modal_coordinates.bin) so
/// that stresses can be recovered afterwards for any element and instant
/// (durability/stress_recovery.h). The file is written record by record
/// and flushed after each, every record with its own checksum, so an
/// interrupted run keeps everything it computed; a reader drops only a
/// truncated last record.
///
/// Layout (little-endian machine order, as written): the 8 bytes
/// "FMBMODAL", uint32 format version (1), uint32 body count, then per body
/// uint32 name length, the name, uint32 path length, the body file path
/// (relative paths are relative to the file's folder), uint32 modal
/// coordinates n_b; then uint64 FNV-1a checksum of all preceding bytes.
/// Then records, each: double t [s], the n_b doubles w of every body in
/// header order, uint64 FNV-1a checksum of the record's bytes.

#include <Eigen/Core>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace flexmb {
class Model;
struct State;
}  // namespace flexmb

namespace flexmb::durability {

/// File name of the modal coordinates in a run folder.
inline constexpr const char* kModalHistoryFile = "modal_coordinates.bin";

/// One flexible body of a modal history file.
struct ModalHistoryBody {
  std::string name;       ///< body name in the model
  std::string body_file;  ///< body file path as resolved by the reader (as stored by the writer)
  int modes = 0;          ///< modal coordinates n
};

/// Writer of a modal history file.
class ModalHistoryWriter {
 public:
  /// Opens `path` for writing (truncating) and writes the header for
  /// `bodies`. Throws InputError naming the path if it cannot be written.
  ModalHistoryWriter(const std::string& path, const std::vector<ModalHistoryBody>& bodies);
  ~ModalHistoryWriter();
  ModalHistoryWriter(const ModalHistoryWriter&) = delete;
  ModalHistoryWriter& operator=(const ModalHistoryWriter&) = delete;

  /// Appends the record (t, w of every body concatenated, sum of n_b
  /// values) and flushes. Throws InputError naming the path if the size is
  /// wrong or writing fails.
  void Write(double t, const double* w, int size);
  /// Records written.
  long records() const { return records_; }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  int size_ = 0;
  long records_ = 0;
  std::vector<unsigned char> buffer_;  // scratch: one record
};

/// Writer of the modal coordinates of all flexible bodies of a model
/// (bodies/flexible_body.h), for the run workflow (apps/flexmb/commands/run.h). A body whose
/// reduced body came from a body file is referred to by that file (the
/// `origin.file` of its mesh elements); a body built in code has its
/// reduced body written to DIR/bodies/NAME.h5 and referred to there.
class ModelModalHistory {
 public:
  /// Writes DIR/modal_coordinates.bin if the model has flexible bodies;
  /// otherwise does nothing. `written` names bodies built in code whose
  /// reduced body the caller has already written (body name -> file path,
  /// relative to DIR or absolute): they are referred to there instead of
  /// being written again to DIR/bodies/. Throws InputError as
  /// ModalHistoryWriter.
  ModelModalHistory(const std::string& dir, const Model& model,
                    const std::map<std::string, std::string>& written = {});
  ~ModelModalHistory();
  /// Appends the modal coordinates of `state` (nothing without flexible bodies).
  void Write(const State& state);
  /// True if the model has flexible bodies.
  bool active() const { return writer_ != nullptr; }

 private:
  std::vector<int> q_offsets_, sizes_;
  std::vector<double> w_;
  std::unique_ptr<ModalHistoryWriter> writer_;
};

/// A modal history read back.
struct ModalHistory {
  std::string path;                     ///< the file read
  std::vector<ModalHistoryBody> bodies; ///< header order
  std::vector<double> times;            ///< record times [s]
  /// Per body, n_b x records: column r holds w at times[r].
  std::vector<Eigen::MatrixXd> coordinates;
  bool truncated = false;               ///< a truncated last record was dropped
  /// Index of the named body; throws InputError naming the file and the
  /// body (and listing the bodies present) if there is none.
  int Body(const std::string& name) const;
};

/// Reads a modal history file. Throws InputError naming the file for a
/// missing file, a wrong magic, version or header checksum, or a complete
/// record with a wrong checksum (naming the record), or non-finite values.
ModalHistory ReadModalHistory(const std::string& path);

/// Reads DIR/modal_coordinates.bin of a run folder; throws InputError
/// naming the folder if it holds no modal coordinates (no flexible bodies,
/// or not a run folder).
ModalHistory ReadRunModalHistory(const std::string& dir);

/// 64-bit FNV-1a hash of `size` bytes continuing from `hash`.
std::uint64_t Fnv1a(const unsigned char* data, std::size_t size,
                    std::uint64_t hash = 1469598103934665603ull);

}  // namespace flexmb::durability
