// The cell grid of the neighbour search (cell_list.cpp): particles sorted by cell, and the gather of one
// particle's list from it. Shared by the whole-list build and the row-by-row gather (cell_list_rows.cpp).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "sph/neighbours.h"

namespace sph {

/// Particles sorted by cell (stable: index order inside a cell), with the cell grid geometry.
struct CellGrid {
  int dim = 1;
  std::array<double, 3> lo{0, 0, 0};
  std::array<double, 3> inv{1, 1, 1};  ///< 1 / cell size per axis
  std::array<int, 3> n{1, 1, 1};       ///< cells per axis
  std::vector<std::uint32_t> start;    ///< first sorted slot of each cell (size cells+1)
  std::vector<std::uint32_t> order;    ///< sorted slot -> particle index
  std::vector<double> sx, sy, sz, sh;  ///< positions and h in sorted order (cache friendly)
  std::vector<double> cell_hmax;       ///< largest h in each cell (prunes cells out of reach)
  std::vector<std::uint32_t> cell_of, fill;  ///< scratch of the counting sort
  std::array<int, 3> reach{1, 1, 1};   ///< stencil half-width in cells per axis (covers radius * h_max)
  std::array<double, 3> size{0, 0, 0}; ///< cell size per axis

  int coord(double x, int k) const {
    const int c = static_cast<int>((x - lo[k]) * inv[k]);
    return std::clamp(c, 0, n[k] - 1);
  }
};

/// Sorts the particles (ghosts included) into a grid for searches within radius * max(h_i, h_j).
void build_grid(const Particles& p, const std::vector<double>& h, double radius, CellGrid& g);

/// Distance from coordinate x to the slab of cell c along axis k (0 inside).
inline double gap(const CellGrid& g, int k, int c, double x) {
  const double lo = g.lo[k] + c * g.size[k], hi = lo + g.size[k];
  return x < lo ? lo - x : (x > hi ? x - hi : 0.0);
}

/// Appends to out (from slot `used` on) every particle j within radius*max(h_i,h_j) of particle i, in a
/// fixed order (cell by cell, index order inside a cell), and returns the new `used`. Each candidate is
/// written and kept or not by its distance test, with no branch to mispredict; `out` grows as needed.
/// The grid's arrays are read through local pointers, which the stores cannot alias.
/// Particle i sits at (xi, yi, zi), its position when the grid was built.
inline std::size_t gather_neighbours(const CellGrid& g, double xi, double yi, double zi, double hi, double radius,
                                     std::vector<std::uint32_t>& out, std::size_t used) {
  const double* const sx = g.sx.data();
  const double* const sy = g.sy.data();
  const double* const sz = g.sz.data();
  const double* const sh = g.sh.data();
  const std::uint32_t* const order = g.order.data();
  const std::uint32_t* const start = g.start.data();
  const double* const cell_hmax = g.cell_hmax.data();
  std::uint32_t* buf = out.data();
  int c[3] = {0, 0, 0};
  const double xk[3] = {xi, yi, zi};
  for (int k = 0; k < g.dim; ++k) c[k] = g.coord(xk[k], k);
  int lo[3], up[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::max(c[k] - g.reach[k], 0);
    up[k] = std::min(c[k] + g.reach[k], g.n[k] - 1);
  }
  for (int c2 = lo[2]; c2 <= up[2]; ++c2) {
    const double g2 = g.dim > 2 ? gap(g, 2, c2, zi) : 0.0;
    for (int c1 = lo[1]; c1 <= up[1]; ++c1) {
      const double g1 = g.dim > 1 ? gap(g, 1, c1, yi) : 0.0;
      const std::size_t row = (static_cast<std::size_t>(c2) * g.n[1] + c1) * g.n[0];
      for (int c0 = lo[0]; c0 <= up[0]; ++c0) {
        const std::size_t cell = row + c0;
        const double g0 = gap(g, 0, c0, xi);
        const double reach = radius * std::max(hi, cell_hmax[cell]);
        if (g0 * g0 + g1 * g1 + g2 * g2 >= reach * reach) continue;  // nobody in this cell is in range
        const std::uint32_t b = start[cell], e = start[cell + 1];
        if (used + (e - b) > out.size()) {  // rare: room for the whole cell
          out.resize(used + (e - b) + out.size() / 4);
          buf = out.data();
        }
        for (std::uint32_t s = b; s < e; ++s) {
          const double dx = xi - sx[s], dy = yi - sy[s], dz = zi - sz[s];
          const double R = radius * std::max(hi, sh[s]);
          buf[used] = order[s];
          used += dx * dx + dy * dy + dz * dz < R * R ? 1 : 0;
        }
      }
    }
  }
  return used;
}

struct NeighbourWorkspace {
  CellGrid grid;
  std::vector<std::size_t> base;
};

}  // namespace sph
