#include "core/spatial_order.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sph {
namespace {

/// Bits per axis of a key: 32 in 1D, 31 in 2D, 21 in 3D (at most 63 in all).
int key_bits(int dim) { return std::min(32, 63 / dim); }

}  // namespace

std::uint64_t morton_key(const std::uint32_t c[3], int dim) {
  const int bits = key_bits(dim);
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int k = dim - 1; k >= 0; --k) key = (key << 1) | ((c[k] >> b) & 1u);
  return key;
}

std::vector<std::uint32_t> morton_order(const Particles& p, std::size_t begin, std::size_t end, double cell) {
  const int dim = p.dim();
  const double max_cell = std::ldexp(1.0, key_bits(dim)) - 1.0;  // largest coordinate a key can hold
  double lo[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < dim; ++k) {
    lo[k] = 1e300;
    for (std::size_t i = begin; i < end; ++i) lo[k] = std::min(lo[k], p.x[k][i]);
  }
  const double inv = cell > 0.0 ? 1.0 / cell : 0.0;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(end - begin);
  for (std::size_t i = begin; i < end; ++i) {
    std::uint32_t c[3] = {0, 0, 0};
    for (int k = 0; k < dim; ++k)
      c[k] = static_cast<std::uint32_t>(std::clamp(std::floor((p.x[k][i] - lo[k]) * inv), 0.0, max_cell));
    keyed[i - begin] = {morton_key(c, dim), static_cast<std::uint32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());  // pairs are unique (index breaks ties): a total order
  std::vector<std::uint32_t> order(keyed.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
  return order;
}

}  // namespace sph
