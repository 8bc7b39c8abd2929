#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace sph::cli {

namespace {
constexpr int kBarWidth = 30;                                  // characters inside [ ]
constexpr auto kMinInterval = std::chrono::milliseconds(100);  // between redraws
}  // namespace

std::string format_duration(double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) return "--:--";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

std::string Progress::format(double fraction, double t, std::int64_t step, double elapsed_s, double eta_s,
                             int width) {
  fraction = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
  const int filled = static_cast<int>(fraction * width + 0.5);
  std::string s;  // built with append: GCC 12 -Wrestrict misfires on chained operator+ here
  s.reserve(static_cast<std::size_t>(width) + 96);
  s.push_back('[');
  s.append(static_cast<std::size_t>(filled), '#');
  s.append(static_cast<std::size_t>(width - filled), '-');
  s.push_back(']');
  char buf[160];
  std::snprintf(buf, sizeof buf, " %5.1f%%  t = %.4f", 100.0 * fraction, t);
  s += buf;
  if (step >= 0) {
    std::snprintf(buf, sizeof buf, "  step %lld", static_cast<long long>(step));
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "  elapsed %s  ETA %s", format_duration(elapsed_s).c_str(),
                format_duration(eta_s).c_str());
  s += buf;
  return s;
}

Progress::Progress(double t_end, double t_start, std::FILE* out)
    : t_start_(t_start), t_end_(t_end), out_(out), enabled_(out != nullptr && ::isatty(::fileno(out))),
      last_t_(t_start), start_(Clock::now()), last_draw_(start_ - kMinInterval) {}

Progress::~Progress() {
  if (enabled_ && drawn_ && !finished_) std::fputc('\n', out_);
}

void Progress::update(double t, std::int64_t step, bool force) {
  last_t_ = t;
  last_step_ = step;
  if (!enabled_ || finished_) return;
  const auto now = Clock::now();
  if (!force && now - last_draw_ < kMinInterval) return;
  last_draw_ = now;
  const double span = t_end_ - t_start_;
  const double fraction = span > 0.0 ? (t - t_start_) / span : 1.0;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // Wall time per simulated time so far, extrapolated; unknown until some progress was made.
  const double eta = fraction > 1e-3 ? elapsed * (1.0 - fraction) / fraction : -1.0;
  const std::string line = format(fraction, t, step, elapsed, eta, kBarWidth);
  std::fprintf(out_, "\r%s\033[K", line.c_str());  // \033[K clears what a longer line left behind
  std::fflush(out_);
  drawn_ = true;
}

void Progress::finish() {
  if (!enabled_ || finished_) return;
  update(last_t_, last_step_, true);
  std::fputc('\n', out_);
  std::fflush(out_);
  finished_ = true;
}

}  // namespace sph::cli
