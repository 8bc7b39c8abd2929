// Building the Barnes-Hut tree (gravity/barnes_hut.h): the cells split until they hold leaf_size
// particles, then each cell's mass, centre of mass, second moments, bmax and hmax, bottom up.
#include "gravity/barnes_hut.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sph::gravity {
namespace {

/// Cells deeper than this are leaves whatever they hold (coincident particles).
constexpr std::uint8_t kMaxDepth = 60;

}  // namespace

void BarnesHutTree::build(const Sources& s, std::uint32_t leaf_size) {
  const std::size_t n = s.n;
  nodes_.clear();
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0u);
  scratch_.resize(n);
  if (n == 0) return;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int k = 0; k < s.dim; ++k) {
    lo[k] = *std::min_element(s.x[k].begin(), s.x[k].begin() + static_cast<std::ptrdiff_t>(n));
    hi[k] = *std::max_element(s.x[k].begin(), s.x[k].begin() + static_cast<std::ptrdiff_t>(n));
  }
  TreeNode root{};
  double extent = 0.0;
  for (int k = 0; k < s.dim; ++k) extent = std::max(extent, hi[k] - lo[k]);
  root.half = 0.5 * extent * (1.0 + 1e-12) + 1e-300;  // every particle strictly inside
  for (int k = 0; k < 3; ++k) root.center[k] = 0.5 * (lo[k] + hi[k]);
  root.first = 0;
  root.count = static_cast<std::uint32_t>(n);
  nodes_.push_back(root);
  split(s, 0, std::max<std::uint32_t>(leaf_size, 1));
  moments(s, 0);
  // the particles in tree order: a leaf's pairs and consecutive walks read contiguous memory
  for (int k = 0; k < 3; ++k) {
    sx_[k].resize(n);
    for (std::size_t q = 0; q < n; ++q) sx_[k][q] = s.x[k][order_[q]];
  }
  sm_.resize(n);
  sh_.resize(n);
  for (std::size_t q = 0; q < n; ++q) { sm_[q] = s.m[order_[q]]; sh_[q] = s.h[order_[q]]; }
}

void BarnesHutTree::split(const Sources& s, std::uint32_t node, std::uint32_t leaf_size) {
  const TreeNode nd = nodes_[node];  // a copy: nodes_ grows below
  if (nd.count <= leaf_size || nd.depth >= kMaxDepth) return;
  const int children = 1 << s.dim;
  auto octant = [&](std::uint32_t i) {
    int o = 0;
    for (int k = 0; k < s.dim; ++k) o |= (s.x[k][i] >= nd.center[k] ? 1 : 0) << k;
    return o;
  };
  std::uint32_t count[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) ++count[octant(order_[q])];
  std::uint32_t start[8] = {0, 0, 0, 0, 0, 0, 0, 0}, at = nd.first;
  for (int o = 0; o < children; ++o) { start[o] = at; at += count[o]; }
  std::uint32_t fill[8];
  std::copy(start, start + 8, fill);
  for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) scratch_[fill[octant(order_[q])]++] = order_[q];
  std::copy(scratch_.begin() + nd.first, scratch_.begin() + nd.first + nd.count, order_.begin() + nd.first);
  const auto first_child = static_cast<std::uint32_t>(nodes_.size());
  std::uint8_t made = 0;
  for (int o = 0; o < children; ++o) {
    if (count[o] == 0) continue;
    TreeNode c{};
    c.half = 0.5 * nd.half;
    for (int k = 0; k < 3; ++k)
      c.center[k] = k < s.dim ? nd.center[k] + ((o >> k) & 1 ? c.half : -c.half) : nd.center[k];
    c.first = start[o];
    c.count = count[o];
    c.depth = static_cast<std::uint8_t>(nd.depth + 1);
    nodes_.push_back(c);
    ++made;
  }
  nodes_[node].child = first_child;
  nodes_[node].n_child = made;
  for (std::uint32_t c = first_child; c < first_child + made; ++c) split(s, c, leaf_size);
}

void BarnesHutTree::moments(const Sources& s, std::uint32_t node) {
  TreeNode& nd = nodes_[node];
  double M = 0.0, c[3] = {0, 0, 0}, S[6] = {0, 0, 0, 0, 0, 0}, hmax = 0.0, bmax = 0.0;
  if (nd.n_child == 0) {
    for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) {
      const std::uint32_t i = order_[q];
      M += s.m[i];
      for (int k = 0; k < 3; ++k) c[k] += s.m[i] * s.x[k][i];
      hmax = std::max(hmax, s.h[i]);
    }
    for (int k = 0; k < 3; ++k) c[k] = M > 0.0 ? c[k] / M : nd.center[k];
    for (std::uint32_t q = nd.first; q < nd.first + nd.count; ++q) {
      const std::uint32_t i = order_[q];
      const double d[3] = {s.x[0][i] - c[0], s.x[1][i] - c[1], s.x[2][i] - c[2]};
      S[0] += s.m[i] * d[0] * d[0]; S[1] += s.m[i] * d[0] * d[1]; S[2] += s.m[i] * d[0] * d[2];
      S[3] += s.m[i] * d[1] * d[1]; S[4] += s.m[i] * d[1] * d[2]; S[5] += s.m[i] * d[2] * d[2];
      bmax = std::max(bmax, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
  } else {
    const std::uint32_t first = nd.child, count = nd.n_child;  // nd stays valid: no growth below
    for (std::uint32_t ch = first; ch < first + count; ++ch) moments(s, ch);
    for (std::uint32_t ch = first; ch < first + count; ++ch) {
      const TreeNode& cn = nodes_[ch];
      M += cn.mass;
      for (int k = 0; k < 3; ++k) c[k] += cn.mass * cn.com[k];
      hmax = std::max(hmax, cn.hmax);
    }
    for (int k = 0; k < 3; ++k) c[k] = M > 0.0 ? c[k] / M : nd.center[k];
    for (std::uint32_t ch = first; ch < first + count; ++ch) {
      const TreeNode& cn = nodes_[ch];
      const double d[3] = {cn.com[0] - c[0], cn.com[1] - c[1], cn.com[2] - c[2]};  // parallel-axis theorem
      S[0] += cn.S[0] + cn.mass * d[0] * d[0]; S[1] += cn.S[1] + cn.mass * d[0] * d[1];
      S[2] += cn.S[2] + cn.mass * d[0] * d[2]; S[3] += cn.S[3] + cn.mass * d[1] * d[1];
      S[4] += cn.S[4] + cn.mass * d[1] * d[2]; S[5] += cn.S[5] + cn.mass * d[2] * d[2];
      bmax = std::max(bmax, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + cn.bmax);
    }
    // the farthest corner of the cell also bounds every particle: keep the tighter bound
    double corner2 = 0.0;
    for (int k = 0; k < s.dim; ++k) {
      const double e = std::abs(c[k] - nd.center[k]) + nd.half;
      corner2 += e * e;
    }
    bmax = std::min(bmax, std::sqrt(corner2));
  }
  nd.mass = M;
  for (int k = 0; k < 3; ++k) nd.com[k] = c[k];
  std::copy(S, S + 6, nd.S);
  nd.bmax = bmax;
  nd.hmax = hmax;
  double delta2 = 0.0;
  for (int k = 0; k < 3; ++k) delta2 += (c[k] - nd.center[k]) * (c[k] - nd.center[k]);
  nd.delta = std::sqrt(delta2);
}

}  // namespace sph::gravity
