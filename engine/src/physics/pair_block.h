// The interacting neighbours of one particle gathered into contiguous arrays before the pair maths
// (measured by calibration_bench and step_cost_bench). A list built with a skin holds about 1.7
// candidates per interacting pair: each candidate is written and kept or not by its distance test (no branch to mispredict). The pair maths then runs
// over plain arrays in loops without reductions, which the compiler vectorises (`omp simd`), and the
// sums are taken afterwards in list order: the result is the same bit for bit whatever the vector width
// and the same as a scalar loop over the list.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/parallel.h"
#include "sph/particles.h"

namespace sph {

/// One thread's pairs of particle i, in list order: index j, r_ij = x_i - x_j [length] and |r_ij|^2,
/// plus `Columns` scratch columns for a loop's own per-pair values (forces, heating, ...).
template <int Columns>
struct PairBlock {
  std::size_t n = 0;  ///< pairs held
  std::vector<std::uint32_t> j;
  std::vector<double> dx, dy, dz, r2;
  std::array<std::vector<double>, Columns> col;

  /// Room for m candidates in every array.
  void fit(std::size_t m) {
    if (j.size() >= m) return;
    const std::size_t cap = std::max<std::size_t>(2 * m, 64);
    j.resize(cap);
    dx.resize(cap); dy.resize(cap); dz.resize(cap); r2.resize(cap);
    for (auto& c : col) c.resize(cap);
  }
  double* operator[](int c) { return col[static_cast<std::size_t>(c)].data(); }
};

/// Fills `b` with the j of `nb` that keep(j, |r_ij|^2) accepts, in list order; returns their count.
/// Every candidate is written and counted or not by the test (no branch). ThreeD = false (1D and 2D,
/// where z = 0) neither reads z nor writes b.dz: a loop built for it must not read b.dz.
template <int Columns, bool ThreeD = true, class Keep>
std::size_t compact_pairs(const Particles& p, std::size_t i, std::span<const std::uint32_t> nb, Keep keep,
                          PairBlock<Columns>& b) {
  b.fit(nb.size());
  const double* x = p.x[0].data();
  const double* y = p.x[1].data();
  const double* z = p.x[2].data();
  const double xi = x[i], yi = y[i], zi = ThreeD ? z[i] : 0.0;
  std::uint32_t* J = b.j.data();
  double* DX = b.dx.data();
  double* DY = b.dy.data();
  double* DZ = b.dz.data();
  double* RR = b.r2.data();
  std::size_t n = 0;
  for (const std::uint32_t jj : nb) {
    const double dx = xi - x[jj], dy = yi - y[jj];
    double r2 = dx * dx + dy * dy;
    if constexpr (ThreeD) {
      const double dz = zi - z[jj];
      r2 += dz * dz;
      DZ[n] = dz;
    }
    J[n] = jj;
    DX[n] = dx;
    DY[n] = dy;
    RR[n] = r2;
    n += keep(jj, r2) ? 1 : 0;
  }
  b.n = n;
  return n;
}

/// R2 = (support h)^2 of every particle, ghosts included: the reach gather_pairs tests against.
inline void support_radii2(const Particles& p, double support, std::vector<double>& R2) {
  const double* h = p[Field::H].data();
  R2.resize(p.total());
#pragma omp parallel for schedule(static) if (p.size() >= kParallelMin)
  for (std::size_t j = 0; j < R2.size(); ++j) {
    const double R = support * h[j];
    R2[j] = R * R;
  }
}

/// The j of `nb` with 0 < |r_ij|^2 < max(R2_i, R2_j), R2 = (support h)^2 per particle (ghosts
/// included): the pairs within support max(h_i, h_j). Without wall particles when skip_walls.
/// ThreeD = false only where z = 0 (see compact_pairs).
template <int Columns, bool ThreeD = true>
std::size_t gather_pairs(const Particles& p, const double* R2, std::size_t i, std::span<const std::uint32_t> nb,
                         bool skip_walls, PairBlock<Columns>& b) {
  const double R2i = R2[i];
  const std::uint8_t* kind = p.kind.data();
  if (skip_walls)  // the test chosen once per call
    return compact_pairs<Columns, ThreeD>(p, i, nb, [=](std::uint32_t j, double r2) {
      return (r2 < std::max(R2i, R2[j])) & (r2 > 0.0) & (kind[j] == 0);
    }, b);
  return compact_pairs<Columns, ThreeD>(
      p, i, nb, [=](std::uint32_t j, double r2) { return (r2 < std::max(R2i, R2[j])) & (r2 > 0.0); }, b);
}

/// The j of `nb` with |r_ij|^2 < R2 (i itself included), without wall particles when skip_walls.
template <int Columns>
std::size_t gather_within(const Particles& p, std::size_t i, std::span<const std::uint32_t> nb, double R2,
                          bool skip_walls, PairBlock<Columns>& b) {
  const std::uint8_t* kind = p.kind.data();
  if (skip_walls)
    return compact_pairs(p, i, nb, [=](std::uint32_t j, double r2) { return (r2 < R2) & (kind[j] == 0); }, b);
  return compact_pairs(p, i, nb, [=](std::uint32_t, double r2) { return r2 < R2; }, b);
}

}  // namespace sph
