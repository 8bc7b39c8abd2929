#include "lesson_job.h"

namespace sph::gui {

LessonJob::LessonJob(const LessonStep& step) {
  work_.start([step] { return evaluate_check(step); });
}

}  // namespace sph::gui
