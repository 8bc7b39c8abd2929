// A bitmap font for overlay text: DejaVu Sans Mono (embedded at build time, font_data.h) rasterised on the
// CPU by stb_truetype at a 13 px line; only printable ASCII is kept. Glyph boxes and advances are whole
// pixels, so text drawn at integer scales with nearest filtering stays crisp. Same bytes on every run.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sph::render {

/// One glyph, in font pixels at scale 1, relative to the pen (x) and the top of the line (y).
struct Glyph {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< quad corners [px]
  float u0 = 0, v0 = 0, u1 = 0, v1 = 0;  ///< atlas coordinates
  float advance = 0;                     ///< pen advance [px]
};

class FontAtlas {
 public:
  /// Rasterises the font; false with *err on failure.
  bool build(std::string* err);

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<std::uint8_t>& coverage() const { return coverage_; }  ///< width*height, rows top-down

  float line_height() const { return line_height_; }  ///< [px] at scale 1
  /// The glyph of c; characters outside printable ASCII map to '?'.
  const Glyph& glyph(char c) const;
  /// Width of the text at scale 1 [px].
  float measure(std::string_view text) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> coverage_;
  float line_height_ = 13.f;
  std::array<Glyph, 95> glyphs_{};  // ' ' .. '~'
};

}  // namespace sph::render
