#include "legend.h"

#include <algorithm>
#include <cmath>

#include "palette.h"

namespace sph::render {

bool add_legend(FrameBuild& f, const PixelRect& box, std::span<const LegendEntry> entries) {
  if (entries.empty()) return false;
  const int s = f.layout.text_scale;
  const float lh = f.text.line_height(s);
  const float sample = 22.f * s;  // sample length [px]
  const float pad = 6.f * s;
  const float gap = 2.f * s;      // between rows [px]
  float label_w = 0.f;
  for (const LegendEntry& e : entries) label_w = std::max(label_w, f.text.measure(e.label, s));
  const float n = static_cast<float>(entries.size());
  const float w = pad * 3 + sample + label_w;
  const float h = pad * 2 + n * lh + (n - 1.f) * gap;
  if (w > box.w - 2.f * pad || h > 0.5f * box.h) return false;
  const PixelRect r{std::round(box.right() - w - pad), std::round(box.y + pad), std::round(w), std::round(h)};
  f.over.fill_rect(r, palette::kLegendFill);
  const float x0 = r.x + pad, x1 = x0 + sample;
  float y = r.y + pad + 0.5f * lh;  // centre of the row
  for (const LegendEntry& e : entries) {
    if (e.dot) {
      f.over.disc(0.5f * (x0 + x1), y, e.size, e.color);
    } else {
      if (e.halo.a > 0.f) f.over.line(x0, y, x1, y, e.size + 2.f, e.halo);
      f.over.line(x0, y, x1, y, e.size, e.color);
    }
    f.text.add(e.label, x1 + pad, y - 0.5f * lh, s, palette::kText);
    y += lh + gap;
  }
  return true;
}

}  // namespace sph::render
