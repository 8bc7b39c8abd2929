// Projector mode: every panel's text and widgets at one scale (1-3), with the UI font rasterised at that
// size (DejaVu Sans through ImGui's font atlas, rebuilt when the scale changes: crisp, not an upscaled
// bitmap) and ImGui's style sizes scaled with it; and a high-contrast theme.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

namespace sph::gui {

struct UiLook {
  float scale = 1.f;           ///< 1 = 16 px text
  bool high_contrast = false;  ///< white on black, bright frames and borders
  bool operator==(const UiLook& o) const { return scale == o.scale && high_contrast == o.high_contrast; }
  bool operator!=(const UiLook& o) const { return !(*this == o); }
};

constexpr float kUiScaleMin = 1.f, kUiScaleMax = 3.f, kUiScaleStep = 0.25f;
constexpr float kUiFontPx = 16.f;  ///< the UI font's size at scale 1 [px]

/// The UI font file: $SPH_GUI_FONT if set, else Debian's DejaVu Sans (fonts-dejavu-core).
std::string ui_font_path();

/// Rebuilds the font atlas (and its GL texture, when the OpenGL3 backend is initialised) at
/// kUiFontPx * scale and restyles the widgets. Call between frames. Returns what was loaded, e.g.
/// "DejaVuSans.ttf at 32 px"; *fallback is set when the font file is missing and ImGui's built-in font
/// is used instead (the text says so).
std::string apply_ui_look(const UiLook& look, bool gl_ready, bool* fallback);

/// Colours (ImU32, ABGR) of the GUI's own plots: the curve plots, the kernel explorer, the convergence
/// panel's log-log plot; white on black in the high-contrast look (the last apply_ui_look's).
struct PlotLook {
  unsigned int axis, grid, fill, text, dim_text;
};
PlotLook plot_look();

/// The scale after `steps` Ctrl+= (+1 each) or Ctrl+- (-1 each) presses, on the grid of kUiScaleStep and
/// clamped to [kUiScaleMin, kUiScaleMax] (steps = 0: a slider's value put on the grid).
inline float step_ui_scale(float scale, int steps) {
  const float s = std::round((scale + static_cast<float>(steps) * kUiScaleStep) / kUiScaleStep) * kUiScaleStep;
  return std::clamp(s, kUiScaleMin, kUiScaleMax);
}

}  // namespace sph::gui
