#include "cli_lesson.h"

#include <omp.h>

#include <cstdio>

#include "exit_codes.h"
#include "sph/lesson.h"
#include "sph/lesson_check.h"
#include "sph/world.h"

namespace sph::cli {

/// Loads the lesson (exit 6 when malformed), then prints it (show) or checks each step in order, printing
/// the measured numbers and a mark; exit 7 if any claim is false, 5 if a run diverges.
int lesson_command(const LessonOptions& opt) {
  if (opt.action != "show" && opt.action != "check") {
    std::fprintf(stderr, "sph: lesson: unknown action '%s' (show or check)\n", opt.action.c_str());
    return kUsage;
  }
  Lesson lesson;
  try {
    lesson = load_lesson(opt.file);
  } catch (const LessonError& e) {
    std::fprintf(stderr, "sph: lesson: %s\n", e.what());
    return kBadLesson;
  }
  if (opt.action == "show") {
    std::fputs(lesson_text(lesson).c_str(), stdout);
    return kOk;
  }
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  int failed = 0;
  std::printf("%s\n", lesson.title.c_str());
  for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
    const LessonStep& st = lesson.steps[i];
    CheckResult r;
    try {
      r = evaluate_check(st);
    } catch (const DivergedError& e) {
      std::fprintf(stderr, "sph: lesson: %s: step %zu (%s): a run diverged: %s\n", opt.file.c_str(), i + 1,
                   st.title.c_str(), e.what());
      return kDiverged;
    }
    failed += r.pass ? 0 : 1;
    std::printf("step %zu/%zu %s: %s\n  %s %s\n", i + 1, lesson.steps.size(), st.title.c_str(), claim_text(st).c_str(),
                r.text.c_str(), r.pass ? "\u2713" : "\u2717 FALSE");
    std::fflush(stdout);
  }
  if (failed > 0) {
    std::fprintf(stderr, "sph: lesson: %s: %d of %zu claims are false\n", opt.file.c_str(), failed, lesson.steps.size());
    return kClaimFalse;
  }
  return kOk;
}

}  // namespace sph::cli
