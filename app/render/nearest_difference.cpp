#include "nearest_difference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "sph/snapshot.h"

namespace sph::render {
namespace {

/// B's fluid particles binned in a uniform grid (about two per cell): nearest-particle queries.
class PointGrid {
 public:
  PointGrid(const sph::Snapshot& s, int dim) : s_(s), dim_(dim) {
    std::vector<std::uint32_t> fluid;
    for (std::size_t i = 0; i < s.count; ++i)
      if (!s.is_wall(i) && std::isfinite(coord(i, 0))) fluid.push_back(static_cast<std::uint32_t>(i));
    if (fluid.empty()) return;
    for (int k = 0; k < 3; ++k) lo_[k] = hi_[k] = k < dim ? coord(fluid[0], k) : 0.f;
    for (std::uint32_t i : fluid)
      for (int k = 0; k < dim; ++k) lo_[k] = std::min(lo_[k], coord(i, k)), hi_[k] = std::max(hi_[k], coord(i, k));
    double volume = 1.0;
    for (int k = 0; k < dim; ++k) volume *= std::max(1e-30f, hi_[k] - lo_[k]);
    cell_ = static_cast<float>(std::pow(2.0 * volume / static_cast<double>(fluid.size()), 1.0 / dim));
    if (!(cell_ > 0.f) || !std::isfinite(cell_)) cell_ = 1.f;
    for (int k = 0; k < 3; ++k) n_[k] = k < dim ? std::min(1024, static_cast<int>((hi_[k] - lo_[k]) / cell_) + 1) : 1;
    start_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
    for (std::uint32_t i : fluid) ++start_[cell_of(i) + 1];
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(fluid.size());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t i : fluid) items_[fill[cell_of(i)]++] = i;
  }

  /// The nearest fluid particle of the grid to p, or -1 if there is none.
  std::int64_t nearest(const float p[3]) const {
    if (items_.empty()) return -1;
    int c[3] = {0, 0, 0};
    for (int k = 0; k < dim_; ++k) c[k] = std::clamp(static_cast<int>((p[k] - lo_[k]) / cell_), 0, n_[k] - 1);
    std::int64_t best = -1;
    float best_d2 = std::numeric_limits<float>::infinity();
    const int max_ring = std::max({n_[0], n_[1], n_[2]});
    for (int ring = 0; ring <= max_ring; ++ring) {
      // every particle found in ring `ring` is nearer than any beyond (ring - 1) cells: stop when the
      // best is closer than that
      if (best >= 0 && std::sqrt(best_d2) < (ring - 1) * cell_) break;
      for (int dz = -ring; dz <= ring; ++dz)
        for (int dy = -ring; dy <= ring; ++dy)
          for (int dx = -ring; dx <= ring; ++dx) {
            if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != ring) continue;  // the shell only
            const int x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
            if (x < 0 || y < 0 || z < 0 || x >= n_[0] || y >= n_[1] || z >= n_[2]) continue;
            const std::size_t cell = (static_cast<std::size_t>(z) * n_[1] + y) * n_[0] + x;
            for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
              const std::uint32_t j = items_[k];
              float d2 = 0.f;
              for (int a = 0; a < dim_; ++a) d2 += (coord(j, a) - p[a]) * (coord(j, a) - p[a]);
              if (d2 < best_d2 || (d2 == best_d2 && static_cast<std::int64_t>(j) < best)) best_d2 = d2, best = j;
            }
          }
    }
    return best;
  }

 private:
  float coord(std::size_t i, int k) const {
    const std::vector<float>& v = k == 0 ? s_.x : k == 1 ? s_.y : s_.z;
    return i < v.size() ? v[i] : 0.f;
  }
  std::size_t cell_of(std::size_t i) const {
    int c[3] = {0, 0, 0};
    for (int k = 0; k < dim_; ++k) c[k] = std::clamp(static_cast<int>((coord(i, k) - lo_[k]) / cell_), 0, n_[k] - 1);
    return (static_cast<std::size_t>(c[2]) * n_[1] + c[1]) * n_[0] + c[0];
  }
  const sph::Snapshot& s_;
  int dim_;
  float lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0}, cell_ = 1.f;
  int n_[3] = {1, 1, 1};
  std::vector<std::uint32_t> start_, items_;
};

}  // namespace

std::vector<float> nearest_difference(const sph::Snapshot& a, std::span<const float> va, const sph::Snapshot& b,
                                      std::span<const float> vb) {
  std::vector<float> out(a.count, std::nanf(""));
  const int dim = std::clamp(a.dim, 1, 3);
  const PointGrid grid(b, dim);
  for (std::size_t i = 0; i < a.count && i < va.size(); ++i) {
    if (a.is_wall(i)) continue;
    const float p[3] = {a.x[i], dim > 1 && i < a.y.size() ? a.y[i] : 0.f, dim > 2 && i < a.z.size() ? a.z[i] : 0.f};
    const std::int64_t j = grid.nearest(p);
    if (j < 0 || static_cast<std::size_t>(j) >= vb.size()) continue;
    const float d = vb[static_cast<std::size_t>(j)] - va[i];
    out[i] = std::isfinite(d) ? d : std::nanf("");
  }
  return out;
}

}  // namespace sph::render
