// Steps per wall second, measured over windows of at least `window` seconds (the last full window is
// reported, so the figure is steady rather than per-step noise).
#pragma once
#include <chrono>
#include <cstdint>

namespace sph::detail {

class RateMeter {
 public:
  using Clock = std::chrono::steady_clock;
  explicit RateMeter(double window = 0.5) : window_(window) {}

  /// Starts a new window (after a pause, a rebuild); keeps the last rate.
  void restart() { start_ = Clock::now(); count_ = 0; }
  /// One event (a step) happened now.
  void tick() {
    ++count_;
    const double dt = std::chrono::duration<double>(Clock::now() - start_).count();
    if (dt >= window_) {
      rate_ = static_cast<double>(count_) / dt;
      restart();
    }
  }
  /// Events per second over the last full window (0 before the first).
  double rate() const { return rate_; }
  void zero() { rate_ = 0.0; restart(); }

 private:
  double window_;
  Clock::time_point start_ = Clock::now();
  std::int64_t count_ = 0;
  double rate_ = 0.0;
};

}  // namespace sph::detail
