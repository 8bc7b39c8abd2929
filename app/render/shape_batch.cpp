#include "shape_batch.h"

#include <cmath>

namespace sph::render {

namespace {
constexpr float kSolid = 1e6f;  // half width of fills: never fades
ShapeVertex vtx(float x, float y, Rgba c, float dist, float half) { return {x, y, c.r, c.g, c.b, c.a, dist, half}; }
}  // namespace

void ShapeBatch::quad(const ShapeVertex& a, const ShapeVertex& b, const ShapeVertex& c, const ShapeVertex& d) {
  // a-b-c-d counter-clockwise or clockwise; two triangles (a,b,c) (a,c,d).
  vertices_.insert(vertices_.end(), {a, b, c, a, c, d});
}

void ShapeBatch::fill_rect(const PixelRect& r, Rgba c) { vertical_gradient(r, c, c); }

void ShapeBatch::vertical_gradient(const PixelRect& r, Rgba bottom, Rgba top) {
  quad(vtx(r.x, r.y, top, 0, kSolid), vtx(r.right(), r.y, top, 0, kSolid),
       vtx(r.right(), r.bottom(), bottom, 0, kSolid), vtx(r.x, r.bottom(), bottom, 0, kSolid));
}

void ShapeBatch::line(float x0, float y0, float x1, float y1, float width, Rgba c) {
  float dx = x1 - x0, dy = y1 - y0;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (!(len > 0.f)) {
    dx = 1.f;  // a dot: draw a square of the line's width
    dy = 0.f;
  } else {
    dx /= len;
    dy /= len;
  }
  const float half = 0.5f * width;
  const float e = half + 1.f;  // one spare pixel for the antialiased fade
  const float nx = -dy * e, ny = dx * e;
  const float cx = dx * half, cy = dy * half;  // square caps
  quad(vtx(x0 - cx + nx, y0 - cy + ny, c, e, half), vtx(x1 + cx + nx, y1 + cy + ny, c, e, half),
       vtx(x1 + cx - nx, y1 + cy - ny, c, -e, half), vtx(x0 - cx - nx, y0 - cy - ny, c, -e, half));
}

void ShapeBatch::polyline(std::span<const float> xy, float width, Rgba c) {
  for (std::size_t i = 0; i + 3 < xy.size(); i += 2) {
    const float x0 = xy[i], y0 = xy[i + 1], x1 = xy[i + 2], y1 = xy[i + 3];
    if (std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) && std::isfinite(y1))
      line(x0, y0, x1, y1, width, c);
  }
}

void ShapeBatch::disc(float cx, float cy, float r, Rgba c) {
  // Triangle fan; the distance attribute grows radially from 0 to r + 1, so the rim fades like a line's.
  constexpr int kSegments = 32;
  const float e = r + 1.f;
  for (int i = 0; i < kSegments; ++i) {
    const float a0 = 6.2831853f * static_cast<float>(i) / kSegments;
    const float a1 = 6.2831853f * static_cast<float>(i + 1) / kSegments;
    vertices_.insert(vertices_.end(), {vtx(cx, cy, c, 0.f, r),
                                       vtx(cx + e * std::cos(a0), cy + e * std::sin(a0), c, e, r),
                                       vtx(cx + e * std::cos(a1), cy + e * std::sin(a1), c, e, r)});
  }
}

void ShapeBatch::rect_outline(const PixelRect& r, float width, Rgba c) {
  const float h = 0.5f * width;
  const float x0 = r.x + h, y0 = r.y + h, x1 = r.right() - h, y1 = r.bottom() - h;
  line(x0, y0, x1, y0, width, c);
  line(x1, y0, x1, y1, width, c);
  line(x1, y1, x0, y1, width, c);
  line(x0, y1, x0, y0, width, c);
}

}  // namespace sph::render
