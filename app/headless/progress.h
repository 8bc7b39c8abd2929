// A one-line progress bar with ETA on stderr for long headless runs. Silent unless the stream is a
// terminal (logs and CI stay clean). Redraws at most ~10 times a second.
#pragma once
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace sph::cli {

class Progress {
 public:
  /// Progress runs from t_start to t_end (simulated time). `out` defaults to stderr.
  explicit Progress(double t_end, double t_start = 0.0, std::FILE* out = stderr);
  ~Progress();  ///< ends the line if a bar was drawn and finish() was not called
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }
  /// Redraws the bar for simulated time t (rate-limited unless force); step < 0 is not shown.
  void update(double t, std::int64_t step = -1, bool force = false);
  /// Draws the last state once more and ends the line.
  void finish();

  /// The bar text for a fraction in [0,1] and the seconds elapsed and remaining (< 0: unknown):
  /// "[#####-----]  50.0%  t = 0.1000  step 120  elapsed 0:03  ETA 0:03".
  static std::string format(double fraction, double t, std::int64_t step, double elapsed_s, double eta_s, int width);

 private:
  using Clock = std::chrono::steady_clock;
  double t_start_, t_end_;
  std::FILE* out_;
  bool enabled_;
  bool drawn_ = false, finished_ = false;
  double last_t_ = 0.0;
  std::int64_t last_step_ = -1;
  Clock::time_point start_, last_draw_;
};

/// "1:05" for 65 s, "1:01:05" for 3665 s, "--:--" for unknown (< 0 or non-finite).
std::string format_duration(double seconds);

}  // namespace sph::cli
