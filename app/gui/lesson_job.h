// A lesson step's check (sph/lesson_check.h) run on a thread of its own beside the engine: the lesson
// panel starts it, polls it every frame and shows the result in green or red.
#pragma once
#include <optional>
#include <string>

#include "background_result.h"
#include "sph/lesson_check.h"

namespace sph::gui {

class LessonJob {
 public:
  explicit LessonJob(const LessonStep& step);  ///< starts the check at once
  LessonJob(const LessonJob&) = delete;
  LessonJob& operator=(const LessonJob&) = delete;

  /// Collects the result once the thread has finished; true while still running.
  bool poll() { return work_.poll(); }
  /// Blocks until the check has finished (the exit report).
  void wait() { work_.wait(); }
  const std::optional<CheckResult>& result() const { return work_.result(); }
  const std::string& error() const { return work_.error(); }  ///< a run diverged or the step cannot be configured

 private:
  BackgroundResult<CheckResult> work_;  // waited for when the job is dropped
};

}  // namespace sph::gui
