// The OpenMP team size of a world's steps, chosen by measured time (issue 14). A team of two costs a
// barrier wait at every loop; for a small problem, or on a two-core machine whose other core is busy
// (the GUI thread, another test), that wait can make two threads slower than one. So the world times its
// steps with a team of one and with the full team, alternately for a few steps, keeps the faster, and
// measures again every so often. Results do not depend on the team size (gather loops in a fixed
// order), so this choice changes only the time.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace sph {

class TeamChooser {
 public:
  /// The team for the next step, at most `max_threads` (the caller's OpenMP setting).
  int next(int max_threads) {
    if (max_threads != max_) restart(max_threads);
    if (max_ <= 1) return 1;
    if (probing_ < kProbeSteps) return probing_ % 2 == 0 ? max_ : 1;  // alternate: full team, one thread
    return choice_;
  }
  /// The step just taken with next()'s team took `seconds`.
  void record(double seconds) {
    if (max_ <= 1) return;
    if (probing_ < kProbeSteps) {
      if (probing_ >= 2) samples_[probing_ % 2].push_back(seconds);  // the first pair warms up
      if (++probing_ == kProbeSteps) decide();
      return;
    }
    if (++since_probe_ >= kRunSteps) restart(max_);
  }
  /// The team the last measurement chose (0 before any).
  int chosen() const { return probing_ >= kProbeSteps ? choice_ : 0; }

 private:
  static constexpr int kProbeSteps = 8;   ///< 2 warm-up steps, then 3 timed steps of each size
  static constexpr int kRunSteps = 256;   ///< steps between two measurements

  void restart(int max_threads) {
    max_ = max_threads;
    probing_ = 0;
    since_probe_ = 0;
    for (auto& s : samples_) s.clear();
  }
  static double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  }
  void decide() {
    // the full team unless one thread is clearly faster (5%: the noise of one step's timing)
    const double team = median(samples_[0]), one = median(samples_[1]);
    choice_ = one < 0.95 * team ? 1 : max_;
  }

  int max_ = 0, choice_ = 1, probing_ = 0;
  std::int64_t since_probe_ = 0;
  std::array<std::vector<double>, 2> samples_;  ///< [0] full team, [1] one thread [s]
};

}  // namespace sph
