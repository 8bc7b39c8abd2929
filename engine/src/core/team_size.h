// The OpenMP team size of a world's steps, chosen by measured time (tests/engine/team_size_test.cpp). A
// team of two costs a barrier wait at every loop; for a small problem, or on a two-core machine whose
// other core is busy (the GUI thread, another program), that wait can make two threads slower than one:
// measured here with a compiler running on the other core, a 20k-particle step took 0.30 s with two
// spinning threads against 0.018 s with one. So the world times its steps with one thread and with the
// full team, keeps the faster, and measures again every so often: sooner when its steps slow down, less
// often while one thread keeps winning. A probe stops at the first team step that is clearly slower, so a
// bad team costs one step per probe. Results do not depend on the team size (gather loops in a fixed
// order): this choice changes only the time.
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
    if (max_threads != max_) {
      max_ = max_threads;
      interval_ = kRunSteps;
      restart();
    }
    if (max_ <= 1) return 1;
    if (probing_ < kProbeSteps) return probing_ < kProbeSteps / 2 ? 1 : max_;  // one thread first, then the team
    return choice_;
  }
  /// The step just taken with next()'s team took `seconds`.
  void record(double seconds) {
    if (max_ <= 1) return;
    if (probing_ < kProbeSteps) {
      probe(seconds);
      return;
    }
    recent_.push_back(seconds);
    if (recent_.size() == kWatchSteps) {
      // steps slower than the probe saw: the machine (or the problem) changed, measure again
      const bool slowed = median(recent_) > kSlowdown * chosen_time_;
      recent_.clear();
      if (slowed) { restart(); return; }
    }
    if (++since_probe_ >= interval_) restart();
  }
  /// The team the last measurement chose (0 before any).
  int chosen() const { return probing_ >= kProbeSteps ? choice_ : 0; }

 private:
  static constexpr int kProbeSteps = 8;          ///< 4 steps of one thread (the first warms up), then 4 of the team
  static constexpr std::int64_t kRunSteps = 256;  ///< steps between two measurements while the team wins
  static constexpr std::int64_t kMaxInterval = 4096;
  static constexpr std::size_t kWatchSteps = 16;  ///< steps whose median is compared with the probe's
  static constexpr double kSlowdown = 1.5;        ///< a median this much slower than the probe's: measure again
  static constexpr double kClearlySlower = 2.0;   ///< a team step this much slower than one thread ends the probe

  void restart() {
    probing_ = 0;
    since_probe_ = 0;
    recent_.clear();
    for (auto& s : samples_) s.clear();
  }
  static double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  }
  void probe(double seconds) {
    const bool team_step = probing_ >= kProbeSteps / 2;
    if (probing_ != 0 && probing_ != kProbeSteps / 2) samples_[team_step ? 0 : 1].push_back(seconds);  // skip warm-ups
    ++probing_;
    // a team step twice as slow as one thread's ends the probe at once (one slow step per probe)
    if (team_step && seconds > kClearlySlower * median(samples_[1])) return decide(1);
    if (probing_ == kProbeSteps) decide(0);
  }
  /// forced = 1: one thread without comparing medians; 0: the faster (the full team unless one thread
  /// is faster by more than 5%, the noise of one step's timing).
  void decide(int forced) {
    const double team = median(samples_[0]), one = median(samples_[1]);
    choice_ = forced == 1 || one < 0.95 * team ? 1 : max_;
    chosen_time_ = choice_ == 1 ? one : team;
    // one thread winning again: the machine stays busy, measure less often (a probe costs a slow step)
    interval_ = choice_ == 1 ? std::min(2 * interval_, kMaxInterval) : kRunSteps;
    probing_ = kProbeSteps;
    since_probe_ = 0;
  }

  int max_ = 0, choice_ = 1, probing_ = 0;
  std::int64_t since_probe_ = 0, interval_ = kRunSteps;
  double chosen_time_ = 0.0;  ///< the chosen team's median step time in the last probe [s]
  std::array<std::vector<double>, 2> samples_;  ///< [0] full team, [1] one thread [s]
  std::vector<double> recent_;                  ///< step times since the last watch [s]
};

}  // namespace sph
