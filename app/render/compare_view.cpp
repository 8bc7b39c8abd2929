#include "compare_view.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "nearest_difference.h"
#include "orbit_view.h"
#include "palette.h"
#include "plane_view.h"
#include "sph/snapshot.h"
#include "ticks.h"

namespace sph::render {
namespace {

/// The field as the view shows it (log10 when asked for), named like the original.
sph::SnapshotField shown_values(const sph::SnapshotField& in, bool log) {
  sph::SnapshotField out = in;
  if (!log) return out;
  for (float& v : out.values) v = v > 0.f ? std::log10(v) : std::nanf("");
  out.min = out.max = std::nanf("");
  return out;
}

/// "A: physics.force=standard, visc.alpha=0" without the keys' groups ("A: force=standard, alpha=0"), or
/// with values only ("A: standard, 0").
std::string short_label(const std::string& label, bool values_only) {
  std::string out;
  std::size_t i = 0;
  while (i < label.size()) {
    const std::size_t eq = label.find('=', i);
    if (eq == std::string::npos) break;
    std::size_t start = label.rfind(' ', eq);  // the key starts after the space before it
    start = start == std::string::npos || start < i ? i : start + 1;
    out += label.substr(i, start - i);
    if (!values_only) {
      const std::string key = label.substr(start, eq - start);
      const auto dot = key.rfind('.');
      out += (dot == std::string::npos ? key : key.substr(dot + 1)) + "=";
    }
    i = eq + 1;
  }
  return out + label.substr(i);
}

/// A small horizontal colour bar of `cmap` over [lo, hi] at (x, y) with its end values beside it.
void mini_colorbar(FrameBuild& f, float x, float y, Colormap cmap, const ValueRange& r) {
  const int s = f.layout.text_scale;
  const float lh = f.text.line_height(s), w = 90.f * s, h = 0.6f * lh;
  x += f.text.add(format_value(r.min), x, y, s, f.pal.text) + 4.f * s;
  const int bands = 32;
  for (int k = 0; k < bands; ++k) {
    const Rgb c = colormap_rgb(cmap, (k + 0.5f) / bands);
    f.over.fill_rect({x + w * k / bands, y + 0.2f * lh, w / bands + 0.5f, h}, {c.r, c.g, c.b, 1.f});
  }
  f.text.add(format_value(r.max), x + w + 4.f * s, y, s, f.pal.text);
}

}  // namespace

ValueRange compare_range(const sph::Snapshot& a, const sph::Snapshot& b, const ViewSettings& view,
                         const sph::SnapshotField& fa) {
  const sph::SnapshotField* fb = b.find(fa.name);
  if (fb == nullptr) return resolve_range(fa, view, a.kind);
  sph::SnapshotField both = fa;
  both.values.insert(both.values.end(), fb->values.begin(), fb->values.end());
  std::vector<std::uint8_t> kind(a.count + b.count, 0);
  for (std::size_t i = 0; i < a.count; ++i) kind[i] = a.is_wall(i);
  for (std::size_t i = 0; i < b.count; ++i) kind[a.count + i] = b.is_wall(i);
  both.min = std::min(fa.min, fb->min);
  both.max = std::max(fa.max, fb->max);
  return resolve_range(both, view, kind);
}

void compose_compare(FrameBuild& f, const FrameScene& scene, const ViewSettings& view, const ShownField& shown) {
  FrameLayout& L = f.layout;
  const sph::Snapshot& a = *scene.a;
  const sph::Snapshot& b = *scene.b;
  const int s = L.text_scale;
  const float lh = f.text.line_height(s), gap = L.margin;
  const bool plane = a.dim == 2;
  const int panels = plane ? 3 : 2;
  const PixelRect content = L.content;
  const float w = (content.w - (panels - 1) * gap) / panels;
  auto area = [&](int k) { return PixelRect{content.x + k * (w + gap), content.y + lh + gap, w, content.h - lh - gap}; };
  auto caption = [&](int k, std::string text, Rgba colour) {  // shortened to its panel's width
    if (f.text.measure(text, s) > w) text = short_label(text, false);
    if (f.text.measure(text, s) > w) text = short_label(text, true);
    while (text.size() > 4 && f.text.measure(text, s) > w) text = text.substr(0, text.size() - 4) + "...";
    f.text.add(text, content.x + k * (w + gap), content.y, s, colour);
  };
  const FixedColors fixed{shown.field ? palette::kInvalid : palette::kNoField, palette::kWall};
  const sph::Snapshot* runs[2] = {&a, &b};
  sph::SnapshotField b_field;  // B's values of the shown field, as shown (log10 when asked for)
  for (int r = 0; r < 2; ++r) {
    ShownField sf = shown;
    if (r == 1 && shown.field) {
      const sph::SnapshotField* fb = b.find(shown.field->name);
      b_field = fb ? shown_values(*fb, view.log_scale) : sph::SnapshotField{};
      sf.field = fb ? &b_field : nullptr;
    }
    L.content = area(r);
    if (plane) compose_plane(f, *runs[r], view, sf);
    else compose_orbit(f, *runs[r], view, sf);
    f.detach_primary(r, shown.cmap, shown.range, fixed);
    caption(r, r == 0 ? scene.label_a : scene.label_b, kRunColors[r]);
  }
  if (plane && shown.field) {  // the difference map at A's particles
    const std::string name = shown.field->name;
    sph::SnapshotField diff;
    diff.name = name;
    diff.label = "B - A " + shown.label;
    // the difference of what is shown (log10 B - log10 A with the log scale)
    const sph::SnapshotField va = shown_values(*a.find(name), view.log_scale);
    const sph::SnapshotField* fb = b.find(name);
    if (fb) diff.values = nearest_difference(a, va.values, b, shown_values(*fb, view.log_scale).values);
    diff.values.resize(a.count, std::nanf(""));
    float m = 0.f;  // symmetric range: the 99th percentile of |B - A|
    std::vector<float> mag;
    for (std::size_t i = 0; i < diff.values.size(); ++i)
      if (std::isfinite(diff.values[i]) && !a.is_wall(i)) mag.push_back(std::abs(diff.values[i]));
    if (!mag.empty()) {
      const auto k = mag.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(mag.size() - 1));
      std::nth_element(mag.begin(), k, mag.end());
      m = *k;
    }
    if (!(m > 0.f)) m = 1e-6f;
    ShownField sd;
    sd.field = &diff;
    sd.label = diff.label;
    sd.cmap = Colormap::Coolwarm;
    sd.range = {-m, m};
    L.content = area(2);
    ViewSettings dv = view;
    dv.show_tree = false;
    compose_plane(f, a, dv, sd);
    const ParticleBatch& d = f.detach_primary(0, Colormap::Coolwarm, sd.range, {palette::kNoField, palette::kWall});
    caption(2, "B - A (nearest B particle)", f.pal.text);
    // its colour bar under the panel's x axis title
    mini_colorbar(f, d.rect.x, d.rect.bottom() + 13.f * s + 2.5f * lh, Colormap::Coolwarm, sd.range);
  }
  L.content = content;
  // pan, zoom and picking read the first panel's mapping
  const ParticleBatch& first = f.batches.front();
  L.plot = first.rect;
  L.plot_to_clip = first.camera.proj * first.camera.view;
}

}  // namespace sph::render
