// Reference outlines (Snapshot::outlines) over 2D views: drawn along their path in the palette's
// colours, clipped to the plot, with a legend for labels; hidden on request; empty, one-point and
// broken outlines are harmless; 3D views and profiles ignore them.
#include <gtest/gtest.h>

#include <cmath>

#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

constexpr int kNx = 20, kNy = 10;
constexpr float kCx = 1.f, kCy = 0.5f, kR = 0.3f;  // the test circle [world units]

class RenderOutline : public OffscreenTest {
 protected:
  static Snapshot with_circle(std::string label = "exact circle") {
    Snapshot s = lattice_2d(kNx, kNy);
    s.outlines = {circle_outline(std::move(label), kCx, kCy, kR, 256)};
    return s;
  }
  bool near(const std::vector<std::uint8_t>& rgba, float wx, float wy, Rgba c, int tol = 12) const {
    float px = 0, py = 0;
    EXPECT_TRUE(layout().to_pixel(wx, wy, 0.f, &px, &py));
    return colour_near(rgba, kWidth, kHeight, px, py, to_pixel8(c), 1, tol);
  }
  // Where the legend goes: the top-right corner of the plot (above the circle).
  PixelRect legend_zone() const {
    const PixelRect& p = layout().plot;
    return {p.right() - 0.45f * p.w, p.y, 0.45f * p.w, 0.15f * p.h};
  }
};

TEST_F(RenderOutline, CircleIsDrawnAlongItsPathOverTheParticles) {
  const Snapshot s = with_circle();
  const auto rgba = render(s, ViewSettings{});
  int found = 0;
  for (int k = 0; k < 36; ++k) {
    const float a = 6.2831853f * k / 36.f;
    found += near(rgba, kCx + kR * std::cos(a), kCy + kR * std::sin(a), palette::kOutlines[0]);
  }
  EXPECT_EQ(found, 36);
  // Inside and outside the line: the particles' colours, no outline.
  for (float r : {0.5f * kR, 1.4f * kR})
    EXPECT_FALSE(near(rgba, kCx + r, kCy, palette::kOutlines[0], 40)) << "radius " << r;
}

TEST_F(RenderOutline, LegendShowsLabelsOnly) {
  const auto labelled = render(with_circle(), ViewSettings{});
  const PixelRect zone = legend_zone();
  const auto unlabelled = render(with_circle(""), ViewSettings{});
  Snapshot bare = lattice_2d(kNx, kNy);
  const auto none = render(bare, ViewSettings{});
  const Pixel white = to_pixel8(palette::kOutlines[0]);
  EXPECT_GT(count_colour(labelled, kWidth, zone, white, 12), 20);  // the legend's sample line
  EXPECT_EQ(count_colour(unlabelled, kWidth, zone, white, 12), 0);
  int differ = 0;
  for (int y = static_cast<int>(zone.y); y < static_cast<int>(zone.bottom()); ++y)
    for (int x = static_cast<int>(zone.x); x < static_cast<int>(zone.right()); ++x)
      differ += channel_distance(pixel_at(unlabelled, kWidth, x, y), pixel_at(none, kWidth, x, y)) > 0;
  EXPECT_EQ(differ, 0);
}

TEST_F(RenderOutline, EachLabelHasItsOwnColour) {
  Snapshot s = with_circle("A");
  Outline b;
  b.label = "B";
  b.x = {0.2f, 0.6f};
  b.y = {0.15f, 0.15f};
  s.outlines.push_back(b);
  s.outlines.push_back(circle_outline("A", 1.6f, 0.5f, 0.1f, 64));  // "A" again: first colour, one legend row
  const auto rgba = render(s, ViewSettings{});
  EXPECT_TRUE(near(rgba, kCx, kCy + kR, palette::kOutlines[0]));
  EXPECT_TRUE(near(rgba, 1.6f, 0.6f, palette::kOutlines[0]));
  EXPECT_TRUE(near(rgba, 0.4f, 0.15f, palette::kOutlines[1]));
  EXPECT_FALSE(near(rgba, 0.4f, 0.15f, palette::kOutlines[0], 40));
}

TEST_F(RenderOutline, ClippedToThePlot) {
  Snapshot s = lattice_2d(kNx, kNy);
  s.outlines = {{"", {-50.f, 50.f}, {0.5f, 0.5f}}};
  const auto rgba = render(s, ViewSettings{});
  const PixelRect& plot = layout().plot;
  float px, py;
  ASSERT_TRUE(layout().to_pixel(1.f, 0.5f, 0.f, &px, &py));
  const Pixel white = to_pixel8(palette::kOutlines[0]);
  EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, plot.x + 10, py, white, 1, 12));
  EXPECT_TRUE(colour_near(rgba, kWidth, kHeight, plot.right() - 10, py, white, 1, 12));
  const Pixel halo = to_pixel8(palette::kOutlineHalo);
  for (float x : {plot.x - 4.f, plot.right() + 3.f, 5.f}) {
    EXPECT_FALSE(colour_near(rgba, kWidth, kHeight, x, py, white, 2, 40)) << "x = " << x;
    EXPECT_FALSE(colour_near(rgba, kWidth, kHeight, x, py, halo, 2, 3)) << "x = " << x;
  }
}

TEST_F(RenderOutline, HiddenOnRequest) {
  ViewSettings v;
  v.show_outlines = false;
  const auto hidden = render(with_circle(), v);
  const auto bare = render(lattice_2d(kNx, kNy), v);
  EXPECT_TRUE(hidden == bare);
}

TEST_F(RenderOutline, EmptyOnePointAndBrokenOutlinesAreHarmless) {
  const Snapshot bare = lattice_2d(kNx, kNy);
  const auto plain = render(bare, ViewSettings{});

  Snapshot empty = bare;
  empty.outlines = {{"nothing", {}, {}}, {"", {1.f}, {}}};  // no vertex at all (x without y)
  EXPECT_TRUE(render(empty, ViewSettings{}) == plain);

  Snapshot one = bare;
  one.outlines = {{"probe", {kCx, 0.3f, 0.9f}, {kCy}}};  // one vertex (the shorter array wins): a dot
  const auto dot = render(one, ViewSettings{});
  EXPECT_TRUE(near(dot, kCx, kCy, palette::kOutlines[0]));
  EXPECT_FALSE(near(dot, 0.3f, kCy, palette::kOutlines[0], 40));

  Snapshot broken = bare;  // non-finite vertices break the line; nothing joins across them
  broken.outlines = {{"broken", {0.2f, NAN, 1.8f, 1.8f, INFINITY}, {0.3f, 0.3f, 0.3f, 0.7f, 0.5f}}};
  const auto b = render(broken, ViewSettings{});
  EXPECT_FALSE(near(b, 1.f, 0.3f, palette::kOutlines[0], 40));  // 0.2 -> 1.8 is not drawn
  EXPECT_TRUE(near(b, 1.8f, 0.5f, palette::kOutlines[0]));      // 1.8,0.3 -> 1.8,0.7 is
}

TEST_F(RenderOutline, ThreeDViewsAndProfilesIgnoreThem) {
  Snapshot ball = ball_3d(500);
  const auto a = render(ball, ViewSettings{});
  ball.outlines = {circle_outline("ring", 0.f, 0.f, 0.5f, 64)};
  EXPECT_TRUE(render(ball, ViewSettings{}) == a);

  ViewSettings v;
  v.profile_axis = 0;
  const auto p = render(lattice_2d(kNx, kNy), v);
  EXPECT_TRUE(render(with_circle(), v) == p);
}

}  // namespace
}  // namespace sph::render::test
