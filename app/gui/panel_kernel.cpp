// Kernel explorer: the dimensionless shape sigma w(q) and its slope sigma dw/dq of a smoothing kernel
// against the Gaussian (seed 000 eqs. 3.2.6-3.2.9; Figs. 3.1-3.4 compare M4, M5, M6 with the Gaussian),
// in 1, 2 or 3 dimensions, with the kernel's support, normalisation and neighbour count.
#include <imgui.h>

#include "curve_plot.h"
#include "panels.h"
#include "ui_flow.h"
#include "sph/kernel.h"

namespace sph::gui {
namespace {

constexpr int kSamples = 241;
constexpr float kQmax = 3.f;  // the widest support (M6, Gaussian cut-off)

Curve sample(const Kernel& k, bool slope, std::string label, ImU32 color, bool dashed) {
  Curve c{std::move(label), color, {}, dashed};
  c.y.resize(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const double q = kQmax * i / (kSamples - 1);
    c.y[static_cast<std::size_t>(i)] = static_cast<float>(k.sigma() * (slope ? k.dw(q) : k.w(q)));
  }
  return c;
}

}  // namespace

void panel_kernel(GuiState& s) {
  bool& follow = s.kernel_view.follow;
  KernelType& chosen = s.kernel_view.kernel;
  int& dim_choice = s.kernel_view.dim;
  if (follow) chosen = s.edit.kernel.type;
  const StepperFrame* f = s.frame();
  const int scene_dim = f && f->config.scene ? f->config.scene->dim : 1;
  const int dim = dim_choice > 0 ? dim_choice : scene_dim;

  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.f);
  if (ImGui::BeginCombo("##kernel", to_string(chosen))) {
    for (KernelType k : {KernelType::M4, KernelType::M5, KernelType::M6, KernelType::Gaussian, KernelType::WendlandC2,
                         KernelType::WendlandC4})
      if (ImGui::Selectable(to_string(k), k == chosen)) {
        chosen = k;
        follow = false;
      }
    ImGui::EndCombo();
  }
  same_line_if_fits(ImGui::GetFrameHeight() + item_width_of("run's kernel"));
  ImGui::Checkbox("run's kernel", &follow);
  same_line_if_fits(ImGui::GetFontSize() * 6.f);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.f);
  const char* dims[] = {"scene D", "1D", "2D", "3D"};
  ImGui::Combo("##dim", &dim_choice, dims, 4);

  const Kernel k(chosen, dim), g(KernelType::Gaussian, dim);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%dD: support %.2g h, sigma %.4g, default eta %.3g (seed 000, Figs. 3.1-3.4)", dim, k.support(),
                     k.sigma(), k.default_eta());
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("W(r,h) = sigma w(q) / h^d, q = r/h (seed 000 eqs. 3.2.6-3.2.10); curves drawn for h = 1.\n"
                      "Default eta gives every kernel the width of M4 with eta = 1.2 (same variance):\n"
                      "about %.0f neighbours inside the support in %dD.",
                      expected_neighbours(k, k.default_eta()), dim);
  // side by side, or one above the other where half the width is too narrow for a plot (projector mode)
  const bool stacked = ImGui::GetContentRegionAvail().x < 24.f * ImGui::GetFontSize();
  const float w = stacked ? ImGui::GetContentRegionAvail().x
                          : (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
  const float h = stacked ? (ImGui::GetContentRegionAvail().y - ImGui::GetStyle().ItemSpacing.y) * 0.5f
                          : ImGui::GetContentRegionAvail().y;
  const ImU32 kc = IM_COL32(90, 170, 255, 255), gc = IM_COL32(235, 235, 235, 255);
  const std::string name = to_string(chosen);
  curve_plot("W", "q", 0.f, kQmax, {sample(g, false, "Gaussian", gc, true), sample(k, false, name + " W(q)", kc, false)},
             ImVec2(w, h));
  if (!stacked) ImGui::SameLine();
  curve_plot("dW", "q", 0.f, kQmax,
             {sample(g, true, "Gaussian", gc, true), sample(k, true, name + " dW/dq", IM_COL32(255, 150, 60, 255), false)},
             ImVec2(w, h));
}

}  // namespace sph::gui
