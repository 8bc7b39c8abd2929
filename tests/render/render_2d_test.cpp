// 2D frames rendered off-screen: particles drawn, colours at particle centres, the colour bar's
// gradient, fixed ranges, determinism, and no GL errors.
#include <gtest/gtest.h>

#include <cmath>

#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

constexpr int kNx = 20, kNy = 10;  // coarse lattice: discs ~45 px across at 1280x720

class Render2D : public OffscreenTest {};

TEST_F(Render2D, FrameHasTheRequestedSizeAndNoGlError) {
  const auto rgba = render(lattice_2d(kNx, kNy), ViewSettings{}, 640, 360);
  EXPECT_EQ(rgba.size(), 640u * 360u * 4u);
}

TEST_F(Render2D, ParticlesCoverTheDomain) {
  const Snapshot s = lattice_2d(kNx, kNy);
  const auto rgba = render(s, ViewSettings{});
  float x0, y0, x1, y1;
  ASSERT_TRUE(layout().to_pixel(0.f, 1.f, 0.f, &x0, &y0));
  ASSERT_TRUE(layout().to_pixel(2.f, 0.f, 0.f, &x1, &y1));
  const PixelRect domain{x0, y0, x1 - x0, y1 - y0};
  ASSERT_GT(domain.w * domain.h, 0.25f * kWidth * kHeight);  // the domain fills a good part of the frame
  const int drawn = count_drawn(rgba, kWidth, domain);
  EXPECT_GT(drawn, 0.85 * domain.w * domain.h);  // discs of radius 0.6 dx leave only small gaps
}

TEST_F(Render2D, ParticleCentreHasTheMapColourOfItsValue) {
  const Snapshot s = lattice_2d(kNx, kNy);
  for (auto name : colormap_names()) {
    ViewSettings v;
    v.cmap = std::string(name);
    const auto rgba = render(s, v);
    const SnapshotField& rho = *s.find("rho");
    for (int i : {0, 3, 9, 14, 19}) {
      const std::size_t k = lattice_index(kNx, i, 4);
      float px, py;
      ASSERT_TRUE(layout().to_pixel(s.x[k], s.y[k], 0.f, &px, &py));
      const float t = (rho.values[k] - rho.min) / (rho.max - rho.min);
      const Pixel want = to_pixel8(colormap_rgb(*parse_colormap(name), t));
      const Pixel got = pixel_at(rgba, kWidth, static_cast<int>(px), static_cast<int>(py));
      EXPECT_LE(channel_distance(got, want), 3) << name << " particle " << i << ": got " << describe(got)
                                                << " want " << describe(want);
    }
  }
}

TEST_F(Render2D, AFieldSpanningDecadesIsColouredByLog10UnlessLinear) {
  // rho = 10^(3 i / (nx - 1)) along x, 1 to 1000: linear colours put all but the last columns near the
  // bottom of the map (a collapsed sphere in one colour); log10 spreads them evenly
  Snapshot s = lattice_2d(kNx, kNy);
  SnapshotField& rho = const_cast<SnapshotField&>(*s.find("rho"));
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i)
      rho.values[lattice_index(kNx, i, j)] = std::pow(10.f, 3.f * static_cast<float>(i) / (kNx - 1));
  rho.min = 1.f;
  rho.max = 1000.f;
  const std::size_t k = lattice_index(kNx, kNx / 2, 4);  // 10^(30/19) = 38: near the log middle
  const float t_log = std::log10(rho.values[k]) / 3.f, t_lin = (rho.values[k] - 1.f) / 999.f;
  for (bool linear : {false, true}) {
    ViewSettings v;
    v.auto_log = !linear;
    const auto rgba = render(s, v);
    float px, py;
    ASSERT_TRUE(layout().to_pixel(s.x[k], s.y[k], 0.f, &px, &py));
    const Pixel want = to_pixel8(colormap_rgb(Colormap::Viridis, linear ? t_lin : t_log));
    const Pixel got = pixel_at(rgba, kWidth, static_cast<int>(px), static_cast<int>(py));
    EXPECT_LE(channel_distance(got, want), 3) << (linear ? "linear" : "auto log") << ": got " << describe(got)
                                              << " want " << describe(want);
  }
}

TEST_F(Render2D, ColourBarShowsTheMapFromMinToMax) {
  const auto rgba = render(lattice_2d(kNx, kNy), ViewSettings{});
  const PixelRect bar = layout().colorbar;
  ASSERT_GT(bar.h, 100.f);
  ASSERT_GT(bar.w, 4.f);
  const int x = static_cast<int>(bar.x + 0.5f * bar.w);
  int worst = 0;
  for (int y = static_cast<int>(bar.y) + 1; y < static_cast<int>(bar.bottom()) - 1; ++y) {
    const float t = (bar.bottom() - (y + 0.5f)) / bar.h;  // 0 at the bottom, 1 at the top
    const Pixel want = to_pixel8(colormap_rgb(Colormap::Viridis, t));
    worst = std::max(worst, channel_distance(pixel_at(rgba, kWidth, x, y), want));
  }
  EXPECT_LE(worst, 3);
  // Ends: the map's first and last colours.
  const Pixel bottom = pixel_at(rgba, kWidth, x, static_cast<int>(bar.bottom()) - 1);
  const Pixel top = pixel_at(rgba, kWidth, x, static_cast<int>(bar.y));
  EXPECT_LE(channel_distance(bottom, to_pixel8(colormap_rgb(Colormap::Viridis, 0.f))), 3) << describe(bottom);
  EXPECT_LE(channel_distance(top, to_pixel8(colormap_rgb(Colormap::Viridis, 1.f))), 3) << describe(top);
}

TEST_F(Render2D, FixedRangeClampsValuesOutsideIt) {
  const Snapshot s = lattice_2d(kNx, kNy);  // rho in (1, 3)
  ViewSettings v;
  v.auto_range = false;
  v.range_min = 1.f;
  v.range_max = 2.f;
  const auto rgba = render(s, v);
  const std::size_t k = lattice_index(kNx, 17, 5);  // rho = 2.75 > max: the map's top colour
  float px, py;
  ASSERT_TRUE(layout().to_pixel(s.x[k], s.y[k], 0.f, &px, &py));
  const Pixel got = pixel_at(rgba, kWidth, static_cast<int>(px), static_cast<int>(py));
  EXPECT_LE(channel_distance(got, to_pixel8(colormap_rgb(Colormap::Viridis, 1.f))), 3) << describe(got);
}

TEST_F(Render2D, FixedPixelSizeDrawsSmallDots) {
  const Snapshot s = lattice_2d(kNx, kNy);
  ViewSettings v;
  v.size_mode = SizeMode::Pixels;
  v.point_px = 4.f;
  const auto rgba = render(s, v);
  float x0, y0, x1, y1;
  ASSERT_TRUE(layout().to_pixel(0.f, 1.f, 0.f, &x0, &y0));
  ASSERT_TRUE(layout().to_pixel(2.f, 0.f, 0.f, &x1, &y1));
  const int drawn = count_drawn(rgba, kWidth, {x0, y0, x1 - x0, y1 - y0});
  const double disc = 3.14159 * 4.5 * 4.5;  // radius 4 px plus the antialiased rim
  EXPECT_GT(drawn, 0.7 * kNx * kNy * disc);
  EXPECT_LT(drawn, 1.6 * kNx * kNy * disc);
}

TEST_F(Render2D, SameStateGivesIdenticalBytes) {
  const Snapshot a = lattice_2d(kNx, kNy), b = random_cloud(2, 2000);
  ViewSettings v;
  const auto first = render(a, v);
  render(b, v);  // something else in between: no state may leak from frame to frame
  v.cmap = "magma";
  render(a, v);
  v.cmap = "viridis";
  const auto again = render(a, v);
  EXPECT_TRUE(first == again);
}

TEST_F(Render2D, MissingFieldFallsBackWithoutGlErrors) {
  ViewSettings v;
  v.color_by = "no_such_field";
  const auto rgba = render(lattice_2d(kNx, kNy), v);
  EXPECT_GT(layout().colorbar.h, 0.f);  // first field shown instead
  Snapshot bare = lattice_2d(kNx, kNy);
  bare.fields.clear();
  render(bare, v);
  EXPECT_EQ(layout().colorbar.h, 0.f);  // no field at all: no bar
}

TEST_F(Render2D, EmptyAndDegenerateSnapshotsRender) {
  Snapshot empty;
  render(empty, ViewSettings{});
  Snapshot one = lattice_2d(1, 1);
  one.bounds = {0, 0, 0, 0, 0, 0};
  render(one, ViewSettings{});
  Snapshot nan = lattice_2d(4, 4);
  nan.fields[0].values[3] = NAN;
  render(nan, ViewSettings{}, 320, 240);
}

}  // namespace
}  // namespace sph::render::test
