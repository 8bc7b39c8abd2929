// Profile frames: the single profile of the colour-by field, or a grid of panels (one per field) with one
// run or the two runs of a comparison; each panel is drawn by compose_panel (profile_panel.h).
#include "profile_view.h"

#include <algorithm>
#include <cmath>

#include "palette.h"
#include "profile_axis.h"
#include "profile_panel.h"
#include "profile_residual.h"
#include "sph/snapshot.h"

namespace sph::render {

namespace {

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
  if (column.empty() || !std::isfinite(v)) return label;  // an error not defined yet: no number, never "nan"
  char buf[64];
  std::snprintf(buf, sizeof buf, "   %s = %.3g", column.c_str(), v);
  return label + buf;
}

/// A run of a comparison or a sweep as the panels draw it.
struct PanelRun {
  const sph::Snapshot* snap = nullptr;
  int run = 0;                      ///< Picked::run
  std::string label, short_label;   ///< legend names: alone, and in a grid (the header has the full ones)
  const std::vector<std::pair<std::string, double>>* errors = nullptr;
  Rgba colour;
  float dot_scale = 1.f;            ///< later runs' dots smaller, drawn over the earlier ones
};

/// Run A and run B, or run A and the sweep's runs; none for a single run.
std::vector<PanelRun> panel_runs(const FrameScene& scene) {
  std::vector<PanelRun> out;
  if (scene.b) {
    out.push_back({scene.a, 0, scene.label_a, "A", &scene.errors_a, kRunColors[0], 1.f});
    out.push_back({scene.b, 1, scene.label_b, "B", &scene.errors_b, kRunColors[1], 0.55f});
  } else if (!scene.sweep.empty()) {
    out.push_back({scene.a, 0, scene.label_a, scene.value_a, &scene.errors_a, kRunColors[0], 1.f});
    float dot = 0.55f;
    for (std::size_t k = 0; k < scene.sweep.size(); ++k, dot *= 0.85f) {
      const SweepRun& r = scene.sweep[k];
      out.push_back({r.snap, kFirstSweepRun + static_cast<int>(k), r.label, r.value, &r.errors,
                     kRunColors[(k + 1) % kRunColorCount], dot});
    }
  }
  return out;
}

/// The runs' names once above a grid of panels, each in its colour ("A: ...   B: ..." or "key:  1.2 (A)
/// 1.0  1.5"); `area` loses that line.
void add_run_header(FrameBuild& f, const FrameScene& scene, const std::vector<PanelRun>& runs, PixelRect& area) {
  std::vector<std::pair<std::string, Rgba>> parts;
  if (!scene.b) parts.emplace_back(scene.sweep_key + ":", f.pal.text);
  for (const PanelRun& r : runs) parts.emplace_back(scene.b ? r.label : r.short_label, r.colour);
  const float gap = scene.b ? 3.f : 1.5f;  // [line heights]
  const auto width = [&](int s) {
    float w = 0.f;
    for (const auto& p : parts) w += f.text.measure(p.first, s) + gap * f.text.line_height(s);
    return w;
  };
  int s = f.layout.text_scale;  // smaller where the line does not fit (a projector's 3x text)
  while (s > 1 && width(s) > area.w) --s;
  const float lh = f.text.line_height(s);
  float x = area.x;
  for (const auto& [text, colour] : parts) {
    const std::string shown = f.text.elided(text, area.right() - x, s);
    if (shown.empty()) break;
    x += f.text.add(shown, x, area.y, s, colour) + gap * lh;
  }
  area.y += lh + f.layout.margin;
  area.h -= lh + f.layout.margin;
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
  compose_with_residuals(f, std::move(p), view, shown, axis, true, view.residuals);
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
  const std::vector<PanelRun> runs = panel_runs(scene);
  const bool several = !runs.empty();
  PixelRect area = L.content;
  if (several && n > 1) add_run_header(f, scene, runs, area);  // the full labels once; legends say "A", "B"
  const float w = (area.w - (cols - 1) * gap) / cols, h = (area.h - (rows - 1) * gap) / rows;
  for (int k = 0; k < n; ++k) {
    const std::string& field = fields[static_cast<std::size_t>(k)];
    // log10 only where the panel plots the colour-by field (velocities change sign)
    const bool log = view.log_scale && field == view.color_by;
    ProfilePanel p;
    p.area = {area.x + (k % cols) * (w + gap), area.y + (k / cols) * (h + gap), w, h};
    if (n > 1) p.legend_scale = std::max(1, L.text_scale - 1);
    p.x_title = a.x_label.empty() ? std::string(profile_axis_name(axis)) : a.x_label;
    const sph::SnapshotField* fa = a.find(field);
    p.y_title = (log ? "log10 " : "") + (fa ? fa->label : field + " (not in this scene)");
    if (view.show_exact) p.curve = curve_of(a, field, axis, log);
    for (std::size_t r = 0; r < std::max<std::size_t>(1, runs.size()); ++r) {
      ProfileRun run;
      run.snap = several ? runs[r].snap : &a;
      run.y = values_of(*run.snap, field, log);
      if (several) {
        run.run = runs[r].run;
        run.solid = runs[r].colour;
        run.dot_scale = runs[r].dot_scale;
        run.legend = legend_of(n > 1 ? runs[r].short_label : runs[r].label, *runs[r].errors, field);
      } else {
        run.colour = shown.field;  // coloured by the colour-by field, as the single plot
        run.legend = a.points_label.empty() ? "SPH particles" : a.points_label;
      }
      p.runs.push_back(std::move(run));
    }
    const Rgb c = colormap_contrast(shown.cmap);
    p.curve_color = several ? kCompareExact : Rgba{c.r, c.g, c.b, 1.f};
    p.curve_label = a.curve_label.empty() ? "exact" : a.curve_label;
    // the strip: B - A for a comparison; each run minus A for a sweep with nothing exact to compare with
    if (scene.b) p.versus_first = "B - A";
    else if (several && p.curve.x.size() < 2) p.versus_first = "run - A";
    const bool strip = view.residuals || scene.b != nullptr || !p.versus_first.empty();
    const std::size_t drawn = compose_with_residuals(f, std::move(p), view, shown, axis, false, strip);
    if (k == 0 && drawn > 0) {  // the first panel stands for the frame (picking hit-tests every batch)
      L.plot = f.batches[drawn - 1].rect;
      L.plot_to_clip = f.batches[drawn - 1].camera.proj;
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
