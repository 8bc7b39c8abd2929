// Diagnostics: the conserved quantities (seed 000 eqs. 3.4.1-3.4.5) and, where the scene has an exact
// solution, the running L1 error, as numbers and as curves against simulated time (curve_plot, with
// axes, on the stepper's history resampled evenly in t).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "curve_plot.h"
#include "diag_text.h"
#include "frame_scene.h"
#include "history_plot.h"
#include "panels.h"

namespace sph::gui {
namespace {

void add(std::vector<DiagRow>& rows, const char* name, double v, int digits, const char* tip) {
  rows.push_back({name, value_text(v, digits), tip});
}

/// One quantity against t, with axes, titled with the value of the frame on screen.
void sparkline(const char* id, const std::vector<HistorySample>& h, std::vector<float> y, const std::string& title,
               float height) {
  const float t0 = h.empty() ? 0.f : static_cast<float>(h.front().t), t1 = h.empty() ? 1.f : static_cast<float>(h.back().t);
  curve_plot(id, "t", t0, t1, {{title, IM_COL32(200, 200, 210, 255), std::move(y), false}}, ImVec2(-1.f, height), false);
}

ImU32 run_colour(int run) {
  const render::Rgba c = render::kRunColors[run];
  return IM_COL32(static_cast<int>(255 * c.r), static_cast<int>(255 * c.g), static_cast<int>(255 * c.b), 255);
}

/// A comparison: one quantity of both runs against t on one set of axes, A solid, B dashed.
void both_runs(const char* id, const std::string& name, std::vector<float> a, std::vector<float> b,
               const std::vector<HistorySample>& h, float height) {
  const float t0 = h.empty() ? 0.f : static_cast<float>(h.front().t), t1 = h.empty() ? 1.f : static_cast<float>(h.back().t);
  curve_plot(id, "t", t0, t1, {{"A " + name, run_colour(0), std::move(a), false}, {"B " + name, run_colour(1), std::move(b), true}},
             ImVec2(-1.f, height), false);
}

/// The rows of numbers: energies, momenta, fallbacks, the reference's columns, run B's beside A's.
std::vector<DiagRow> diag_rows(const StepperFrame& f, double dE, double P, double L, bool compare) {
  const Diagnostics& d = f.diagnostics;
  std::vector<DiagRow> rows;
  add(rows, "E_kin", d.E_kin, 6, "kinetic energy, sum 1/2 m v^2 (seed 000 eq. 3.4.4)");
  add(rows, "E_int", d.E_int, 6, "internal energy of the EOS: sum m u (gas), sum m e(rho) (Tait liquid)");
  add(rows, "E_pot", d.E_pot, 6, "potential energy of the body force, the Lennard-Jones walls and self-gravity (1/2 sum m phi)");
  add(rows, "E_tot", d.E_tot, 6, "total energy (seed 000 eq. 3.4.5): conserved without boundaries that do work");
  rows.push_back(energy_change_row(dE, f.config.scene && f.config.scene->energy_bound > 0.0));
  add(rows, "|P|", P, 4, "linear momentum, |sum m v| (seed 000 eq. 3.4.1); walls exchange momentum");
  add(rows, "|L|", L, 4, "angular momentum about the origin, |sum r x m v| (seed 000 eq. 3.4.3)");
  add(rows, "v_max", d.v_max, 4, "largest particle speed");
  if (d.correction_fallbacks > 0)
    add(rows, "fallbacks", static_cast<double>(d.correction_fallbacks), 9,
        "particles whose gradient correction was ill-conditioned and fell back to L = I");
  for (std::size_t k = 0; k < f.ref_columns.size() && k < f.ref_values.size(); ++k)
    rows.push_back({f.ref_columns[k].name, value_text(f.ref_values[k], 5), f.ref_columns[k].description});
  if (compare) {  // run B's energy and primary error beside A's
    add(rows, "B E_tot", f.compare.diagnostics.E_tot, 6, "run B's total energy");
    const std::size_t k = static_cast<std::size_t>(std::max(0, f.ref_primary));
    if (f.ref_primary >= 0 && k < f.compare.ref_values.size())
      rows.push_back({"B " + f.ref_columns[k].name, value_text(f.compare.ref_values[k], 5), "run B's error"});
  }
  return rows;
}

/// The numbers' table: each quantity's name (with its explanation as a tooltip) and value.
void numbers_table(const std::vector<DiagRow>& rows, const DiagWidths& w) {
  if (ImGui::BeginTable("numbers", 2, ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed, w.name);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthFixed, w.value);
    for (const DiagRow& r : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.name.c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.tip.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r.value.c_str());
    }
    ImGui::EndTable();
  }
}

/// The curves against t, sharing the column's height: the reference's series, its primary error, the
/// energies, E_tot and |P| (run B's beside A's when compared).
void diag_plots(const StepperFrame& f, bool compare, double P) {
  const Diagnostics& d = f.diagnostics;
  const auto& h = f.history;
  const bool err_plot = f.ref_primary >= 0 && static_cast<std::size_t>(f.ref_primary) < f.ref_columns.size();
  const int n = 3 + (err_plot ? 1 : 0) + static_cast<int>(f.ref_series.size());
  const float text_h = ImGui::GetTextLineHeightWithSpacing();
  const float avail = ImGui::GetContentRegionAvail().y - text_h;
  // readable plots even when a reference brings several (the column scrolls)
  const float ph = std::max(3.5f * text_h, avail / n - ImGui::GetStyle().ItemSpacing.y);
  for (const auto& [measured, exact] : f.ref_series) {  // e.g. the drop's semi-axes against the exact ODE
    if (static_cast<std::size_t>(std::max(measured, exact)) >= f.ref_columns.size()) continue;
    std::vector<Curve> curves;
    curves.push_back({f.ref_columns[static_cast<std::size_t>(measured)].name, IM_COL32(255, 200, 80, 255),
                      resample_ref(h, static_cast<std::size_t>(measured), 240), false});
    curves.push_back({f.ref_columns[static_cast<std::size_t>(exact)].name, IM_COL32(120, 200, 255, 255),
                      resample_ref(h, static_cast<std::size_t>(exact), 240), true});
    const std::string id = "series" + std::to_string(measured);
    curve_plot(id.c_str(), "t", h.empty() ? 0.f : static_cast<float>(h.front().t),
               h.empty() ? 1.f : static_cast<float>(h.back().t), curves, ImVec2(-1.f, ph));
  }
  if (err_plot) {
    const std::size_t k = static_cast<std::size_t>(f.ref_primary);
    const double now = k < f.ref_values.size() ? f.ref_values[k] : std::nan("");
    if (compare)
      both_runs("err", f.ref_columns[k].name, resample_ref(h, k, 240), resample_ref(f.compare.history, k, 240), h, ph);
    else
      sparkline("err", h, resample_ref(h, k, 240), plot_title(f.ref_columns[k].name, now, f), ph);
  }
  {  // the energies on one set of axes, as seed 003's figures show them (the sparkline below magnifies E_tot)
    const float t0 = h.empty() ? 0.f : static_cast<float>(h.front().t), t1 = h.empty() ? 1.f : static_cast<float>(h.back().t);
    std::vector<Curve> curves{{"E_kin", IM_COL32(255, 200, 80, 255), resample(h, &HistorySample::E_kin, 240), false},
                              {"E_int", IM_COL32(255, 110, 110, 255), resample(h, &HistorySample::E_int, 240), false},
                              {"E_pot", IM_COL32(120, 200, 255, 255), resample(h, &HistorySample::E_pot, 240), false},
                              {"E_tot", IM_COL32(230, 230, 230, 255), resample(h, &HistorySample::E_tot, 240), true}};
    if (compare)  // run B's energies dashed, in the same colours
      for (std::size_t c = 0; c < 3; ++c)
        curves.push_back({"B " + curves[c].label, curves[c].color,
                          resample(f.compare.history, c == 0 ? &HistorySample::E_kin : c == 1 ? &HistorySample::E_int
                                                                                                : &HistorySample::E_pot, 240),
                          true});
    curve_plot("energies", "t", t0, t1, curves, ImVec2(-1.f, ph));
  }
  if (compare)
    both_runs("E_tot", "E_tot", resample(h, &HistorySample::E_tot, 240), resample(f.compare.history, &HistorySample::E_tot, 240),
              h, ph);
  else
    sparkline("E_tot", h, resample(h, &HistorySample::E_tot, 240), plot_title("E_tot", d.E_tot, f), ph);
  sparkline("|P|", h, resample(h, &HistorySample::P, 240), plot_title("|P|", P, f), ph);
  if (!h.empty()) ImGui::TextDisabled("against t = %.4g ... %.4g  (%zu samples)", h.front().t, h.back().t, h.size());
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
  const bool compare = f->comparing && f->compare.history.size() == h.size();
  const std::vector<DiagRow> rows = diag_rows(*f, dE, P, L, compare);
  // Columns as wide as their widest text, so that no value runs into the plots.
  const DiagWidths w = diag_widths(rows, [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; });
  const float pad = ImGui::GetStyle().CellPadding.x, values_w = w.name + w.value + 6.f * pad;
  if (values_w > 0.45f * ImGui::GetContentRegionAvail().x) {  // narrow (projector mode): numbers, then plots
    numbers_table(rows, w);
    diag_plots(*f, compare, P);
    return;
  }
  if (!ImGui::BeginTable("diag", 2, ImGuiTableFlags_SizingStretchProp)) return;
  ImGui::TableSetupColumn("values", ImGuiTableColumnFlags_WidthFixed, values_w);
  ImGui::TableSetupColumn("plots", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  numbers_table(rows, w);
  ImGui::TableNextColumn();
  diag_plots(*f, compare, P);
  ImGui::EndTable();
}

}  // namespace sph::gui
