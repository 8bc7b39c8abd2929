// The Lesson panel's editor ("Record a step"): the run on screen, its view and a claim on one of its
// metrics become a step of a lesson being written, saved as a lesson file (lesson_editor.h).
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>

#include "frame_scene.h"
#include "lesson_editor.h"
#include "panels.h"
#include "sph/lesson_check.h"

namespace sph::gui {
namespace {

/// The metrics a claim can name on this frame: its reference's columns, then the extra metrics.
std::vector<std::string> metric_choices(const StepperFrame& f) {
  std::vector<std::string> out;
  for (const RefColumn& c : f.ref_columns) out.push_back(c.name);
  for (const std::string& m : extra_metrics()) out.push_back(m);
  return out;
}

/// The metric's value on this frame, if the frame has it (reference columns only); NaN otherwise.
double value_now(const StepperFrame& f, const std::string& metric) {
  for (std::size_t k = 0; k < f.ref_columns.size() && k < f.ref_values.size(); ++k)
    if (f.ref_columns[k].name == metric) return f.ref_values[k];
  return std::nan("");
}

}  // namespace

void lesson_editor(GuiState& s) {
  const StepperFrame* f = s.frame();
  if (f == nullptr || f->config.scene == nullptr) return;
  LessonUi& L = s.lesson;
  StepDraft& d = L.draft;
  ImGui::PushItemWidth(-ImGui::CalcTextSize("question  ").x);
  ImGui::InputText("title", &d.title);
  ImGui::InputTextMultiline("text", &d.text, ImVec2(-ImGui::CalcTextSize("question  ").x, 3.5f * ImGui::GetTextLineHeight()));
  ImGui::InputText("question", &d.predict);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Optional: a question to answer before running (\"predict first\")");
  ImGui::InputText("answer", &d.answer);
  const std::vector<std::string> metrics = metric_choices(*f);
  if (d.metric.empty() && !metrics.empty()) d.metric = metrics.front();
  if (ImGui::BeginCombo("metric", d.metric.c_str())) {
    for (const std::string& m : metrics)
      if (ImGui::Selectable(m.c_str(), m == d.metric)) d.metric = m;
    ImGui::EndCombo();
  }
  int kind = d.above ? 1 : 0;
  ImGui::RadioButton("below", &kind, 0);
  ImGui::SameLine();
  ImGui::RadioButton("above", &kind, 1);
  d.above = kind == 1;
  ImGui::SameLine();
  ImGui::InputDouble("##limit", &d.limit, 0.0, 0.0, "%.4g");
  const double now = value_now(*f, d.metric);
  if (std::isfinite(now)) {
    ImGui::SameLine();
    if (ImGui::SmallButton("now x1.5")) d.limit = d.above ? now / 1.5 : now * 1.5;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s = %.4g now: a limit with a margin of 1.5", d.metric.c_str(), now);
  }
  ImGui::PopItemWidth();
  ImGui::BeginDisabled(d.title.empty() || d.metric.empty());
  if (ImGui::Button("Add this run as a step")) {
    L.recorded.steps.push_back(record_step(f->config, s.view, f->snapshot.t, d));
    if (!f->sweep.empty()) {  // the sweep on screen: its key and values
      LessonStep& st = L.recorded.steps.back();
      st.sweep_key = f->sweep_key;
      for (const CompareFrame& r : f->sweep)
        if (!r.overrides.empty()) st.sweep_values.push_back(render::value_of_label(r.overrides.front()));
    }
    L.editor_message = "step " + std::to_string(L.recorded.steps.size()) + " recorded at t = " + lesson_number(f->snapshot.t);
  }
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("The scene, the parameters changed from its defaults, the view and the claim at the run's time");
  ImGui::InputText("file", &L.save_path);
  ImGui::BeginDisabled(L.recorded.steps.empty());
  if (ImGui::Button("Save the lesson")) {
    if (L.recorded.title.empty()) L.recorded.title = L.recorded.steps.front().title;
    const std::string err = save_lesson(L.recorded, L.save_path);
    L.editor_message = err.empty() ? "saved " + std::to_string(L.recorded.steps.size()) + " steps to " + L.save_path : err;
    if (err.empty()) L.files.clear();  // listed again, with the new file
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Clear")) L.recorded.steps.clear();
  if (!L.editor_message.empty()) {
    ImGui::PushTextWrapPos(0.f);
    ImGui::TextUnformatted(L.editor_message.c_str());
    ImGui::PopTextWrapPos();
  }
}

}  // namespace sph::gui
