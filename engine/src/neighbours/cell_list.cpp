// Cell-sorted neighbour search (seed 002 §3.2: the head/next linked list, stored as sorted arrays).
#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/neighbours.h"

namespace sph {
namespace {

/// Particles sorted by cell (stable: index order inside a cell), with the cell grid geometry.
struct Grid {
  int dim = 1;
  std::array<double, 3> lo{0, 0, 0};
  std::array<double, 3> inv{1, 1, 1};  ///< 1 / cell size per axis
  std::array<int, 3> n{1, 1, 1};       ///< cells per axis
  std::vector<std::uint32_t> start;    ///< first sorted slot of each cell (size cells+1)
  std::vector<std::uint32_t> order;    ///< sorted slot -> particle index
  std::vector<double> sx, sy, sz, sh;  ///< positions and h in sorted order (cache friendly)

  int coord(double x, int k) const {
    const int c = static_cast<int>((x - lo[k]) * inv[k]);
    return std::clamp(c, 0, n[k] - 1);
  }
};

void build_grid(const Particles& p, const std::vector<double>& h, double cell, Grid& g) {
  const std::size_t N = p.total();
  g.dim = p.dim();
  std::array<double, 3> hi{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    g.lo[k] = 0.0;
    g.n[k] = 1;
    g.inv[k] = 0.0;
  }
  // Cap the number of cells so that a sparse cloud cannot allocate a huge grid.
  const double max_cells = 4.0 * static_cast<double>(N) + 64.0;
  const double per_axis = std::pow(max_cells, 1.0 / g.dim);
  for (int k = 0; k < g.dim; ++k) {
    const auto [mn, mx] = std::minmax_element(p.x[k].begin(), p.x[k].end());
    g.lo[k] = *mn;
    hi[k] = *mx;
    const double extent = hi[k] - g.lo[k];
    int cells = cell > 0.0 ? static_cast<int>(std::floor(extent / cell)) : 1;
    cells = std::clamp(cells, 1, static_cast<int>(std::max(1.0, per_axis)));
    g.n[k] = cells;
    g.inv[k] = extent > 0.0 ? cells / extent : 0.0;
  }
  const std::size_t ncell = static_cast<std::size_t>(g.n[0]) * g.n[1] * g.n[2];
  std::vector<std::uint32_t> cell_of(N);
  g.start.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < N; ++i) {
    std::size_t c = 0;
    for (int k = g.dim - 1; k >= 0; --k) c = c * g.n[k] + g.coord(p.x[k][i], k);
    cell_of[i] = static_cast<std::uint32_t>(c);
    ++g.start[c + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) g.start[c + 1] += g.start[c];
  std::vector<std::uint32_t> fill(g.start.begin(), g.start.end() - 1);
  g.order.resize(N);
  for (std::size_t i = 0; i < N; ++i) g.order[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  g.sx.resize(N); g.sy.resize(N); g.sz.resize(N); g.sh.resize(N);
  for (std::size_t s = 0; s < N; ++s) {
    const std::uint32_t i = g.order[s];
    g.sx[s] = p.x[0][i]; g.sy[s] = p.x[1][i]; g.sz[s] = p.x[2][i]; g.sh[s] = h[i];
  }
}

/// Calls fn(j) for every particle j within radius*max(h_i,h_j) of particle i, in a fixed order.
template <class Fn>
void for_each_neighbour(const Grid& g, const Particles& p, const std::vector<double>& h, double radius,
                        std::size_t i, Fn&& fn) {
  const double xi = p.x[0][i], yi = p.x[1][i], zi = p.x[2][i], hi = h[i];
  int c[3] = {0, 0, 0};
  for (int k = 0; k < g.dim; ++k) c[k] = g.coord(p.x[k][i], k);
  const int lo2 = g.dim > 2 ? std::max(c[2] - 1, 0) : 0, hi2 = g.dim > 2 ? std::min(c[2] + 1, g.n[2] - 1) : 0;
  const int lo1 = g.dim > 1 ? std::max(c[1] - 1, 0) : 0, hi1 = g.dim > 1 ? std::min(c[1] + 1, g.n[1] - 1) : 0;
  const int lo0 = std::max(c[0] - 1, 0), hi0 = std::min(c[0] + 1, g.n[0] - 1);
  for (int c2 = lo2; c2 <= hi2; ++c2)
    for (int c1 = lo1; c1 <= hi1; ++c1) {
      // cells c0 = lo0..hi0 are contiguous in the sorted arrays
      const std::size_t row = (static_cast<std::size_t>(c2) * g.n[1] + c1) * g.n[0];
      const std::uint32_t s0 = g.start[row + lo0], s1 = g.start[row + hi0 + 1];
      for (std::uint32_t s = s0; s < s1; ++s) {
        const double dx = xi - g.sx[s], dy = yi - g.sy[s], dz = zi - g.sz[s];
        const double R = radius * std::max(hi, g.sh[s]);
        if (dx * dx + dy * dy + dz * dz < R * R) fn(g.order[s]);
      }
    }
}

}  // namespace

void build_neighbours(const Particles& p, const std::vector<double>& h, double radius, NeighbourList& out) {
  const std::size_t n = p.size();
  double hmax = 0.0;
  for (std::size_t i = 0; i < p.total(); ++i) hmax = std::max(hmax, h[i]);
  Grid g;
  build_grid(p, h, radius * hmax, g);
  out.offset.assign(n + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t count = 0;
    for_each_neighbour(g, p, h, radius, i, [&](std::uint32_t) { ++count; });
    out.offset[i + 1] = count;
  }
  for (std::size_t i = 0; i < n; ++i) out.offset[i + 1] += out.offset[i];
  out.index.resize(out.offset[n]);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t* dst = out.index.data() + out.offset[i];
    for_each_neighbour(g, p, h, radius, i, [&](std::uint32_t j) { *dst++ = j; });
  }
}

void build_neighbours_brute(const Particles& p, const std::vector<double>& h, double radius, NeighbourList& out) {
  const std::size_t n = p.size();
  out.offset.assign(n + 1, 0);
  out.index.clear();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < p.total(); ++j) {
      const Vec3 d = p.pos(i) - p.pos(j);
      const double R = radius * std::max(h[i], h[j]);
      if (d.norm2() < R * R) out.index.push_back(static_cast<std::uint32_t>(j));
    }
    out.offset[i + 1] = static_cast<std::uint32_t>(out.index.size());
  }
}

}  // namespace sph
