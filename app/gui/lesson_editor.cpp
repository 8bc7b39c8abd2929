// The lesson editor's logic (lesson_editor.h), free of ImGui so the tests can drive it.
#include "lesson_editor.h"

#include <nlohmann/json.hpp>

#include "sph/atomic_file.h"

namespace sph::gui {
namespace {

/// A parameter's value as RunConfig::set takes it: strings as they are, numbers in their exact text.
std::string value_text(const nlohmann::ordered_json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "on" : "off";
  if (v.is_number()) return lesson_number(v.get<double>());
  return v.dump();
}

}  // namespace

LessonSets changed_sets(const RunConfig& cfg) {
  LessonSets out;
  if (cfg.scene == nullptr) return out;
  const nlohmann::ordered_json now = nlohmann::ordered_json::parse(cfg.to_json())["params"];
  RunConfig base = cfg.source_file.empty() ? RunConfig::from_scene(cfg.scene->name) : RunConfig::load(cfg.source_file);
  const nlohmann::ordered_json was = nlohmann::ordered_json::parse(base.to_json())["params"];
  for (auto it = now.begin(); it != now.end(); ++it)
    if (!was.contains(it.key()) || was[it.key()] != it.value()) out.emplace_back(it.key(), value_text(it.value()));
  return out;
}

LessonView recorded_view(const render::ViewSettings& v) {
  LessonView out;
  out.color_by = v.color_by;
  out.panels = v.panels;
  out.log = v.log_scale ? 1 : 0;
  out.profile_axis = std::string(v.profile_axis == 0 ? "x" : v.profile_axis == 1 ? "y" : v.profile_axis == 3 ? "r" : "off");
  if (!v.auto_range) out.range = std::make_pair(double(v.range_min), double(v.range_max));
  if (!v.camera2d.fit) out.zoom = std::array<double, 3>{v.camera2d.center_x, v.camera2d.center_y, v.camera2d.zoom};
  if (v.cut_axis >= 0 && v.cut_axis < 3) {
    out.cut_axis = v.cut_axis;
    out.cut_at = v.cut_at;
  }
  out.residuals = v.residuals ? 1 : 0;
  return out;
}

LessonStep record_step(const RunConfig& cfg, const render::ViewSettings& view, double t, const StepDraft& d) {
  LessonStep st;
  st.title = d.title;
  st.text = d.text;
  st.predict = d.predict;
  st.answer = d.answer;
  st.scene = cfg.source_file.empty() && cfg.scene ? cfg.scene->name : cfg.source_file;
  st.sets = changed_sets(cfg);
  st.view = recorded_view(view);
  st.check.type = d.above ? LessonCheck::Type::Above : LessonCheck::Type::Below;
  st.check.metric = d.metric;
  st.check.limit = d.limit;
  if (t > 0.0) st.check.until = t;
  return st;
}

std::string save_lesson(const Lesson& lesson, const std::string& path) {
  const std::string text = lesson_json(lesson);
  try {
    parse_lesson(text, path);  // what sph lesson check and the panel will read
  } catch (const LessonError& e) {
    return e.what();
  }
  return write_file_atomic(path, text);
}

}  // namespace sph::gui
