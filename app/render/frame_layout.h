// Where things go in a frame: title row, plot (the particles' viewport), colour bar; and the mapping
// from plot coordinates to frame pixels, kept for tests and for the GUI (picking, pan and zoom).
#pragma once
#include <string>
#include <vector>

#include "mat4.h"
#include "overlay_types.h"

namespace sph::render {

struct FrameLayout {
  int width = 0, height = 0;  ///< frame size [px]
  int text_scale = 1;         ///< integer scale of the 13 px font
  float margin = 10.f;        ///< outer margin [px]
  PixelRect title;            ///< title row
  PixelRect content;          ///< area left of the colour-bar panel, below the title
  PixelRect plot;             ///< particles' viewport: axes box (1D, 2D) or 3D view; whole pixels
  PixelRect colorbar;         ///< the gradient bar (empty when no field is shown)
  PixelRect legend;           ///< the plot's legend box (empty when it has none)
  std::vector<std::string> legend_rows;  ///< the text of every legend row drawn, in order (tests, reports)
  PixelRect panel;            ///< colour-bar panel: field label, bar, value labels
  Mat4 plot_to_clip;          ///< 2D/3D: world -> clip; 1D: (x, value, 0) -> clip

  /// Frame pixel (top-left origin, continuous: pixel (i, j) spans [i, i+1)) of a plot-space point;
  /// false if it is behind the 3D camera.
  bool to_pixel(float x, float y, float z, float* px, float* py) const;
};

/// Text scale for a frame height (720 px -> 2, i.e. 26 px text), unless `requested` > 0.
int text_scale_for(int height, int requested);

}  // namespace sph::render
