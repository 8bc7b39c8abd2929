#include "plane_inset.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "camera.h"
#include "outline_overlay.h"
#include "palette.h"
#include "particle_instances.h"
#include "sph/snapshot.h"

namespace sph::render {

void add_plane_inset(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown) {
  const sph::ViewInset& in = snap.inset;
  if (!(in.half > 0.0) || snap.dim != 2) return;
  const FrameLayout& L = f.layout;
  const int s = L.text_scale;
  const float lh = f.text.line_height(s);
  const float side = std::round(0.32f * std::min(L.plot.w, L.plot.h));
  if (side < std::max(96.f, 4.5f * lh)) return;  // no room for a readable inset
  const auto cx = static_cast<float>(in.cx), cy = static_cast<float>(in.cy), half = static_cast<float>(in.half);
  float ax = 0.f, ay = 0.f, bx = 0.f, by = 0.f;
  if (!L.to_pixel(cx - half, cy - half, 0.f, &ax, &ay) || !L.to_pixel(cx + half, cy + half, 0.f, &bx, &by)) return;
  const float shown_px = std::abs(bx - ax);  // the region's width in the view itself
  if (!(shown_px > 0.f) || shown_px >= 0.5f * side) return;
  const float gap = 0.5f * lh;
  const PixelRect box{std::round(L.plot.right() - side - gap), std::round(L.plot.bottom() - side - gap), side, side};
  const WorldRect w{cx - half, cx + half, cy - half, cy + half};
  ParticleBatch& b = f.batches.emplace_back();
  b.rect = box;
  b.fill = box;
  b.opaque = true;  // over the view's own particles and trails
  b.camera = camera_2d(w);
  b.pixel_radius = f.pixel_radius;
  b.min_radius = f.min_radius;
  b.cmap = shown.cmap;
  b.range = shown.range;
  b.colors = {shown.field ? palette::kInvalid : palette::kNoField, palette::kWall};
  build_instances(snap, shown, {Placement::Positions, 0, view.h_scale, view.show_walls}, &b.instances, &b.index);
  if (view.show_outlines) add_outlines_in(b.clipped, snap, box, w, s);
  f.over.rect_outline({box.x - 1.f, box.y - 1.f, box.w + 2.f, box.h + 2.f}, 1.f, f.pal.axis);
  // the caption in the box, a size smaller; the enlargement alone where the label does not fit
  const int cs = std::max(1, s - 1);
  char zoom[32];
  std::snprintf(zoom, sizeof zoom, "x%.0f", side / shown_px);
  std::string caption = (in.label.empty() ? std::string("detail") : in.label) + "  " + zoom;
  if (f.text.measure(caption, cs) > box.w - 0.8f * lh) caption = zoom;
  f.text.add(caption, box.x + 0.4f * lh, box.y + 0.25f * lh, cs, f.pal.text);
}

}  // namespace sph::render
