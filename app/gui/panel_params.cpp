// Run parameters, one widget per entry of sph::param_table(): first the physics slots (one option per
// stage of the pipeline, only the options the scene accepts), then the parameters of the stages the
// scene runs, grouped by stage. Live ones are posted to the engine's mailbox at once (they take effect
// at the next step); the others wait for Reset and say so. Parameters of stages that do not run are not
// shown.
#include <imgui.h>

#include "panels.h"
#include "param_widgets.h"
#include "sph/kernel.h"

namespace sph::gui {
namespace {

/// Heading of a parameter group.
const char* group_title(std::string_view g) {
  if (g == "physics") return "physics: the stages of the step";
  if (g == "kernel") return "kernel";
  if (g == "density") return "density (continuity)";
  if (g == "h") return "smoothing length solve";
  if (g == "time") return "time integration";
  if (g == "gas") return "gas";
  if (g == "liquid") return "liquid (Tait EOS)";
  if (g == "visc") return "viscosity";
  if (g == "conduction") return "conduction";
  if (g == "xsph") return "XSPH";
  if (g == "body") return "body force";
  if (g == "walls") return "walls";
  if (g == "correction") return "kernel-gradient correction";
  return "other";
}

}  // namespace

void panel_params(GuiState& s) {
  const StepperFrame* f = s.frame();
  std::string& error = s.param_error;
  const SceneSpec* scene = f ? f->config.scene : nullptr;
  std::string_view group;
  for (const ParamInfo& info : param_table()) {
    if (info.key == "time.dt_out") continue;  // output interval of headless runs: nothing to do here
    if (!info.is_active(s.edit)) continue;    // a stage this scene does not run
    if (info.group != group) {
      group = info.group;
      ImGui::Separator();
      ImGui::TextDisabled("%s", group_title(group));
    }
    const bool pending = f && !info.live && info.get(s.edit) != info.get(f->config.params);
    ImGui::PushID(info.key.data(), info.key.data() + info.key.size());
    std::vector<std::string> allowed;
    if (info.is_slot() && scene) allowed = scene->allowed[static_cast<std::size_t>(info.slot)];
    if (param_widget(info, s.edit, pending, &error, allowed)) {
      const std::string why = s.edit.physics.validate();
      if (!why.empty()) {
        error = why;  // shown below; the engine keeps running the last valid physics
      } else if (info.live) {
        s.post_live();
      }
    }
    ImGui::PopID();
  }
  if (!error.empty()) {
    ImGui::PushTextWrapPos(0.f);
    ImGui::TextColored(ImVec4(1.f, 0.4f, 0.4f, 1.f), "%s", error.c_str());
    ImGui::PopTextWrapPos();
  }
  // What eta = 0 and dt = 0 mean for this run.
  const int dim = scene ? scene->dim : 1;
  const Kernel k(s.edit.kernel.type, dim);
  const double eta = s.edit.kernel.eta > 0.0 ? s.edit.kernel.eta : k.default_eta();
  ImGui::TextDisabled("eta = %.3g%s: ~%.1f neighbours (%dD)", eta, s.edit.kernel.eta > 0.0 ? "" : " (default)",
                      expected_neighbours(k, eta), dim);
  ImGui::TextDisabled("dt %s", s.edit.time.dt > 0.0 ? "fixed" : "= cfl min(h/v_sig, sqrt(h/|a|), stage limits)");
  if (f && !f->stages.empty() && ImGui::TreeNode("stages", "pipeline: %zu stages run", f->stages.size())) {
    for (const std::string& st : f->stages) ImGui::BulletText("%s", st.c_str());
    ImGui::TreePop();
  }
}

}  // namespace sph::gui
