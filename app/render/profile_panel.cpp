// compose_panel: a panel's axes (x over every run's extent, y fixed or fitted to the data), its runs' dots
// (the primary run's as the frame's particles, the others as batches), the exact curve and the legend.
#include "profile_panel.h"

#include <algorithm>
#include <cmath>

#include "axes.h"
#include "legend.h"
#include "palette.h"
#include "particle_instances.h"
#include "profile_axis.h"
#include "ticks.h"

namespace sph::render {

namespace {

constexpr double kXPad = 0.02;  // air left and right of the domain, fraction of its length
constexpr double kYPad = 0.06;  // air above and below the data (auto range), fraction of the range

/// Every run's finite fluid values and the curve, padded and rounded outwards to ticks.
void auto_limits(const ProfilePanel& p, double& lo, double& hi) {
  lo = INFINITY, hi = -INFINITY;
  for (const ProfileRun& r : p.runs)
    for (std::size_t i = 0; i < r.y.size(); ++i)
      if (std::isfinite(r.y[i]) && !r.snap->is_wall(i)) lo = std::min(lo, double(r.y[i])), hi = std::max(hi, double(r.y[i]));
  for (float v : p.curve.value)
    if (std::isfinite(v)) lo = std::min(lo, double(v)), hi = std::max(hi, double(v));
  if (!(lo <= hi)) lo = -1.0, hi = 1.0;
  const ValueRange w = widen_degenerate(static_cast<float>(lo), static_cast<float>(hi));
  lo = w.min, hi = w.max;
  const double pad = kYPad * (hi - lo);
  lo -= pad;
  hi += pad;
  nice_limits(lo, hi, 10);  // round to a tenth of the range: little wasted headroom
}

/// The coordinate's extent along `axis` (r: from 0 to the farthest particle).
void x_extent(const sph::Snapshot& snap, int axis, float& c0, float& c1) {
  if (axis == kRadialAxis) {
    c0 = 0.f, c1 = 0.f;
    for (std::size_t i = 0; i < snap.x.size(); ++i) {
      const float rr = profile_coordinate(snap, i, kRadialAxis);
      if (std::isfinite(rr)) c1 = std::max(c1, rr);
    }
    if (!(c1 > 0.f)) c1 = 1.f;
    return;
  }
  const Bounds b = view_bounds(snap);
  c0 = b[2 * axis];
  c1 = b[2 * axis + 1];
}

/// The panel's ranges: x over every run's extent with some air, y as given or fitted to the data.
AxesRanges panel_ranges(const ProfilePanel& p, int axis) {
  AxesRanges r;
  float c0 = 0.f, c1 = 1.f;
  x_extent(*p.runs.front().snap, axis, c0, c1);
  for (std::size_t k = 1; k < p.runs.size(); ++k) {  // a run B of another size: both fit
    float d0 = 0.f, d1 = 1.f;
    x_extent(*p.runs[k].snap, axis, d0, d1);
    c0 = std::min(c0, d0), c1 = std::max(c1, d1);
  }
  const double dx = kXPad * (c1 - c0);
  r.x0 = c0 - dx;
  r.x1 = c1 + dx;
  if (p.fixed) r.y0 = p.y0, r.y1 = p.y1;
  else auto_limits(p, r.y0, r.y1);
  return r;
}

/// Where a panel's dots go: its axes box and camera, the layout that maps its plot to pixels, the dot radius.
struct PanelPlace {
  PixelRect box;
  CameraMatrices camera;
  FrameLayout M;
  float radius = 0.f;
};

/// The instances' positions in pixels, appended to data (the legend keeps off them).
void add_dot_pixels(const FrameLayout& M, const std::vector<float>& inst, std::vector<float>& data) {
  for (std::size_t i = 0; i + 1 < inst.size(); i += kInstanceFloats) {
    float px = NAN, py = NAN;
    if (M.to_pixel(inst[i], inst[i + 1], 0.f, &px, &py)) data.push_back(px), data.push_back(py);
  }
}

/// Every run's dots: the primary panel's first run as the frame's particles, the others each a batch of
/// their own. Returns the shape batch the curve goes into (over every run's dots).
ShapeBatch* add_runs(FrameBuild& f, const ProfilePanel& p, const ShownField& shown, int axis, bool primary,
                     const PanelPlace& at, std::vector<float>& data) {
  ShapeBatch* clipped = &f.clipped;
  for (std::size_t k = 0; k < p.runs.size(); ++k) {
    const ProfileRun& run = p.runs[k];
    ShownField colour = shown;
    colour.field = run.colour;
    InstanceOptions o{Placement::Profile, axis, 0.f, false, &run.y, run.colour == nullptr};
    if (primary && k == 0) {
      build_instances(*run.snap, colour, o, &f.instances, &f.index);
      f.pixel_radius = at.radius;
      add_dot_pixels(at.M, f.instances, data);
      continue;
    }
    ParticleBatch& b = f.batches.emplace_back();
    b.rect = at.box;
    if (k == 0) b.fill = at.box;
    b.camera = at.camera;
    b.run = run.run;
    // later runs' dots smaller, over run A's: where the runs agree all stay visible
    b.pixel_radius = run.dot_scale < 1.f ? std::max(1.5f, run.dot_scale * at.radius) : at.radius;
    b.cmap = shown.cmap;
    b.range = shown.range;
    b.colors = {run.colour ? palette::kInvalid : run.solid, run.solid};
    build_instances(*run.snap, colour, o, &b.instances, &b.index);
    add_dot_pixels(at.M, b.instances, data);
    clipped = &b.clipped;  // the curve over every run's dots: into the panel's last batch
  }
  return clipped;
}

/// The exact curve into `clipped` and the legend rows of the curve and the runs, the legend kept off the
/// dots and the curve. primary: the legend stands for the frame's.
void add_curve_and_legend(FrameBuild& f, const ProfilePanel& p, const ShownField& shown, bool primary,
                          const PanelPlace& at, ShapeBatch* clipped, std::vector<float>& data) {
  FrameLayout& L = f.layout;
  const int s = L.text_scale;
  std::vector<LegendEntry> rows;
  if (p.curve.x.size() >= 2) {
    std::vector<float> xy;
    xy.reserve(2 * p.curve.x.size());
    for (std::size_t i = 0; i < p.curve.x.size(); ++i) {
      float px = NAN, py = NAN;
      at.M.to_pixel(p.curve.x[i], p.curve.value[i], 0.f, &px, &py);
      xy.push_back(px);
      xy.push_back(py);
    }
    // Thinner than the dots, so that the particles stay visible on both sides of the curve.
    const float w = 0.75f * s + 0.5f;
    clipped->polyline(xy, w, p.curve_color);
    if (!p.curve_label.empty()) rows.push_back({p.curve_label, false, p.curve_color, w, {0, 0, 0, 0}});
    densify(xy, 2.f, &data);
  }
  for (const ProfileRun& run : p.runs) {
    if (run.legend.empty()) continue;
    const Rgb mid = colormap_rgb(shown.cmap, 0.5f);
    const float dot = run.dot_scale < 1.f ? std::max(1.5f, run.dot_scale * at.radius) : at.radius;
    rows.push_back({run.legend, true, run.colour ? Rgba{mid.r, mid.g, mid.b, 1.f} : run.solid, dot, {0, 0, 0, 0}});
  }
  // Keep the legend off the particles and the curve (it hid the shock in v_x and the u plateau).
  const PixelRect legend_before = L.legend;
  if (!rows.empty() && (p.curve.x.size() >= 2 || p.runs.size() > 1))
    add_legend(f, at.box, rows, data, at.radius + 2.f, p.legend_scale);
  if (!primary && legend_before.w > 0.f) L.legend = legend_before;  // the first panel's legend is the frame's
}

}  // namespace

/// The exact curve of `field` along `axis` (log10 of its positive values when `log`), or an empty one.
sph::ExactCurve curve_of(const sph::Snapshot& snap, const std::string& field, int axis, bool log) {
  sph::ExactCurve out;
  for (const sph::ExactCurve& c : snap.exact) {
    if (c.field != field || c.axis != axis || c.x.size() < 2 || c.value.size() < c.x.size()) continue;
    out.field = c.field;
    out.axis = c.axis;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      if (log && !(c.value[i] > 0.f)) continue;
      out.x.push_back(c.x[i]);
      out.value.push_back(log ? std::log10(c.value[i]) : c.value[i]);
    }
    if (out.x.size() < 2) out = {};
    break;
  }
  return out;
}

float panel_label_width(const FrameBuild& f, const ProfilePanel& p, int axis) {
  const int s = f.layout.text_scale;
  const float lh = f.text.line_height(s);
  const AxesRanges r = panel_ranges(p, axis);
  // Two passes: the y labels' width depends on the box height, which depends on the labels.
  const float first = std::max(p.y_label_min, y_label_width(f.text, r.y0, r.y1, p.area.h, s));
  const PixelRect box = axes_box(p.area, first, s, lh, 0.f, p.x_labels);
  return std::max(p.y_label_min, y_label_width(f.text, r.y0, r.y1, box.h, s));
}

void compose_panel(FrameBuild& f, const ProfilePanel& p, const ViewSettings& view, const ShownField& shown, int axis,
                   bool primary) {
  FrameLayout& L = f.layout;
  const int s = L.text_scale;
  const float lh = f.text.line_height(s);
  const AxesRanges r = panel_ranges(p, axis);
  const PixelRect box = axes_box(p.area, panel_label_width(f, p, axis), s, lh, 0.f, p.x_labels);
  const CameraMatrices camera{Mat4{}, ortho(static_cast<float>(r.x0), static_cast<float>(r.x1), static_cast<float>(r.y0),
                                            static_cast<float>(r.y1), -1.f, 1.f),
                              Vec3f{}};
  // The plot's fill is a scissored clear (f.fill, set by add_axes; a batch's own for other panels).
  const PixelRect fill_before = f.fill;
  add_axes(f, box, r, {p.x_title, p.y_title, true, p.x_labels});
  if (!primary) f.fill = fill_before;
  const float radius = view.point_px * 0.5f * static_cast<float>(1 + s);  // grows with the text: 3 px -> 4.5 px at 720p

  // the camera of the box, also for placing the curve and the legend
  PanelPlace at{box, camera, L, radius};
  at.M.plot = box;
  at.M.plot_to_clip = camera.proj;
  if (primary) {
    L.plot = box;
    f.camera = camera;
    L.plot_to_clip = camera.proj;
  }
  std::vector<float> data;  // dots and curve in pixels: the legend keeps off them
  ShapeBatch* clipped = add_runs(f, p, shown, axis, primary, at, data);
  add_curve_and_legend(f, p, shown, primary, at, clipped, data);
}

}  // namespace sph::render
