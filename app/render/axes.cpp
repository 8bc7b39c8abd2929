#include "axes.h"

#include <string>

#include <algorithm>
#include <cmath>

#include "palette.h"
#include "ticks.h"

namespace sph::render {

namespace {
constexpr int kTick = 5;  // tick length [px at text scale 1]
constexpr int kGap = 4;   // label gap [px at text scale 1]
}  // namespace

int x_tick_target(float box_w, int s) { return std::max(2, static_cast<int>(box_w / (110.f * s))); }
int y_tick_target(float box_h, int s) { return std::max(2, static_cast<int>(box_h / (50.f * s))); }

PixelRect axes_box(const PixelRect& area, float y_label_width, int s, float lh, float aspect, bool x_labels) {
  const float left = y_label_width + (kTick + kGap) * s;
  const float top = lh + kGap * s;  // y title above the box
  const float bottom = x_labels ? (kTick + 2 * kGap) * s + 2.f * lh : (kTick + kGap) * s;  // tick labels, x title
  PixelRect b{area.x + left, area.y + top, area.w - left, area.h - top - bottom};
  b.w = std::max(b.w, 8.f);
  b.h = std::max(b.h, 8.f);
  if (aspect > 0.f) {
    if (b.w / b.h > aspect) {
      const float w = b.h * aspect;
      b.x += 0.5f * (b.w - w);
      b.w = w;
    } else {
      const float h = b.w / aspect;
      b.y += 0.5f * (b.h - h);
      b.h = h;
    }
  }
  const float x0 = std::round(b.x), y0 = std::round(b.y);
  return {x0, y0, std::max(std::round(b.right()) - x0, 8.f), std::max(std::round(b.bottom()) - y0, 8.f)};
}

float y_label_width(const TextBatch& text, double y0, double y1, float box_h, int s) {
  const Ticks t = nice_ticks(y0, y1, y_tick_target(box_h, s));
  float w = 0.f;
  for (double v : t.values) w = std::max(w, text.measure(format_tick(v, t.step), s));
  return std::max(w, text.measure("0.0", s));
}

void add_axes(FrameBuild& f, const PixelRect& box, const AxesRanges& r, const AxesStyle& style) {
  const int s = f.layout.text_scale;
  const float lh = f.text.line_height(s);
  const float lw = static_cast<float>(s);  // line width [px]
  auto px = [&](double x) { return box.x + static_cast<float>((x - r.x0) / (r.x1 - r.x0)) * box.w; };
  auto py = [&](double y) { return box.bottom() - static_cast<float>((y - r.y0) / (r.y1 - r.y0)) * box.h; };
  // Centre lines of odd widths on pixel centres so that they stay crisp.
  auto crisp = [&](float v) { return s % 2 ? std::floor(v) + 0.5f : std::round(v); };

  f.fill = box;  // a scissored clear: much cheaper than a blended quad on software GL
  const Ticks xt = nice_ticks(r.x0, r.x1, x_tick_target(box.w, s));
  const Ticks yt = nice_ticks(r.y0, r.y1, y_tick_target(box.h, s));
  float last_right = -1e30f;  // a label that would touch the one before it is left out (a tiny box at 3x text)
  for (double x : xt.values) {
    const float X = crisp(px(x));
    if (style.grid) f.under.line(X, box.y, X, box.bottom(), 1.f, f.pal.grid);
    f.over.line(X, box.bottom(), X, box.bottom() + kTick * s, lw, f.pal.axis);
    const std::string label = format_tick(x, xt.step);
    const float half = 0.5f * f.text.measure(label, s);
    if (style.x_labels && X - half >= last_right + 0.5f * lh) {
      f.text.add(label, X, box.bottom() + (kTick + kGap) * s, s, f.pal.text, Align::Center);
      last_right = X + half;
    }
  }
  // labels a line apart at least: in a box too short for that, only the label nearest its middle
  const float spacing = yt.values.size() > 1 ? box.h * static_cast<float>(yt.step / (r.y1 - r.y0)) : box.h;
  const double middle = 0.5 * (r.y0 + r.y1);
  double only = yt.values.empty() ? middle : yt.values.front();
  for (double y : yt.values)
    if (std::abs(y - middle) < std::abs(only - middle)) only = y;
  for (double y : yt.values) {
    const float Y = crisp(py(y));
    if (style.grid) f.under.line(box.x, Y, box.right(), Y, 1.f, f.pal.grid);
    f.over.line(box.x - kTick * s, Y, box.x, Y, lw, f.pal.axis);
    if (spacing >= lh || y == only)
      f.text.add(format_tick(y, yt.step), box.x - (kTick + kGap) * s, Y - 0.5f * lh, s, f.pal.text, Align::Right);
  }
  f.over.rect_outline({box.x - lw, box.y - lw, box.w + 2 * lw, box.h + 2 * lw}, lw, f.pal.axis);
  if (style.x_labels)
    f.text.add(style.x_title, box.x + 0.5f * box.w, box.bottom() + (kTick + 2 * kGap) * s + lh, s, f.pal.text,
               Align::Center);
  // a narrow panel's title (stacked panels at a projector's 3x text): smaller, then cut, never past the box
  const int ts = f.text.fitting_scale(style.y_title, box.w, s);
  f.text.add(f.text.elided(style.y_title, box.w, ts), box.x, box.y - lh - kGap * s, ts, f.pal.text);
}

}  // namespace sph::render
