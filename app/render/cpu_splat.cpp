#include "cpu_splat.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "frame_build.h"

namespace sph::render {

struct SplatProjected {
  float wx, wy;  // window position [px], y up
  float r;       // radius [px]
  float eye_z;   // eye-space depth of the centre
  float eye_r;   // radius in eye units
  Rgb color;
};

SplatImage::SplatImage() = default;
SplatImage::~SplatImage() = default;

namespace {

constexpr int kTile = 32;  // tile side [px]: a tile's rows stay in L1 cache

// Light of particles.frag (unit vector, eye space).
constexpr float kLx = -0.3841f, kLy = 0.5762f, kLz = 0.7215f;

using Projected = SplatProjected;

// Rows of a matrix for the affine point transform m * (x, y, z, 1).
struct Rows {
  float r[4][4];
  explicit Rows(const Mat4& m) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) r[i][j] = m.at(i, j);
  }
  float row(int i, const float* v) const { return r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2] + r[i][3]; }
};

// particles.vert: position, pixel radius and colour of one particle; false if not drawable.
bool project(const float* in, const SplatParams& p, const Rows& mvp, const Rows& view, Projected* o) {
  const Vec4f clip{mvp.row(0, in), mvp.row(1, in), mvp.row(2, in), mvp.row(3, in)};
  if (!(clip.w > 0.f)) return false;
  const float eye_z = view.row(2, in);
  const float px_per_unit = 0.5f * static_cast<float>(p.height) * p.proj.at(1, 1) / clip.w;
  float r = p.pixel_radius > 0.f ? p.pixel_radius : in[3] * px_per_unit;
  r = std::max(r, p.min_radius);
  o->wx = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(p.width);
  o->wy = (clip.y / clip.w * 0.5f + 0.5f) * static_cast<float>(p.height);
  o->r = r;
  o->eye_z = eye_z;
  o->eye_r = r / px_per_unit;
  if (!std::isfinite(o->wx) || !std::isfinite(o->wy) || !std::isfinite(r)) return false;
  const float v = in[4];
  const bool wall = in[5] > 0.5f;  // walls: their own colour, whatever the value
  const Rgba& fixed = wall ? p.colors.wall : p.colors.invalid;
  o->color = std::isfinite(v) && !wall ? colormap_rgb(p.cmap, (v - p.range.min) / (p.range.max - p.range.min))
                                       : Rgb{fixed.r, fixed.g, fixed.b};
  return true;
}

// Pixel index range whose centres (i + 0.5) lie within [c - e, c + e], clipped to [lo, hi].
bool span(float c, float e, int lo, int hi, int* a, int* b) {
  const float fa = std::ceil(c - e - 0.5f), fb = std::floor(c + e - 0.5f);
  if (!(fb >= static_cast<float>(lo)) || !(fa <= static_cast<float>(hi))) return false;
  *a = std::max(lo, static_cast<int>(fa));
  *b = std::min(hi, static_cast<int>(fb));
  return *a <= *b;
}

// A rectangle of pixels [x0, x1] x [y0, y1] (inclusive).
struct Region {
  int x0, x1, y0, y1;
};

std::uint8_t to8(float v) { return static_cast<std::uint8_t>(std::clamp(v, 0.f, 1.f) * 255.f + 0.5f); }

void disc(const Projected& q, const Region& t, SplatImage* img) {
  int x0, x1, y0, y1;
  const float e = q.r + 1.f;
  if (!span(q.wx, e, t.x0, t.x1, &x0, &x1) || !span(q.wy, e, t.y0, t.y1, &y0, &y1)) return;
  const float inner = q.r - 0.5f;  // closer than this: coverage 1
  const float inner2 = inner > 0.f ? inner * inner : -1.f, outer2 = (q.r + 0.5f) * (q.r + 0.5f);
  const std::uint8_t solid[4] = {to8(q.color.r), to8(q.color.g), to8(q.color.b), 255};
  const float c[3] = {q.color.r * 255.f, q.color.g * 255.f, q.color.b * 255.f};
  for (int y = y0; y <= y1; ++y) {
    const float dy = static_cast<float>(y) + 0.5f - q.wy;
    std::uint8_t* row = img->rgba.data() + static_cast<std::size_t>(y) * img->width * 4;
    for (int x = x0; x <= x1; ++x) {
      const float dx = static_cast<float>(x) + 0.5f - q.wx;
      const float d2 = dx * dx + dy * dy;
      if (d2 >= outer2) continue;  // coverage 0
      std::uint8_t* d = row + 4 * x;
      if (d2 <= inner2) {
        std::copy(solid, solid + 4, d);
        continue;
      }
      // The rim: "over" with coverage a, premultiplied, rounded to 8 bits like a framebuffer.
      const float a = std::clamp(q.r + 0.5f - std::sqrt(d2), 0.f, 1.f), k = 1.f - a;
      for (int ch = 0; ch < 3; ++ch) d[ch] = static_cast<std::uint8_t>(c[ch] * a + d[ch] * k + 0.5f);
      d[3] = static_cast<std::uint8_t>(255.f * a + d[3] * k + 0.5f);
    }
  }
}

void sphere(const Projected& q, const Region& t, SplatImage* img) {
  int x0, x1, y0, y1;
  const float e = q.r + 1.f;
  if (!span(q.wx, e, t.x0, t.x1, &x0, &x1) || !span(q.wy, e, t.y0, t.y1, &y0, &y1)) return;
  const float inv_r = 1.f / q.r;
  for (int y = y0; y <= y1; ++y) {
    const float py = (static_cast<float>(y) + 0.5f - q.wy) * inv_r;
    const std::size_t row = static_cast<std::size_t>(y) * img->width;
    for (int x = x0; x <= x1; ++x) {
      const float px = (static_cast<float>(x) + 0.5f - q.wx) * inv_r;
      const float s = px * px + py * py;
      if (s > 1.f) continue;
      const float nz = std::sqrt(1.f - s);
      const float z = q.eye_z + nz * q.eye_r;  // larger = nearer the eye
      float& depth = img->depth[row + x];
      if (!(z > depth)) continue;  // equal depth: the earlier particle stays, as with GL_LESS
      depth = z;
      const float diffuse = std::max(px * kLx + py * kLy + nz * kLz, 0.f);
      const float rz = std::max(2.f * diffuse * nz - kLz, 0.f);  // (reflect(-light, n)).z
      const float r3 = rz * rz * rz, r6 = r3 * r3, r12 = r6 * r6, spec = 0.25f * r12 * r12;  // 0.25 rz^24
      const float light = 0.35f + 0.75f * diffuse;
      std::uint8_t* d = img->rgba.data() + 4 * (row + x);
      d[0] = to8(q.color.r * light + spec);
      d[1] = to8(q.color.g * light + spec);
      d[2] = to8(q.color.b * light + spec);
      d[3] = 255;
    }
  }
}

}  // namespace

void splat_particles(const std::vector<float>& instances, const SplatParams& p, SplatImage* out) {
  const int w = std::max(p.width, 0), h = std::max(p.height, 0);
  const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  out->width = w;
  out->height = h;
  out->rgba.assign(pixels * 4, 0);
  if (p.shaded) out->depth.assign(pixels, -INFINITY);
  if (pixels == 0) return;

  // Project every particle once, in order.
  const std::size_t n = instances.size() / kInstanceFloats;
  const Rows mvp(p.proj * p.view), view(p.view);
  std::vector<Projected>& q = out->projected;
  q.clear();
  q.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    Projected pr;
    if (project(instances.data() + i * kInstanceFloats, p, mvp, view, &pr)) q.push_back(pr);
  }

  // Bin into tiles (counting sort keeps the drawing order within each tile). Every pixel sees the
  // particles that cover it in their original order, so the result equals drawing them one by one,
  // while a tile's pixels stay in cache.
  const int tx = (w + kTile - 1) / kTile, ty = (h + kTile - 1) / kTile;
  std::vector<std::uint32_t>& start = out->tile_start;
  start.assign(static_cast<std::size_t>(tx) * ty + 1, 0);
  auto tiles_of = [&](const Projected& v, int* a0, int* a1, int* b0, int* b1) {
    const float e = v.r + 1.f;
    int x0, x1, y0, y1;
    if (!span(v.wx, e, 0, w - 1, &x0, &x1) || !span(v.wy, e, 0, h - 1, &y0, &y1)) return false;
    *a0 = x0 / kTile, *a1 = x1 / kTile, *b0 = y0 / kTile, *b1 = y1 / kTile;
    return true;
  };
  int a0, a1, b0, b1;
  for (const Projected& v : q)
    if (tiles_of(v, &a0, &a1, &b0, &b1))
      for (int j = b0; j <= b1; ++j)
        for (int i = a0; i <= a1; ++i) ++start[static_cast<std::size_t>(j) * tx + i + 1];
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  // Copies rather than indices: the splat then reads each tile's particles sequentially.
  std::vector<std::uint32_t>& fill = out->tile_fill;
  fill.assign(start.begin(), start.end() - 1);
  std::vector<Projected>& list = out->binned;
  list.resize(start.back());
  for (const Projected& v : q)
    if (tiles_of(v, &a0, &a1, &b0, &b1))
      for (int j = b0; j <= b1; ++j)
        for (int i = a0; i <= a1; ++i) list[fill[static_cast<std::size_t>(j) * tx + i]++] = v;

  // Tiles are disjoint: rows of tiles are shared out between threads (deterministic result).
  auto work = [&](int first_row, int stride) {
    for (int j = first_row; j < ty; j += stride)
      for (int i = 0; i < tx; ++i) {
        const std::size_t t = static_cast<std::size_t>(j) * tx + i;
        const Region r{i * kTile, std::min(w, (i + 1) * kTile) - 1, j * kTile, std::min(h, (j + 1) * kTile) - 1};
        for (std::uint32_t k = start[t]; k < start[t + 1]; ++k) {
          if (p.shaded)
            sphere(list[k], r, out);
          else
            disc(list[k], r, out);
        }
      }
  };
  const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 4u));
  if (threads == 1 || q.size() < 2000) {
    work(0, 1);
    return;
  }
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t, threads);
  work(0, threads);
  for (auto& th : pool) th.join();
}

}  // namespace sph::render
