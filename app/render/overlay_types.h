// Shared plain types of the overlay: colours and rectangles in frame pixels (origin top-left, y down).
#pragma once

namespace sph::render {

/// Straight-alpha colour, channels in [0,1].
struct Rgba {
  float r = 0.f, g = 0.f, b = 0.f, a = 1.f;
};

/// Axis-aligned rectangle in frame pixels.
struct PixelRect {
  float x = 0.f, y = 0.f, w = 0.f, h = 0.f;
  float right() const { return x + w; }
  float bottom() const { return y + h; }
  bool contains(float px, float py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

enum class Align { Left, Center, Right };

}  // namespace sph::render
