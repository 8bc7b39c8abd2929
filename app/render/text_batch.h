// CPU-side text layout: glyph quads in frame pixels for the text.vert/.frag program.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "font_atlas.h"
#include "overlay_types.h"

namespace sph::render {

/// Where one line of text went: its box [px] (the glyphs' ink) and the text, for layout checks.
struct TextSpan {
  std::string text;
  float x0 = 0.f, y0 = 0.f, x1 = 0.f, y1 = 0.f;
};

/// One vertex of text.vert: position [px], atlas coordinates, colour.
struct TextVertex {
  float x, y;
  float u, v;
  float r, g, b, a;
};

class TextBatch {
 public:
  explicit TextBatch(const FontAtlas& font) : font_(&font) {}
  void clear() {
    vertices_.clear();
    spans_.clear();
  }
  const std::vector<TextVertex>& vertices() const { return vertices_; }
  const std::vector<TextSpan>& spans() const { return spans_; }

  /// Draws one line of text; (x, y_top) is the anchor on the top edge of the line, aligned by `align`.
  /// `scale` is an integer pixel scale of the 13 px font. Returns the text width [px].
  float add(std::string_view text, float x, float y_top, int scale, Rgba color, Align align = Align::Left);
  float measure(std::string_view text, int scale) const { return font_->measure(text) * static_cast<float>(scale); }
  float line_height(int scale) const { return font_->line_height() * static_cast<float>(scale); }
  /// The largest scale in [1, scale] at which `text` is at most `width` wide (1 when none is).
  int fitting_scale(std::string_view text, float width, int scale) const;
  /// `text` cut with ".." to at most `width` at `scale` (whole when it fits).
  std::string elided(std::string text, float width, int scale) const;

 private:
  const FontAtlas* font_;
  std::vector<TextVertex> vertices_;
  std::vector<TextSpan> spans_;
};

}  // namespace sph::render
