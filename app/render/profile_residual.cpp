// Residual panels of profiles (profile_residual.h).
#include "profile_residual.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "frame_scene.h"
#include "profile_axis.h"

namespace sph::render {
namespace {

/// Run r's fluid values as a curve over its coordinates, sorted (ties in particle order).
sph::ExactCurve as_curve(const ProfileRun& r, int axis) {
  std::vector<float> c(r.y.size());
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < r.y.size(); ++i) {
    c[i] = profile_coordinate(*r.snap, i, axis);
    if (std::isfinite(r.y[i]) && std::isfinite(c[i]) && !r.snap->is_wall(i)) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c[a] < c[b]; });
  sph::ExactCurve out;
  for (std::size_t i : order) {
    out.x.push_back(c[i]);
    out.value.push_back(r.y[i]);
  }
  return out;
}

/// A strip run at `base`'s particles: other(c_i) - y_i, or y_i - other(c_i); `largest` takes the largest |value|.
ProfileRun difference(const ProfileRun& base, const sph::ExactCurve& other, bool other_minus_base, int axis,
                      Rgba colour, float& largest) {
  ProfileRun d;
  d.snap = base.snap;
  d.run = base.run;
  d.solid = colour;
  d.y.assign(base.y.size(), std::nanf(""));
  for (std::size_t i = 0; i < base.y.size(); ++i) {
    const float o = exact_at(other, profile_coordinate(*base.snap, i, axis));
    d.y[i] = other_minus_base ? o - base.y[i] : base.y[i] - o;
    if (std::isfinite(d.y[i]) && !base.snap->is_wall(i)) largest = std::max(largest, std::abs(d.y[i]));
  }
  return d;
}

/// The strip shows each later run minus the first: asked for, and every run 1D.
bool versus_first(const ProfilePanel& p) {
  if (p.versus_first.empty() || p.runs.size() < 2) return false;
  for (const ProfileRun& r : p.runs)
    if (r.snap == nullptr || r.snap->dim != 1) return false;
  return true;
}

}  // namespace

float exact_at(const sph::ExactCurve& curve, float c) {
  const std::vector<float>& x = curve.x;
  if (x.size() < 2 || curve.value.size() < x.size() || !(c >= x.front() && c <= x.back())) return std::nanf("");
  const auto hi = std::upper_bound(x.begin(), x.end(), c);
  const std::size_t k = hi == x.end() ? x.size() - 1 : static_cast<std::size_t>(hi - x.begin());
  const std::size_t j = k - 1;
  const float dx = x[k] - x[j];
  const float w = dx > 0.f ? (c - x[j]) / dx : 0.f;
  return curve.value[j] + w * (curve.value[k] - curve.value[j]);
}

bool has_residuals(const ProfilePanel& p) { return versus_first(p) || (p.curve.x.size() >= 2 && !p.runs.empty()); }

ProfilePanel residual_panel(const ProfilePanel& p, int axis) {
  ProfilePanel r;
  r.area = p.area;
  r.x_title = p.x_title;
  r.legend_scale = p.legend_scale;
  float largest = 0.f;
  float x0 = 0.f, x1 = 1.f;
  if (versus_first(p)) {  // B - A (each later run minus A) at A's particles
    r.y_title = p.versus_first;
    for (std::size_t k = 1; k < p.runs.size(); ++k) {
      const sph::ExactCurve b = as_curve(p.runs[k], axis);
      r.runs.push_back(difference(p.runs[0], b, true, axis, p.runs[k].solid, largest));
      r.runs.back().dot_scale = std::pow(0.85f, static_cast<float>(k - 1));  // run B's full size: alone in the strip
      if (k == 1 && b.x.size() >= 2) x0 = b.x.front(), x1 = b.x.back();
    }
  } else {  // each run minus the exact curve
    r.y_title = "minus exact";
    for (const ProfileRun& run : p.runs)  // a colour-mapped single run in run A's colour
      r.runs.push_back(difference(run, p.curve, false, axis, run.colour ? kRunColors[0] : run.solid, largest));
    x0 = p.curve.x.front(), x1 = p.curve.x.back();
  }
  r.curve.field = p.curve.field;
  r.curve.axis = p.curve.axis;
  r.curve.x = {x0, x1};
  r.curve.value = {0.f, 0.f};
  r.curve_color = p.curve_color;
  r.curve_label = "";  // no legend: the title says what the strip is
  r.fixed = true;      // symmetric about the zero line
  char scale[48];  // the strip is short: its title gives the scale
  std::snprintf(scale, sizeof scale, "   (largest |%s| %.3g)", versus_first(p) ? p.versus_first.c_str() : "error",
                double(largest));
  r.y_title += scale;
  const double m = largest > 0.f ? 1.1 * largest : 1.0;
  r.y0 = -m;
  r.y1 = m;
  return r;
}

std::size_t compose_with_residuals(FrameBuild& f, ProfilePanel p, const ViewSettings& view, const ShownField& shown,
                                   int axis, bool primary, bool residuals) {
  // the strip: its title, a box of at least 2.5 lines and the x labels; the profile keeps 10 lines (room for
  // its legend) or there is no strip
  const float lh = f.text.line_height(f.layout.text_scale);
  const float strip = std::round(4.f * lh + std::max(2.5f * lh, 0.22f * p.area.h));
  if (!residuals || !has_residuals(p) || p.area.h - strip < 10.f * lh) {
    compose_panel(f, p, view, shown, axis, primary);
    return f.batches.size();
  }
  const float gap = f.layout.margin;
  const PixelRect whole = p.area;
  const float top = whole.h - strip - gap;
  p.area = {whole.x, whole.y, whole.w, top};
  p.x_labels = false;
  ProfilePanel r = residual_panel(p, axis);
  r.area = {whole.x, whole.y + top + gap, whole.w, whole.h - top - gap};
  const float w = std::max(panel_label_width(f, p, axis), panel_label_width(f, r, axis));
  p.y_label_min = r.y_label_min = w;
  compose_panel(f, p, view, shown, axis, primary);
  const std::size_t drawn = f.batches.size();
  compose_panel(f, r, view, shown, axis, false);
  return drawn;
}

}  // namespace sph::render
