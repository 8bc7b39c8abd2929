// The radial profile view (ViewSettings::profile_axis = 3, "r"): a 3D snapshot drawn as its field against
// the distance from the origin, with the reference curve of axis 3; and the log10 colour scale.
#include <gtest/gtest.h>

#include <cmath>

#include "profile_axis.h"
#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class RenderRadial : public OffscreenTest {};

TEST_F(RenderRadial, ThreeDParticlesSitAtTheirRadiusAndValue) {
  const Snapshot s = ball_3d(400);  // rho = 1 / (2 pi r)
  ViewSettings v;
  v.profile_axis = kRadialAxis;
  v.color_by = "rho";
  const auto rgba = render(s, v);
  const SnapshotField& rho = *s.find("rho");
  int found = 0;
  for (std::size_t k : {std::size_t{3}, std::size_t{50}, std::size_t{211}, std::size_t{399}}) {
    const float r = std::sqrt(s.x[k] * s.x[k] + s.y[k] * s.y[k] + s.z[k] * s.z[k]);
    float px = 0, py = 0;
    ASSERT_TRUE(layout().to_pixel(r, rho.values[k], 0.f, &px, &py));
    if (!layout().plot.contains(px, py)) continue;
    const Pixel want = to_pixel8(colormap_rgb(Colormap::Viridis, (rho.values[k] - rho.min) / (rho.max - rho.min)));
    found += colour_near(rgba, kWidth, kHeight, px, py, want, 2, 10) ? 1 : 0;
  }
  EXPECT_GE(found, 3);
  // the horizontal axis starts at r = 0 and reaches the farthest particle (< 1)
  float x0, x1, py;
  ASSERT_TRUE(layout().to_pixel(0.f, rho.min, 0.f, &x0, &py));
  ASSERT_TRUE(layout().to_pixel(0.97f, rho.min, 0.f, &x1, &py));
  EXPECT_TRUE(layout().plot.contains(x0 + 2, layout().plot.y + 5));
  EXPECT_LE(x1, layout().plot.right());
}

TEST_F(RenderRadial, ReferenceCurveAgainstRIsDrawn) {
  Snapshot s = ball_3d(400);
  // a flat reference at rho = 2 along r: drawn in the colour map's contrast colour across the plot
  s.exact = {ExactCurve{"rho", {0.f, 1.f}, {2.f, 2.f}, kRadialAxis}};
  ViewSettings v;
  v.profile_axis = kRadialAxis;
  v.color_by = "rho";
  const auto rgba = render(s, v);
  const Pixel c = to_pixel8(colormap_contrast(Colormap::Viridis));
  float px, py;
  ASSERT_TRUE(layout().to_pixel(0.5f, 2.f, 0.f, &px, &py));
  EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, px, py, c, 2, 12));
}

TEST_F(RenderRadial, LogScaleColoursByLog10) {
  // in a 1D profile the y axis is the shown value: with log_scale, a particle of rho sits at log10 rho
  const Snapshot s = sod_profile_1d(200);
  ViewSettings v;
  v.color_by = "rho";
  v.log_scale = true;
  const auto rgba = render(s, v);
  const SnapshotField& rho = *s.find("rho");
  const std::size_t k = 20;  // left state, rho = 1: log10 = 0
  float px, py;
  ASSERT_TRUE(layout().to_pixel(s.x[k], std::log10(rho.values[k]), 0.f, &px, &py));
  EXPECT_TRUE(layout().plot.contains(px, py));
  EXPECT_GT(count_drawn(rgba, kWidth, {px - 3, py - 3, 6, 6}), 0);
  // and not at the linear value 1 (above log10 of every density here, which is at most 0)
  ASSERT_TRUE(layout().to_pixel(s.x[k], 1.f, 0.f, &px, &py));
  EXPECT_FALSE(layout().plot.contains(px, py) && count_drawn(rgba, kWidth, {px - 3, py - 3, 6, 6}) > 0);
}

}  // namespace
}  // namespace sph::render::test
