// The help window: the text `sph help SCENE` prints (sph/help_text.h, one source for both programs), for
// the scene on screen with the parameters and scene values being edited. F1 or H opens and closes it.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include "panels.h"
#include "sph/help_text.h"

namespace sph::gui {

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
  if (ImGui::Begin("Help: the scene, its stages and parameters  (F1)", &h.open, ImGuiWindowFlags_HorizontalScrollbar))
    ImGui::TextUnformatted(h.text.c_str());
  ImGui::End();
}

}  // namespace sph::gui
