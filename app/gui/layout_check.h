// Text layout checks on what Dear ImGui drew (the layout tests): every glyph quad of a frame's draw data,
// found by its texture coordinates in the font atlas, is checked for being cut by its clip rectangle
// (horizontally: a label cut by its column or window; vertically only in windows without a vertical scroll
// bar, such as the status line: a window that scrolls cuts its lines at its edge by design) and for overlapping a glyph of other text of its window (a dialog lies over the
// windows by design). Tooltips, which follow the mouse, are left out.
#pragma once
#include <string>
#include <vector>

struct ImDrawData;
struct ImFontAtlas;

namespace sph::gui {

struct LayoutProblem {
  std::string window;  ///< the draw list's owner (window name)
  std::string text;    ///< the text around the glyph, as drawn on its line
  float x = 0.f, y = 0.f;  ///< where [px]
};

struct LayoutReport {
  int glyphs = 0;
  std::vector<LayoutProblem> clipped, overlapping;
};

/// Checks the frame's draw data (the current ImGui context's last frame: its windows tell which scroll).
LayoutReport check_layout(const ImDrawData& dd, const ImFontAtlas& atlas);

/// Whether the current ImGui context's last frame laid out its windows as the next will: every active window's
/// content drawn this frame has the size its layout was made for. Dear ImGui sizes scroll bars and
/// auto-fitting children from the previous frame's content, so the frame where content first appears (a run's
/// first state) shows them a frame late; the layout report waits for a settled frame.
bool layout_settled();

/// "N glyphs, C clipped, O overlapping" and the first few problems, one per line.
std::string layout_text(const LayoutReport& r, std::size_t max_listed = 8);

}  // namespace sph::gui
