// The fixed tiling of ImGui windows (see layout.h): controls column, diagnostics, kernel explorer,
// status line, and the divergence dialog over them.
#include <imgui.h>

#include "panels.h"

namespace sph::gui {
namespace {

void place(const Rect& r) {
  ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
}

}  // namespace

void draw_panels(GuiState& s, const Layout& L, const FrameStats& stats) {
  // The tiled windows draw no background of their own: the window is cleared to the panel colour before
  // ImGui draws (a software rasteriser pays per textured pixel; a clear is nearly free).
  constexpr ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground;
  place(L.controls);
  if (ImGui::Begin("SPH sandbox", nullptr, fixed)) {
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 7.5f);
    if (ImGui::CollapsingHeader("Lesson", s.lesson.lesson ? ImGuiTreeNodeFlags_DefaultOpen : 0)) panel_lesson(s);
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) panel_scene(s);
    if (ImGui::CollapsingHeader("Run", ImGuiTreeNodeFlags_DefaultOpen)) panel_run(s);
    const bool params = ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen);
    const float y = ImGui::GetItemRectMin().y - ImGui::GetWindowPos().y + ImGui::GetScrollY();
    (s.frame() && s.frame()->running ? s.params_row.running : s.params_row.stopped) = y;
    if (params) panel_params(s);
    if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) panel_display(s);
    if (ImGui::CollapsingHeader("Compare (A/B)")) panel_compare(s);
    if (ImGui::CollapsingHeader("Sweep (overlays)")) panel_sweep(s);
    if (ImGui::CollapsingHeader("State (checkpoint)")) panel_state(s);
    if (ImGui::CollapsingHeader("Convergence study")) panel_converge(s);
    ImGui::PopItemWidth();
  }
  ImGui::End();
  place(L.diagnostics);
  if (ImGui::Begin("Diagnostics", nullptr, fixed)) panel_diagnostics(s);
  ImGui::End();
  if (L.kernel.w > 0.f) {  // not shown where the text is too large for it beside the diagnostics
    place(L.kernel);
    if (ImGui::Begin("Kernel explorer", nullptr, fixed)) panel_kernel(s);
    ImGui::End();
  }
  place(L.status);
  if (ImGui::Begin("##status", nullptr, fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar))
    status_line(s, stats);
  ImGui::End();
  if (L.inspector.w > 0.f) {
    place(L.inspector);
    if (ImGui::Begin("Particle inspector", nullptr, fixed)) panel_inspector(s);
    ImGui::End();
  }
  panel_help(s);
  divergence_modal(s);
}

}  // namespace sph::gui
