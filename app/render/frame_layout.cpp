#include "frame_layout.h"

#include <algorithm>

namespace sph::render {

bool FrameLayout::to_pixel(float x, float y, float z, float* px, float* py) const {
  const Vec4f c = plot_to_clip * Vec4f{x, y, z, 1.f};
  if (!(c.w > 0.f)) return false;
  const float nx = c.x / c.w, ny = c.y / c.w;
  *px = plot.x + (0.5f * nx + 0.5f) * plot.w;
  *py = plot.y + (0.5f - 0.5f * ny) * plot.h;
  return true;
}

int text_scale_for(int height, int requested) {
  if (requested > 0) return requested;
  return std::max(1, (height + 180) / 450);  // 480 -> 1, 720 -> 2, 1080 -> 2, 1440 -> 3
}

}  // namespace sph::render
