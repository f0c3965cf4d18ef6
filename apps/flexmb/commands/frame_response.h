#pragma once
/// \file frame_response.h
/// The lane change's elastic-frame response at its output instants
/// (FrameResponse), batched; used by lane_change.cc only.

#include <algorithm>
#include <cstdio>
#include <vector>

#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/reduction/stress_modes.h"

namespace flexmb::vehicle {

/// Deflection and stress of the elastic frame at the output instants: the
/// largest elastic node displacement relative to the floating frame and the
/// largest von Mises stress of the shell stress modes, with where. The
/// instants are evaluated in batches of kBatch: one matrix-matrix product
/// with the node translations and one with the stress modes per batch
/// instead of two matrix-vector products per instant, which stream the
/// 16 MB of modes from memory every time (docs/PERFORMANCE.md). The rows
/// of results.csv wait in the batch for their frame columns; Flush()
/// writes them. Buffers are allocated once.
class FrameResponse {
 public:
  /// Instants per batch.
  static constexpr int kBatch = 32;
  /// Length of one CSV row without the frame columns for a truck of
  /// `axles` axles: each value is at most 14 characters with its comma
  /// (%.6g), 16 values for the truck, 6 per axle and its two wheels.
  static size_t RowChars(size_t axles) { return 16 + 14 * (16 + 6 * axles); }

  /// body: the elastic frame (nullptr: rigid frame, inactive); csv: the
  /// results file the rows go to (nullptr: none); row_chars: the rows'
  /// length (RowChars).
  FrameResponse(const FlexibleBody* body, std::FILE* csv, size_t row_chars) : body_(body), csv_(csv) {
    if (!body_) return;
    for (Instant& in : rows_) in.text.assign(row_chars, '\0');
    const reduction::ReducedBody& b = body_->reduced();
    const Eigen::Index nodes = b.modes.rows() / 6, n = body_->modes();
    translation_modes_.resize(3 * nodes, n);
    for (Eigen::Index k = 0; k < nodes; ++k) translation_modes_.middleRows(3 * k, 3) = b.modes.middleRows(6 * k, 3);
    w_.resize(n, kBatch);
    u_.resize(3 * nodes, kBatch);
    s_.resize(b.stress.shell.modes.rows(), kBatch);
    vm_.resize(static_cast<Eigen::Index>(b.stress.shell.elements.size()));
    centroid_.resize(b.stress.shell.elements.size());
    for (size_t k = 0; k < centroid_.size(); ++k) {
      const fe::Element& e = b.mesh.elements[static_cast<size_t>(b.stress.shell.elements[k])];
      Vec3 c = Vec3::Zero();
      for (int nd : e.nodes) c += b.mesh.nodes[static_cast<size_t>(nd)].x / static_cast<double>(e.nodes.size());
      centroid_[k] = c;
    }
  }
  bool active() const { return body_ != nullptr; }

  /// Adds the instant t with the frame's coordinates q (7 + n). row: its
  /// CSV text without the frame columns and newline (nullptr: no row);
  /// record: the instant counts for the maxima kept in r. Flushes a full
  /// batch.
  void Add(double t, const double* q, bool record, const char* row, LaneChangeResult& r) {
    w_.col(count_) = Eigen::Map<const VecX>(q + 7, body_->modes());
    Instant& in = rows_[static_cast<size_t>(count_)];
    in.t = t;
    in.record = record;
    in.has_row = row != nullptr;
    if (row) std::snprintf(in.text.data(), in.text.size(), "%s", row);
    if (++count_ == kBatch) Flush(r);
  }

  /// Evaluates the waiting instants, keeps their maxima in r and writes
  /// their rows.
  void Flush(LaneChangeResult& r) {
    if (!body_ || count_ == 0) return;
    const reduction::ReducedBody& b = body_->reduced();
    const reduction::StressTable& table = b.stress.shell;
    const Eigen::Index n = count_;
    u_.leftCols(n).noalias() = translation_modes_ * w_.leftCols(n);
    if (!table.elements.empty()) s_.leftCols(n).noalias() = table.modes * w_.leftCols(n);
    for (Eigen::Index c = 0; c < n; ++c) {
      Instant& in = rows_[static_cast<size_t>(c)];
      double disp = 0, stress = 0;
      int node = 0, element = 0;
      for (Eigen::Index k = 0; 3 * k < u_.rows(); ++k) {
        const double d = u_.col(c).segment<3>(3 * k).norm();
        if (d > disp) {
          disp = d;
          node = static_cast<int>(k);
        }
      }
      if (!table.elements.empty()) {
        reduction::ElementVonMisesOfValues(table, s_.col(c), vm_);
        Eigen::Index k = 0;
        stress = vm_.maxCoeff(&k);
        element = static_cast<int>(k);
      }
      const fe::Node& nd = b.mesh.nodes[static_cast<size_t>(node)];
      const int element_id = table.elements.empty() ? -1 : b.mesh.elements[static_cast<size_t>(table.elements[static_cast<size_t>(element)])].id;
      const double element_x = table.elements.empty() ? 0.0 : centroid_[static_cast<size_t>(element)].x();
      if (in.record && disp > r.max_frame_displacement) {
        r.max_frame_displacement = disp;
        r.max_displacement_node = nd.id;
        r.max_displacement_position = nd.x;
        r.max_displacement_time = in.t;
      }
      if (in.record && stress > r.max_frame_stress) {
        r.max_frame_stress = stress;
        r.max_stress_element = element_id;
        r.max_stress_position = centroid_[static_cast<size_t>(element)];
        r.max_stress_time = in.t;
      }
      if (csv_ && in.has_row)
        std::fprintf(csv_, "%s,%.6g,%d,%.4g,%.6g,%d,%.4g\n", in.text.data(), disp * 1e3, nd.id, nd.x.x(), stress / 1e6,
                     element_id, element_x);
    }
    count_ = 0;
  }

 private:
  struct Instant {
    double t = 0;
    bool record = false, has_row = false;
    std::vector<char> text;  ///< sized once (RowChars)
  };
  const FlexibleBody* body_;
  std::FILE* csv_;
  MatX translation_modes_, w_, u_, s_;
  VecX vm_;
  std::vector<Vec3> centroid_;
  std::vector<Instant> rows_ = std::vector<Instant>(kBatch);
  Eigen::Index count_ = 0;
};

}  // namespace flexmb::vehicle
