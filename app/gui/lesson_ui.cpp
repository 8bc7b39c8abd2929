#include "lesson_ui.h"

#include <algorithm>
#include <filesystem>

#include "profile_axis.h"
#include "sph/lesson_check.h"

namespace sph::gui {

std::vector<std::string> lesson_files() {
  std::vector<std::string> out;
  for (const std::filesystem::path& dir : {std::filesystem::path("assets/lessons"),
                                          std::filesystem::path(SPH_SOURCE_DIR) / "assets" / "lessons"}) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) continue;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
      if (e.path().extension() == ".json") out.push_back(e.path().string());
    if (!out.empty()) break;  // the working directory's copy first
  }
  std::sort(out.begin(), out.end());
  return out;
}

RunConfig step_config(const LessonStep& step) {
  const LessonCheck& k = step.check;
  if (k.type == LessonCheck::Type::Compare) return lesson_config(step, k.a);
  if (k.type == LessonCheck::Type::Falls) return lesson_config(step, {{k.key, lesson_number(k.values.front())}});
  return lesson_config(step, {});
}

void apply_step_view(const LessonView& step, render::ViewSettings& view) {
  if (!step.color_by.empty()) view.color_by = step.color_by;
  if (step.panels) view.panels = *step.panels;
  if (step.log >= 0) view.log_scale = step.log == 1;
  if (const auto axis = render::parse_profile_axis(step.profile_axis)) view.profile_axis = *axis;
  if (step.range) {
    view.auto_range = false;
    view.range_min = static_cast<float>(step.range->first);
    view.range_max = static_cast<float>(step.range->second);
  }
  if (step.zoom) {
    view.camera2d.fit = false;
    view.camera2d.center_x = static_cast<float>((*step.zoom)[0]);
    view.camera2d.center_y = static_cast<float>((*step.zoom)[1]);
    view.camera2d.zoom = static_cast<float>((*step.zoom)[2]);
  }
  if (step.cut_axis >= 0) {
    view.cut_axis = step.cut_axis;
    view.cut_at = static_cast<float>(step.cut_at);
  }
  if (step.residuals >= 0) view.residuals = step.residuals == 1;
}

std::vector<std::string> step_compare(const LessonStep& step) {
  std::vector<std::string> out;
  if (step.check.type != LessonCheck::Type::Compare) return out;
  for (const auto& [key, value] : step.check.b) out.push_back(key + "=" + value);
  return out;
}

}  // namespace sph::gui
