// What the particle view shows: colour by one of the snapshot's fields (only the fields the scene's
// modules allocate), the colour map, an automatic or fixed range, particle size, and the camera.
#include <imgui.h>

#include <algorithm>
#include <string_view>

#include "colormap.h"
#include "panels.h"

namespace sph::gui {

void panel_display(GuiState& s) {
  const StepperFrame* f = s.frame();
  render::ViewSettings& v = s.view;
  if (f == nullptr) return;
  const Snapshot& snap = f->snapshot;
  const SnapshotField* shown = snap.find(v.color_by);
  if (ImGui::BeginCombo(snap.dim == 1 ? "plot / colour" : "colour by", shown ? shown->label.c_str() : v.color_by.c_str())) {
    for (const SnapshotField& fld : snap.fields)
      if (ImGui::Selectable(fld.label.c_str(), fld.name == v.color_by)) v.color_by = fld.name;
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Fields this scene's physics modules allocate (1D: also the y axis)");
  if (ImGui::BeginCombo("colour map", v.cmap.c_str())) {
    for (std::string_view name : render::colormap_names())
      if (ImGui::Selectable(std::string(name).c_str(), name == v.cmap)) v.cmap = std::string(name);
    ImGui::EndCombo();
  }
  if (ImGui::Checkbox("auto range", &v.auto_range) && !v.auto_range && shown) {
    v.range_min = shown->min;  // start the fixed range from what is shown now
    v.range_max = shown->max;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("On: every frame uses the field's min..max. Off: a fixed range.");
  if (!v.auto_range) {
    float r[2] = {v.range_min, v.range_max};
    if (ImGui::InputFloat2("range", r, "%.4g", ImGuiInputTextFlags_EnterReturnsTrue) && r[1] > r[0]) {
      v.range_min = r[0];
      v.range_max = r[1];
    }
  }
  if (snap.dim == 1) {
    if (!snap.exact.empty()) ImGui::Checkbox("exact solution", &v.show_exact);
    ImGui::SliderFloat("dot size", &v.point_px, 1.f, 8.f, "%.1f px");
  } else {
    bool by_h = v.size_mode == render::SizeMode::Smoothing;
    if (ImGui::Checkbox("size from h", &by_h))
      v.size_mode = by_h ? render::SizeMode::Smoothing : render::SizeMode::Pixels;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.f);
    if (by_h)
      ImGui::SliderFloat("##hs", &v.h_scale, 0.05f, 2.f, "radius %.2f h");
    else
      ImGui::SliderFloat("##px", &v.point_px, 0.5f, 10.f, "radius %.1f px");
    if (ImGui::Button("Fit view")) {
      v.camera2d = render::Camera2D{};
      v.orbit = render::OrbitCamera{};
    }
    ImGui::SameLine();
    ImGui::TextDisabled(snap.dim == 2 ? "drag: pan, wheel: zoom" : "drag: orbit, wheel: zoom");
  }
  ImGui::SliderInt("text size", &v.text_scale, 0, 4, v.text_scale == 0 ? "auto" : "%d x");
}

}  // namespace sph::gui
