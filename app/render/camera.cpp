#include "camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sph/snapshot.h"

namespace sph::render {

namespace {
constexpr float kFitPadding = 1.04f;  // fitted views leave 4% of air around the bounds
float deg(float d) { return d * std::numbers::pi_v<float> / 180.f; }
}  // namespace

Bounds view_bounds(const sph::Snapshot& snap) {
  Bounds b = snap.bounds;
  const std::vector<float>* pos[3] = {&snap.x, &snap.y, &snap.z};
  for (int a = 0; a < 3; ++a) {
    float& lo = b[2 * a];
    float& hi = b[2 * a + 1];
    const bool used = a < snap.dim;
    if (used && !(hi > lo && std::isfinite(lo) && std::isfinite(hi))) {
      // Fall back to the particles' extent along this axis.
      lo = INFINITY;
      hi = -INFINITY;
      for (float v : *pos[a])
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (!used) lo = hi = 0.f;
    if (!(hi > lo)) {
      const float c = std::isfinite(lo) && std::isfinite(hi) ? 0.5f * (lo + hi) : 0.f;
      lo = c - 0.5f;
      hi = c + 0.5f;
    }
  }
  return b;
}

WorldRect visible_rect_2d(const Bounds& b, const Camera2D& cam, float pw, float ph) {
  const float bw = b[1] - b[0], bh = b[3] - b[2];
  const float zoom = cam.zoom > 0.f ? cam.zoom : 1.f;
  const float per_px = std::max(bw / pw, bh / ph) * kFitPadding / zoom;  // world units per pixel
  const float cx = cam.fit ? 0.5f * (b[0] + b[1]) : cam.center_x;
  const float cy = cam.fit ? 0.5f * (b[2] + b[3]) : cam.center_y;
  return {cx - 0.5f * pw * per_px, cx + 0.5f * pw * per_px, cy - 0.5f * ph * per_px, cy + 0.5f * ph * per_px};
}

CameraMatrices camera_2d(const WorldRect& r) {
  return {Mat4{}, ortho(r.x0, r.x1, r.y0, r.y1, -1.f, 1.f), Vec3f{}};
}

CameraMatrices camera_3d(const Bounds& b, const OrbitCamera& cam, float aspect) {
  const Vec3f centre{0.5f * (b[0] + b[1]), 0.5f * (b[2] + b[3]), 0.5f * (b[4] + b[5])};
  const float radius = 0.5f * std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                        (b[5] - b[4]) * (b[5] - b[4]));
  const float fovy = deg(std::clamp(cam.fov_deg, 5.f, 120.f));
  const float fovx = 2.f * std::atan(std::tan(0.5f * fovy) * aspect);
  const float fit = radius / std::sin(0.5f * std::min(fovy, fovx));  // the bounding sphere just fits
  const float zoom = cam.zoom > 0.f ? cam.zoom : 1.f;
  const float dist = (cam.distance > 0.f ? cam.distance : fit) / zoom;

  // Right-handed frame (a, b, up): yaw 0 looks along +b with a pointing right on screen.
  static constexpr Vec3f kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1}, kMinusZ{0, 0, -1};
  const int up_axis = std::clamp(cam.up_axis, 0, 2);
  const Vec3f a = up_axis == 0 ? kY : kX;
  const Vec3f bb = up_axis == 0 ? kZ : (up_axis == 1 ? kMinusZ : kY);
  const Vec3f up = up_axis == 0 ? kX : (up_axis == 1 ? kY : kZ);

  const float yaw = deg(cam.yaw_deg);
  const float pitch = deg(std::clamp(cam.pitch_deg, -89.f, 89.f));
  const float ca = std::cos(pitch) * std::sin(yaw), cb = -std::cos(pitch) * std::cos(yaw), cu = std::sin(pitch);
  const Vec3f dir{ca * a.x + cb * bb.x + cu * up.x, ca * a.y + cb * bb.y + cu * up.y, ca * a.z + cb * bb.z + cu * up.z};
  const Vec3f eye{centre.x + dist * dir.x, centre.y + dist * dir.y, centre.z + dist * dir.z};

  const float near_plane = std::max(0.01f * dist, dist - 2.f * radius);
  const float far_plane = dist + 2.f * radius;
  return {look_at(eye, centre, up), perspective(fovy, aspect, near_plane, far_plane), eye};
}

}  // namespace sph::render
