// Diagnostics: the conserved quantities (seed 000 eqs. 3.4.1-3.4.5) and, where the scene has an exact
// solution, the running L1 error, as numbers and as curves against simulated time (ImGui::PlotLines
// on the stepper's history resampled evenly in t).
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "history_plot.h"
#include "panels.h"

namespace sph::gui {
namespace {

void row(const char* name, const char* fmt, double v, const char* tip) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  ImGui::TableNextColumn();
  ImGui::Text(fmt, v);
}

void plot(const std::vector<HistorySample>& h, double HistorySample::*field, const char* name, float height) {
  const std::vector<float> y = resample(h, field, 240);
  char overlay[96];
  std::snprintf(overlay, sizeof overlay, "%s = %.6g", name, y.empty() ? 0.0 : static_cast<double>(y.back()));
  ImGui::PushID(name);
  ImGui::PlotLines("##plot", y.data(), static_cast<int>(y.size()), 0, overlay, FLT_MAX, FLT_MAX,
                   ImVec2(ImGui::GetContentRegionAvail().x, height));
  ImGui::PopID();
}

}  // namespace

void panel_diagnostics(GuiState& s) {
  const StepperFrame* f = s.frame();
  if (f == nullptr) return;
  const Diagnostics& d = f->diagnostics;
  const auto& h = f->history;
  const double E0 = h.empty() ? d.E_tot : h.front().E_tot;
  const double dE = E0 != 0.0 ? (d.E_tot - E0) / std::abs(E0) : d.E_tot - E0;
  const double P = std::sqrt(d.P[0] * d.P[0] + d.P[1] * d.P[1] + d.P[2] * d.P[2]);
  const double L = std::sqrt(d.L[0] * d.L[0] + d.L[1] * d.L[1] + d.L[2] * d.L[2]);
  if (!ImGui::BeginTable("diag", 2, ImGuiTableFlags_SizingStretchProp)) return;
  ImGui::TableSetupColumn("values", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFontSize() * 11.f);
  ImGui::TableSetupColumn("plots", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  if (ImGui::BeginTable("numbers", 2)) {
    row("E_kin", "%.6g", d.E_kin, "kinetic energy, sum 1/2 m v^2 (seed 000 eq. 3.4.4)");
    row("E_int", "%.6g", d.E_int, "internal energy, sum m u");
    row("E_tot", "%.6g", d.E_tot, "total energy (seed 000 eq. 3.4.5): conserved without boundaries that do work");
    row("dE/E0", "%+.2e", dE, "relative change of E_tot since t = 0");
    row("|P|", "%.3e", P, "linear momentum, |sum m v| (seed 000 eq. 3.4.1); walls exchange momentum");
    row("|L|", "%.3e", L, "angular momentum about the origin, |sum r x m v| (seed 000 eq. 3.4.3)");
    row("v_max", "%.4g", d.v_max, "largest particle speed");
    if (f->has_reference) {
      row("L1 rho", "%.4e", f->errors.L1_rho, "mean |rho - rho_exact| over the particles in the scene's window");
      row("L1 v", "%.4e", f->errors.L1_v, "mean |v - v_exact|");
      row("L1 p", "%.4e", f->errors.L1_p, "mean |P - P_exact|");
      row("L1 u", "%.4e", f->errors.L1_u, "mean |u - u_exact|");
    }
    ImGui::EndTable();
  }
  ImGui::TableNextColumn();
  const int n = f->has_reference ? 4 : 3;
  const float text_h = ImGui::GetTextLineHeightWithSpacing();
  const float avail = ImGui::GetContentRegionAvail().y - text_h;
  const float ph = std::max(24.f, avail / n - ImGui::GetStyle().ItemSpacing.y);
  if (f->has_reference) plot(h, &HistorySample::L1_rho, "L1 rho", ph);
  plot(h, &HistorySample::E_tot, "E_tot", ph);
  plot(h, &HistorySample::E_kin, "E_kin", ph);
  plot(h, &HistorySample::P, "|P|", ph);
  if (!h.empty()) ImGui::TextDisabled("against t = %.4g ... %.4g  (%zu samples)", h.front().t, h.back().t, h.size());
  ImGui::EndTable();
}

}  // namespace sph::gui
