// Cell-sorted neighbour search (seed 002 §3.2: the head/next linked list, stored as sorted arrays).
#include <algorithm>
#include "core/parallel.h"
#include <cmath>
#include <limits>
#include <omp.h>

#include "cell_grid.h"

namespace sph {

/// Cell size: radius * h_max in 3D; smaller in 1D/2D when h varies a lot (shock tubes), so that a particle
/// with a small h does not test the many candidates inside a large-h support. Cells out of reach of
/// both h_i and the cell's largest h are skipped, so the result does not depend on the cell size.
void build_grid(const Particles& p, const std::vector<double>& h, double radius, CellGrid& g) {
  const std::size_t N = p.total();
  g.dim = p.dim();
  double hmin = 1e300, hmax = 0.0;
  for (std::size_t i = 0; i < N; ++i) { hmin = std::min(hmin, h[i]); hmax = std::max(hmax, h[i]); }
  // Cells of half the search radius (at most: a quarter or a third where h varies a lot): the cells a
  // particle's stencil visits, minus those out of reach, cover about 1.8x the area of its search circle
  // in 2D, against 2.9x with cells of the full radius.
  const double shrink[3] = {4.0, 3.0, 2.0};  // max stencil half-width per dimension
  const double cell = radius * std::max(0.5 * hmin, hmax / shrink[g.dim - 1]);
  // Cap the number of cells so that a sparse cloud cannot allocate a huge grid.
  const double max_cells = 4.0 * static_cast<double>(N) + 64.0;
  const double per_axis = std::pow(max_cells, 1.0 / g.dim);
  for (int k = 0; k < 3; ++k) { g.lo[k] = 0.0; g.n[k] = 1; g.inv[k] = 0.0; g.reach[k] = 0; g.size[k] = 1e300; }
  for (int k = 0; k < g.dim; ++k) {
    const auto [mn, mx] = std::minmax_element(p.x[k].begin(), p.x[k].end());
    g.lo[k] = *mn;
    const double extent = *mx - *mn;
    int cells = cell > 0.0 ? static_cast<int>(std::floor(extent / cell)) : 1;
    cells = std::clamp(cells, 1, static_cast<int>(std::max(1.0, per_axis)));
    g.n[k] = cells;
    g.inv[k] = extent > 0.0 ? cells / extent : 0.0;
    g.size[k] = extent > 0.0 ? extent / cells : 1e300;
    g.reach[k] = extent > 0.0 ? std::min(cells, static_cast<int>(std::ceil(radius * hmax / g.size[k]))) : 0;
  }
  const std::size_t ncell = static_cast<std::size_t>(g.n[0]) * g.n[1] * g.n[2];
  auto& cell_of = g.cell_of;
  cell_of.resize(N);
  g.start.assign(ncell + 1, 0);
  g.cell_hmax.assign(ncell, 0.0);
#pragma omp parallel for schedule(static) if (N >= kParallelMin)
  for (std::size_t i = 0; i < N; ++i) {
    std::size_t c = 0;
    for (int k = g.dim - 1; k >= 0; --k) c = c * g.n[k] + g.coord(p.x[k][i], k);
    cell_of[i] = static_cast<std::uint32_t>(c);
  }
  for (std::size_t i = 0; i < N; ++i) {
    const std::uint32_t c = cell_of[i];
    ++g.start[c + 1];
    g.cell_hmax[c] = std::max(g.cell_hmax[c], h[i]);
  }
  for (std::size_t c = 0; c < ncell; ++c) g.start[c + 1] += g.start[c];
  auto& fill = g.fill;
  fill.assign(g.start.begin(), g.start.end() - 1);
  g.order.resize(N);
  for (std::size_t i = 0; i < N; ++i) g.order[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  g.sx.resize(N); g.sy.resize(N); g.sz.resize(N); g.sh.resize(N);
#pragma omp parallel for schedule(static) if (N >= kParallelMin)
  for (std::size_t s = 0; s < N; ++s) {
    const std::uint32_t i = g.order[s];
    g.sx[s] = p.x[0][i]; g.sy[s] = p.x[1][i]; g.sz[s] = p.x[2][i]; g.sh[s] = h[i];
  }
}



void build_neighbours(const Particles& p, const std::vector<double>& h, double radius, NeighbourList& out) {
  const std::size_t n = p.size();
  if (!out.work) out.work = std::make_shared<NeighbourWorkspace>();
  CellGrid& g = out.work->grid;
  build_grid(p, h, radius, g);
  // One pass: each thread gathers the lists of a contiguous block of particles; the blocks are then
  // concatenated in block order, so the result is the same for any thread count. One thread gathers
  // straight into the list. With a team, each thread fills a buffer of its own stack (the vector objects
  // of a shared array would share a cache line: false sharing) that is freed once copied, so between
  // builds only the list itself is kept.
  out.offset.assign(n + 1, 0);
  auto& base = out.work->base;
  if (!(n >= kParallelMin && omp_get_max_threads() > 1)) {
    std::vector<std::uint32_t>& list = out.index;
    list.resize(std::max<std::size_t>(list.capacity(), 1024));  // kept from the last build: no new pages
    std::size_t used = 0;
    for (std::size_t i = 0; i < n; ++i) {
      out.offset[i] = static_cast<std::uint32_t>(used);
      used = gather_neighbours(g, p.x[0][i], p.x[1][i], p.x[2][i], h[i], radius, list, used);
    }
    list.resize(used);
    out.offset[n] = static_cast<std::uint32_t>(used);
    return;
  }
#pragma omp parallel
  {
    const int T = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    base.assign(T + 1, 0);
    const std::size_t b = n * t / T, e = n * (t + 1) / T;
    // room for the block at the mean list length of the last build (grown if needed)
    const double mean = n > 0 && !out.index.empty() ? static_cast<double>(out.index.size()) / n : 32.0;
    std::vector<std::uint32_t> local(static_cast<std::size_t>(1.25 * mean * (e - b)) + 1024);
    std::size_t used = 0;
    for (std::size_t i = b; i < e; ++i) {
      out.offset[i] = static_cast<std::uint32_t>(used);  // relative to the block for now
      used = gather_neighbours(g, p.x[0][i], p.x[1][i], p.x[2][i], h[i], radius, local, used);
    }
    base[t + 1] = used;
#pragma omp barrier
#pragma omp single
    {
      for (int k = 0; k < T; ++k) base[k + 1] += base[k];  // sizes -> offsets
      out.index.resize(base[T]);
      out.offset[n] = static_cast<std::uint32_t>(base[T]);
    }
    std::copy(local.begin(), local.begin() + static_cast<std::ptrdiff_t>(used),
              out.index.begin() + static_cast<std::ptrdiff_t>(base[t]));
    for (std::size_t i = b; i < e; ++i) out.offset[i] += static_cast<std::uint32_t>(base[t]);
  }
}

void filter_neighbours(const Particles& p, const std::vector<double>& h, double radius, const NeighbourList& wide,
                       NeighbourList& out) {
  const std::size_t n = wide.offset.size() - 1;
  const double* x = p.x[0].data();
  const double* y = p.x[1].data();
  const double* z = p.x[2].data();
  const double* hh = h.data();
  auto keep = [&](std::size_t i, std::uint32_t j) {
    const double dx = x[i] - x[j], dy = y[i] - y[j], dz = z[i] - z[j];
    const double R = radius * std::max(hh[i], hh[j]);
    return dx * dx + dy * dy + dz * dz < R * R;
  };
  // Two branch-free passes, each a parallel loop over particles: count, then (after the prefix sum) fill.
  // Each list keeps its order, so the result is the same for any thread count.
  out.offset.assign(n + 1, 0);
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t count = 0;
    for (std::uint32_t s = wide.offset[i], e = wide.offset[i + 1]; s < e; ++s) count += keep(i, wide.index[s]) ? 1 : 0;
    out.offset[i + 1] = count;
  }
  for (std::size_t i = 0; i < n; ++i) out.offset[i + 1] += out.offset[i];
  out.index.resize(out.offset[n]);
  std::uint32_t* buf = out.index.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t used = out.offset[i];
    const std::uint32_t last = out.offset[i + 1];
    for (std::uint32_t s = wide.offset[i], e = wide.offset[i + 1]; s < e && used < last; ++s) {
      const std::uint32_t j = wide.index[s];
      buf[used] = j;
      used += keep(i, j) ? 1 : 0;
    }
  }
}

void permute_neighbours(NeighbourList& nl, std::span<const std::uint32_t> order) {
  const std::size_t n = order.size();
  if (nl.offset.size() != n + 1) return;  // no lists yet
  std::vector<std::uint32_t> slot(n);
  for (std::size_t k = 0; k < n; ++k) slot[order[k]] = static_cast<std::uint32_t>(k);
  std::vector<std::uint32_t> offset(n + 1, 0), index(nl.index.size());
  for (std::size_t k = 0; k < n; ++k) offset[k + 1] = offset[k] + (nl.offset[order[k] + 1] - nl.offset[order[k]]);
  // each new list a copy of an old one, renumbered: the same result for any team
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t b = nl.offset[order[k]], e = nl.offset[order[k] + 1];
    for (std::uint32_t s = b; s < e; ++s) {
      const std::uint32_t j = nl.index[s];
      index[offset[k] + (s - b)] = j < n ? slot[j] : j;
    }
  }
  nl.offset.swap(offset);
  nl.index.swap(index);
  // the kept grid too, so that lists gathered later (gather_neighbour_rows) come renumbered alike
  if (nl.work)
    for (std::uint32_t& o : nl.work->grid.order)
      if (o < n) o = slot[o];
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
