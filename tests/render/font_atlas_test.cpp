// The overlay font (app/render/font_atlas.h): DejaVu Sans Mono embedded at build time and rasterised by
// stb_truetype. A 13 px line with whole-pixel, monospace advances (the layout's widths), ink on every
// printable glyph inside its atlas cell, and the same bytes from every build.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "font_atlas.h"

namespace sph::render {
namespace {

FontAtlas built() {
  FontAtlas font;
  std::string err;
  EXPECT_TRUE(font.build(&err)) << err;
  return font;
}

// Sum of the coverage under a glyph's atlas rectangle.
long ink(const FontAtlas& font, const Glyph& g) {
  const auto texel = [](float t, int size) { return static_cast<int>(std::lround(t * static_cast<float>(size))); };
  const int x0 = texel(g.u0, font.width()), x1 = texel(g.u1, font.width());
  const int y0 = texel(g.v0, font.height()), y1 = texel(g.v1, font.height());
  long sum = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) sum += font.coverage()[static_cast<std::size_t>(y * font.width() + x)];
  return sum;
}

TEST(FontAtlas, ThirteenPixelLineAndSevenPixelMonospaceAdvance) {
  const FontAtlas font = built();
  EXPECT_EQ(font.line_height(), 13.f);
  for (char c = ' '; c <= '~'; ++c) EXPECT_EQ(font.glyph(c).advance, 7.f) << c;
  EXPECT_EQ(font.measure("t = 0.2000"), 70.f);
}

TEST(FontAtlas, EveryPrintableGlyphHasInkOnWholePixels) {
  const FontAtlas font = built();
  ASSERT_EQ(font.coverage().size(), static_cast<std::size_t>(font.width() * font.height()));
  for (char c = '!'; c <= '~'; ++c) {
    const Glyph& g = font.glyph(c);
    EXPECT_GT(g.x1, g.x0) << c;
    EXPECT_GT(g.y1, g.y0) << c;
    for (float v : {g.x0, g.y0, g.x1, g.y1}) EXPECT_EQ(v, std::round(v)) << c;
    // the quad and its atlas rectangle have the same size in pixels (drawn 1:1 at scale 1)
    EXPECT_NEAR((g.u1 - g.u0) * static_cast<float>(font.width()), g.x1 - g.x0, 1e-3) << c;
    EXPECT_NEAR((g.v1 - g.v0) * static_cast<float>(font.height()), g.y1 - g.y0, 1e-3) << c;
    EXPECT_GT(ink(font, g), 0) << c;
  }
  const Glyph& space = font.glyph(' ');
  EXPECT_EQ(space.x1 - space.x0, 0.f);  // nothing drawn, only the advance
}

TEST(FontAtlas, CapitalsSitOnTheSameBaselineWithinTheLine) {
  const FontAtlas font = built();
  const Glyph& h = font.glyph('H');
  EXPECT_EQ(font.glyph('E').y1, h.y1);
  EXPECT_GE(h.y0, 0.f);
  EXPECT_LE(font.glyph('g').y1, font.line_height());  // descenders stay inside the line
  EXPECT_GT(font.glyph('g').y1, h.y1);
}

TEST(FontAtlas, OutsideAsciiMapsToTheQuestionMark) {
  const FontAtlas font = built();
  EXPECT_EQ(&font.glyph('\t'), &font.glyph('?'));
  EXPECT_EQ(&font.glyph(static_cast<char>(0xe9)), &font.glyph('?'));
}

TEST(FontAtlas, EveryBuildGivesTheSameBytes) {
  const FontAtlas a = built(), b = built();
  EXPECT_EQ(a.width(), b.width());
  EXPECT_EQ(a.height(), b.height());
  EXPECT_EQ(a.coverage(), b.coverage());
}

}  // namespace
}  // namespace sph::render
