// When the engine finds a NaN or inf it pauses; this dialog says which particle and step, suggests what
// to change, and offers a reset (or keeping the broken state on screen to look at it, or saving it).
#include <imgui.h>

#include <algorithm>

#include "panels.h"
#include "ui_flow.h"

namespace sph::gui {

void divergence_modal(GuiState& s) {
  const StepperFrame* f = s.frame();
  const char* title = "The simulation diverged";
  if (f && f->diverged && s.acknowledged_divergence != f->world_serial && !ImGui::IsPopupOpen(title))
    ImGui::OpenPopup(title);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  if (f == nullptr || !f->diverged) {  // reset from elsewhere (R key, scene picker): nothing to say
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  // lines of 34 characters' width, or narrower where the window is (3x text on 1280 px ran past its edge)
  const float fs = ImGui::GetFontSize();
  ImGui::PushTextWrapPos(std::min(fs * 34.f, ImGui::GetMainViewport()->Size.x - 4.f * fs));
  ImGui::TextUnformatted(f->error.c_str());
  if (f->diverged_particle >= 0)
    ImGui::Text("particle %lld, step %lld, t = %.6g", static_cast<long long>(f->diverged_particle),
                static_cast<long long>(f->diverged_step), f->snapshot.t);
  else
    ImGui::Text("step %lld, t = %.6g", static_cast<long long>(f->diverged_step), f->snapshot.t);
  ImGui::TextDisabled("The engine is paused. Try a smaller dt or cfl, more viscosity (alpha, beta), or another "
                      "integrator, then reset.");
  if (!f->notice.empty()) ImGui::TextDisabled("%s", f->notice.c_str());
  ImGui::PopTextWrapPos();
  if (ImGui::Button("Reset and run")) {
    s.reset();
    s.resume();
    s.acknowledged_divergence = f->world_serial;
    ImGui::CloseCurrentPopup();
  }
  same_line_if_fits(item_width_of("Save state"));
  if (ImGui::Button("Save state")) s.save_state(s.state_path);  // the broken state, to look at later
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Write the state as it is now to %s (a checkpoint; the State panel "
                                                "loads it)", s.state_path.c_str());
  same_line_if_fits(item_width_of("Keep paused"));
  if (ImGui::Button("Keep paused")) {
    s.acknowledged_divergence = f->world_serial;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace sph::gui
