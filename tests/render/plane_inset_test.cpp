// The inset of a plane view (plane_inset.h): a scene's region (Snapshot::inset) drawn enlarged in the
// plot's lower-right corner over the view, its particles where the enlargement puts them and picked there;
// no inset where the view is zoomed in on the region, or where the scene has none.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "render_test_util.h"
#include "sph/snapshot.h"

namespace sph::render::test {
namespace {

class PlaneInset : public OffscreenTest {};

/// Two particles near the origin and one far out, in a domain 8 wide; the inset is the origin's +-0.2.
Snapshot two_near_one_far() {
  Snapshot s;
  s.dim = 2;
  s.count = 3;
  s.x = {0.1f, -0.1f, 3.f};
  s.y = {0.f, 0.1f, 3.f};
  s.z = {0.f, 0.f, 0.f};
  s.h = {0.f, 0.f, 0.f};
  s.bounds = {-4.f, 4.f, -4.f, 4.f, 0.f, 0.f};
  s.inset = {0.0, 0.0, 0.2, "centre"};
  return s;
}

ViewSettings dots() {
  ViewSettings v;
  v.size_mode = SizeMode::Pixels;
  v.point_px = 4.f;
  return v;
}

/// The lower-right third of the plot, where the inset goes.
PixelRect corner(const FrameLayout& L) {
  return {L.plot.x + 0.6f * L.plot.w, L.plot.y + 0.6f * L.plot.h, 0.4f * L.plot.w, 0.4f * L.plot.h};
}

TEST_F(PlaneInset, TheRegionEnlargedInTheCornerWithItsParticles) {
  const Snapshot s = two_near_one_far();
  const auto rgba = render(s, dots());
  const PixelRect c = corner(layout());
  const Pixel dot = to_pixel8(palette::kNoField);
  const int drawn = count_colour(rgba, kWidth, c, dot, 6);
  EXPECT_GT(drawn, 40) << "two dots of radius 4 px in the inset";
  // the dots are where the inset's mapping puts them: particle 0 (0.1, 0) right of particle 1 (-0.1, 0.1)
  // by half the inset's side, which is 0.32 of the plot's smaller side (about 6 times the 0.2 / 8 of the
  // plot they are apart in the view itself)
  const float side = std::round(0.32f * std::min(layout().plot.w, layout().plot.h));
  float sx[2] = {0.f, 0.f}, n[2] = {0.f, 0.f};
  for (int y = static_cast<int>(c.y); y < static_cast<int>(c.bottom()); ++y)
    for (int x = static_cast<int>(c.x); x < static_cast<int>(c.right()); ++x) {
      // a dot's inside (text strokes, antialiased, pass through its colour: never 3 px wide)
      bool inside = true;
      for (const auto& [dx, dy] : {std::pair{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}})
        inside = inside && channel_distance(pixel_at(rgba, kWidth, x + dx, y + dy), dot) <= 6;
      if (!inside) continue;
      const auto p = renderer_->renderer().pick(static_cast<float>(x), static_cast<float>(y), 6.f);
      ASSERT_TRUE(p.has_value()) << x << " " << y;
      ASSERT_LT(p->index, 2u);  // the inset holds the two near particles only
      sx[p->index] += static_cast<float>(x);
      n[p->index] += 1.f;
    }
  ASSERT_GT(n[0], 0.f);
  ASSERT_GT(n[1], 0.f);
  EXPECT_NEAR(sx[0] / n[0] - sx[1] / n[1], 0.5f * side, 2.f);
}

TEST_F(PlaneInset, NoneWhenZoomedInOnTheRegionOrWithoutOne) {
  Snapshot s = two_near_one_far();
  ViewSettings v = dots();
  v.camera2d.fit = false;  // the view 0.8 wide about the origin: the region fills half of it
  v.camera2d.center_x = 0.f;
  v.camera2d.center_y = 0.f;
  v.camera2d.zoom = 10.f;
  auto rgba = render(s, v);
  EXPECT_EQ(count_colour(rgba, kWidth, corner(layout()), to_pixel8(palette::kNoField), 6), 0);
  s.inset = {};
  rgba = render(s, dots());
  EXPECT_EQ(count_colour(rgba, kWidth, corner(layout()), to_pixel8(palette::kNoField), 6), 0);
}

}  // namespace
}  // namespace sph::render::test
