#include "flexmb/durability/modal_history.h"

#include <cmath>
#include <cstring>
#include <filesystem>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/model/model.h"
#include "flexmb/model/state.h"

namespace flexmb::durability {
namespace {

constexpr char kModalMagic[8] = {'F', 'M', 'B', 'M', 'O', 'D', 'A', 'L'};
constexpr std::uint32_t kModalVersion = 1;

void ModalAppend(std::vector<unsigned char>& b, const void* p, std::size_t n) {
  const auto* c = static_cast<const unsigned char*>(p);
  b.insert(b.end(), c, c + n);
}

void ModalAppendString(std::vector<unsigned char>& b, const std::string& s) {
  const auto n = static_cast<std::uint32_t>(s.size());
  ModalAppend(b, &n, sizeof n);
  ModalAppend(b, s.data(), s.size());
}

// reads from a byte buffer; false when the buffer ends
class ModalReader {
 public:
  ModalReader(const std::vector<unsigned char>& b, const std::string& path) : b_(b), path_(path) {}
  template <class T>
  T Get(const char* what) {
    T v{};
    Need(sizeof v, what);
    std::memcpy(&v, b_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return v;
  }
  std::string GetString(const char* what) {
    const auto n = Get<std::uint32_t>(what);
    Need(n, what);
    std::string s(reinterpret_cast<const char*>(b_.data() + pos_), n);
    pos_ += n;
    return s;
  }
  void Need(std::size_t n, const char* what) const {
    if (pos_ + n > b_.size())
      throw InputError(std::string("not a modal coordinates file: header ends in the ") + what, {path_, 0, ""});
  }
  std::size_t pos() const { return pos_; }

 private:
  const std::vector<unsigned char>& b_;
  const std::string& path_;
  std::size_t pos_ = 0;
};

}  // namespace

std::uint64_t Fnv1a(const unsigned char* data, std::size_t size, std::uint64_t hash) {
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

ModalHistoryWriter::ModalHistoryWriter(const std::string& path, const std::vector<ModalHistoryBody>& bodies)
    : path_(path) {
  std::vector<unsigned char> h;
  ModalAppend(h, kModalMagic, sizeof kModalMagic);
  ModalAppend(h, &kModalVersion, sizeof kModalVersion);
  const auto count = static_cast<std::uint32_t>(bodies.size());
  ModalAppend(h, &count, sizeof count);
  for (const ModalHistoryBody& b : bodies) {
    ModalAppendString(h, b.name);
    ModalAppendString(h, b.body_file);
    const auto n = static_cast<std::uint32_t>(b.modes);
    ModalAppend(h, &n, sizeof n);
    size_ += b.modes;
  }
  const std::uint64_t sum = Fnv1a(h.data(), h.size());
  ModalAppend(h, &sum, sizeof sum);
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) throw InputError("cannot write the modal coordinates file", {path, 0, ""});
  if (std::fwrite(h.data(), 1, h.size(), file_) != h.size() || std::fflush(file_) != 0)
    throw InputError("cannot write the modal coordinates file", {path, 0, ""});
  buffer_.resize(sizeof(double) * (1 + size_) + sizeof(std::uint64_t));
}

ModalHistoryWriter::~ModalHistoryWriter() {
  if (file_) std::fclose(file_);
}

void ModalHistoryWriter::Write(double t, const double* w, int size) {
  if (size != size_)
    throw InputError("modal coordinates record of " + std::to_string(size) + " values, expected " +
                         std::to_string(size_), {path_, 0, ""});
  unsigned char* p = buffer_.data();
  std::memcpy(p, &t, sizeof t);
  if (size > 0) std::memcpy(p + sizeof t, w, sizeof(double) * size);
  const std::size_t n = sizeof(double) * (1 + size_);
  const std::uint64_t sum = Fnv1a(p, n);
  std::memcpy(p + n, &sum, sizeof sum);
  if (std::fwrite(p, 1, buffer_.size(), file_) != buffer_.size() || std::fflush(file_) != 0)
    throw InputError("cannot write the modal coordinates file", {path_, 0, ""});
  ++records_;
}

ModelModalHistory::ModelModalHistory(const std::string& dir, const Model& model,
                                     const std::map<std::string, std::string>& written) {
  std::vector<ModalHistoryBody> bodies;
  for (const auto& body : model.bodies) {
    const auto* flex = dynamic_cast<const FlexibleBody*>(body.get());
    if (!flex) continue;
    ModalHistoryBody h;
    h.name = flex->name();
    h.modes = flex->modes();
    const reduction::ReducedBody& r = flex->reduced();
    if (!r.mesh.elements.empty() && !r.mesh.elements[0].origin.file.empty()) {
      std::error_code ec;
      const std::filesystem::path abs = std::filesystem::absolute(r.mesh.elements[0].origin.file, ec);
      h.body_file = ec ? r.mesh.elements[0].origin.file : abs.string();
    } else if (const auto it = written.find(h.name); it != written.end()) {
      h.body_file = it->second;
    } else {
      // a body built in code: its reduced body goes into the run folder
      const std::filesystem::path rel = std::filesystem::path("bodies") / (h.name + ".h5");
      std::error_code ec;
      std::filesystem::create_directories(std::filesystem::path(dir) / "bodies", ec);
      io::WriteBody(r, (std::filesystem::path(dir) / rel).string());
      h.body_file = rel.string();
    }
    bodies.push_back(h);
    q_offsets_.push_back(flex->q_offset + 7);
    sizes_.push_back(h.modes);
  }
  if (bodies.empty()) return;
  int total = 0;
  for (int n : sizes_) total += n;
  w_.resize(total);
  writer_ = std::make_unique<ModalHistoryWriter>((std::filesystem::path(dir) / kModalHistoryFile).string(), bodies);
}

ModelModalHistory::~ModelModalHistory() = default;

void ModelModalHistory::Write(const State& state) {
  if (!writer_) return;
  int k = 0;
  for (size_t b = 0; b < sizes_.size(); ++b)
    for (int i = 0; i < sizes_[b]; ++i) w_[k++] = state.q[q_offsets_[b] + i];
  writer_->Write(state.t, w_.data(), k);
}

int ModalHistory::Body(const std::string& name) const {
  std::string names;
  for (size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].name == name) return static_cast<int>(b);
    names += (b ? ", '" : "'") + bodies[b].name + "'";
  }
  throw InputError("no flexible body '" + name + "' in the run (bodies: " + names + ")",
                   {path, 0, "body '" + name + "'"});
}

ModalHistory ReadModalHistory(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw InputError("cannot open the modal coordinates file", {path, 0, ""});
  std::vector<unsigned char> bytes;
  unsigned char chunk[65536];
  for (std::size_t got; (got = std::fread(chunk, 1, sizeof chunk, f)) > 0;) bytes.insert(bytes.end(), chunk, chunk + got);
  std::fclose(f);

  // header
  ModalHistory h;
  h.path = path;
  ModalReader r(bytes, path);
  r.Need(sizeof kModalMagic, "magic");
  if (std::memcmp(bytes.data(), kModalMagic, sizeof kModalMagic) != 0)
    throw InputError("not a modal coordinates file (no FMBMODAL magic)", {path, 0, ""});
  for (size_t i = 0; i < sizeof kModalMagic; ++i) r.Get<char>("magic");
  const auto version = r.Get<std::uint32_t>("version");
  if (version != kModalVersion)
    throw InputError("modal coordinates file version " + std::to_string(version) + ", expected " +
                         std::to_string(kModalVersion), {path, 0, ""});
  const auto count = r.Get<std::uint32_t>("body count");
  if (count > 100000) throw InputError("modal coordinates file: corrupt body count", {path, 0, ""});
  int size = 0;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (std::uint32_t b = 0; b < count; ++b) {
    ModalHistoryBody body;
    body.name = r.GetString("body name");
    body.body_file = r.GetString("body file");
    body.modes = static_cast<int>(r.Get<std::uint32_t>("mode count"));
    if (body.modes < 0 || body.modes > 1000000)
      throw InputError("modal coordinates file: corrupt mode count", {path, 0, "body '" + body.name + "'"});
    if (std::filesystem::path(body.body_file).is_relative()) body.body_file = (folder / body.body_file).string();
    size += body.modes;
    h.bodies.push_back(body);
  }
  const std::size_t header_end = r.pos();
  const auto sum = r.Get<std::uint64_t>("checksum");
  if (sum != Fnv1a(bytes.data(), header_end))
    throw InputError("modal coordinates file: header checksum mismatch (damaged file)", {path, 0, ""});

  // records: complete ones are checked, a truncated last one is dropped
  const std::size_t start = r.pos();
  const std::size_t data = sizeof(double) * (1 + size), rec = data + sizeof(std::uint64_t);
  const std::size_t n = (bytes.size() - start) / rec;
  h.truncated = (bytes.size() - start) % rec != 0;
  h.times.resize(n);
  for (const ModalHistoryBody& b : h.bodies) h.coordinates.emplace_back(b.modes, static_cast<Eigen::Index>(n));
  std::vector<double> values(1 + size);
  for (std::size_t k = 0; k < n; ++k) {
    const unsigned char* p = bytes.data() + start + k * rec;
    std::uint64_t s;
    std::memcpy(&s, p + data, sizeof s);
    if (s != Fnv1a(p, data))
      throw InputError("modal coordinates file: checksum mismatch in record " + std::to_string(k + 1) +
                           " (damaged file)", {path, 0, ""});
    std::memcpy(values.data(), p, data);
    for (double v : values)
      if (!std::isfinite(v))
        throw InputError("modal coordinates file: non-finite value in record " + std::to_string(k + 1), {path, 0, ""});
    h.times[k] = values[0];
    int i = 1;
    for (size_t b = 0; b < h.bodies.size(); ++b)
      for (int j = 0; j < h.bodies[b].modes; ++j) h.coordinates[b](j, static_cast<Eigen::Index>(k)) = values[i++];
  }
  return h;
}

ModalHistory ReadRunModalHistory(const std::string& dir) {
  const std::filesystem::path p = std::filesystem::path(dir) / kModalHistoryFile;
  if (!std::filesystem::exists(p))
    throw InputError(std::string("no modal coordinates in this folder (") + kModalHistoryFile +
                         " is missing: not a run folder, or the model has no flexible body)", {dir, 0, ""});
  return ReadModalHistory(p.string());
}

}  // namespace flexmb::durability
