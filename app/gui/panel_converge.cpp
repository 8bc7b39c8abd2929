// The convergence study of the current scene (the GUI's `sph converge`): key, values and time (the
// scene's defaults to start with), a button that runs the series beside the engine, then the table of
// errors and observed orders and a log-log plot of error against spacing with the fitted slope.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "converge_job.h"
#include "ui_look.h"
#include "panels.h"

namespace sph::gui {
namespace {

std::string join(const std::vector<double>& v) {
  std::string s;
  char buf[32];
  for (double x : v) {
    std::snprintf(buf, sizeof buf, "%s%g", s.empty() ? "" : ",", x);
    s += buf;
  }
  return s;
}

std::vector<double> split(const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) {
    std::size_t used = 0;
    try {
      const double v = std::stod(item, &used);
      if (used == item.size() && std::isfinite(v)) out.push_back(v);
      else throw ConfigError("'" + item + "' is not a number");
    } catch (const std::invalid_argument&) {
      throw ConfigError("'" + item + "' is not a number");
    }
  }
  return out;
}

/// log10 e against log10 h: the runs as dots, the least-squares line through them.
void loglog_plot(const ConvergenceResult& r) {
  const ImVec2 size(ImGui::GetContentRegionAvail().x, 12.f * ImGui::GetFontSize());
  const ImVec2 p0 = ImGui::GetCursorScreenPos(), p1(p0.x + size.x, p0.y + size.y);
  ImGui::InvisibleButton("##loglog", size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const PlotLook look = plot_look();
  dl->AddRect(p0, p1, look.axis);
  std::vector<float> x, y;
  for (const ConvergenceRun& run : r.runs) {
    if (!(run.error > 0.0)) continue;
    x.push_back(static_cast<float>(std::log10(run.h)));
    y.push_back(static_cast<float>(std::log10(run.error)));
  }
  if (x.size() < 2) return;
  const auto [xl, xh] = std::minmax_element(x.begin(), x.end());
  const auto [yl, yh] = std::minmax_element(y.begin(), y.end());
  const float x0 = *xl - 0.1f, x1 = *xh + 0.1f, y0 = *yl - 0.1f, y1 = *yh + 0.1f;
  auto at = [&](float xx, float yy) {
    return ImVec2(p0.x + (xx - x0) / (x1 - x0) * size.x, p1.y - (yy - y0) / (y1 - y0) * size.y);
  };
  float mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) { mx += x[k]; my += y[k]; }
  mx /= static_cast<float>(x.size());
  my /= static_cast<float>(y.size());
  const auto slope = static_cast<float>(r.slope);
  dl->AddLine(at(x0, my + slope * (x0 - mx)), at(x1, my + slope * (x1 - mx)), IM_COL32(230, 90, 90, 255), 1.5f);
  for (std::size_t k = 0; k < x.size(); ++k) dl->AddCircleFilled(at(x[k], y[k]), 4.f, IM_COL32(90, 200, 255, 255));
  char buf[96];
  std::snprintf(buf, sizeof buf, "log10 %s  (slope %.2f)", r.column.c_str(), r.slope);
  dl->AddText(ImVec2(p0.x + 4, p0.y + 2), look.text, buf);
  std::snprintf(buf, sizeof buf, "log10 h: %.2f ... %.2f", x0, x1);
  dl->AddText(ImVec2(p0.x + 4, p1.y - ImGui::GetFontSize() - 2), look.dim_text, buf);
}

}  // namespace

void panel_converge(GuiState& s) {
  const StepperFrame* f = s.frame();
  if (f == nullptr) return;
  if (!f->has_reference) {
    ImGui::TextDisabled("This scene has no reference to converge to.");
    return;
  }
  ConvergeUi& u = s.converge;
  const bool running = u.job && u.job->poll();
  if (u.scene != f->config.scene->name && !running) {  // another scene: its default study
    u = ConvergeUi{};
    u.scene = f->config.scene->name;
    try {
      const ConvergenceStudy d = resolve_study(f->config, {});
      u.key = d.key;
      u.values = join(d.values);
      u.t = d.t;
      u.column = d.column;
    } catch (const std::exception& e) {
      u.message = e.what();
    }
  }
  ImGui::BeginDisabled(running);
  char key[64], values[256], column[64];
  std::snprintf(key, sizeof key, "%s", u.key.c_str());
  std::snprintf(values, sizeof values, "%s", u.values.c_str());
  std::snprintf(column, sizeof column, "%s", u.column.c_str());
  if (ImGui::InputText("key", key, sizeof key)) u.key = key;
  if (ImGui::InputText("values", values, sizeof values)) u.values = values;
  ImGui::InputDouble("at t", &u.t, 0.0, 0.0, "%.4g");
  if (ImGui::InputText("error column", column, sizeof column)) u.column = column;
  if (ImGui::Button("Run study")) {
    try {
      ConvergenceStudy st{u.key, split(u.values), u.t, u.column};
      RunConfig base = f->config;
      base.params = f->config.params;  // the parameters the scene runs with now
      st = resolve_study(base, st);
      u.job = std::make_unique<ConvergeJob>(base, st);
      u.message.clear();
    } catch (const std::exception& e) {
      u.message = e.what();
    }
  }
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Runs the scene once per value (beside the running engine) and compares the error column\n"
                      "at time t; the same study as `sph converge %s`.", u.scene.c_str());
  if (running) {
    ImGui::SameLine();
    ImGui::ProgressBar(static_cast<float>(u.job->finished()) / static_cast<float>(std::max(1, u.job->total())),
                       ImVec2(-1, 0), "running");
  }
  if (!u.message.empty()) ImGui::TextColored(ImVec4(1.f, 0.7f, 0.25f, 1.f), "%s", u.message.c_str());
  if (!u.job || running) return;
  if (!u.job->error().empty()) {
    ImGui::TextColored(ImVec4(1.f, 0.7f, 0.25f, 1.f), "study failed: %s", u.job->error().c_str());
    return;
  }
  const ConvergenceResult& r = *u.job->result();
  if (ImGui::BeginTable("##conv", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn(r.key.c_str());
    ImGui::TableSetupColumn("h");
    ImGui::TableSetupColumn(r.column.c_str());
    ImGui::TableSetupColumn("order");
    ImGui::TableHeadersRow();
    for (const ConvergenceRun& run : r.runs) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn(); ImGui::Text("%g", run.value);
      ImGui::TableNextColumn(); ImGui::Text("%.3g", run.h);
      ImGui::TableNextColumn(); ImGui::Text("%.3g", run.error);
      ImGui::TableNextColumn();
      if (std::isnan(run.order)) ImGui::TextUnformatted("-");
      else ImGui::Text("%.2f", run.order);
    }
    ImGui::EndTable();
  }
  loglog_plot(r);
}

}  // namespace sph::gui
