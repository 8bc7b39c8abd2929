// Compare (A/B): run B is this run with some parameters changed (key=value, as `sph run --compare-set`:
// the kernel, eta, alpha, the formulation, the integrator, a particle count...). Starting restarts both
// from t = 0, stepped together to the same times on the engine thread; the view shows both (profiles in
// two colours with each run's L1, 2D side by side with the difference map) and the diagnostics both
// runs' energies and errors.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <cstdio>

#include "diag_text.h"
#include "frame_scene.h"
#include "panels.h"
#include "sph/compare.h"
#include "overrides_text.h"

namespace sph::gui {
namespace {

ImVec4 colour_of(int run) {
  const render::Rgba c = render::kRunColors[run];
  return ImVec4(c.r, c.g, c.b, 1.f);
}

/// A quick choice: puts `overrides` in the field.
void preset(GuiState& s, const char* label, const std::string& overrides, const char* tip) {
  if (ImGui::SmallButton(label)) s.compare_text = overrides;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  ImGui::SameLine();
}

/// The scene's resolution key (its convergence study's), doubled: "scene.n_left=800".
std::string doubled_resolution(const StepperFrame& f) {
  const SceneSpec* scene = f.config.scene;
  if (scene == nullptr || scene->convergence.key.rfind("scene.", 0) != 0) return {};
  const auto it = f.config.values.find(scene->convergence.key.substr(6));
  if (it == f.config.values.end()) return {};
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s=%g", scene->convergence.key.c_str(), 2.0 * it->second);
  return buf;
}

}  // namespace

void panel_compare(GuiState& s) {
  const StepperFrame* f = s.frame();
  if (f == nullptr) return;
  ImGui::TextWrapped("Run B = this run with (key=value, comma-separated):");
  ImGui::SetNextItemWidth(-1.f);
  ImGui::InputText("##overrides", &s.compare_text);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Any --set key: kernel.type=M6, kernel.eta=1.5, visc.alpha=0, physics.force=standard,\n"
                      "time.integrator=rk4, scene.n_left=800 ... Both runs restart from t = 0.");
  preset(s, "M6", "kernel.type=M6", "the sixth-order B-spline against this run's kernel");
  preset(s, "alpha 0", "visc.alpha=0, visc.beta=0", "no artificial viscosity: the post-shock oscillations");
  preset(s, "RK4", "time.integrator=rk4", "fourth-order Runge-Kutta against this run's integrator");
  const std::string twice = doubled_resolution(*f);
  if (!twice.empty()) preset(s, "2N", twice, "twice the particles along the scene's resolution key");
  ImGui::NewLine();
  const std::vector<std::string> overrides = split_overrides(s.compare_text);
  ImGui::BeginDisabled(overrides.empty());
  if (ImGui::Button(f->comparing ? "Restart A/B" : "Compare")) s.set_compare(overrides);
  ImGui::EndDisabled();
  if (f->comparing) {
    ImGui::SameLine();
    if (ImGui::Button("Stop comparing")) s.set_compare({});
    const std::string a = compare_label(f->config, f->compare.overrides), b = compare_label(f->compare.config, f->compare.overrides);
    ImGui::TextColored(colour_of(0), "A: %s", a.c_str());
    ImGui::TextColored(colour_of(1), "B: %s", b.c_str());
    const int k = f->ref_primary;
    if (k >= 0 && static_cast<std::size_t>(k) < f->ref_values.size() &&
        static_cast<std::size_t>(k) < f->compare.ref_values.size())
      ImGui::Text("%s   A %s   B %s", f->ref_columns[static_cast<std::size_t>(k)].name.c_str(),
                  value_text(f->ref_values[static_cast<std::size_t>(k)], 4).c_str(),
                  value_text(f->compare.ref_values[static_cast<std::size_t>(k)], 4).c_str());
  }
}

}  // namespace sph::gui
