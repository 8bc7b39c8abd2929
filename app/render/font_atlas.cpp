#include "font_atlas.h"

#include <stb/stb_truetype.h>  // declarations only: the implementation is Debian's libstb

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "font_data.h"

namespace sph::render {

namespace {

constexpr int kFirst = 32, kLast = 126;  // printable ASCII
constexpr int kCount = kLast - kFirst + 1;
// Ascent + descent [px]: DejaVu Sans Mono then advances ~6.7 px (rounded to 7, as ProggyClean's).
constexpr float kPixelHeight = 13.f;
constexpr int kAtlasWidth = 128;  // [texels]; the height follows from the packing
constexpr int kPad = 1;           // empty texels around each glyph (no bleeding between neighbours)

// Where one glyph's bitmap sits: its box relative to the pen on the baseline, and its atlas corner [px].
struct Placement {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int ax = 0, ay = 0;
};

// Shelf packing in code order: glyphs left to right, a new row when one does not fit. Returns the
// atlas height.
int pack(const stbtt_fontinfo& info, float scale, std::array<Placement, kCount>* places) {
  int x = kPad, y = kPad, row = 0;
  for (int i = 0; i < kCount; ++i) {
    Placement& p = (*places)[static_cast<std::size_t>(i)];
    stbtt_GetCodepointBitmapBox(&info, kFirst + i, scale, scale, &p.x0, &p.y0, &p.x1, &p.y1);
    const int w = p.x1 - p.x0, h = p.y1 - p.y0;
    if (x + w + kPad > kAtlasWidth) {
      x = kPad;
      y += row + kPad;
      row = 0;
    }
    p.ax = x;
    p.ay = y;
    x += w + kPad;
    row = std::max(row, h);
  }
  return y + row + kPad;
}

}  // namespace

bool FontAtlas::build(std::string* err) {
  const std::span<const unsigned char> ttf = overlay_font_ttf();
  stbtt_fontinfo info{};
  if (ttf.empty() || stbtt_InitFont(&info, ttf.data(), stbtt_GetFontOffsetForIndex(ttf.data(), 0)) == 0) {
    if (err) *err = "could not read the overlay font";
    return false;
  }
  const float scale = stbtt_ScaleForPixelHeight(&info, kPixelHeight);
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
  const int baseline = static_cast<int>(std::lround(static_cast<float>(ascent) * scale));
  line_height_ = std::round(static_cast<float>(ascent - descent + gap) * scale);

  std::array<Placement, kCount> places{};
  width_ = kAtlasWidth;
  height_ = pack(info, scale, &places);
  coverage_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0);
  const float iw = 1.f / static_cast<float>(width_), ih = 1.f / static_cast<float>(height_);
  for (int i = 0; i < kCount; ++i) {
    const Placement& p = places[static_cast<std::size_t>(i)];
    const int w = p.x1 - p.x0, h = p.y1 - p.y0;
    if (w > 0 && h > 0) {
      std::uint8_t* corner = coverage_.data() + static_cast<std::size_t>(p.ay) * static_cast<std::size_t>(width_) +
                             static_cast<std::size_t>(p.ax);
      stbtt_MakeCodepointBitmap(&info, corner, w, h, width_, scale, scale, kFirst + i);
    }
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&info, kFirst + i, &advance, &bearing);
    Glyph& g = glyphs_[static_cast<std::size_t>(i)];
    g.x0 = static_cast<float>(p.x0);
    g.x1 = static_cast<float>(p.x1);
    g.y0 = static_cast<float>(baseline + p.y0);
    g.y1 = static_cast<float>(baseline + p.y1);
    g.u0 = static_cast<float>(p.ax) * iw;
    g.u1 = static_cast<float>(p.ax + w) * iw;
    g.v0 = static_cast<float>(p.ay) * ih;
    g.v1 = static_cast<float>(p.ay + h) * ih;
    g.advance = std::round(static_cast<float>(advance) * scale);  // whole pixels: glyphs stay on the grid
  }
  return true;
}

const Glyph& FontAtlas::glyph(char c) const {
  const int i = (c >= kFirst && c <= kLast) ? c : '?';
  return glyphs_[static_cast<std::size_t>(i - kFirst)];
}

float FontAtlas::measure(std::string_view text) const {
  float w = 0.f;
  for (char c : text) w += glyph(c).advance;
  return w;
}

}  // namespace sph::render
