#include "text_batch.h"

#include <algorithm>
#include <cmath>

namespace sph::render {

float TextBatch::add(std::string_view text, float x, float y_top, int scale, Rgba c, Align align) {
  const float s = static_cast<float>(scale);
  const float width = measure(text, scale);
  float pen = x;
  if (align == Align::Center) pen -= 0.5f * width;
  if (align == Align::Right) pen -= width;
  // Whole pixels: with integer scales every glyph texel lands on whole screen pixels.
  pen = std::round(pen);
  const float top = std::round(y_top);
  TextSpan span{std::string(text), INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (char ch : text) {
    const Glyph& g = font_->glyph(ch);
    const float x0 = pen + g.x0 * s, x1 = pen + g.x1 * s, y0 = top + g.y0 * s, y1 = top + g.y1 * s;
    if (x1 > x0 && y1 > y0) {
      const TextVertex a{x0, y0, g.u0, g.v0, c.r, c.g, c.b, c.a}, b{x1, y0, g.u1, g.v0, c.r, c.g, c.b, c.a},
          d{x1, y1, g.u1, g.v1, c.r, c.g, c.b, c.a}, e{x0, y1, g.u0, g.v1, c.r, c.g, c.b, c.a};
      vertices_.insert(vertices_.end(), {a, b, d, a, d, e});
      span.x0 = std::min(span.x0, x0), span.y0 = std::min(span.y0, y0);
      span.x1 = std::max(span.x1, x1), span.y1 = std::max(span.y1, y1);
    }
    pen += g.advance * s;
  }
  if (span.x0 < span.x1) spans_.push_back(std::move(span));
  return width;
}

int TextBatch::fitting_scale(std::string_view text, float width, int scale) const {
  while (scale > 1 && measure(text, scale) > width) --scale;
  return std::max(scale, 1);
}

std::string TextBatch::elided(std::string text, float width, int scale) const {
  if (measure(text, scale) <= width) return text;
  while (!text.empty() && measure(text + "..", scale) > width) text.pop_back();
  return text.empty() ? text : text + "..";
}

}  // namespace sph::render
