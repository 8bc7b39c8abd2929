// The lesson editor (the Lesson panel's "Record a step"): what is on screen becomes a lesson step — the
// run's scene and the parameters it changed from the scene's defaults, the view (colour-by, panels, log,
// profile axis, range, 2D centre and zoom, cutaway, error strip), and a claim on a metric at the run's
// time — and the steps recorded so far are saved as a lesson file (sph/lesson.h lesson_json), which is
// read back and checked before it is written.
#pragma once
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/lesson.h"
#include "view_settings.h"

namespace sph::gui {

/// What the editor's fields hold besides what is on screen.
struct StepDraft {
  std::string title, text, predict, answer;
  bool above = false;  ///< the claim: metric above `limit` (else below)
  std::string metric;
  double limit = 0.0;
};

/// key=value of cfg's run parameters and scene values that differ from its scene's defaults (physics
/// slots first, as the scene file lists them).
LessonSets changed_sets(const RunConfig& cfg);

/// The view part of a step: what `view` shows that a step can set.
LessonView recorded_view(const render::ViewSettings& view);

/// A step from the run on screen (cfg at time t > 0; 0: the check runs to t_end) and the draft.
LessonStep record_step(const RunConfig& cfg, const render::ViewSettings& view, double t, const StepDraft& draft);

/// Writes the lesson to `path` after reading its JSON back (parse_lesson: scenes, keys and metrics
/// checked). Returns "" or the message of what is wrong (nothing is written then).
std::string save_lesson(const Lesson& lesson, const std::string& path);

}  // namespace sph::gui
