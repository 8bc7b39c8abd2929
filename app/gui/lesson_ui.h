// The lesson panel's state (GuiState::lesson): the open lesson, its step, and the step's check, running
// or done. Loading a step puts its scene and parameters on screen (a compare check: run A with the a
// sets, the A/B comparison with the b sets; a falls check: the first value).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sph/config.h"
#include "sph/lesson.h"
#include "lesson_editor.h"
#include "view_settings.h"

namespace sph::gui {

class LessonJob;

struct LessonUi {
  std::optional<Lesson> lesson;
  int step = 0;                     ///< index of the step shown
  std::string path;                 ///< the file field
  std::string error;                ///< why the last file could not be opened
  std::shared_ptr<LessonJob> job;   ///< the current step's check (null: not run)
  int job_step = -1;                ///< the step the job checks
  std::vector<std::string> files;   ///< lesson_files(), listed once
  bool answer_shown = false;        ///< the step's "predict first" answer is on screen (key A)
  StepDraft draft;                  ///< the editor's fields
  Lesson recorded;                  ///< the steps recorded so far
  std::string save_path = "my_lesson.json", editor_message;
};

/// The lesson files shipped beside the program: assets/lessons/*.json under the working directory and the
/// source tree, sorted by name.
std::vector<std::string> lesson_files();
/// The run a step starts on screen: its scene and sets, plus the check's first run's sets.
RunConfig step_config(const LessonStep& step);
/// The A/B overrides of a compare step ("key=value" of the b sets), empty for other checks.
std::vector<std::string> step_compare(const LessonStep& step);
/// Puts the step's view (colour-by, panels, log scale, profile axis, range, 2D centre and zoom, 3D cutaway,
/// error strip) into the viewer's settings; what the step leaves open stays as it was.
void apply_step_view(const LessonView& step, render::ViewSettings& view);

}  // namespace sph::gui
