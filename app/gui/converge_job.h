// A convergence study (sph/convergence.h) run from the GUI on a thread of its own, beside the engine:
// the panel starts it, polls it every frame and shows its table and plot when it is done.
#pragma once
#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "background_result.h"
#include "sph/convergence.h"

namespace sph::gui {

class ConvergeJob {
 public:
  /// Starts the (resolved) study from `base` at once.
  ConvergeJob(const RunConfig& base, const ConvergenceStudy& study);
  ConvergeJob(const ConvergeJob&) = delete;
  ConvergeJob& operator=(const ConvergeJob&) = delete;

  /// Collects the result once the thread has finished; true while still running.
  bool poll() { return work_.poll(); }
  int finished() const { return finished_.load(); }
  int total() const { return total_; }
  const std::optional<ConvergenceResult>& result() const { return work_.result(); }
  const std::string& error() const { return work_.error(); }

 private:
  int total_ = 0;
  std::shared_ptr<std::atomic<int>> counter_;  // shared with the thread
  std::atomic<int>& finished_;
  BackgroundResult<ConvergenceResult> work_;  // last: waited for before the counter goes
};

}  // namespace sph::gui
