// A convergence study (sph/convergence.h) run from the GUI on a thread of its own, beside the engine:
// the panel starts it, polls it every frame and shows its table and plot when it is done.
#pragma once
#include <atomic>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "sph/convergence.h"

namespace sph::gui {

class ConvergeJob {
 public:
  /// Starts the (resolved) study from `base` at once.
  ConvergeJob(const RunConfig& base, const ConvergenceStudy& study);
  ~ConvergeJob();  ///< waits for the study to end (a run cannot be interrupted)
  ConvergeJob(const ConvergeJob&) = delete;
  ConvergeJob& operator=(const ConvergeJob&) = delete;

  /// Collects the result once the thread has finished; true while still running.
  bool poll();
  int finished() const { return finished_.load(); }
  int total() const { return total_; }
  const std::optional<ConvergenceResult>& result() const { return result_; }
  const std::string& error() const { return error_; }

 private:
  int total_ = 0;
  std::shared_ptr<std::atomic<int>> counter_;  // shared with the thread
  std::atomic<int>& finished_;
  std::future<ConvergenceResult> future_;
  std::optional<ConvergenceResult> result_;
  std::string error_;
};

}  // namespace sph::gui
