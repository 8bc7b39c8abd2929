// Items placed side by side while they fit: at a large UI scale or in a narrow window the next item goes
// to a new line instead of running past the window's edge (where it was cut).
#pragma once
#include <imgui.h>

namespace sph::gui {

/// The width [px] of a button or tree node labelled `label`.
inline float item_width_of(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + 2.f * ImGui::GetStyle().FramePadding.x;
}

/// ImGui::SameLine() if an item `width` px wide fits after the last one, else nothing (a new line).
inline void same_line_if_fits(float width) {
  const float x = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (x + width <= right) ImGui::SameLine();
}

}  // namespace sph::gui
