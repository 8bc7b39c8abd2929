#include "highlight.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "palette.h"

namespace sph::render {
namespace {

/// A plot's particles as the functions below walk them.
struct DrawnSet {
  const std::vector<float>* instances;
  const std::vector<std::uint32_t>* index;
  const CameraMatrices* camera;
  PixelRect rect;
  int run;
};

std::vector<DrawnSet> drawn_sets(const FrameBuild& f) {
  std::vector<DrawnSet> out;
  if (!f.instances.empty()) out.push_back({&f.instances, &f.index, &f.camera, f.layout.plot, 0});
  for (const ParticleBatch& b : f.batches) out.push_back({&b.instances, &b.index, &b.camera, b.rect, b.run});
  return out;
}

/// Frame pixel of the set's plot point (x, y, z); false if behind the camera.
bool project(const DrawnSet& s, float x, float y, float z, float* px, float* py) {
  const Vec4f c = s.camera->proj * (s.camera->view * Vec4f{x, y, z, 1.f});
  if (!(c.w > 0.f)) return false;
  *px = s.rect.x + (0.5f * c.x / c.w + 0.5f) * s.rect.w;
  *py = s.rect.y + (0.5f - 0.5f * c.y / c.w) * s.rect.h;
  return true;
}

/// Frame pixel of instance k of the set; false if behind the camera or outside the plot.
bool pixel_of(const DrawnSet& s, std::size_t k, float* px, float* py) {
  const float* p = s.instances->data() + k * kInstanceFloats;
  return project(s, p[0], p[1], p[2], px, py) && s.rect.contains(*px, *py);
}

void ring(ShapeBatch& b, float cx, float cy, float r, float width, Rgba c) {
  constexpr int kSegments = 28;
  std::vector<float> xy;
  for (int k = 0; k <= kSegments; ++k) {
    const float t = 6.2831853f * static_cast<float>(k) / kSegments;
    xy.push_back(cx + r * std::cos(t));
    xy.push_back(cy + r * std::sin(t));
  }
  b.polyline(xy, width, c);
}

/// The picked particle's kernel support: a circle of radius R in a plane view (the largest projection of R
/// along the axes in 3D: the sphere's outline), an interval x +- R in a profile (along the plotted axis).
void support_mark(ShapeBatch& b, const DrawnSet& s, std::size_t k, float R, bool profile, float width) {
  const float* p = s.instances->data() + k * kInstanceFloats;
  const auto to_px = [&](float x, float y, float z, float* px, float* py) { return project(s, x, y, z, px, py); };
  float cx = 0.f, cy = 0.f;
  if (!to_px(p[0], p[1], p[2], &cx, &cy)) return;
  const Rgba colour = palette::kKernelSupport;
  if (profile) {  // the interval the kernel reaches, with end ticks
    float x0 = 0.f, x1 = 0.f, y = 0.f;
    if (!to_px(p[0] - R, p[1], p[2], &x0, &y) || !to_px(p[0] + R, p[1], p[2], &x1, &y)) return;
    const float tick = 4.f * width;
    for (const std::array<float, 4>& seg : {std::array<float, 4>{x0, cy - tick, x0, cy + tick},
                                            std::array<float, 4>{x0, cy, x1, cy},
                                            std::array<float, 4>{x1, cy - tick, x1, cy + tick}})
      b.polyline(seg, width, colour);
    return;
  }
  float r = 0.f;
  for (int axis = 0; axis < 3; ++axis) {
    float q[3] = {p[0], p[1], p[2]};
    q[axis] += R;
    float px = 0.f, py = 0.f;
    if (to_px(q[0], q[1], q[2], &px, &py)) r = std::max(r, std::hypot(px - cx, py - cy));
  }
  if (r > 1.f) ring(b, cx, cy, r, width, colour);
}

}  // namespace

void add_highlight(FrameBuild& f, const Highlight& h, bool profile) {
  if (h.index < 0) return;
  const int s = f.layout.text_scale;
  const float r0 = 5.f * static_cast<float>(s) + 2.f;
  for (const DrawnSet& set : drawn_sets(f)) {
    if (set.run != h.run) continue;
    const std::size_t n = set.index->size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t i = (*set.index)[k];
      float px = 0.f, py = 0.f;
      for (const auto& [j, w] : h.neighbours) {
        if (j != i || !pixel_of(set, k, &px, &py)) continue;
        const float a = 0.35f + 0.65f * std::clamp(w, 0.f, 1.f);
        ring(f.over, px, py, r0, 0.5f + 1.5f * a * static_cast<float>(s), {1.00f, 0.85f, 0.30f, a});
      }
      if (static_cast<std::int64_t>(i) == h.index && pixel_of(set, k, &px, &py)) {
        ring(f.over, px, py, r0 + 2.f * s, 2.f * s + 2.f, palette::kOutlineHalo);
        ring(f.over, px, py, r0 + 2.f * s, 1.5f * s, f.pal.text);
        if (h.support > 0.f) support_mark(f.over, set, k, h.support, profile, 1.f * s);
      }
    }
  }
}

std::optional<Picked> pick_particle(const FrameBuild& f, float px, float py, float max_px) {
  std::optional<Picked> best;
  for (const DrawnSet& set : drawn_sets(f)) {
    if (!set.rect.contains(px, py)) continue;
    for (std::size_t k = 0; k < set.index->size(); ++k) {
      float x = 0.f, y = 0.f;
      if (!pixel_of(set, k, &x, &y)) continue;
      const float d = std::hypot(x - px, y - py);
      if (d <= max_px && (!best || d < best->distance_px)) best = Picked{set.run, (*set.index)[k], d};
    }
  }
  return best;
}

std::optional<std::array<float, 2>> locate_particle(const FrameBuild& f, int run, std::uint32_t index) {
  for (const DrawnSet& set : drawn_sets(f)) {
    if (set.run != run) continue;
    for (std::size_t k = 0; k < set.index->size(); ++k) {
      float x = 0.f, y = 0.f;
      if ((*set.index)[k] == index && pixel_of(set, k, &x, &y)) return std::array<float, 2>{x, y};
    }
  }
  return std::nullopt;
}

}  // namespace sph::render
