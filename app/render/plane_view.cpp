#include "plane_view.h"

#include <algorithm>

#include "axes.h"
#include "outline_overlay.h"
#include "plane_inset.h"
#include "tree_overlay.h"
#include "palette.h"
#include "particle_instances.h"
#include "sph/snapshot.h"

namespace sph::render {

void compose_plane(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown) {
  FrameLayout& L = f.layout;
  const int s = L.text_scale;
  const float lh = f.text.line_height(s);
  const Bounds b = view_bounds(snap);
  // A chart (a snapshot with its own title: the convergence and work-precision plots) fills the frame with
  // its bounds; space keeps one scale on both axes (a chart at that was a narrow strip with no room for
  // its legend).
  const bool chart = !snap.title.empty();
  const float aspect = chart ? L.content.w / std::max(1.f, L.content.h) : (b[1] - b[0]) / (b[3] - b[2]);
  const auto visible = [&](const PixelRect& r) {
    return chart ? WorldRect{b[0], b[1], b[2], b[3]} : visible_rect_2d(b, view.camera2d, r.w, r.h);
  };

  // Two passes: the y labels' width depends on the visible range, which depends on the box.
  PixelRect box = axes_box(L.content, y_label_width(f.text, b[2], b[3], L.content.h, s), s, lh, aspect);
  WorldRect w = visible(box);
  box = axes_box(L.content, y_label_width(f.text, w.y0, w.y1, box.h, s), s, lh, aspect);
  w = visible(box);
  L.plot = box;
  f.camera = camera_2d(w);
  L.plot_to_clip = f.camera.proj * f.camera.view;

  add_axes(f, box, {w.x0, w.x1, w.y0, w.y1},
           {snap.x_label.empty() ? std::string("x") : snap.x_label, snap.y_label.empty() ? std::string("y") : snap.y_label,
            false});

  // Domain outline (snapshot bounds), thin, under the particles.
  float x0 = 0.f, y0 = 0.f, x1 = 0.f, y1 = 0.f;
  if (L.to_pixel(snap.bounds[0], snap.bounds[2], 0.f, &x0, &y1) && L.to_pixel(snap.bounds[1], snap.bounds[3], 0.f, &x1, &y0) &&
      x1 > x0 && y1 > y0) {
    f.under.rect_outline({x0 - 1.f, y0 - 1.f, x1 - x0 + 2.f, y1 - y0 + 2.f}, 1.f, f.pal.domain);
  }

  const bool from_h = view.size_mode == SizeMode::Smoothing && has_smoothing_lengths(snap);
  build_instances(snap, shown, {Placement::Positions, 0, view.h_scale, view.show_walls}, &f.instances, &f.index);
  f.pixel_radius = from_h ? 0.f : view.point_px;
  f.min_radius = view.min_radius_px;

  if (view.show_outlines) add_outlines(f, snap);  // over the particles, clipped to the plot
  if (view.show_tree) add_tree_overlay(f, snap);
  add_plane_inset(f, snap, view, shown);
}

}  // namespace sph::render
