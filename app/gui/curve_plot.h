// Several curves y_k(x) on one set of axes, drawn with ImGui's draw list (ImGui::PlotLines shows one
// series only): x and y ranges, a zero line, tick values at the ends, a legend.
#pragma once
#include <imgui.h>

#include <string>
#include <vector>

namespace sph::gui {

struct Curve {
  std::string label;
  ImU32 color = IM_COL32_WHITE;
  std::vector<float> y;  ///< values at evenly spaced x over [x0, x1]
  bool dashed = false;
};

/// Draws the curves in a box of `size` (negative width: fill the available width). The value range
/// includes 0 unless `include_zero` is false (a sparkline magnifying a nearly constant E_tot).
/// Non-finite values leave gaps.
void curve_plot(const char* id, const char* x_label, float x0, float x1, const std::vector<Curve>& curves,
                ImVec2 size, bool include_zero = true);

}  // namespace sph::gui
