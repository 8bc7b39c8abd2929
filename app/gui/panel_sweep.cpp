// Sweep: run A beside up to five more runs that differ from it in one key (kernel.eta = 1.0, 1.5 beside
// A's 1.2), started from t = 0 and stepped together on the engine thread. The profiles draw every run
// over the others in its own colour, each with its L1 error in the legend (2D and 3D scenes in their x,
// y or r profile views).
#include <imgui.h>
#include <imgui_stdlib.h>

#include "diag_text.h"
#include "frame_scene.h"
#include "overrides_text.h"
#include "panels.h"
#include "sph/compare.h"

namespace sph::gui {
namespace {

ImVec4 colour_of(std::size_t run) {
  const render::Rgba c = render::kRunColors[run % render::kRunColorCount];
  return ImVec4(c.r, c.g, c.b, 1.f);
}

/// The line of run `run` (0 = A): its key=value and its primary reference value.
void run_row(const StepperFrame& f, std::size_t run, const std::string& label, const std::vector<double>& values) {
  const int k = f.ref_primary;
  std::string err;
  if (k >= 0 && static_cast<std::size_t>(k) < values.size())
    err = "   " + f.ref_columns[static_cast<std::size_t>(k)].name + " " + value_text(values[static_cast<std::size_t>(k)], 4);
  const std::string name = run == 0 ? render::mark_run_a(label) : label;
  ImGui::TextColored(colour_of(run), "%s%s", name.c_str(), err.c_str());
}

}  // namespace

void panel_sweep(GuiState& s) {
  const StepperFrame* f = s.frame();
  if (f == nullptr) return;
  ImGui::TextWrapped("Run A beside one more run for each value of a key (at most 5):");
  ImGui::SetNextItemWidth(-1.f);
  ImGui::InputText("##sweep_key", &s.sweep_key);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Any --set key: kernel.eta, visc.alpha, time.cfl, scene.n_left ...");
  ImGui::SetNextItemWidth(-1.f);
  ImGui::InputText("##sweep_values", &s.sweep_values);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Its values, comma-separated: 1.0, 1.5. All runs restart from t = 0.");
  const std::vector<std::string> values = sweep_values(s.sweep_values);
  ImGui::BeginDisabled(values.empty() || s.sweep_key.empty());
  if (ImGui::Button(f->sweep.empty() ? "Sweep" : "Restart sweep")) s.set_sweep(s.sweep_key, values);
  ImGui::EndDisabled();
  if (f->sweep.empty()) return;
  ImGui::SameLine();
  if (ImGui::Button("Stop sweep")) s.set_sweep(s.sweep_key, {});
  run_row(*f, 0, compare_label(f->config, f->sweep.front().overrides), f->ref_values);
  for (std::size_t i = 0; i < f->sweep.size(); ++i) {
    const CompareFrame& r = f->sweep[i];
    run_row(*f, i + 1, compare_label(r.config, r.overrides), r.ref_values);
  }
  if (f->snapshot.dim > 1) ImGui::TextWrapped("The runs are drawn in the profile views (Display: profile x, y or r).");
}

}  // namespace sph::gui
