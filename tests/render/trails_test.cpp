// Orbit trails: one polyline per body through the positions of the snapshots recorded, once per time,
// restarted by a reset (time going back) or another particle count; only few-body point-mass scenes.
#include "trails.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sph/snapshot.h"

namespace sph::render {
namespace {

sph::Snapshot bodies(double t, std::size_t n) {
  sph::Snapshot s;
  s.scene = "kepler";
  s.dim = 2;
  s.t = t;
  s.count = n;
  s.bounds = {0, 100, 0, 100, 0, 1};
  for (std::size_t i = 0; i < n; ++i) {
    s.x.push_back(static_cast<float>(i) + static_cast<float>(t));
    s.y.push_back(static_cast<float>(2 * t));
  }
  return s;
}

TEST(Trails, OnePolylinePerBodyThroughTheRecordedPositions) {
  Trails tr;
  for (double t : {0.0, 0.5, 0.5, 1.0}) tr.record(bodies(t, 2));  // the repeated time adds nothing
  sph::Snapshot s = bodies(1.0, 2);
  tr.decorate(s);
  ASSERT_EQ(s.outlines.size(), 2u);
  EXPECT_EQ(s.outlines[1].label, "orbits");
  EXPECT_EQ(s.outlines[1].x, (std::vector<float>{1.0f, 1.5f, 2.0f}));
  EXPECT_EQ(s.outlines[1].y, (std::vector<float>{0.0f, 1.0f, 2.0f}));
}

TEST(Trails, AFarJumpBreaksTheLine) {
  Trails tr;
  tr.record(bodies(0.0, 1));
  tr.record(bodies(0.25, 1));
  tr.record(bodies(10.0, 1));  // moved (9.75, 19.5): more than 5% of the 100 x 100 box
  sph::Snapshot s = bodies(10.0, 1);
  tr.decorate(s);
  ASSERT_EQ(s.outlines[0].x.size(), 4u);
  EXPECT_TRUE(std::isnan(s.outlines[0].x[2]));
  EXPECT_EQ(s.outlines[0].x[3], 10.0f);
}

TEST(Trails, RestartOnResetAndOnlyForFewPointMasses) {
  Trails tr;
  tr.record(bodies(0.0, 2));
  tr.record(bodies(1.0, 2));
  tr.record(bodies(0.0, 2));  // reset: time went back
  EXPECT_EQ(tr.points(), 1u);
  tr.record(bodies(0.5, 3));  // another particle count
  EXPECT_EQ(tr.points(), 1u);
  EXPECT_TRUE(Trails::applies(bodies(0.0, 10)));
  EXPECT_FALSE(Trails::applies(bodies(0.0, 65)));  // a dust sphere is not drawn with trails
  sph::Snapshot gas = bodies(0.0, 10);
  gas.fields.push_back({"rho", "density", {}, 0, 0});
  EXPECT_FALSE(Trails::applies(gas));
}

}  // namespace
}  // namespace sph::render
