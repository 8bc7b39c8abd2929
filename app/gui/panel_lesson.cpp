// The lesson panel: a lesson file's steps one at a time (text, what to change, what to look at, the
// claim), previous/next (buttons, Page Up / Page Down) loading each step's scene, and the step's check run
// beside the engine with its measured numbers in green (true) or red (false).
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "lesson_job.h"
#include "panels.h"
#include "ui_flow.h"

namespace sph::gui {

bool open_lesson(GuiState& s, const std::string& path, int step) {
  LessonUi& L = s.lesson;
  try {
    Lesson lesson = load_lesson(path);
    L.lesson = std::move(lesson);
    L.path = path;
    L.error.clear();
  } catch (const LessonError& e) {
    L.error = e.what();
    s.notify(e.what(), true);
    return false;
  }
  show_lesson_step(s, std::clamp(step, 0, static_cast<int>(L.lesson->steps.size()) - 1));
  return true;
}

void show_lesson_step(GuiState& s, int step) {
  LessonUi& L = s.lesson;
  if (!L.lesson) return;
  L.step = step;
  const LessonStep& st = L.lesson->steps[static_cast<std::size_t>(step)];
  try {
    s.load(step_config(st));
    s.set_compare(step_compare(st));  // empty: no comparison
    s.set_sweep(st.sweep_key, st.sweep_values);  // no values: no sweep
    s.set_pause_at(st.pause_at);      // <= 0: none
    apply_step_view(st.view, s.view);  // what the step's text asks to look at
    L.answer_shown = false;
    s.notify("lesson step " + std::to_string(step + 1) + ": " + st.title);
  } catch (const std::exception& e) {
    s.notify(e.what(), true);
  }
}

void check_lesson_step(GuiState& s) {
  LessonUi& L = s.lesson;
  if (!L.lesson) return;
  if (L.job && L.job->poll()) return;  // a check is running (replacing it would wait for it)
  L.job = std::make_shared<LessonJob>(L.lesson->steps[static_cast<std::size_t>(L.step)]);
  L.job_step = L.step;
}

namespace {

/// The step's "predict first" question, its answer hidden until the button or key A shows it.
void predict_first(const LessonStep& st, LessonUi& L) {
  if (st.predict.empty()) return;
  ImGui::TextColored(ImVec4(0.6f, 0.95f, 0.8f, 1.f), "Predict first: %s", st.predict.c_str());
  if (L.answer_shown) {
    ImGui::TextColored(ImVec4(0.6f, 0.95f, 0.8f, 1.f), "Answer: %s", st.answer.c_str());
  } else if (ImGui::SmallButton("Show the answer (A)")) {
    L.answer_shown = true;
  }
}

/// The step's check: running, failed to run, or its result in green (true) or red (false).
void check_result(const LessonUi& L, bool running) {
  if (!L.job) return;
  if (running && L.job_step != L.step) ImGui::TextColored(ImVec4(1.f, 0.8f, 0.35f, 1.f), "checking step %d ...", L.job_step + 1);
  if (L.job_step != L.step) return;
  ImGui::PushTextWrapPos(0.f);
  if (running) {
    ImGui::TextColored(ImVec4(1.f, 0.8f, 0.35f, 1.f), "checking ...");
  } else if (!L.job->error().empty()) {
    ImGui::TextColored(ImVec4(1.f, 0.45f, 0.45f, 1.f), "check failed to run: %s", L.job->error().c_str());
  } else if (const auto& r = L.job->result()) {
    if (r->pass) ImGui::TextColored(ImVec4(0.45f, 0.95f, 0.45f, 1.f), "true: %s", r->text.c_str());
    else ImGui::TextColored(ImVec4(1.f, 0.4f, 0.4f, 1.f), "FALSE: %s", r->text.c_str());
  }
  ImGui::PopTextWrapPos();
}

/// The lesson editor, folded away until opened.
void editor_section(GuiState& s) {
  ImGui::Separator();
  if (ImGui::CollapsingHeader("Record a step (lesson editor)")) lesson_editor(s);
}

}  // namespace

void panel_lesson(GuiState& s) {
  LessonUi& L = s.lesson;
  if (L.files.empty()) L.files = lesson_files();
  const std::string preview = L.lesson ? std::filesystem::path(L.path).filename().string() : "(choose a lesson)";
  if (ImGui::BeginCombo("lesson", preview.c_str())) {
    for (const std::string& f : L.files)
      if (ImGui::Selectable(std::filesystem::path(f).filename().string().c_str(), f == L.path)) open_lesson(s, f, 0);
    ImGui::EndCombo();
  }
  if (!L.error.empty()) {
    ImGui::PushTextWrapPos(0.f);
    ImGui::TextColored(ImVec4(1.f, 0.45f, 0.45f, 1.f), "%s", L.error.c_str());
    ImGui::PopTextWrapPos();
  }
  if (!L.lesson) {
    editor_section(s);
    return;
  }
  const int n = static_cast<int>(L.lesson->steps.size());
  if (!ImGui::GetIO().WantTextInput)
    for (int key : s.key_presses) {
      if (key == GLFW_KEY_PAGE_DOWN && L.step + 1 < n) show_lesson_step(s, L.step + 1);
      if (key == GLFW_KEY_PAGE_UP && L.step > 0) show_lesson_step(s, L.step - 1);
      if (key == GLFW_KEY_A) L.answer_shown = !L.answer_shown;
    }
  const LessonStep& st = L.lesson->steps[static_cast<std::size_t>(L.step)];
  ImGui::PushTextWrapPos(0.f);
  ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.f, 1.f), "%s", L.lesson->title.c_str());
  ImGui::Text("Step %d/%d: %s", L.step + 1, n, st.title.c_str());
  ImGui::TextUnformatted(st.text.c_str());
  predict_first(st, L);
  if (!st.change.empty()) ImGui::Text("Change: %s", st.change.c_str());
  if (!st.look_at.empty()) ImGui::Text("Look at: %s", st.look_at.c_str());
  ImGui::SetWindowFontScale(1.15f);  // the claim is what the step is about: larger, and in colour
  ImGui::TextColored(ImVec4(1.f, 0.85f, 0.4f, 1.f), "Claim: %s", claim_text(st).c_str());
  ImGui::SetWindowFontScale(1.f);
  ImGui::PopTextWrapPos();

  ImGui::BeginDisabled(L.step == 0);
  if (ImGui::Button("< Previous")) show_lesson_step(s, L.step - 1);
  ImGui::EndDisabled();
  same_line_if_fits(item_width_of("Next >"));
  ImGui::BeginDisabled(L.step + 1 >= n);
  if (ImGui::Button("Next >")) show_lesson_step(s, L.step + 1);
  ImGui::EndDisabled();
  same_line_if_fits(item_width_of("Load again"));
  if (ImGui::Button("Load again")) show_lesson_step(s, L.step);
  same_line_if_fits(item_width_of("Check"));
  const bool running = L.job && L.job->poll();
  ImGui::BeginDisabled(running);
  if (ImGui::Button("Check")) check_lesson_step(s);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Run the claim headless, beside the engine (what `sph lesson check` does for this step)");

  check_result(L, running);
  editor_section(s);
}

}  // namespace sph::gui
