// CPU-side overlay geometry: filled rectangles, gradients and antialiased thick lines, as triangles
// in frame pixels for the lines.vert/.frag program.
#pragma once
#include <span>
#include <vector>

#include "overlay_types.h"

namespace sph::render {

/// One vertex of lines.vert: position [px], colour, (signed distance from centre, half width) [px].
struct ShapeVertex {
  float x, y;
  float r, g, b, a;
  float dist, half_width;
};

class ShapeBatch {
 public:
  void clear() { vertices_.clear(); }
  bool empty() const { return vertices_.empty(); }
  const std::vector<ShapeVertex>& vertices() const { return vertices_; }

  void fill_rect(const PixelRect& r, Rgba c);
  /// Rectangle whose colour goes linearly from `bottom` (at r.bottom()) to `top` (at r.y).
  void vertical_gradient(const PixelRect& r, Rgba bottom, Rgba top);
  /// Line of the given width [px] with square caps; centres on pixel centres (k + 0.5) give crisp lines.
  void line(float x0, float y0, float x1, float y1, float width, Rgba c);
  /// Consecutive points (x0,y0,x1,y1,...) joined by lines; non-finite points break the line.
  void polyline(std::span<const float> xy, float width, Rgba c);
  /// Filled, antialiased disc of radius r [px].
  void disc(float cx, float cy, float r, Rgba c);
  /// Outline drawn just inside r.
  void rect_outline(const PixelRect& r, float width, Rgba c);

 private:
  void quad(const ShapeVertex& a, const ShapeVertex& b, const ShapeVertex& c, const ShapeVertex& d);
  std::vector<ShapeVertex> vertices_;
};

}  // namespace sph::render
