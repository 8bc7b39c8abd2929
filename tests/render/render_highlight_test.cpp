// The inspector's marks (app/render/highlight.h): the picked particle's kernel support drawn as a circle
// of radius R (support x h) in the plane view and as the interval x +- R in a profile.
#include <gtest/gtest.h>

#include "frame_scene.h"
#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class RenderHighlight : public OffscreenTest {};

TEST_F(RenderHighlight, ThePlaneViewCirclesTheKernelSupport) {
  const Snapshot s = lattice_2d(40, 20);  // [0, 2] x [0, 1]
  const std::size_t k = lattice_index(40, 20, 10);
  FrameScene scene;
  scene.a = &s;
  scene.highlight.index = static_cast<std::int64_t>(k);
  scene.highlight.support = 0.3f;
  const auto rgba = render(scene, ViewSettings{});
  float cx, cy, ex, ey;
  ASSERT_TRUE(layout().to_pixel(s.x[k], s.y[k], 0.f, &cx, &cy));
  ASSERT_TRUE(layout().to_pixel(s.x[k] + 0.3f, s.y[k], 0.f, &ex, &ey));
  const float r = ex - cx;
  ASSERT_GT(r, 40.f);
  const Pixel c = to_pixel8(palette::kKernelSupport);
  for (int deg = 0; deg < 360; deg += 45) {  // on the circle, every 45 degrees
    const float a = static_cast<float>(deg) * 3.14159265f / 180.f;
    EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, cx + r * std::cos(a), cy + r * std::sin(a), c, 2, 40)) << deg;
  }
  EXPECT_FALSE(colour_near(rgba, kWidth, kHeight, cx + 0.5f * r, cy, c, 2, 40));  // inside: not the circle
  scene.highlight.support = 0.f;  // none asked for: none drawn
  const auto plain = render(scene, ViewSettings{});
  EXPECT_FALSE(colour_near(plain, kWidth, kHeight, cx + r, cy, c, 2, 40));
}

TEST_F(RenderHighlight, AProfileMarksTheIntervalTheKernelReaches) {
  const Snapshot s = sod_profile_1d(100);
  FrameScene scene;
  scene.a = &s;
  scene.highlight.index = 30;
  scene.highlight.support = 0.1f;
  ViewSettings v;
  v.show_exact = false;
  const auto rgba = render(scene, v);
  float x0, x1, y, cy;
  ASSERT_TRUE(layout().to_pixel(s.x[30] - 0.1f, s.fields[0].values[30], 0.f, &x0, &cy));
  ASSERT_TRUE(layout().to_pixel(s.x[30] + 0.1f, s.fields[0].values[30], 0.f, &x1, &y));
  const Pixel c = to_pixel8(palette::kKernelSupport);
  EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, x0, cy - 4.f, c, 1, 40));  // the end ticks
  EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, x1, cy + 4.f, c, 1, 40));
}

}  // namespace
}  // namespace sph::render::test
