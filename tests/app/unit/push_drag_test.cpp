// The right-drag push without ImGui (app/gui/push_drag.h): automatic R and tau, the pace measured from
// frame times, the mouse velocity turned into simulated units and capped (0.3 cfl h / dt and 4 R / tau).
#include <gtest/gtest.h>

#include <cmath>

#include "push_drag.h"
#include "sph/snapshot.h"

namespace sph::gui {
namespace {

TEST(PushDrag, AutomaticRadiusAndTau) {
  Snapshot snap;
  snap.bounds = {-0.5f, 0.5f, 0.f, 0.25f, 0.f, 0.f};
  EXPECT_DOUBLE_EQ(auto_push_radius(snap), 0.025);  // a tenth of the smaller side
  EXPECT_DOUBLE_EQ(auto_push_tau(0.002, 1.0), 0.04);  // 20 steps
  EXPECT_DOUBLE_EQ(auto_push_tau(0.0, 0.2), 2e-4);  // before the first step: t_end / 1000
}

TEST(PushDrag, PaceFromFrameTimes) {
  PushDrag d;
  see_frame_time(d, 0.0, 10.0);
  see_frame_time(d, 0.5, 11.0);  // half a simulated second per wall second
  EXPECT_DOUBLE_EQ(d.rate, 0.5);
  see_frame_time(d, 0.5, 11.2);  // the same frame again: no new measurement yet
  EXPECT_DOUBLE_EQ(d.rate, 0.5);
  see_frame_time(d, 0.5, 11.6);  // still for more than half a second: paused
  EXPECT_EQ(d.rate, 0.0);
}

TEST(PushDrag, MouseVelocityInSimulatedUnitsCapped) {
  PushDrag d;
  d.rate = 0.5;  // simulated seconds per wall second
  move_mouse(d, 0.0, 0.0, 1.0, true);
  EXPECT_EQ(d.vx, 0.0);
  move_mouse(d, 0.1, -0.05, 1.1, false);  // 1, -0.5 per wall second, smoothed: 0.4 of it
  EXPECT_NEAR(d.vx, 0.4, 1e-12);
  EXPECT_NEAR(d.vy, -0.2, 1e-12);
  Push p = drag_push(d, 0.5, 1.0);  // cap 4 R / tau = 2: not reached
  EXPECT_EQ(p.x[0], 0.1);
  EXPECT_EQ(p.x[1], -0.05);
  EXPECT_NEAR(p.v[0], 0.8, 1e-12);  // / 0.5: twice as fast in simulated time
  EXPECT_NEAR(p.v[1], -0.4, 1e-12);
  EXPECT_TRUE(p.active());
  p = drag_push(d, 0.1, 0.5);  // cap 4 R / tau = 0.8: |v| = 0.894 scaled down
  EXPECT_NEAR(std::hypot(p.v[0], p.v[1]), 0.8, 1e-12);
  EXPECT_NEAR(p.v[0] / p.v[1], -2.0, 1e-12);
  d.vmax = auto_push_vmax(0.01, 0.25, 0.04);  // 0.3 x 0.25 x 0.04 / 0.01 = 0.3: below 4 R / tau
  EXPECT_DOUBLE_EQ(d.vmax, 0.3);
  p = drag_push(d, 0.1, 0.5);
  EXPECT_NEAR(std::hypot(p.v[0], p.v[1]), 0.3, 1e-12);
  EXPECT_EQ(auto_push_vmax(0.0, 0.25, 0.04), 0.0);  // before the first step: no limit of its own
  d.rate = 0.0;  // unknown pace: holds the particles (v = 0)
  p = drag_push(d, 0.1, 1.0);
  EXPECT_EQ(p.v[0], 0.0);
}

}  // namespace
}  // namespace sph::gui
