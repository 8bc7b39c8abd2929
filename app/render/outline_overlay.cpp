#include "outline_overlay.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "legend.h"
#include "palette.h"
#include "sph/snapshot.h"

namespace sph::render {

namespace {

constexpr std::size_t kColours = std::size(palette::kOutlines);

// One outline in frame pixels (x0, y0, x1, y1, ...; NaN breaks the line) and its colour.
struct PixelOutline {
  std::vector<float> xy;
  Rgba color;
};

}  // namespace

float outline_width(int s) { return 0.75f * static_cast<float>(s) + 0.5f; }  // as thin as the exact curves

namespace {

/// Every outline in pixels through `to_pixel`, coloured by its label's place in `labels` (appended);
/// `drawn_as_lines` gets the labels with a line (the others are markers only: legend dots).
template <class ToPixel>
std::vector<PixelOutline> pixel_outlines(const sph::Snapshot& snap, const ToPixel& to_pixel, std::vector<std::string>& labels,
                                         std::vector<std::string>& drawn_as_lines) {
  auto colour_of = [&](const std::string& label) {
    auto it = std::find(labels.begin(), labels.end(), label);
    if (it == labels.end()) it = labels.insert(labels.end(), label);
    return palette::kOutlines[static_cast<std::size_t>(it - labels.begin()) % kColours];
  };
  std::vector<PixelOutline> lines;
  lines.reserve(snap.outlines.size());
  for (const sph::Outline& o : snap.outlines) {
    const std::size_t n = std::min(o.x.size(), o.y.size());
    if (n == 0) continue;
    PixelOutline p{{}, colour_of(o.label)};
    if (n > 1) drawn_as_lines.push_back(o.label);
    p.xy.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      float px = NAN, py = NAN;
      if (!std::isfinite(o.x[i]) || !std::isfinite(o.y[i]) || !to_pixel(o.x[i], o.y[i], &px, &py)) px = py = NAN;
      p.xy.push_back(px);
      p.xy.push_back(py);
    }
    lines.push_back(std::move(p));
  }
  return lines;
}

/// All rims before all lines, so that no rim covers a neighbouring segment's line at a joint.
void draw_lines(ShapeBatch& out, const std::vector<PixelOutline>& lines, float w) {
  for (int layer = 0; layer < 2; ++layer) {
    const float lw = layer == 0 ? w + 2.f : w;
    for (const PixelOutline& p : lines) {
      const Rgba c = layer == 0 ? palette::kOutlineHalo : p.color;
      if (p.xy.size() == 2) {  // one vertex: a dot
        if (std::isfinite(p.xy[0]) && std::isfinite(p.xy[1])) out.disc(p.xy[0], p.xy[1], 1.5f * lw + 1.f, c);  // a marker: wider than the lines
      } else {
        out.polyline(p.xy, lw, c);
      }
    }
  }
}

}  // namespace

void add_outlines(FrameBuild& f, const sph::Snapshot& snap) {
  if (snap.outlines.empty()) return;
  const FrameLayout& L = f.layout;
  const float w = outline_width(L.text_scale);
  // Distinct labels in order of appearance: each gets the next palette colour and a legend row.
  std::vector<std::string> labels, drawn_as_lines;
  const auto to_pixel = [&](float x, float y, float* px, float* py) { return L.to_pixel(x, y, 0.f, px, py); };
  const std::vector<PixelOutline> lines = pixel_outlines(snap, to_pixel, labels, drawn_as_lines);
  draw_lines(f.clipped, lines, w);

  std::vector<LegendEntry> rows;
  for (std::size_t k = 0; k < labels.size() && k < kColours; ++k)
    if (!labels[k].empty()) {
      const bool dot = std::find(drawn_as_lines.begin(), drawn_as_lines.end(), labels[k]) == drawn_as_lines.end();
      rows.push_back({labels[k], dot, palette::kOutlines[k], dot ? 1.5f * w + 1.f : w, palette::kOutlineHalo});
    }
  std::vector<float> dots;  // the legend keeps off the markers (a chart's data points)
  for (const PixelOutline& p : lines)
    if (p.xy.size() == 2) dots.insert(dots.end(), p.xy.begin(), p.xy.end());
  add_legend(f, L.plot, rows, dots, 4.f);
}

void add_outlines_in(ShapeBatch& out, const sph::Snapshot& snap, const PixelRect& box, const WorldRect& w, int s) {
  if (snap.outlines.empty() || !(w.x1 > w.x0) || !(w.y1 > w.y0)) return;
  std::vector<std::string> labels, drawn_as_lines;
  const auto to_pixel = [&](float x, float y, float* px, float* py) {
    *px = box.x + (x - w.x0) / (w.x1 - w.x0) * box.w;
    *py = box.bottom() - (y - w.y0) / (w.y1 - w.y0) * box.h;
    return true;
  };
  draw_lines(out, pixel_outlines(snap, to_pixel, labels, drawn_as_lines), outline_width(s));
}

}  // namespace sph::render
