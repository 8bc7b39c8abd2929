// Where everything goes in the window: the controls column on the left, the particle view top right,
// diagnostics and the kernel explorer below it, the status line along the bottom. Recomputed from the
// framebuffer size every frame (no saved layout), so a screenshot always looks the same.
#pragma once

namespace sph::gui {

struct Rect {
  float x = 0.f, y = 0.f, w = 0.f, h = 0.f;  ///< [px], origin top-left
  bool contains(float px, float py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

struct Layout {
  Rect controls;     ///< scene, run, parameters, display
  Rect view;         ///< the particle view (renderer output)
  Rect diagnostics;  ///< energies, momentum, L1 error against time
  Rect kernel;       ///< kernel explorer (empty where the diagnostics need the whole row)
  Rect status;       ///< one status line
  Rect inspector;    ///< the particle inspector, when open (carve_inspector); empty otherwise
};

/// Gives the particle inspector a column at the right of the view (about 30 lines of text wide).
void carve_inspector(Layout& L, float line_height);

/// line_height: the UI font's height [px] (16 at UI scale 1; the controls column widens with it);
/// pad_y: the windows' vertical padding [px] (the status line holds one line between two paddings).
Layout compute_layout(int width, int height, float line_height, float pad_y = 6.f);

}  // namespace sph::gui
