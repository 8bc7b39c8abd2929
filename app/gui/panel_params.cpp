// Live run parameters, one widget per entry of sph::param_table(): live ones are posted to the engine's
// mailbox at once (they take effect at the next step); the others wait for Reset and say so.
#include <imgui.h>

#include "panels.h"
#include "param_widgets.h"
#include "sph/kernel.h"

namespace sph::gui {

void panel_params(GuiState& s) {
  const StepperFrame* f = s.frame();
  std::string& error = s.param_error;
  for (const ParamInfo& info : param_table()) {
    if (info.key == "dt_out") continue;  // output interval of headless runs: nothing to do here
    const bool pending = f && !info.live && info.get(s.edit) != info.get(f->config.params);
    ImGui::PushID(info.key.data(), info.key.data() + info.key.size());
    if (param_widget(info, s.edit, pending, &error) && info.live) s.post_live();
    ImGui::PopID();
  }
  if (!error.empty()) ImGui::TextColored(ImVec4(1.f, 0.4f, 0.4f, 1.f), "%s", error.c_str());
  // What eta = 0 and dt = 0 mean for this run.
  const int dim = f && f->config.scene ? f->config.scene->dim : 1;
  const Kernel k(s.edit.kernel, dim);
  const double eta = s.edit.eta > 0.0 ? s.edit.eta : k.default_eta();
  ImGui::TextDisabled("eta = %.3g%s: ~%.1f neighbours (%dD)", eta, s.edit.eta > 0.0 ? "" : " (default)",
                      expected_neighbours(k, eta), dim);
  ImGui::TextDisabled("dt %s", s.edit.dt > 0.0 ? "fixed" : "= cfl min(h/v_sig, sqrt(h/|a|))");
}

}  // namespace sph::gui
