#include "profile_view.h"

#include <algorithm>
#include <cmath>

#include "axes.h"
#include "legend.h"
#include "palette.h"
#include "particle_instances.h"
#include "profile_axis.h"
#include "sph/snapshot.h"
#include "ticks.h"

namespace sph::render {

namespace {

constexpr double kXPad = 0.02;  // air left and right of the domain, fraction of its length
constexpr double kYPad = 0.06;  // air above and below the data (auto range), fraction of the range

const sph::ExactCurve* shown_curve(const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown,
                                   int axis) {
  if (!view.show_exact || shown.field == nullptr) return nullptr;
  for (const sph::ExactCurve& c : snap.exact)
    if (c.field == shown.field->name && c.axis == axis && c.x.size() >= 2 && c.value.size() >= c.x.size()) return &c;
  return nullptr;
}

// Vertical limits: a fixed colour range as given; else every fluid value (a percentile colour range
// would push outliers off the plot), widened to include the exact curve and rounded outwards to ticks.
void y_limits(const sph::Snapshot& snap, const ShownField& shown, const sph::ExactCurve* curve, const ViewSettings& view,
              double& lo, double& hi) {
  lo = shown.range.min;
  hi = shown.range.max;
  if (shown.field == nullptr) {
    lo = -1.0, hi = 1.0;
    return;
  }
  if (!view.auto_range) return;
  ViewSettings all = view;
  all.percentile_lo = 0.f;
  all.percentile_hi = 100.f;
  const ValueRange data = resolve_range(*shown.field, all, snap.kind);
  lo = data.min;
  hi = data.max;
  if (curve)
    for (float v : curve->value)
      if (std::isfinite(v)) lo = std::min(lo, double(v)), hi = std::max(hi, double(v));
  const double pad = kYPad * (hi - lo);
  lo -= pad;
  hi += pad;
  nice_limits(lo, hi, 10);  // round to a tenth of the range: little wasted headroom
}

}  // namespace

void compose_profile(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown,
                     int axis) {
  axis = std::clamp(axis, 0, kRadialAxis);
  if (axis == 2) axis = 0;
  FrameLayout& L = f.layout;
  const int s = L.text_scale;
  const float lh = f.text.line_height(s);
  const Bounds b = view_bounds(snap);
  AxesRanges r;
  float c0 = 0.f, c1 = 0.f;  // the coordinate's extent
  if (axis == kRadialAxis) {
    for (std::size_t i = 0; i < snap.x.size(); ++i) {
      const float x = snap.x[i], y = i < snap.y.size() ? snap.y[i] : 0.f, z = i < snap.z.size() ? snap.z[i] : 0.f;
      const float rr = std::sqrt(x * x + y * y + z * z);
      if (std::isfinite(rr)) c1 = std::max(c1, rr);
    }
    if (!(c1 > 0.f)) c1 = 1.f;
  } else {
    c0 = b[2 * axis];
    c1 = b[2 * axis + 1];
  }
  const double dx = kXPad * (c1 - c0);
  r.x0 = c0 - dx;
  r.x1 = c1 + dx;
  const sph::ExactCurve* curve = shown_curve(snap, view, shown, axis);
  sph::ExactCurve log_curve;  // with the log10 scale, the reference in the same units (points <= 0 left out)
  if (curve != nullptr && view.log_scale) {
    log_curve.field = curve->field;
    log_curve.axis = curve->axis;
    for (std::size_t i = 0; i < curve->x.size() && i < curve->value.size(); ++i)
      if (curve->value[i] > 0.f) {
        log_curve.x.push_back(curve->x[i]);
        log_curve.value.push_back(std::log10(curve->value[i]));
      }
    curve = log_curve.x.size() >= 2 ? &log_curve : nullptr;
  }
  y_limits(snap, shown, curve, view, r.y0, r.y1);

  // Two passes: the y labels' width depends on the box height, which depends on the labels.
  PixelRect box = axes_box(L.content, y_label_width(f.text, r.y0, r.y1, L.content.h, s), s, lh, 0.f);
  box = axes_box(L.content, y_label_width(f.text, r.y0, r.y1, box.h, s), s, lh, 0.f);
  L.plot = box;
  f.camera = {Mat4{}, ortho(static_cast<float>(r.x0), static_cast<float>(r.x1), static_cast<float>(r.y0),
                            static_cast<float>(r.y1), -1.f, 1.f),
              Vec3f{}};
  L.plot_to_clip = f.camera.proj;

  add_axes(f, box, r, {snap.x_label.empty() ? std::string(profile_axis_name(axis)) : snap.x_label, shown.field ? shown.label : std::string("(no field)"), true});
  build_instances(snap, shown, {Placement::Profile, axis, 0.f, false}, &f.instances);
  f.pixel_radius = view.point_px * 0.5f * static_cast<float>(1 + s);  // grows with the text: 3 px -> 4.5 px at 720p

  if (curve != nullptr) {
    std::vector<float> xy;
    xy.reserve(2 * curve->x.size());
    for (std::size_t i = 0; i < curve->x.size(); ++i) {
      float px = NAN, py = NAN;
      L.to_pixel(curve->x[i], curve->value[i], 0.f, &px, &py);
      xy.push_back(px);
      xy.push_back(py);
    }
    const Rgb c = colormap_contrast(shown.cmap);
    // Thinner than the dots, so that the particles stay visible on both sides of the curve.
    f.clipped.polyline(xy, 0.75f * s + 0.5f, {c.r, c.g, c.b, 1.f});
    const Rgb mid = colormap_rgb(shown.cmap, 0.5f);
    const std::string curve = snap.curve_label.empty() ? "exact" : snap.curve_label;
    const std::string points = snap.points_label.empty() ? "SPH particles" : snap.points_label;
    const LegendEntry rows[2] = {{curve, false, {c.r, c.g, c.b, 1.f}, 0.75f * s + 0.5f, {0, 0, 0, 0}},
                                 {points, true, {mid.r, mid.g, mid.b, 1.f}, f.pixel_radius, {0, 0, 0, 0}}};
    // Keep the legend off the particles and the curve (it hid the shock in v_x and the u plateau).
    std::vector<float> data;
    data.reserve(2 * (f.instances.size() / kInstanceFloats) + 2 * xy.size());
    for (std::size_t i = 0; i + 1 < f.instances.size(); i += kInstanceFloats) {
      float px = NAN, py = NAN;
      if (L.to_pixel(f.instances[i], f.instances[i + 1], 0.f, &px, &py)) data.push_back(px), data.push_back(py);
    }
    densify(xy, 2.f, &data);
    add_legend(f, box, rows, data, f.pixel_radius + 2.f);
  }
}

}  // namespace sph::render
