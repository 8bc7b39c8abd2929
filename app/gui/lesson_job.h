// A lesson step's check (sph/lesson_check.h) run on a thread of its own beside the engine: the lesson
// panel starts it, polls it every frame and shows the result in green or red.
#pragma once
#include <future>
#include <optional>
#include <string>

#include "sph/lesson_check.h"

namespace sph::gui {

class LessonJob {
 public:
  explicit LessonJob(const LessonStep& step);  ///< starts the check at once
  ~LessonJob();                                ///< waits for it (a run cannot be interrupted)
  LessonJob(const LessonJob&) = delete;
  LessonJob& operator=(const LessonJob&) = delete;

  /// Collects the result once the thread has finished; true while still running.
  bool poll();
  /// Blocks until the check has finished (the exit report).
  void wait();
  const std::optional<CheckResult>& result() const { return result_; }
  const std::string& error() const { return error_; }  ///< a run diverged or the step cannot be configured

 private:
  std::future<CheckResult> future_;
  std::optional<CheckResult> result_;
  std::string error_;
};

}  // namespace sph::gui
