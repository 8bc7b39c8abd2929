#include "orbit_view.h"

#include <algorithm>
#include <cmath>

#include "palette.h"
#include "particle_instances.h"
#include "tree_overlay.h"
#include "sph/snapshot.h"

namespace sph::render {

namespace {

// Box corner k: bit 0 -> x max, bit 1 -> y max, bit 2 -> z max.
Vec3f corner(const Bounds& b, int k) { return {b[(k & 1) ? 1 : 0], b[(k & 2) ? 3 : 2], b[(k & 4) ? 5 : 4]}; }

// Is the box face on side `side` (0 min, 1 max) of `axis` turned towards the eye?
bool face_visible(const Bounds& b, int axis, int side, const Vec3f& eye) {
  const float e[3] = {eye.x, eye.y, eye.z};
  return side ? e[axis] > b[2 * axis + 1] : e[axis] < b[2 * axis];
}

void add_box(FrameBuild& f, const Bounds& b, const Vec3f& eye, int up_axis) {
  const FrameLayout& L = f.layout;
  const int s = L.text_scale;
  const float lw = static_cast<float>(s);
  const float lh = f.text.line_height(s);
  float cx = 0.f, cy = 0.f;  // the box centre on screen
  L.to_pixel(0.5f * (b[0] + b[1]), 0.5f * (b[2] + b[3]), 0.5f * (b[4] + b[5]), &cx, &cy);

  // Per axis, the visible edge that names it: the lowest on screen, or the leftmost for the up axis.
  float best_score[3] = {-INFINITY, -INFINITY, -INFINITY};
  float label_x[3] = {0, 0, 0}, label_y[3] = {0, 0, 0};
  for (int k = 0; k < 8; ++k)
    for (int axis = 0; axis < 3; ++axis) {
      if (k & (1 << axis)) continue;  // each edge once: from the corner with the lower coordinate
      const int k2 = k | (1 << axis);
      // The edge touches the two faces perpendicular to the other two axes.
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      const bool visible = face_visible(b, a1, (k >> a1) & 1, eye) || face_visible(b, a2, (k >> a2) & 1, eye);
      float x0 = 0.f, y0 = 0.f, x1 = 0.f, y1 = 0.f;
      const Vec3f p = corner(b, k), q = corner(b, k2);
      if (!L.to_pixel(p.x, p.y, p.z, &x0, &y0) || !L.to_pixel(q.x, q.y, q.z, &x1, &y1)) continue;
      // Hidden (both faces turned away): behind every particle inside; otherwise drawn on top.
      (visible ? f.over : f.under).line(x0, y0, x1, y1, lw, f.pal.domain);
      const float mx = 0.5f * (x0 + x1), my = 0.5f * (y0 + y1);
      const float score = axis == up_axis ? -mx : my;
      if (visible && score > best_score[axis]) {
        best_score[axis] = score;
        // Half a line beyond the edge's midpoint, away from the box centre.
        const float dx = mx - cx, dy = my - cy, n = std::max(std::sqrt(dx * dx + dy * dy), 1.f);
        label_x[axis] = mx + dx / n * 1.2f * lh;
        label_y[axis] = my + dy / n * 1.2f * lh;
      }
    }
  const char* names[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis)
    if (best_score[axis] > -INFINITY)
      f.text.add(names[axis], label_x[axis], label_y[axis] - 0.5f * lh, s, f.pal.text, Align::Center);
}

}  // namespace

void compose_orbit(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown) {
  FrameLayout& L = f.layout;
  const PixelRect& c = L.content;
  L.plot = {std::round(c.x), std::round(c.y), std::round(c.w), std::round(c.h)};
  const Bounds b = view_bounds(snap);
  f.camera = camera_3d(b, view.orbit, L.plot.w / L.plot.h);
  L.plot_to_clip = f.camera.proj * f.camera.view;
  add_box(f, b, f.camera.eye, std::clamp(view.orbit.up_axis, 0, 2));

  const bool from_h = view.size_mode == SizeMode::Smoothing && has_smoothing_lengths(snap);
  InstanceOptions o{Placement::Positions, 0, view.h_scale, view.show_walls};
  o.cut_axis = view.cut_axis;  // a cutaway: the inside of a sphere shows on the cut
  o.cut_at = view.cut_at;
  build_instances(snap, shown, o, &f.instances, &f.index);
  f.pixel_radius = from_h ? 0.f : view.point_px;
  f.min_radius = view.min_radius_px;
  f.shaded = true;
  if (view.show_tree) add_tree_overlay(f, snap);
}

}  // namespace sph::render
