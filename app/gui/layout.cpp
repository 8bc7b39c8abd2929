#include "layout.h"

#include <algorithm>
#include <cmath>

namespace sph::gui {

Layout compute_layout(int width, int height, float line_height, float pad_y) {
  const float W = static_cast<float>(width), H = static_cast<float>(height);
  Layout L;
  const float status_h = std::round(line_height + 2.f * pad_y);  // at 1.5x, line + 12 px cut its text
  // the column grows with the UI font (projector mode), up to 45% of the window
  const float k = std::max(1.f, line_height / 16.f);
  const float controls_w = std::round(std::min(std::clamp(0.26f * W, 330.f * k, 430.f * k), std::max(330.f, 0.45f * W)));
  const float body_h = H - status_h;
  const float right_w = W - controls_w;
  const float view_h = std::round(std::max(0.f, body_h * 0.63f));
  const float bottom_h = body_h - view_h;
  // the kernel explorer beside the diagnostics while both hold about 30 characters a line; else (a
  // projector's large text on a small screen) the diagnostics take the row and the explorer is not shown
  const float diag_w = right_w * 0.44f >= 15.f * line_height ? std::round(right_w * 0.56f) : right_w;
  L.controls = {0.f, 0.f, controls_w, body_h};
  L.view = {controls_w, 0.f, right_w, view_h};
  L.diagnostics = {controls_w, view_h, diag_w, bottom_h};
  L.kernel = {controls_w + diag_w, view_h, right_w - diag_w, bottom_h};
  L.status = {0.f, body_h, W, status_h};
  return L;
}

void carve_inspector(Layout& L, float line_height) {
  const float w = std::round(std::min(0.45f * L.view.w, 30.f * line_height));
  L.view.w -= w;
  L.inspector = {L.view.x + L.view.w, L.view.y, w, L.view.h};
}

}  // namespace sph::gui
