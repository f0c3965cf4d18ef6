#include "flexmb/results/progress.h"

#include <algorithm>
#include <cstring>

namespace flexmb {

ProgressBar::ProgressBar(std::FILE* out, bool enabled, double t0, double t_end,
                         double min_interval_s)
    : out_(out),
      enabled_(enabled && out != nullptr),
      t0_(t0),
      t_end_(t_end),
      min_interval_(min_interval_s),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

ProgressBar::~ProgressBar() {
  if (enabled_ && drawn_) {
    std::fputc('\n', out_);
    std::fflush(out_);
  }
}

int ProgressBar::Format(char* buf, int size, double t0, double t_end, double t, long steps,
                        double wall_s) {
  const double span = t_end - t0;
  const double frac = span > 0 ? std::clamp((t - t0) / span, 0.0, 1.0) : 1.0;
  constexpr int kWidth = 24;
  char bar[kWidth + 1];
  const int filled = static_cast<int>(frac * kWidth);
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
  bar[kWidth] = '\0';
  const double rtf = wall_s > 0 ? (t - t0) / wall_s : 0.0;
  return std::snprintf(buf, size, "[%s] %5.1f%%  t = %.4g / %.4g s  %.3gx real time  %ld steps",
                       bar, 100.0 * frac, t, t_end, rtf, steps);
}

void ProgressBar::Draw(double t, long steps) {
  const auto now = std::chrono::steady_clock::now();
  const double wall = std::chrono::duration<double>(now - start_).count();
  char line[160];
  Format(line, sizeof(line), t0_, t_end_, t, steps, wall);
  // "\033[K" clears what is left of a longer previous line
  std::fprintf(out_, "\r%s\033[K", line);
  std::fflush(out_);
  last_ = now;
  drawn_ = true;
}

void ProgressBar::Update(double t, long steps) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && std::chrono::duration<double>(now - last_).count() < min_interval_) return;
  Draw(t, steps);
}

void ProgressBar::Finish(double t, long steps) {
  if (!enabled_ || !drawn_) return;
  Draw(t, steps);
  std::fputc('\n', out_);
  std::fflush(out_);
  enabled_ = false;
}

}  // namespace flexmb
