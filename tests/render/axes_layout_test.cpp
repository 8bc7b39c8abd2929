// CPU-side view maths: bounds, cameras, value ranges, frame layout helpers, field messages.
#include <gtest/gtest.h>

#include <cmath>

#include "camera.h"
#include "field_range.h"
#include "frame_layout.h"
#include "synthetic_snapshots.h"

namespace sph::render {
namespace {

TEST(ViewBounds, UsesSnapshotBoundsOrFallsBackToParticles) {
  Snapshot s = test::lattice_2d(4, 2);
  Bounds b = view_bounds(s);
  EXPECT_FLOAT_EQ(b[0], 0.f);
  EXPECT_FLOAT_EQ(b[1], 2.f);
  EXPECT_FLOAT_EQ(b[3], 1.f);
  EXPECT_FLOAT_EQ(b[5] - b[4], 1.f);  // unused z widened to a unit extent

  s.bounds = {0, 0, 0, 0, 0, 0};  // no bounds: the particles' extent
  b = view_bounds(s);
  EXPECT_FLOAT_EQ(b[0], 0.25f);
  EXPECT_FLOAT_EQ(b[1], 1.75f);
  EXPECT_FLOAT_EQ(b[2], 0.25f);
  EXPECT_FLOAT_EQ(b[3], 0.75f);
}

TEST(Camera2D, FitKeepsEqualAspectAndContainsTheBounds) {
  const Bounds b{0, 2, 0, 1, 0, 0};
  const WorldRect r = visible_rect_2d(b, Camera2D{}, 800.f, 600.f);
  EXPECT_NEAR((r.x1 - r.x0) / 800.f, (r.y1 - r.y0) / 600.f, 1e-6f);  // same scale on both axes
  EXPECT_LE(r.x0, 0.f);
  EXPECT_GE(r.x1, 2.f);
  EXPECT_LE(r.y0, 0.f);
  EXPECT_GE(r.y1, 1.f);
  EXPECT_NEAR(0.5f * (r.x0 + r.x1), 1.f, 1e-6f);

  Camera2D zoomed;
  zoomed.zoom = 2.f;
  zoomed.fit = false;
  zoomed.center_x = 0.5f;
  zoomed.center_y = 0.25f;
  const WorldRect z = visible_rect_2d(b, zoomed, 800.f, 600.f);
  EXPECT_NEAR(z.x1 - z.x0, 0.5f * (r.x1 - r.x0), 1e-5f);
  EXPECT_NEAR(0.5f * (z.x0 + z.x1), 0.5f, 1e-6f);
  EXPECT_NEAR(0.5f * (z.y0 + z.y1), 0.25f, 1e-6f);
}

TEST(Camera3D, CentreProjectsToTheMiddleAndTheBoxFits) {
  const Bounds b{-1, 1, -1, 1, -1, 1};
  for (float yaw : {0.f, 35.f, 120.f})
    for (float pitch : {-30.f, 0.f, 25.f, 80.f}) {
      OrbitCamera cam;
      cam.yaw_deg = yaw;
      cam.pitch_deg = pitch;
      const CameraMatrices m = camera_3d(b, cam, 16.f / 9.f);
      const Mat4 vp = m.proj * m.view;
      const Vec4f c = vp * Vec4f{0, 0, 0, 1};
      EXPECT_NEAR(c.x / c.w, 0.f, 1e-5f);
      EXPECT_NEAR(c.y / c.w, 0.f, 1e-5f);
      for (int k = 0; k < 8; ++k) {  // every corner inside the clip volume
        const Vec4f p = vp * Vec4f{(k & 1) ? 1.f : -1.f, (k & 2) ? 1.f : -1.f, (k & 4) ? 1.f : -1.f, 1.f};
        EXPECT_GT(p.w, 0.f);
        EXPECT_LE(std::abs(p.x / p.w), 1.f);
        EXPECT_LE(std::abs(p.y / p.w), 1.f);
        EXPECT_LE(std::abs(p.z / p.w), 1.f);
      }
    }
}

TEST(Camera3D, UpAxisPointsUpOnScreen) {
  const Bounds b{-1, 1, -1, 1, -1, 1};
  for (int up = 0; up < 3; ++up) {
    OrbitCamera cam;
    cam.up_axis = up;
    cam.pitch_deg = 10.f;
    const CameraMatrices m = camera_3d(b, cam, 1.f);
    const Mat4 vp = m.proj * m.view;
    Vec4f top{0, 0, 0, 1};
    (up == 0 ? top.x : up == 1 ? top.y : top.z) = 0.5f;
    const Vec4f p = vp * top;
    EXPECT_GT(p.y / p.w, 0.1f) << "up axis " << up;
    EXPECT_NEAR(p.x / p.w, 0.f, 1e-4f);
  }
}

TEST(FieldRange, AutoFixedAndDegenerate) {
  SnapshotField f{"rho", "density", {1.f, 2.f, 3.f}, 1.f, 3.f};
  ViewSettings v;
  ValueRange r = resolve_range(f, v);
  EXPECT_FLOAT_EQ(r.min, 1.f);
  EXPECT_FLOAT_EQ(r.max, 3.f);

  v.auto_range = false;
  v.range_min = 0.f;
  v.range_max = 10.f;
  r = resolve_range(f, v);
  EXPECT_FLOAT_EQ(r.max, 10.f);

  v.auto_range = true;
  SnapshotField flat{"rho", "", {2.f, 2.f}, 2.f, 2.f};
  r = resolve_range(flat, v);
  EXPECT_LT(r.min, 2.f);
  EXPECT_GT(r.max, 2.f);
  EXPECT_FLOAT_EQ(0.5f * (r.min + r.max), 2.f);

  SnapshotField stale{"rho", "", {NAN, 4.f, 5.f}, NAN, NAN};  // min/max recomputed from finite values
  r = resolve_range(stale, v);
  EXPECT_FLOAT_EQ(r.min, 4.f);
  EXPECT_FLOAT_EQ(r.max, 5.f);
}

TEST(FieldRange, MissingFieldMessageListsTheAvailableOnes) {
  const Snapshot s = test::lattice_2d(2, 2);
  EXPECT_EQ(missing_field_message(s, "vel"), "field 'vel' is not in this snapshot; available: rho, p");
  Snapshot empty;
  EXPECT_EQ(missing_field_message(empty, "rho"), "field 'rho' is not in this snapshot; it has no fields");
}

TEST(FrameLayout, TextScaleFollowsTheFrameHeight) {
  EXPECT_EQ(text_scale_for(480, 0), 1);
  EXPECT_EQ(text_scale_for(720, 0), 2);
  EXPECT_EQ(text_scale_for(1080, 0), 2);
  EXPECT_EQ(text_scale_for(1440, 0), 3);
  EXPECT_EQ(text_scale_for(720, 1), 1);
}

}  // namespace
}  // namespace sph::render
