// Frames of an A/B comparison and profile panels (compare_view.cpp, profile_view.cpp): in 1D both runs'
// dots in their two colours with the exact curve and each run's L1 in the legend; panels one per field,
// each with its exact curve; in 2D the difference map B - A in the right third, red where B is larger.
#include <gtest/gtest.h>

#include <cmath>

#include "frame_scene.h"
#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class RenderCompare : public OffscreenTest {};

TEST_F(RenderCompare, ProfileShowsBothRunsInTheirColoursWithTheirL1) {
  const Snapshot a = sod_profile_1d(400), b = sod_profile_1d_run_b(400);
  FrameScene scene = m4_against_m6(a, b);
  scene.errors_a = {{"count", 400}, {"L1_rho", 0.00304}};
  scene.errors_b = {{"count", 400}, {"L1_rho", 0.0121}};
  const auto rgba = render(scene, ViewSettings{});
  ASSERT_EQ(layout().legend_rows.size(), 3u);
  EXPECT_EQ(layout().legend_rows[0], "exact");
  EXPECT_EQ(layout().legend_rows[1], "A: kernel.type=M4   L1_rho = 0.00304");
  EXPECT_EQ(layout().legend_rows[2], "B: kernel.type=M6   L1_rho = 0.0121");
  {  // an error not defined yet (NaN): the label alone, never "nan"
    FrameScene undefined = scene;
    undefined.errors_b = {{"L1_rho", std::nan("")}};
    render(undefined, ViewSettings{});
    ASSERT_EQ(layout().legend_rows.size(), 3u);
    EXPECT_EQ(layout().legend_rows[2], "B: kernel.type=M6");
    render(scene, ViewSettings{});  // the frame the checks below look at
  }
  EXPECT_EQ(layout().colorbar.w, 0.f);  // two colours, no colour map
  // where the runs differ, each run's dots are in its own colour at its own values
  const Pixel ca = to_pixel8(kRunColors[0]), cb = to_pixel8(kRunColors[1]);
  int checked = 0, found_a = 0, found_b = 0;
  for (std::size_t i = 0; i < a.count; i += 3) {
    if (!(a.x[i] > 0.02f && a.x[i] < 0.13f)) continue;
    float px, py;
    ASSERT_TRUE(layout().to_pixel(a.x[i], a.fields[0].values[i], 0.f, &px, &py));
    found_a += colour_near(rgba, kWidth, kHeight, px, py, ca, 3, 20);  // beside the exact curve over it
    ASSERT_TRUE(layout().to_pixel(b.x[i], b.fields[0].values[i], 0.f, &px, &py));
    found_b += colour_near(rgba, kWidth, kHeight, px, py, cb, 1, 20);
    ++checked;
  }
  EXPECT_GT(checked, 10);
  EXPECT_EQ(found_a, checked);
  EXPECT_EQ(found_b, checked);
  // the exact curve in the comparison's white
  float px, py;
  ASSERT_TRUE(layout().to_pixel(-0.45f, 1.f, 0.f, &px, &py));
  EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, px, py, to_pixel8(kCompareExact), 2, 30));
}

TEST_F(RenderCompare, PanelsOnePerFieldEachWithItsExactCurve) {
  const Snapshot s = sod_profile_1d(400);
  ViewSettings v;
  v.panels = {"rho", "p"};
  const auto rgba = render(s, v);
  // two legends (exact, particles), the colour bar of the colour-by field
  ASSERT_EQ(layout().legend_rows.size(), 4u);
  EXPECT_GT(layout().colorbar.h, 50.f);
  // the exact curves: the density's in the left half, the pressure's in the right half
  const Pixel curve = to_pixel8(colormap_contrast(Colormap::Viridis));
  const PixelRect left{0, 0, kWidth / 2.f, static_cast<float>(kHeight)}, right{kWidth / 2.f, 0, kWidth / 2.f, static_cast<float>(kHeight)};
  EXPECT_GT(count_colour(rgba, kWidth, left, curve, 12), 200);
  EXPECT_GT(count_colour(rgba, kWidth, right, curve, 12), 200);
  // a field the scene lacks is a panel saying so, not a crash
  v.panels = {"rho", "u"};
  render(s, v);
  EXPECT_EQ(layout().legend_rows.size(), 2u);  // no curve, one run: the u panel has no legend
}

TEST_F(RenderCompare, DifferenceMapIsRedWhereBIsLarger) {
  const Snapshot a = lattice_2d(40, 20);
  Snapshot b = a;
  SnapshotField& rho = b.fields.front();
  for (std::size_t i = 0; i < b.count; ++i)
    if (b.x[i] > 1.5f) rho.values[i] += 0.5f;  // B larger on the right quarter of the domain
  rho.max += 0.5f;
  FrameScene scene;
  scene.a = &a;
  scene.b = &b;
  const auto rgba = render(scene, ViewSettings{});
  const Rgb hot = colormap_rgb(Colormap::Coolwarm, 1.f), cold = colormap_rgb(Colormap::Coolwarm, 0.f);
  const float third = kWidth / 3.f;
  const PixelRect left{0, 0, 2.f * third, static_cast<float>(kHeight)}, right{2.f * third, 0, third, static_cast<float>(kHeight)};
  // the map: B - A > 0 on a quarter of the particles, nowhere < 0 (the map's own colour bar has a few
  // pixels of each end)
  const int n_hot = count_colour(rgba, kWidth, right, to_pixel8(hot), 20);
  const int n_cold = count_colour(rgba, kWidth, right, to_pixel8(cold), 20);
  EXPECT_GT(n_hot - n_cold, 500) << n_hot << " " << n_cold;
  EXPECT_LT(n_cold, 150);
  EXPECT_EQ(count_colour(rgba, kWidth, left, to_pixel8(hot), 20), 0);  // A and B use viridis
}

TEST_F(RenderCompare, PickFindsTheParticleAndTheHighlightRingsIt) {
  const Snapshot s = sod_profile_1d(100);
  FrameScene scene;
  scene.a = &s;
  scene.highlight.index = 60;
  scene.highlight.neighbours = {{59, 1.f}, {61, 0.5f}};
  ViewSettings v;
  v.show_exact = false;
  const auto rgba = render(scene, v);
  float px, py;
  ASSERT_TRUE(layout().to_pixel(s.x[60], s.fields[0].values[60], 0.f, &px, &py));
  const auto picked = renderer_->renderer().pick(px + 1.f, py, 5.f);
  ASSERT_TRUE(picked.has_value());
  EXPECT_EQ(picked->index, 60u);
  EXPECT_EQ(picked->run, 0);
  EXPECT_FALSE(renderer_->renderer().pick(px, py - 200.f, 5.f).has_value());
  // a white ring of radius ~ 5 s + 2 + 2 s px around it (text scale 2 at 720 px)
  const float r = 5.f * 2 + 2.f + 2.f * 2;
  EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, px + r, py, to_pixel8(palette::kText), 2, 40));
  EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, px, py - r, to_pixel8(palette::kText), 2, 40));
}

}  // namespace
}  // namespace sph::render::test
