// 1D frames: a profile plot of the field against x, with the exact curve drawn over the particles.
#include <gtest/gtest.h>

#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class Render1D : public OffscreenTest {
 protected:
  // Is there a pixel within +-radius of (px, py) with colour c?
  static bool colour_near(const std::vector<std::uint8_t>& rgba, float px, float py, Pixel c, int radius, int tol) {
    return test::colour_near(rgba, kWidth, kHeight, px, py, c, radius, tol);
  }
};

TEST_F(Render1D, ExactCurveIsDrawnAlongItsPath) {
  const Snapshot s = sod_profile_1d(400);
  const auto rgba = render(s, ViewSettings{});
  const Pixel curve = to_pixel8(colormap_contrast(Colormap::Viridis));
  int checked = 0, found = 0;
  for (float x = -0.48f; x <= 0.48f; x += 0.01f) {
    // Skip the jumps, where the curve runs vertically.
    if (std::abs(x - 0.1855f) < 0.01f || std::abs(x - 0.3504f) < 0.01f) continue;
    float px, py;
    ASSERT_TRUE(layout().to_pixel(x, sod_exact_rho(x), 0.f, &px, &py));
    ++checked;
    found += colour_near(rgba, px, py, curve, 1, 12);
  }
  EXPECT_EQ(found, checked);
}

TEST_F(Render1D, ParticlesAreDotsAtTheirValues) {
  const Snapshot s = sod_profile_1d(200);
  ViewSettings v;
  v.show_exact = false;  // nothing drawn over the dots
  const auto rgba = render(s, v);
  const SnapshotField& rho = *s.find("rho");
  for (std::size_t i = 0; i < s.count; i += 17) {
    float px, py;
    ASSERT_TRUE(layout().to_pixel(s.x[i], rho.values[i], 0.f, &px, &py));
    const Pixel want = to_pixel8(colormap_rgb(Colormap::Viridis, (rho.values[i] - rho.min) / (rho.max - rho.min)));
    EXPECT_TRUE(colour_near(rgba, px, py, want, 1, 6)) << "particle " << i;
  }
  // And the curve colour appears nowhere.
  const Pixel curve = to_pixel8(colormap_contrast(Colormap::Viridis));
  int curve_pixels = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) curve_pixels += channel_distance(pixel_at(rgba, kWidth, x, y), curve) <= 12;
  EXPECT_EQ(curve_pixels, 0);
}

TEST_F(Render1D, AxesCoverTheDataAndTheColourBarIsThere) {
  const Snapshot s = sod_profile_1d(400);
  const auto rgba = render(s, ViewSettings{});
  const PixelRect plot = layout().plot;
  for (float x : {-0.5f, 0.5f})
    for (float v : {0.125f, 1.0f}) {
      float px, py;
      ASSERT_TRUE(layout().to_pixel(x, v, 0.f, &px, &py));
      EXPECT_TRUE(plot.contains(px, py)) << x << " " << v;
    }
  EXPECT_GT(layout().colorbar.h, 100.f);
  EXPECT_GT(count_drawn(rgba, kWidth, plot), 2000);
}

TEST_F(Render1D, OtherFieldUsesItsOwnCurve) {
  const Snapshot s = sod_profile_1d(400);
  ViewSettings v;
  v.color_by = "p";
  v.cmap = "magma";
  const auto rgba = render(s, v);
  const Pixel curve = to_pixel8(colormap_contrast(Colormap::Magma));
  float px, py;
  ASSERT_TRUE(layout().to_pixel(0.1f, 0.30313f, 0.f, &px, &py));  // pressure plateau between the waves
  EXPECT_TRUE(colour_near(rgba, px, py, curve, 1, 12));
}


// The legend sat in the top-right corner over the data (the shock in v_x, the u plateau). Mirrored Sod
// has its rho = 1 plateau along the top right: the legend moves to where no particle or curve is.
TEST_F(Render1D, LegendCoversNoData) {
  Snapshot s = sod_profile_1d(400);
  for (float& x : s.x) x = -x;
  for (ExactCurve& c : s.exact)
    for (float& x : c.x) x = -x;
  for (const char* field : {"rho", "p"}) {
    ViewSettings v;
    v.color_by = field;
    render(s, v);
    const FrameLayout L = layout();
    const PixelRect r = L.legend;
    ASSERT_GT(r.w, 0.f) << field;
    const float clear = 0.5f * v.point_px * 3.f;  // a dot's radius at this frame size
    auto covered = [&](float x, float value) {
      float px, py;
      return L.to_pixel(x, value, 0.f, &px, &py) && px >= r.x - clear && px <= r.right() + clear &&
             py >= r.y - clear && py <= r.bottom() + clear;
    };
    const SnapshotField& f = *s.find(field);
    for (std::size_t i = 0; i < s.count; ++i) EXPECT_FALSE(covered(s.x[i], f.values[i])) << field << " particle " << i;
    for (const ExactCurve& c : s.exact) {
      if (c.field != field) continue;
      for (std::size_t i = 0; i < c.x.size(); ++i) EXPECT_FALSE(covered(c.x[i], c.value[i])) << field << " curve " << i;
    }
  }
}

}  // namespace
}  // namespace sph::render::test
