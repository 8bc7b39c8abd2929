// Scene picker: every built-in scene, or a JSON scene file; then the scene's own values (particle
// counts, initial states), which need a rebuild: edited here, applied by Reset.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "panels.h"
#include "ui_flow.h"
#include "param_help.h"
#include "scene_text.h"

namespace sph::gui {
namespace {

/// The scene picker, as wide as the scene's name needs; its label only where the line has room.
void scene_combo(GuiState& s, const SceneSpec* current) {
  const std::string preview = current ? current->name + "  (" + std::to_string(current->dim) + "D)" : "(loading)";
  const ImGuiStyle& st = ImGui::GetStyle();
  const float need = ImGui::CalcTextSize(preview.c_str()).x + 2.f * st.FramePadding.x + ImGui::GetFrameHeight();
  const float rest = item_width_of("scene") + item_width_of("Help") + 2.f * st.ItemSpacing.x;
  ImGui::SetNextItemWidth(std::min(std::max(need, ImGui::CalcItemWidth()), ImGui::GetContentRegionAvail().x));
  const bool label_fits = ImGui::GetContentRegionAvail().x >= std::max(need, ImGui::CalcItemWidth()) + rest;
  if (ImGui::BeginCombo(label_fits ? "scene" : "##scene", preview.c_str())) {
    for (const SceneSpec& spec : scene_registry()) {
      const std::string item = spec.name + "  (" + std::to_string(spec.dim) + "D)";
      if (ImGui::Selectable(item.c_str(), &spec == current)) {
        s.load(RunConfig::from_scene(spec.name));
        s.notify("loading " + spec.name);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n%s", spec.category.c_str(), spec.description.c_str());
    }
    ImGui::EndCombo();
  }
}

/// The scene file field beside its button where the hint fits in it, else a line of its own.
void file_row(GuiState& s) {
  std::string hint = scene_file_hint(s.scene_name());
  const float button = item_width_of("Open file"), spacing = ImGui::GetStyle().ItemSpacing.x;
  const float beside = ImGui::GetContentRegionAvail().x - button - spacing;
  const bool one_line = ImGui::CalcTextSize(hint.c_str()).x + 2.f * ImGui::GetStyle().FramePadding.x <= beside;
  const float field = one_line ? beside : ImGui::GetContentRegionAvail().x;
  if (ImGui::CalcTextSize(hint.c_str()).x + 2.f * ImGui::GetStyle().FramePadding.x > field)
    hint = std::filesystem::path(hint).filename().string();  // the path does not fit: its file name
  ImGui::SetNextItemWidth(field);
  ImGui::InputTextWithHint("##file", hint.c_str(), &s.file_path);
  if (one_line) ImGui::SameLine();
  if (ImGui::Button("Open file") && !s.file_path.empty()) s.open_file(s.file_path);
}

}  // namespace

void panel_scene(GuiState& s) {
  const StepperFrame* f = s.frame();
  const SceneSpec* current = f ? f->config.scene : nullptr;
  scene_combo(s, current);
  same_line_if_fits(item_width_of("Help"));
  if (ImGui::SmallButton("Help")) s.help.open = !s.help.open;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("The scene's stages, every parameter (unit, range, default, seed equation),\n"
                                                "its reference and error norms: what `sph help SCENE` prints (F1 or H)");
  if (current) {
    ImGui::PushTextWrapPos(0.f);
    ImGui::TextDisabled("%s: %s", current->category.c_str(), describe_scene(*current, f->config.values).c_str());
    ImGui::PopTextWrapPos();
  }
  file_row(s);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("A JSON scene file: {\"scene\": NAME, \"params\": {key: value, ...}},\n"
                                                "or an HDF5 initial condition in the SWIFT/GADGET layout (.hdf5)");
  if (s.recent && !s.recent->files().empty()) {
    if (ImGui::BeginCombo("recent", "(recent files)")) {
      const std::vector<std::string> files = s.recent->files();  // a copy: opening one reorders the list
      for (const std::string& path : files)
        if (ImGui::Selectable(path.c_str())) {
          s.file_path = path;
          s.open_file(path);
        }
      ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Scene files opened before (kept in %s)", s.recent->file().c_str());
  }
  if (s.message_is_error && !s.message.empty()) {
    ImGui::PushTextWrapPos(0.f);
    ImGui::TextColored(ImVec4(1.f, 0.45f, 0.45f, 1.f), "%s", s.message.c_str());
    ImGui::PopTextWrapPos();
  }

  if (!current || current->params.empty()) return;
  const std::size_t changed = std::count_if(s.values.begin(), s.values.end(), [&](const auto& kv) {
    const auto it = f->config.values.find(kv.first);
    return it == f->config.values.end() || it->second != kv.second;
  });
  const std::string title = "scene values (needs reset)" + (changed ? "  " + std::to_string(changed) + " changed" : "");
  if (!ImGui::TreeNodeEx("scene values", changed ? ImGuiTreeNodeFlags_DefaultOpen : 0, "%s", title.c_str())) return;
  for (const SceneParam& sp : current->params) {
    auto it = s.values.find(sp.name);
    if (it == s.values.end()) continue;
    const auto applied = f->config.values.find(sp.name);
    const bool pending = applied == f->config.values.end() || applied->second != it->second;
    if (pending) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.45f, 0.30f, 0.08f, 1.f));
    double v = it->second;
    const std::string label = sp.name + (pending ? "  (reset!)" : "");
    if (ImGui::InputDouble(label.c_str(), &v, 0.0, 0.0, sp.integer ? "%.0f" : "%.6g",
                           ImGuiInputTextFlags_EnterReturnsTrue)) {
      if (sp.integer) v = std::round(v);
      it->second = std::min(sp.max, std::max(sp.min, v));
    }
    if (pending) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", scene_value_help(sp).c_str());
  }
  ImGui::TreePop();
}

}  // namespace sph::gui
