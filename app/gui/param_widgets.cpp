#include "param_widgets.h"

#include "log_scale.h"
#include "param_help.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sph::gui {
namespace {

std::string format(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

enum class Widget { Linear, Logarithmic, Text };

/// A short range from 0 (eta, alpha) gets a linear slider; a positive range over decades (h_tol,
/// visc_eps, cfl) a logarithmic one; anything open-ended (dt, t_end, iteration caps) a text field.
Widget widget_for(const ParamInfo& info) {
  if (info.max > 20.0 || info.min < 0.0) return Widget::Text;
  if (info.min > 0.0 && info.max / info.min > 100.0) return Widget::Logarithmic;
  return Widget::Linear;
}

}  // namespace

std::string zero_text(const ParamInfo& info) {
  const std::size_t k = info.description.rfind("0 = ");
  if (k == std::string_view::npos || (k > 0 && info.description[k - 1] != ' ')) return "";
  std::string meaning;
  for (const char c : info.description.substr(k + 4)) meaning += c == '%' ? std::string("%%") : std::string(1, c);
  return "0 (" + meaning + ")";  // an ImGui format without a conversion: shown as it is
}

void param_tooltip(const ParamInfo& info) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.f);
  ImGui::Text("%.*s", static_cast<int>(info.key.size()), info.key.data());
  ImGui::TextWrapped("%.*s", static_cast<int>(info.description.size()), info.description.data());
  if (info.choices.empty()) ImGui::TextDisabled("%s", param_unit_line(info).c_str());
  if (!info.stage.empty())
    ImGui::TextDisabled("used by %.*s", static_cast<int>(info.stage.size()), info.stage.data());
  if (info.live)
    ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.f), "live: takes effect at the next step");
  else
    ImGui::TextColored(ImVec4(1.f, 0.7f, 0.3f, 1.f), "needs reset: applied when you press Reset");
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

bool param_widget(const ParamInfo& info, Params& p, bool pending, std::string* err,
                  const std::vector<std::string>& allowed) {
  const std::string key(info.key);
  const std::string full_label = key + (info.live ? "" : pending ? "  (reset!)" : "  (reset)");
  // A label longer than the column beside the widgets goes on its own line above a full-width widget
  // (it was cut: "physics.smoothin", "physics.eos (rese" at 1x; every label at 3x).
  const float column = ImGui::GetContentRegionAvail().x - ImGui::CalcItemWidth() - ImGui::GetStyle().ItemInnerSpacing.x;
  const bool stacked = ImGui::CalcTextSize(full_label.c_str()).x > column;
  if (stacked) {
    ImGui::TextUnformatted(full_label.c_str());
    param_tooltip(info);
    ImGui::PushItemWidth(-1.f);
  }
  const std::string label = stacked ? "##" + key : full_label;
  const std::string current = info.get(p);
  bool changed = false;
  std::string text;
  if (pending) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.45f, 0.30f, 0.08f, 1.f));
  if (!info.choices.empty()) {
    if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
      for (const std::string& c : info.choices) {
        if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), c) == allowed.end()) continue;
        if (ImGui::Selectable(c.c_str(), c == current) && c != current) {
          text = c;
          changed = true;
        }
      }
      ImGui::EndCombo();
    }
  } else {
    double v = std::strtod(current.c_str(), nullptr);
    switch (widget_for(info)) {
      case Widget::Linear: {
        const std::string zero = v == 0.0 ? zero_text(info) : std::string();
        changed = ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &v, &info.min, &info.max,
                                      zero.empty() ? "%.4g" : zero.c_str());
        break;
      }
      case Widget::Logarithmic: {
        // Slide log10(v); show v itself (the "format" is the formatted value: it holds no conversion).
        // ImGui 1.86's own logarithmic sliders clamp values below 10^-precision, e.g. h_tol = 1e-10.
        // Ctrl+click text input is off (it would read the typed number as log10 v): the field beside
        // the slider takes typed values as they are.
        const double lo = std::log10(info.min), hi = std::log10(info.max);
        double u = log_position(v, info.min, info.max);
        char shown[32];
        std::snprintf(shown, sizeof shown, "%.3g", v);
        const float full = ImGui::CalcItemWidth(), field = std::max(60.f, 0.3f * full);
        ImGui::SetNextItemWidth(full - field - ImGui::GetStyle().ItemInnerSpacing.x);
        const std::string slider_id = "##log " + key;
        if (ImGui::SliderScalar(slider_id.c_str(), ImGuiDataType_Double, &u, &lo, &hi, shown,
                                ImGuiSliderFlags_NoInput)) {
          v = log_value(u, info.min, info.max);
          changed = true;
        }
        param_tooltip(info);
        ImGui::SameLine(0.f, ImGui::GetStyle().ItemInnerSpacing.x);
        ImGui::SetNextItemWidth(field);
        double typed = v;
        if (ImGui::InputDouble(label.c_str(), &typed, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue)) {
          v = typed;
          changed = true;
        }
        break;
      }
      case Widget::Text:
        changed = ImGui::InputDouble(label.c_str(), &v, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue);
        break;
    }
    if (changed) text = format(v);
  }
  if (pending) ImGui::PopStyleColor();
  if (stacked) ImGui::PopItemWidth();
  param_tooltip(info);
  if (!changed || text == current) return false;
  if (!info.set(p, text, *err)) return false;
  err->clear();
  return true;
}

}  // namespace sph::gui
