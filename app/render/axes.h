// Axes for the 1D profile and the 2D view: a box with ticks, round-number labels, axis titles
// and optional grid lines. Data map linearly onto the box.
#pragma once
#include <string>

#include "frame_build.h"

namespace sph::render {

/// Linear data ranges shown by an axes box.
struct AxesRanges {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
};

struct AxesStyle {
  std::string x_title = "x";
  std::string y_title;
  bool grid = false;
  bool x_labels = true;  ///< false: ticks only, no x tick labels or x title (a panel stacked on another)
};

/// Tick counts that suit a box of this size (about one label per 100 px across, 50 px up at scale 1).
int x_tick_target(float box_w, int s);
int y_tick_target(float box_h, int s);

/// Room the labels need around the box inside `area`, given the widest y label [px]. `aspect`
/// (width/height) > 0 shrinks the box to that shape, centred; without x_labels no room is kept for the
/// x tick labels and title. The result has whole-pixel edges.
PixelRect axes_box(const PixelRect& area, float y_label_width, int s, float lh, float aspect, bool x_labels = true);
/// Width of the widest y tick label for these data limits and box height.
float y_label_width(const TextBatch& text, double y0, double y1, float box_h, int s);

/// Draws the box (fill into `under`, frame and ticks into `over`), grid, labels and titles.
void add_axes(FrameBuild& f, const PixelRect& box, const AxesRanges& r, const AxesStyle& style);

}  // namespace sph::render
