// 3D frames: spheres under the orbit camera, depth ordering, and camera changes.
#include <gtest/gtest.h>

#include <cmath>

#include "camera.h"
#include "render_test_util.h"
#include "synthetic_snapshots.h"

namespace sph::render::test {
namespace {

class Render3D : public OffscreenTest {};

// Two particles on the line of sight through the box centre: the near one must hide the far one.
Snapshot two_on_axis(const ViewSettings& v, float near_value, float far_value) {
  Snapshot s;
  s.scene = "pair";
  s.dim = 3;
  s.count = 2;
  s.bounds = {-1, 1, -1, 1, -1, 1};
  const CameraMatrices m = camera_3d(s.bounds, v.orbit, 16.f / 9.f);
  const Vec3f e = m.eye;
  const float n = std::sqrt(e.x * e.x + e.y * e.y + e.z * e.z);
  for (float d : {0.3f, -0.3f}) {  // +0.3: towards the eye
    s.x.push_back(e.x / n * d);
    s.y.push_back(e.y / n * d);
    s.z.push_back(e.z / n * d);
    s.h.push_back(0.6f);
  }
  s.fields = {{"rho", "density", {near_value, far_value}, std::min(near_value, far_value),
               std::max(near_value, far_value)}};
  return s;
}

TEST_F(Render3D, BallIsDrawnAndCentred) {
  const Snapshot s = ball_3d(3000);
  const auto rgba = render(s, ViewSettings{});
  const PixelRect plot = layout().plot;
  EXPECT_GT(count_drawn(rgba, kWidth, plot), 0.05 * plot.w * plot.h);
  float cx, cy;
  ASSERT_TRUE(layout().to_pixel(0, 0, 0, &cx, &cy));
  EXPECT_NEAR(cx, plot.x + 0.5f * plot.w, 1.f);
  EXPECT_NEAR(cy, plot.y + 0.5f * plot.h, 1.f);
  EXPECT_GT(count_drawn(rgba, kWidth, {cx - 20, cy - 20, 40, 40}), 1200);  // the middle is covered
}

TEST_F(Render3D, NearParticleHidesTheFarOne) {
  ViewSettings v;
  for (bool near_is_high : {true, false}) {
    const Snapshot s = near_is_high ? two_on_axis(v, 2.f, 1.f) : two_on_axis(v, 1.f, 2.f);
    const auto rgba = render(s, v);
    float cx, cy;
    ASSERT_TRUE(layout().to_pixel(0, 0, 0, &cx, &cy));
    const Pixel p = pixel_at(rgba, kWidth, static_cast<int>(cx), static_cast<int>(cy));
    // viridis: high values are yellow (r > b), low values purple (b > r); shading keeps the hue.
    if (near_is_high)
      EXPECT_GT(p.r, p.b) << describe(p);
    else
      EXPECT_GT(p.b, p.r) << describe(p);
  }
}

TEST_F(Render3D, OrbitChangesTheImageAndFixedSizesWork) {
  const Snapshot s = random_cloud(3, 3000);
  ViewSettings v;
  const auto a = render(s, v);
  v.orbit.yaw_deg += 60.f;
  const auto b = render(s, v);
  EXPECT_FALSE(a == b);
  v.size_mode = SizeMode::Pixels;
  v.point_px = 2.f;
  v.orbit.up_axis = 1;
  const auto c = render(s, v);
  EXPECT_GT(count_drawn(c, kWidth, layout().plot), 3000);
}

}  // namespace
}  // namespace sph::render::test
