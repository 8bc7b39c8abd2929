// Colour maps: the published end points, the 8-bit table, the GPU-equivalent interpolation, and the
// properties that make them fit for data (monotone lightness for the sequential maps).
#include <gtest/gtest.h>

#include <cmath>

#include "colormap.h"
#include "palette.h"

namespace sph::render {
namespace {

// Relative luminance of sRGB (ITU-R BT.709 weights on linearised channels).
float luminance(Rgb c) {
  auto lin = [](float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); };
  return 0.2126f * lin(c.r) + 0.7152f * lin(c.g) + 0.0722f * lin(c.b);
}

void expect_rgb(Rgb c, float r, float g, float b, float tol) {
  EXPECT_NEAR(c.r, r, tol);
  EXPECT_NEAR(c.g, g, tol);
  EXPECT_NEAR(c.b, b, tol);
}

TEST(Colormap, NamesParseAndRoundTrip) {
  ASSERT_EQ(colormap_names().size(), 4u);
  EXPECT_EQ(colormap_names()[0], "viridis");  // the default comes first
  for (auto name : colormap_names()) {
    const auto map = parse_colormap(name);
    ASSERT_TRUE(map.has_value()) << name;
    EXPECT_EQ(to_string(*map), name);
  }
  EXPECT_FALSE(parse_colormap("jet").has_value());
  EXPECT_EQ(colormap_name_list(), "viridis, magma, cividis, coolwarm");
}

TEST(Colormap, EndPointsAreThePublishedValues) {
  // First and last entries of the published tables (matplotlib _cm_listed.py; Moreland 2009).
  expect_rgb(colormap_exact(Colormap::Viridis, 0.f), 0.267004f, 0.004874f, 0.329415f, 1e-6f);
  expect_rgb(colormap_exact(Colormap::Viridis, 1.f), 0.993248f, 0.906157f, 0.143936f, 1e-6f);
  expect_rgb(colormap_exact(Colormap::Magma, 0.f), 0.001462f, 0.000466f, 0.013866f, 1e-6f);
  expect_rgb(colormap_exact(Colormap::Magma, 1.f), 0.987053f, 0.991438f, 0.749504f, 1e-6f);
  expect_rgb(colormap_exact(Colormap::Cividis, 0.f), 0.0f, 0.135112f, 0.304751f, 1e-6f);
  expect_rgb(colormap_exact(Colormap::Cividis, 1.f), 0.995737f, 0.909344f, 0.217772f, 1e-6f);
  expect_rgb(colormap_exact(Colormap::Coolwarm, 0.f), 0.2298057f, 0.29871797f, 0.75368315f, 1e-6f);
  expect_rgb(colormap_exact(Colormap::Coolwarm, 1.f), 0.70567316f, 0.01555616f, 0.15023281f, 1e-6f);
  // Interior published entries: viridis #128 and magma #64 of 256.
  expect_rgb(colormap_exact(Colormap::Viridis, 128.f / 255.f), 0.127568f, 0.566949f, 0.550556f, 1e-6f);
  expect_rgb(colormap_exact(Colormap::Magma, 64.f / 255.f), 0.316654f, 0.071690f, 0.485380f, 1e-6f);
}

TEST(Colormap, InterpolationReproducesPublishedEntriesBetweenControlPoints) {
  // Entries that are not control points: within 0.6/255 by construction of the tables.
  const float tol = 0.6f / 255.f;
  expect_rgb(colormap_exact(Colormap::Viridis, 100.f / 255.f), 0.166617f, 0.463708f, 0.558119f, tol);
  expect_rgb(colormap_exact(Colormap::Viridis, 220.f / 255.f), 0.636902f, 0.856542f, 0.216620f, tol);
  expect_rgb(colormap_exact(Colormap::Magma, 100.f / 255.f), 0.537755f, 0.156894f, 0.506551f, tol);
  expect_rgb(colormap_exact(Colormap::Magma, 200.f / 255.f), 0.992785f, 0.594891f, 0.410283f, tol);
  expect_rgb(colormap_exact(Colormap::Cividis, 20.f / 255.f), 0.0f, 0.188769f, 0.439563f, tol);
  expect_rgb(colormap_exact(Colormap::Cividis, 180.f / 255.f), 0.687957f, 0.641966f, 0.442886f, tol);
  expect_rgb(colormap_exact(Colormap::Coolwarm, 0.5f), 0.865395197f, 0.86541021f, 0.865395561f, 1e-6f);
}

TEST(Colormap, OutOfRangeAndNaNClamp) {
  for (auto name : colormap_names()) {
    const Colormap m = *parse_colormap(name);
    const Rgb lo = colormap_exact(m, 0.f), hi = colormap_exact(m, 1.f);
    expect_rgb(colormap_exact(m, -3.f), lo.r, lo.g, lo.b, 0.f);
    expect_rgb(colormap_exact(m, 7.f), hi.r, hi.g, hi.b, 0.f);
    expect_rgb(colormap_exact(m, NAN), lo.r, lo.g, lo.b, 0.f);
  }
}

TEST(Colormap, LutIsTheExactMapRoundedTo8Bits) {
  for (auto name : colormap_names()) {
    const Colormap m = *parse_colormap(name);
    const ColormapLut& lut = colormap_lut(m);
    const float t0 = colormap_low_end(m);
    for (int i = 0; i < kColormapLutSize; ++i) {
      const Rgb e = colormap_exact(m, t0 + (1.f - t0) * (i / 255.f));
      EXPECT_NEAR(lut[4 * i] / 255.f, e.r, 0.5f / 255.f + 1e-6f) << name << " " << i;
      EXPECT_NEAR(lut[4 * i + 1] / 255.f, e.g, 0.5f / 255.f + 1e-6f) << name << " " << i;
      EXPECT_NEAR(lut[4 * i + 2] / 255.f, e.b, 0.5f / 255.f + 1e-6f) << name << " " << i;
      EXPECT_EQ(lut[4 * i + 3], 255);
      // colormap_rgb hits the table entries exactly at t = i/255.
      const Rgb g = colormap_rgb(m, i / 255.f);
      EXPECT_NEAR(g.r * 255.f, lut[4 * i], 1e-3f);
    }
  }
}

// Low values were dark purple (viridis) or black (magma) dots on the dark-grey plot: every shown colour of
// every map now keeps a contrast ratio of 1.5 against the plot fill and the frame background.
TEST(Colormap, EveryShownColourStandsOutFromTheBackgrounds) {
  for (auto name : colormap_names()) {
    const Colormap m = *parse_colormap(name);
    for (int i = 0; i <= 1020; ++i) {
      const Rgb c = colormap_rgb(m, i / 1020.f);
      for (const Rgba& bg : {palette::kPlotFill, palette::kBackground})
        EXPECT_GE(contrast_ratio(c, {bg.r, bg.g, bg.b}), kMinBackgroundContrast) << name << " at t = " << i / 1020.f;
    }
    EXPECT_LT(colormap_low_end(m), 0.4f) << name << " keeps most of its published range";
  }
  EXPECT_EQ(colormap_low_end(Colormap::Coolwarm), 0.f);  // its blue end is light enough already
  EXPECT_GT(contrast_ratio({1, 1, 1}, {0, 0, 0}), 20.9f);
  EXPECT_LT(contrast_ratio({1, 1, 1}, {0, 0, 0}), 21.1f);
}

TEST(Colormap, SequentialMapsGetLighterMonotonically) {
  for (Colormap m : {Colormap::Viridis, Colormap::Magma, Colormap::Cividis}) {
    float prev = -1.f;
    for (int i = 0; i <= 64; ++i) {
      const float y = luminance(colormap_exact(m, i / 64.f));
      EXPECT_GT(y, prev) << to_string(m) << " at " << i;
      prev = y;
    }
  }
}

TEST(Colormap, CoolwarmIsBlueToRedThroughLightGrey) {
  const Rgb lo = colormap_exact(Colormap::Coolwarm, 0.f), mid = colormap_exact(Colormap::Coolwarm, 0.5f),
            hi = colormap_exact(Colormap::Coolwarm, 1.f);
  EXPECT_GT(lo.b, lo.r);
  EXPECT_GT(hi.r, hi.b);
  EXPECT_NEAR(mid.r, mid.g, 0.05f);  // nearly neutral at the centre
  EXPECT_NEAR(mid.g, mid.b, 0.05f);
  EXPECT_GT(luminance(mid), luminance(lo));
  EXPECT_GT(luminance(mid), luminance(hi));
}

TEST(Colormap, ContrastColourIsFarFromEveryColourOfItsMap) {
  for (auto name : colormap_names()) {
    const Colormap m = *parse_colormap(name);
    const Rgb c = colormap_contrast(m);
    float nearest = 1e9f;
    for (int i = 0; i <= 255; ++i) {
      const Rgb e = colormap_exact(m, i / 255.f);
      nearest = std::min(nearest, std::hypot(c.r - e.r, c.g - e.g, c.b - e.b));
    }
    EXPECT_GT(nearest, 0.25f) << name;
  }
}

}  // namespace
}  // namespace sph::render
