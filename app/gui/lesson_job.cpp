#include "lesson_job.h"

#include <chrono>

namespace sph::gui {

LessonJob::LessonJob(const LessonStep& step) {
  future_ = std::async(std::launch::async, [step] { return evaluate_check(step); });
}

LessonJob::~LessonJob() {
  if (future_.valid()) future_.wait();
}

bool LessonJob::poll() {
  if (!future_.valid()) return false;
  if (future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return true;
  try {
    result_ = future_.get();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  return false;
}

void LessonJob::wait() {
  if (future_.valid()) future_.wait();
  poll();
}

}  // namespace sph::gui
