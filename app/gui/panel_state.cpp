// The state panel: the run's whole state to a checkpoint file and back (the format of `sph run
// --checkpoint-every`; a state loaded here steps on bitwise as the saved run would have).
#include <imgui.h>
#include <imgui_stdlib.h>

#include "panels.h"

namespace sph::gui {

void panel_state(GuiState& s) {
  ImGui::InputText("file##state", &s.state_path);
  if (ImGui::Button("Save state")) s.save_state(s.state_path);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Write the whole state (particles, neighbour lists, integrator history, counters) to the file:\n"
                      "a checkpoint as `sph run --checkpoint-every` writes");
  ImGui::SameLine();
  if (ImGui::Button("Load state") && !s.state_path.empty()) s.load_state(s.state_path);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Replace the run by the state in the file (saved here, or an OUT/checkpoint.sph of `sph run`)");
}

}  // namespace sph::gui
