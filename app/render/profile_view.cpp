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

/// One run's dots in a panel.
struct ProfileRun {
  const sph::Snapshot* snap = nullptr;
  int run = 0;
  std::vector<float> y;                  ///< plotted values, one per snapshot particle
  const sph::SnapshotField* colour = nullptr;  ///< colour-mapped field; nullptr: drawn in `solid`
  Rgba solid;
  std::string legend;                    ///< its legend row ("" for none)
};

struct ProfilePanel {
  PixelRect area;
  std::string y_title, x_title;
  std::vector<ProfileRun> runs;
  sph::ExactCurve curve;  ///< empty: none
  Rgba curve_color;
  std::string curve_label;
  bool fixed = false;     ///< y limits [y0, y1] as given
  double y0 = 0.0, y1 = 1.0;
  int legend_scale = 0;   ///< > 0: the legend's text scale (small panels)
};

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
      const float x = snap.x[i], y = i < snap.y.size() ? snap.y[i] : 0.f, z = i < snap.z.size() ? snap.z[i] : 0.f;
      const float rr = std::sqrt(x * x + y * y + z * z);
      if (std::isfinite(rr)) c1 = std::max(c1, rr);
    }
    if (!(c1 > 0.f)) c1 = 1.f;
    return;
  }
  const Bounds b = view_bounds(snap);
  c0 = b[2 * axis];
  c1 = b[2 * axis + 1];
}

/// Draws one panel. primary: its first run becomes the frame's primary particles (f.instances in
/// layout.plot); otherwise every run is a batch of its own.
void compose_panel(FrameBuild& f, const ProfilePanel& p, const ViewSettings& view, const ShownField& shown, int axis,
                   bool primary) {
  FrameLayout& L = f.layout;
  const int s = L.text_scale;
  const float lh = f.text.line_height(s);
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

  // Two passes: the y labels' width depends on the box height, which depends on the labels.
  PixelRect box = axes_box(p.area, y_label_width(f.text, r.y0, r.y1, p.area.h, s), s, lh, 0.f);
  box = axes_box(p.area, y_label_width(f.text, r.y0, r.y1, box.h, s), s, lh, 0.f);
  const CameraMatrices camera{Mat4{}, ortho(static_cast<float>(r.x0), static_cast<float>(r.x1), static_cast<float>(r.y0),
                                            static_cast<float>(r.y1), -1.f, 1.f),
                              Vec3f{}};
  // The plot's fill is a scissored clear (f.fill, set by add_axes; a batch's own for other panels).
  const PixelRect fill_before = f.fill;
  add_axes(f, box, r, {p.x_title, p.y_title, true});
  if (!primary) f.fill = fill_before;
  const float radius = view.point_px * 0.5f * static_cast<float>(1 + s);  // grows with the text: 3 px -> 4.5 px at 720p

  // the camera of the box, also for placing the curve and the legend
  FrameLayout M = L;
  M.plot = box;
  M.plot_to_clip = camera.proj;
  if (primary) {
    L.plot = box;
    f.camera = camera;
    L.plot_to_clip = camera.proj;
  }
  std::vector<float> data;  // dots and curve in pixels: the legend keeps off them
  auto add_dots = [&](const std::vector<float>& inst) {
    for (std::size_t i = 0; i + 1 < inst.size(); i += kInstanceFloats) {
      float px = NAN, py = NAN;
      if (M.to_pixel(inst[i], inst[i + 1], 0.f, &px, &py)) data.push_back(px), data.push_back(py);
    }
  };
  ShapeBatch* clipped = &f.clipped;
  for (std::size_t k = 0; k < p.runs.size(); ++k) {
    const ProfileRun& run = p.runs[k];
    ShownField colour = shown;
    colour.field = run.colour;
    InstanceOptions o{Placement::Profile, axis, 0.f, false, &run.y, run.colour == nullptr};
    if (primary && k == 0) {
      build_instances(*run.snap, colour, o, &f.instances, &f.index);
      f.pixel_radius = radius;
      add_dots(f.instances);
      continue;
    }
    ParticleBatch& b = f.batches.emplace_back();
    b.rect = box;
    if (k == 0) b.fill = box;
    b.camera = camera;
    b.run = run.run;
    // run B's dots smaller, over run A's: where the runs agree both stay visible
    b.pixel_radius = run.run == 1 ? std::max(1.5f, 0.55f * radius) : radius;
    b.cmap = shown.cmap;
    b.range = shown.range;
    b.colors = {run.colour ? palette::kInvalid : run.solid, run.solid};
    build_instances(*run.snap, colour, o, &b.instances, &b.index);
    add_dots(b.instances);
    clipped = &b.clipped;  // the curve over every run's dots: into the panel's last batch
  }

  std::vector<LegendEntry> rows;
  if (p.curve.x.size() >= 2) {
    std::vector<float> xy;
    xy.reserve(2 * p.curve.x.size());
    for (std::size_t i = 0; i < p.curve.x.size(); ++i) {
      float px = NAN, py = NAN;
      M.to_pixel(p.curve.x[i], p.curve.value[i], 0.f, &px, &py);
      xy.push_back(px);
      xy.push_back(py);
    }
    // Thinner than the dots, so that the particles stay visible on both sides of the curve.
    const float w = 0.75f * s + 0.5f;
    clipped->polyline(xy, w, p.curve_color);
    rows.push_back({p.curve_label, false, p.curve_color, w, {0, 0, 0, 0}});
    densify(xy, 2.f, &data);
  }
  for (const ProfileRun& run : p.runs) {
    if (run.legend.empty()) continue;
    const Rgb mid = colormap_rgb(shown.cmap, 0.5f);
    const float dot = run.run == 1 ? std::max(1.5f, 0.55f * radius) : radius;
    rows.push_back({run.legend, true, run.colour ? Rgba{mid.r, mid.g, mid.b, 1.f} : run.solid, dot, {0, 0, 0, 0}});
  }
  // Keep the legend off the particles and the curve (it hid the shock in v_x and the u plateau).
  const PixelRect legend_before = L.legend;
  if (!rows.empty() && (p.curve.x.size() >= 2 || p.runs.size() > 1))
    add_legend(f, box, rows, data, radius + 2.f, p.legend_scale);
  if (!primary && legend_before.w > 0.f) L.legend = legend_before;  // the first panel's legend is the frame's
}

/// The plotted values of field `name` of snap (log10 when asked for; NaN where not positive).
std::vector<float> values_of(const sph::Snapshot& snap, const std::string& name, bool log) {
  const sph::SnapshotField* fld = snap.find(name);
  std::vector<float> y(snap.count, std::nanf(""));
  if (fld == nullptr) return y;
  for (std::size_t i = 0; i < y.size() && i < fld->values.size(); ++i) {
    const float v = fld->values[i];
    y[i] = !log ? v : v > 0.f ? std::log10(v) : std::nanf("");
  }
  return y;
}

std::string legend_of(const std::string& label, const std::vector<std::pair<std::string, double>>& errors,
                      const std::string& field) {
  double v = 0.0;
  const std::string column = error_column(errors, field, &v);
  if (column.empty()) return label;
  char buf[64];
  std::snprintf(buf, sizeof buf, "   %s = %.3g", column.c_str(), v);
  return label + buf;
}

}  // namespace

void compose_profile(FrameBuild& f, const sph::Snapshot& snap, const ViewSettings& view, const ShownField& shown,
                     int axis) {
  axis = std::clamp(axis, 0, kRadialAxis);
  if (axis == 2) axis = 0;
  ProfilePanel p;
  p.area = f.layout.content;
  p.x_title = snap.x_label.empty() ? std::string(profile_axis_name(axis)) : snap.x_label;
  p.y_title = shown.field ? shown.label : std::string("(no field)");
  ProfileRun run;
  run.snap = &snap;
  run.colour = shown.field;
  if (shown.field) run.y.assign(shown.field->values.begin(), shown.field->values.end());
  run.y.resize(snap.count, std::nanf(""));
  run.legend = snap.points_label.empty() ? "SPH particles" : snap.points_label;
  p.runs.push_back(std::move(run));
  if (view.show_exact && shown.field) p.curve = curve_of(snap, shown.field->name, axis, view.log_scale);
  const Rgb c = colormap_contrast(shown.cmap);
  p.curve_color = {c.r, c.g, c.b, 1.f};
  p.curve_label = snap.curve_label.empty() ? "exact" : snap.curve_label;
  // a fixed colour range fixes the vertical limits; else every fluid value (a percentile colour range
  // would push outliers off the plot)
  p.fixed = !view.auto_range && shown.field != nullptr;
  p.y0 = shown.range.min;
  p.y1 = shown.range.max;
  compose_panel(f, p, view, shown, axis, true);
}

std::vector<std::string> panel_fields(const sph::Snapshot& snap, const std::vector<std::string>& panels) {
  std::vector<std::string> out;
  for (const std::string& name : panels) {
    if (name == "v") out.push_back(snap.find("vx") ? "vx" : "speed");
    else out.push_back(name);
  }
  return out;
}

void compose_profile_panels(FrameBuild& f, const FrameScene& scene, const ViewSettings& view, const ShownField& shown,
                            int axis, const std::vector<std::string>& fields) {
  axis = std::clamp(axis, 0, kRadialAxis);
  if (axis == 2) axis = 0;
  const sph::Snapshot& a = *scene.a;
  FrameLayout& L = f.layout;
  const int n = static_cast<int>(fields.size());
  const int cols = n <= 1 ? 1 : n <= 4 ? 2 : 3, rows = (n + cols - 1) / cols;
  const float gap = L.margin;
  const bool compare = scene.b != nullptr;
  PixelRect area = L.content;
  const int s = L.text_scale;
  if (compare && n > 1) {  // the runs' full labels once, above the panels; each legend says "A", "B"
    const float lh = f.text.line_height(s);
    const float wa = f.text.add(scene.label_a, area.x, area.y, s, kRunColors[0]);
    f.text.add(scene.label_b, area.x + wa + 3.f * lh, area.y, s, kRunColors[1]);
    area.y += lh + gap;
    area.h -= lh + gap;
  }
  const float w = (area.w - (cols - 1) * gap) / cols, h = (area.h - (rows - 1) * gap) / rows;
  for (int k = 0; k < n; ++k) {
    const std::string& field = fields[static_cast<std::size_t>(k)];
    // log10 only where the panel plots the colour-by field (velocities change sign)
    const bool log = view.log_scale && field == view.color_by;
    ProfilePanel p;
    p.area = {area.x + (k % cols) * (w + gap), area.y + (k / cols) * (h + gap), w, h};
    if (n > 1) p.legend_scale = std::max(1, s - 1);
    p.x_title = a.x_label.empty() ? std::string(profile_axis_name(axis)) : a.x_label;
    const sph::SnapshotField* fa = a.find(field);
    p.y_title = (log ? "log10 " : "") + (fa ? fa->label : field + " (not in this scene)");
    const sph::Snapshot* snaps[2] = {&a, scene.b};
    for (int r = 0; r < (compare ? 2 : 1); ++r) {
      ProfileRun run;
      run.snap = snaps[r];
      run.run = r;
      run.y = values_of(*snaps[r], field, log);
      if (compare) {
        run.solid = kRunColors[r];
        const std::string name = n > 1 ? (r == 0 ? "A" : "B") : (r == 0 ? scene.label_a : scene.label_b);
        run.legend = legend_of(name, r == 0 ? scene.errors_a : scene.errors_b, field);
      } else {
        run.colour = shown.field;  // coloured by the colour-by field, as the single plot
        run.legend = a.points_label.empty() ? "SPH particles" : a.points_label;
      }
      p.runs.push_back(std::move(run));
    }
    if (view.show_exact) p.curve = curve_of(a, field, axis, log);
    const Rgb c = colormap_contrast(shown.cmap);
    p.curve_color = compare ? kCompareExact : Rgba{c.r, c.g, c.b, 1.f};
    p.curve_label = a.curve_label.empty() ? "exact" : a.curve_label;
    compose_panel(f, p, view, shown, axis, false);
    if (k == 0) {  // the first panel stands for the frame (picking hit-tests every batch)
      L.plot = f.batches.back().rect;
      L.plot_to_clip = f.batches.back().camera.proj;
    }
  }
}

std::string error_column(const std::vector<std::pair<std::string, double>>& errors, const std::string& field,
                         double* value) {
  const std::string key = field == "vx" || field == "speed" ? "v" : field;
  for (const auto& [name, v] : errors)
    if (name == "L1_" + key) {
      *value = v;
      return name;
    }
  return {};
}

}  // namespace sph::render
