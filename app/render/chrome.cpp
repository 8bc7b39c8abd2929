#include "chrome.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "palette.h"
#include "sph/snapshot.h"
#include "ticks.h"

namespace sph::render {

namespace {

constexpr int kBarWidth = 14;   // colour bar width [px at text scale 1]
constexpr int kTickLength = 4;  // [px at text scale 1]

// Interior colour-bar ticks: nice values, not too close to the labelled ends.
Ticks bar_ticks(const ValueRange& r) { return nice_ticks(r.min, r.max, 4); }

std::string time_string(double t) {
  char buf[48];
  const double a = std::abs(t);
  std::snprintf(buf, sizeof buf, (a == 0.0 || (a >= 1e-3 && a < 1e5)) ? "%.4f" : "%.4e", t);
  return buf;
}

}  // namespace

void layout_chrome(FrameBuild& f, const ShownField& shown, int width, int height, int text_scale_request) {
  FrameLayout& L = f.layout;
  L = FrameLayout{};
  L.width = width;
  L.height = height;
  L.text_scale = text_scale_for(height, text_scale_request);
  const int s = L.text_scale;
  const float lh = f.text.line_height(s);
  const float m = 10.f * s;
  L.margin = m;
  L.title = {m, m, width - 2 * m, lh};
  const float top = m + lh + m;

  float panel_w = 0.f;
  if (shown.field != nullptr) {
    float values_w = std::max(f.text.measure(format_value(shown.range.min), s),
                              f.text.measure(format_value(shown.range.max), s));
    const Ticks t = bar_ticks(shown.range);
    for (double v : t.values) values_w = std::max(values_w, f.text.measure(format_tick(v, t.step), s));
    panel_w = static_cast<float>((kBarWidth + 2 * kTickLength) * s) + values_w;
    panel_w = std::max(panel_w, f.text.measure(shown.label, s));
    panel_w = std::min(panel_w, 0.4f * static_cast<float>(width));
  }
  L.panel = {std::floor(width - m - panel_w), top, panel_w, height - m - top};
  const float content_right = panel_w > 0.f ? L.panel.x - 2 * m : width - m;
  L.content = {m, top, std::max(content_right - m, 1.f), std::max(height - m - top, 1.f)};
  L.plot = L.content;
}

void add_title(FrameBuild& f, const sph::Snapshot& snap, const ShownField& shown) {
  const FrameLayout& L = f.layout;
  const int s = L.text_scale;
  if (!snap.title.empty()) {
    f.text.add(snap.title, L.title.x, L.title.y, s, f.pal.text);
    return;
  }
  const std::string scene = snap.scene.empty() ? "sph" : snap.scene;
  std::string title = scene + "  t = " + time_string(snap.t) + "  step " + std::to_string(snap.step);
  const float room = L.title.w - (shown.warning.empty() ? 0.f : f.text.measure(shown.warning, s) + f.text.line_height(s));
  if (f.text.measure(title, s) > room) title = scene + "  t = " + time_string(snap.t);  // a projector's 3x text
  const int ts = f.text.fitting_scale(title, room, s);
  float x = L.title.x;
  x += f.text.add(f.text.elided(title, room, ts), x, L.title.y, ts, f.pal.text);
  const std::string count = "   N = " + std::to_string(snap.count) + "  (" + std::to_string(snap.dim) + "D)";
  if (x + f.text.measure(count, s) <= L.title.right())  // only where it fits (a projector's 3x text: not)
    x += f.text.add(count, x, L.title.y, s, f.pal.dim_text);
  if (!shown.warning.empty()) f.text.add(shown.warning, L.title.right(), L.title.y, s, palette::kWarning, Align::Right);
}

void add_colorbar(FrameBuild& f, const ShownField& shown) {
  FrameLayout& L = f.layout;
  if (shown.field == nullptr) {
    L.colorbar = {};
    return;
  }
  const int s = L.text_scale;
  const float lh = f.text.line_height(s);
  const float gap = 6.f * s;
  // Level with the plot, but never shorter than ~150 px (scaled) where the panel allows.
  const float lo_y = L.panel.y + lh + gap + 0.5f * lh;  // room for the label and the max value
  const float hi_y = L.panel.bottom() - 0.5f * lh;
  float y0 = std::max(L.plot.y, lo_y), y1 = std::min(L.plot.bottom(), hi_y);
  const float want = std::min(150.f * s, hi_y - lo_y);
  if (y1 - y0 < want) {
    const float mid = std::clamp(0.5f * (y0 + y1), lo_y + 0.5f * want, hi_y - 0.5f * want);
    y0 = mid - 0.5f * want;
    y1 = mid + 0.5f * want;
  }
  y0 = std::round(y0);
  y1 = std::round(y1);
  const PixelRect bar{L.panel.x, y0, static_cast<float>(kBarWidth * s), std::max(y1 - y0, 1.f)};
  L.colorbar = bar;

  // Gradient: one band per pair of neighbouring table entries, colours interpolated by the rasterizer.
  const ColormapLut& lut = colormap_lut(shown.cmap);
  auto entry = [&](int i) { return Rgba{lut[4 * i] / 255.f, lut[4 * i + 1] / 255.f, lut[4 * i + 2] / 255.f, 1.f}; };
  const float n = kColormapLutSize - 1;
  for (int i = 0; i + 1 < kColormapLutSize; ++i) {
    const float ya = bar.bottom() - bar.h * static_cast<float>(i) / n;
    const float yb = bar.bottom() - bar.h * static_cast<float>(i + 1) / n;
    f.over.vertical_gradient({bar.x, yb, bar.w, ya - yb}, entry(i), entry(i + 1));
  }
  f.over.rect_outline({bar.x - 1.f, bar.y - 1.f, bar.w + 2.f, bar.h + 2.f}, 1.f, f.pal.axis);

  // Ticks and values on the right: max at the top, min at the bottom, round values between.
  const ValueRange& r = shown.range;
  const float tick_x0 = bar.right(), tick_x1 = bar.right() + kTickLength * s;
  const float text_x = tick_x1 + kTickLength * s;
  auto y_of = [&](double v) { return bar.bottom() - bar.h * static_cast<float>((v - r.min) / (r.max - r.min)); };
  auto tick = [&](float y, const std::string& label, Rgba color) {
    const float yc = std::floor(y) + 0.5f;
    f.over.line(tick_x0, yc, tick_x1, yc, 1.f * s, f.pal.axis);
    f.text.add(label, text_x, y - 0.5f * lh, s, color);
  };
  tick(bar.y, format_value(r.max), f.pal.text);
  tick(bar.bottom(), format_value(r.min), f.pal.text);
  const Ticks t = bar_ticks(r);
  for (double v : t.values) {
    const float y = y_of(v);
    if (y - bar.y > 1.8f * lh && bar.bottom() - y > 1.8f * lh) tick(y, format_tick(v, t.step), f.pal.dim_text);
  }
  // Field label above the bar (cut with "..." if the panel is too narrow).
  std::string label = shown.label;
  while (label.size() > 4 && f.text.measure(label, s) > L.panel.w + L.margin)
    label = label.substr(0, label.size() - 4) + "...";
  f.text.add(label, bar.x, bar.y - gap - 1.5f * lh, s, f.pal.text);
}

}  // namespace sph::render
