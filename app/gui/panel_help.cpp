// The help window (F1 or H opens and closes it): every key and mouse action, then the text `sph help SCENE`
// prints (sph/help_text.h, one source for both programs) for the scene on screen with the parameters and
// scene values being edited.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include "panels.h"
#include "sph/help_text.h"

namespace sph::gui {
namespace {

/// Text line by line, each wrapped at the window's edge and its continuation under the line's own
/// indentation (the help's lines ran past the window, behind a horizontal scroll bar).
void wrapped_lines(const std::string& text) {
  const float space = ImGui::CalcTextSize(" ").x;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    const std::size_t lead = line.find_first_not_of(' ');
    if (lead == std::string::npos) {
      ImGui::NewLine();
    } else {
      const float indent = space * static_cast<float>(lead);
      if (indent > 0.f) ImGui::Indent(indent);
      ImGui::TextWrapped("%s", line.c_str() + lead);
      if (indent > 0.f) ImGui::Unindent(indent);
    }
    start = end + 1;
  }
}

/// Every key and mouse action of the window (README "The desktop program").
constexpr const char* kKeys[][2] = {
    {"Space", "play / pause (at t_end with 'stop at t_end': replay from t = 0)"},
    {"S", "one step"},
    {"R", "reset to t = 0 (applies the edits marked 'reset')"},
    {"F1, H", "this help"},
    {"F12", "screenshot of the window (PNG in the working directory)"},
    {"Ctrl+=, Ctrl+-", "projector mode: scale every panel's text and widgets (1x-3x)"},
    {"Ctrl+0", "UI scale back to 1x"},
    {"Ctrl+S", "save the state to the State panel's file (load it with --load-state or Load state)"},
    {"Page Down / Page Up", "next / previous lesson step (Lesson panel)"},
    {"A", "show / hide the lesson step's answer (its \"predict first\" question)"},
    {"Left / Right (paused)", "scrub back / forward through the last 240 frames (view only)"},
    {"left drag (2D)", "pan the view"},
    {"left drag (3D)", "orbit the camera"},
    {"right drag (2D plane)", "push: drag the fluid within R of the cursor along (circle; R, tau: Display)"},
    {"mouse wheel", "zoom the view"},
    {"left click on a particle", "open the particle inspector on it"},
    {"hover a particle", "its id and the coloured field's value"},
    {"hover a widget", "its unit, seed equation and stage"},
};

}  // namespace

void panel_help(GuiState& s) {
  const bool typing = ImGui::GetIO().WantTextInput;
  const int taps = static_cast<int>(std::count_if(s.key_presses.begin(), s.key_presses.end(), [&](int k) {
    return k == GLFW_KEY_F1 || (k == GLFW_KEY_H && !typing);
  }));
  if (taps % 2 == 1) s.help.open = !s.help.open;
  const StepperFrame* f = s.frame();
  if (!s.help.open || !f) return;
  GuiState::HelpView& h = s.help;
  if (h.scene != f->config.scene || !(h.params == s.edit) || h.values != s.values || h.text.empty()) {
    RunConfig cfg = f->config;  // the scene as the widgets show it
    cfg.params = s.edit;
    cfg.values = s.values;
    h.scene = f->config.scene;
    h.params = s.edit;
    h.values = s.values;
    h.text = scene_help(cfg);
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x * 0.55f, vp->Size.y * 0.75f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.4f, vp->Pos.y + vp->Size.y * 0.1f), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Help  (F1)", &h.open)) {  // a short title: the window is narrow at a projector's scale
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Keys, then the scene, its stages and parameters (sph help %s)",
                       h.scene ? h.scene->name.c_str() : "SCENE");
    ImGui::PopStyleColor();
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
      ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
      ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
      for (const auto& k : kKeys) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(k[0]);
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", k[1]);
      }
      ImGui::EndTable();
    }
    ImGui::Separator();
    wrapped_lines(h.text);  // `sph help`'s text, each line wrapped at the window's edge under its indent
  }
  ImGui::End();
}

}  // namespace sph::gui
