// Where the legend goes (app/render/legend.h): top right unless data is there, then the next free
// corner; a long segment counts as data along its whole length.
#include <gtest/gtest.h>

#include <vector>

#include "legend.h"

namespace sph::render {
namespace {

const PixelRect kBox{100.f, 50.f, 800.f, 400.f};  // x 100..900, y 50..450

bool inside(const PixelRect& r, float x, float y) { return x >= r.x && x <= r.right() && y >= r.y && y <= r.bottom(); }

TEST(LegendPlacement, TopRightWhenItIsFree) {
  const std::vector<float> xy = {150.f, 400.f, 500.f, 300.f};  // lower left and middle
  const PixelRect r = place_legend(kBox, 200.f, 60.f, 6.f, 4.f, xy);
  EXPECT_EQ(r.x, 900.f - 6.f - 200.f);
  EXPECT_EQ(r.y, 56.f);
  EXPECT_EQ(r.w, 200.f);
  EXPECT_EQ(r.h, 60.f);
}

TEST(LegendPlacement, MovesToAFreeCornerWhenDataIsTopRight) {
  std::vector<float> xy;
  for (float x = 500.f; x <= 900.f; x += 5.f) xy.insert(xy.end(), {x, 70.f});   // a plateau along the top right
  for (float y = 70.f; y <= 450.f; y += 5.f) xy.insert(xy.end(), {150.f, y});   // and a column on the left
  const PixelRect r = place_legend(kBox, 200.f, 60.f, 6.f, 4.f, xy);
  for (std::size_t i = 0; i < xy.size(); i += 2) EXPECT_FALSE(inside(r, xy[i], xy[i + 1])) << xy[i] << "," << xy[i + 1];
  EXPECT_EQ(r.y, 450.f - 6.f - 60.f);  // bottom right: the first free candidate
  EXPECT_EQ(r.x, 900.f - 6.f - 200.f);
}

TEST(LegendPlacement, FewestPointsWhenNoCornerIsFree) {
  std::vector<float> xy;
  for (float x = 100.f; x <= 900.f; x += 10.f) xy.insert(xy.end(), {x, 80.f, x, 420.f});  // top and bottom rows
  xy.insert(xy.end(), {880.f, 420.f, 870.f, 421.f});  // the bottom right has two more
  const PixelRect r = place_legend(kBox, 200.f, 60.f, 6.f, 4.f, xy);
  EXPECT_EQ(r.y, 56.f);  // a top position: the candidates tie at best, the first of them wins
}

TEST(LegendPlacement, DensifyCoversAVerticalJump) {
  const std::vector<float> jump = {800.f, 60.f, 800.f, 440.f};  // two vertices, a shock's vertical segment
  std::vector<float> pts;
  densify(jump, 2.f, &pts);
  EXPECT_GE(pts.size() / 2, 190u);
  const PixelRect r = place_legend(kBox, 200.f, 60.f, 6.f, 4.f, pts);
  for (std::size_t i = 0; i < pts.size(); i += 2) ASSERT_FALSE(inside(r, pts[i], pts[i + 1]));
  EXPECT_LT(r.right(), 800.f);  // not over the jump at x = 800
}

}  // namespace
}  // namespace sph::render
