#include "tree_overlay.h"

#include <string>

#include "frame_build.h"
#include "outline_overlay.h"
#include "palette.h"
#include "sph/snapshot.h"

namespace sph::render {

namespace {

constexpr Rgba kWhole = palette::kOutlines[2];  // sky blue
constexpr Rgba kLeaf = palette::kOutlines[1];   // amber

void add_cell(FrameBuild& f, const sph::TreeCell& c, int dim, float width) {
  const Rgba col = c.whole ? kWhole : kLeaf;
  const FrameLayout& L = f.layout;
  const int corners = dim == 3 ? 8 : 4;
  float px[8], py[8];
  for (int k = 0; k < corners; ++k) {
    const float x = c.center[0] + ((k & 1) ? c.half : -c.half);
    const float y = c.center[1] + ((k & 2) ? c.half : -c.half);
    const float z = dim == 3 ? c.center[2] + ((k & 4) ? c.half : -c.half) : 0.f;
    if (!L.to_pixel(x, y, z, &px[k], &py[k])) return;  // behind the eye
  }
  for (int k = 0; k < corners; ++k)
    for (int axis = 0; axis < (dim == 3 ? 3 : 2); ++axis) {
      if (k & (1 << axis)) continue;  // each edge once, from its lower corner
      const int k2 = k | (1 << axis);
      f.clipped.line(px[k], py[k], px[k2], py[k2], width, col);
    }
}

}  // namespace

void add_tree_overlay(FrameBuild& f, const sph::Snapshot& snap) {
  if (snap.tree_cells.empty() || snap.dim < 2 || snap.tree_probe < 0 ||
      static_cast<std::size_t>(snap.tree_probe) >= snap.count)
    return;
  const FrameLayout& L = f.layout;
  const int s = L.text_scale;
  const float width = outline_width(s);  // as thin as the reference outlines
  std::size_t whole = 0;
  for (const sph::TreeCell& c : snap.tree_cells) {
    add_cell(f, c, snap.dim, width);
    whole += c.whole ? 1 : 0;
  }
  const auto i = static_cast<std::size_t>(snap.tree_probe);
  float cx = 0.f, cy = 0.f;
  if (L.to_pixel(snap.x[i], snap.y[i], snap.dim == 3 ? snap.z[i] : 0.f, &cx, &cy)) {
    const float r = 5.f * static_cast<float>(s);
    f.clipped.disc(cx, cy, r + 1.5f * static_cast<float>(s), palette::kOutlineHalo);
    f.clipped.disc(cx, cy, r, f.pal.text);
  }
  const std::string caption = "tree walk of particle " + std::to_string(i) + ": " + std::to_string(whole) +
                              " cells whole (blue), " + std::to_string(snap.tree_cells.size() - whole) +
                              " leaves pair by pair (amber)";
  const float lh = f.text.line_height(s);
  f.text.add(caption, L.plot.x + 0.5f * lh, L.plot.y + 0.4f * lh, s, f.pal.text, Align::Left);
}

}  // namespace sph::render
