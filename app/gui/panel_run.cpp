// Run controls: play/pause, single step, reset (which applies the structural edits), pacing (as fast
// as possible or a real-time factor), stop at t_end, screenshot and PNG-sequence recording, and the
// scrub slider over the stored frames while paused.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "panels.h"
#include "ui_flow.h"

namespace sph::gui {
namespace {

/// Pause and scrub: while paused, a slider (and Left / Right) over the stored frames; view-only, Play
/// returns to the live run. Running, the row stays, greyed: the panel does not move by a row when a run
/// stops (a click meant for visc.beta landed on visc.alpha).
void scrub_slider(GuiState& s) {
  const StepperFrame* f = s.frame();
  const int n = static_cast<int>(s.ring.size());
  if (!f || f->running || n < 2) {
    ImGui::BeginDisabled();
    int none = 0;
    ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 4.f);
    ImGui::SliderInt("scrub", &none, 0, 1, f && f->running ? "(pause to look back)" : "(no frames yet)");
    ImGui::EndDisabled();
    return;
  }
  int k = s.scrub < 0 ? n - 1 : s.scrub;
  if (!ImGui::GetIO().WantTextInput)
    for (int key : s.key_presses) {
      if (key == GLFW_KEY_LEFT) k = std::max(0, k - 1);
      if (key == GLFW_KEY_RIGHT) k = std::min(n - 1, k + 1);
    }
  const StepperFrame& at = s.ring.at(static_cast<std::size_t>(k));
  char label[96];
  std::snprintf(label, sizeof label, "t = %.5g (%d/%d)%s", at.snapshot.t, k + 1, n, k == n - 1 ? " live" : "");
  ImGui::SetNextItemWidth(-ImGui::GetFontSize() * 4.f);
  ImGui::SliderInt("scrub", &k, 0, n - 1, label);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The last %d frames shown (at most %zu): drag or Left / Right to look back; view only.\n"
                      "Play returns to the live run.", n, SnapshotRing::kMaxFrames);
  s.scrub = k == n - 1 ? -1 : k;
}

/// Keyboard shortcuts (when no text field has the keyboard), from the key events of this frame in
/// order, so that quick taps are never lost. GLFW's letter keys are their upper-case ASCII codes.
void run_keys(GuiState& s, bool running) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  bool run = running;
  for (const int key : s.key_presses) {
    if (key == GLFW_KEY_SPACE) {
      run ? s.pause() : s.resume();
      run = !run;
    } else if (key == GLFW_KEY_S) {
      s.step_once();
      run = false;
    } else if (key == GLFW_KEY_R) {
      s.reset();
    }
  }
}

/// The screenshot button and the PNG-sequence recording with its settings (folder, interval, size).
void picture_controls(GuiState& s) {
  if (ImGui::Button("Screenshot")) s.requests.screenshot = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The whole window as a PNG in the working directory (F12)");
  ImGui::SameLine();
  if (!s.recording) {
    if (ImGui::Button("Record")) s.requests.start_recording = true;
  } else {
    ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.7f, 0.15f, 0.15f, 1.f));
    if (ImGui::Button("Stop recording")) s.requests.stop_recording = true;
    ImGui::PopStyleColor();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("PNG frames of the particle view at fixed simulated-time intervals:\n"
                      "DIR/frame_00000.png, ... (the same files as `sph run --frames`)");
  same_line_if_fits(item_width_of("recording settings") + ImGui::GetTreeNodeToLabelSpacing());
  if (!ImGui::TreeNode("recording settings")) return;
  if (s.recording) ImGui::BeginDisabled();
  ImGui::InputText("dir", &s.record_dir);
  ImGui::InputDouble("every", &s.record_every, 0.0, 0.0, "%.4g");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("simulated time between recorded frames [time units]");
  int size[2] = {s.record_width, s.record_height};
  if (ImGui::InputInt2("size", size)) {
    s.record_width = std::max(16, size[0] & ~1);
    s.record_height = std::max(16, size[1] & ~1);
  }
  if (s.recording) ImGui::EndDisabled();
  ImGui::TreePop();
}

}  // namespace

void panel_run(GuiState& s) {
  const StepperFrame* f = s.frame();
  const bool running = f && f->running;
  const float bw = (ImGui::GetContentRegionAvail().x - 2.f * ImGui::GetStyle().ItemSpacing.x) / 3.f;
  if (ImGui::Button(running ? "Pause" : "Play", ImVec2(bw, 0))) running ? s.pause() : s.resume();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Space (at t_end with 'stop at t_end': replay from t = 0)");
  ImGui::SameLine();
  if (ImGui::Button("Step", ImVec2(bw, 0))) s.step_once();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Pause and advance exactly one step (S)");
  ImGui::SameLine();
  const std::vector<std::string> pending = s.pending();
  if (!pending.empty()) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.65f, 0.40f, 0.08f, 1.f));
  if (ImGui::Button(pending.empty() ? "Reset" : "Reset*", ImVec2(bw, 0))) s.reset();
  if (!pending.empty()) ImGui::PopStyleColor();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Rebuild the scene at t = 0 with the current parameters and scene values (R)");
  for (const std::string& p : pending) ImGui::TextColored(ImVec4(1.f, 0.7f, 0.3f, 1.f), "needs reset: %s", p.c_str());
  run_keys(s, running);
  scrub_slider(s);
  bool realtime = s.real_time_factor > 0.0;
  if (ImGui::Checkbox("real time x", &realtime)) s.set_real_time_factor(realtime ? 0.1 : 0.0);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Pace the engine: simulated seconds per wall-clock second.\nOff: as fast as possible.");
  ImGui::SameLine();
  if (!realtime) ImGui::BeginDisabled();
  double rtf = realtime ? s.real_time_factor : 0.1;
  ImGui::SetNextItemWidth(-1.f);
  const double lo = 1e-4, hi = 10.0;
  if (ImGui::SliderScalar("##rtf", ImGuiDataType_Double, &rtf, &lo, &hi, "%.4g sim s / s",
                          ImGuiSliderFlags_Logarithmic) && realtime)
    s.set_real_time_factor(rtf);
  if (!realtime) ImGui::EndDisabled();
  bool stop = s.stop_at_end;
  if (ImGui::Checkbox("stop at t_end", &stop)) s.set_stop_at_end(stop);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Pause when t reaches the t_end parameter; Play there replays from t = 0.\n"
                      "Untick (or raise t_end) to run on.");

  picture_controls(s);
}

}  // namespace sph::gui
