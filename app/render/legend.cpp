#include "legend.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "palette.h"

namespace sph::render {

PixelRect place_legend(const PixelRect& box, float w, float h, float pad, float clear, std::span<const float> xy) {
  const float left = box.x + pad, right = box.right() - w - pad, mid = box.x + 0.5f * (box.w - w);
  const float top = box.y + pad, bottom = box.bottom() - h - pad;
  const float at[6][2] = {{right, top}, {left, top}, {right, bottom}, {left, bottom}, {mid, top}, {mid, bottom}};
  PixelRect best{};
  std::size_t fewest = SIZE_MAX;
  for (const auto& c : at) {
    const PixelRect r{std::round(c[0]), std::round(c[1]), std::round(w), std::round(h)};
    std::size_t inside = 0;
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2)
      inside += xy[i] >= r.x - clear && xy[i] <= r.right() + clear && xy[i + 1] >= r.y - clear &&
                xy[i + 1] <= r.bottom() + clear;
    if (inside < fewest) best = r, fewest = inside;
    if (inside == 0) break;
  }
  return best;
}

void densify(std::span<const float> xy, float step, std::vector<float>* out) {
  for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
    if (!std::isfinite(xy[i]) || !std::isfinite(xy[i + 1])) continue;
    out->push_back(xy[i]);
    out->push_back(xy[i + 1]);
    if (i + 3 >= xy.size() || !std::isfinite(xy[i + 2]) || !std::isfinite(xy[i + 3])) continue;
    const float dx = xy[i + 2] - xy[i], dy = xy[i + 3] - xy[i + 1];
    const int n = static_cast<int>(std::min(4096.f, std::ceil(std::hypot(dx, dy) / step)));
    for (int k = 1; k < n; ++k) {
      out->push_back(xy[i] + dx * static_cast<float>(k) / static_cast<float>(n));
      out->push_back(xy[i + 1] + dy * static_cast<float>(k) / static_cast<float>(n));
    }
  }
}

bool add_legend(FrameBuild& f, const PixelRect& box, std::span<const LegendEntry> entries,
                std::span<const float> avoid_xy, float clear, int text_scale) {
  if (entries.empty()) return false;
  // at the frame's text scale, or smaller where that does not fit the box (the A/B legend vanished from
  // a short plot at 1280 x 720); none below scale 1
  int s = text_scale > 0 ? text_scale : f.layout.text_scale;
  float lh = 0.f, sample = 0.f, pad = 0.f, gap = 0.f, w = 0.f, h = 0.f;
  const float n = static_cast<float>(entries.size());
  for (;; --s) {
    lh = f.text.line_height(s);
    sample = 22.f * s;  // sample length [px]
    pad = 6.f * s;
    gap = 2.f * s;  // between rows [px]
    float label_w = 0.f;
    for (const LegendEntry& e : entries) label_w = std::max(label_w, f.text.measure(e.label, s));
    w = pad * 3 + sample + label_w;
    h = pad * 2 + n * lh + (n - 1.f) * gap;
    if (w <= box.w - 2.f * pad && h <= 0.5f * box.h) break;
    if (s <= 1) return false;
  }
  const PixelRect r = place_legend(box, w, h, pad, clear, avoid_xy);
  f.layout.legend = r;
  f.over.fill_rect(r, f.pal.legend_fill);
  const float x0 = r.x + pad, x1 = x0 + sample;
  float y = r.y + pad + 0.5f * lh;  // centre of the row
  for (const LegendEntry& e : entries) {
    if (e.dot) {
      f.over.disc(0.5f * (x0 + x1), y, e.size, e.color);
    } else {
      if (e.halo.a > 0.f) f.over.line(x0, y, x1, y, e.size + 2.f, e.halo);
      f.over.line(x0, y, x1, y, e.size, e.color);
    }
    f.text.add(e.label, x1 + pad, y - 0.5f * lh, s, f.pal.text);
    f.layout.legend_rows.push_back(e.label);
    y += lh + gap;
  }
  return true;
}

}  // namespace sph::render
