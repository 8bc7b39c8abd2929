// Ghost particles for periodic boundaries (seed 000 §4.1.1) and mirror walls (seed 000 §4.2.1).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include "core/parallel.h"
#include <vector>

#include "sph/domain.h"

namespace sph {
namespace {

struct Ghost {
  std::array<double, 3> x;
  std::uint32_t src;
  std::uint8_t flip;
  std::array<double, 3> offset;  ///< x[k] = (flipped on k ? -x_src[k] : x_src[k]) + offset[k]
};

}  // namespace

void make_ghosts(const Domain& d, double margin, Particles& p) {
  const std::size_t n = p.size();
  const std::size_t most = kMaxGhostsPerParticle * n + 512;
  std::vector<Ghost> g;
  auto too_many = [&](int k) {
    char what[200];
    std::snprintf(what, sizeof what, "the ghost layer (margin %.3g along axis %d of length %.3g) would hold over %zu "
                  "copies of the %zu particles: h has outgrown the box", margin, k, d.length(k), kMaxGhostsPerParticle, n);
    throw GhostOverflow(what);
  };
  // Each axis sees the real particles and the ghosts made for the previous axes (this fills corners).
  auto visit = [&](std::size_t count, auto&& fn) {
    for (std::size_t j = 0; j < count; ++j) {
      if (j < n) fn(Ghost{{p.x[0][j], p.x[1][j], p.x[2][j]}, static_cast<std::uint32_t>(j), 0, {0.0, 0.0, 0.0}});
      else fn(g[j - n]);
    }
  };
  for (int k = 0; k < p.dim(); ++k) {
    const std::size_t count = n + g.size();
    const double lo = d.lo[k], hi = d.hi[k], L = hi - lo;
    if (d.bc[k] == Boundary::Periodic) {
      const int images = static_cast<int>(std::ceil(margin / L));
      // every particle gets about 2 margin/L images on this axis: refuse before allocating them
      if (!(2.0 * margin / L * static_cast<double>(count) <= static_cast<double>(most))) too_many(k);
      visit(count, [&](Ghost s) {
        const double xk = s.x[k];
        for (int m = 1; m <= images; ++m) {
          if (xk + m * L < hi + margin) { Ghost c = s; c.offset[k] = m * L; c.x[k] = xk + c.offset[k]; g.push_back(c); }
          if (xk - m * L > lo - margin) { Ghost c = s; c.offset[k] = -(m * L); c.x[k] = xk + c.offset[k]; g.push_back(c); }
        }
      });
    } else if (d.bc[k] == Boundary::Wall) {
      const std::uint8_t bit = static_cast<std::uint8_t>(1u << k);
      visit(count, [&](Ghost s) {
        const double xk = s.x[k];
        if (xk - lo < margin) { Ghost c = s; c.offset[k] = 2.0 * lo; c.x[k] = -xk + c.offset[k]; c.flip ^= bit; g.push_back(c); }
        if (hi - xk < margin) { Ghost c = s; c.offset[k] = 2.0 * hi; c.x[k] = -xk + c.offset[k]; c.flip ^= bit; g.push_back(c); }
      });
    }
  }
  if (g.size() > most) too_many(p.dim() - 1);
  p.resize_total(n + g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    for (int k = 0; k < 3; ++k) p.x[k][n + i] = g[i].x[k];
    p.ghost_src[i] = g[i].src;
    p.ghost_flip[i] = g[i].flip;
    for (int k = 0; k < 3; ++k) p.ghost_offset[k][i] = g[i].offset[k];
    p.id[n + i] = p.id[g[i].src];
    p.kind[n + i] = p.kind[g[i].src];
  }
}

void update_ghost_positions(Particles& p) {
  const std::size_t n = p.size(), G = p.ghost_src.size();
  for (int k = 0; k < p.dim(); ++k) {
    double* x = p.x[k].data();
    const double* off = p.ghost_offset[k].data();
    const std::uint8_t bit = static_cast<std::uint8_t>(1u << k);
#pragma omp parallel for schedule(static) if (G >= kParallelMin)
    for (std::size_t g = 0; g < G; ++g) {
      const double xs = x[p.ghost_src[g]];
      x[n + g] = (p.ghost_flip[g] & bit ? -xs : xs) + off[g];
    }
  }
}

void copy_ghost_velocity(Particles& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < p.ghost_src.size(); ++i) {
    const std::uint32_t s = p.ghost_src[i];
    for (int k = 0; k < 3; ++k) {
      const double sign = (p.ghost_flip[i] >> k) & 1u ? -1.0 : 1.0;
      p.v[k][n + i] = sign * p.v[k][s];
    }
  }
}

void copy_ghost_field(Particles& p, Field f) {
  auto& a = p[f];
  const std::size_t n = p.size();
  const std::uint8_t axes = info(f).flip_axes;
  if (axes == 0) {
    for (std::size_t i = 0; i < p.ghost_src.size(); ++i) a[n + i] = a[p.ghost_src[i]];
    return;
  }
  // A vector or tensor component changes sign under an odd number of mirrors of its axes.
  for (std::size_t i = 0; i < p.ghost_src.size(); ++i) {
    const bool odd = std::popcount(static_cast<unsigned>(axes & p.ghost_flip[i])) & 1u;
    a[n + i] = odd ? -a[p.ghost_src[i]] : a[p.ghost_src[i]];
  }
}

void copy_ghost_fields(Particles& p, FieldSet fields) {
  fields.for_each([&](Field f) { copy_ghost_field(p, f); });
}

WallCrossings apply_boundaries(const Domain& d, Particles& p) {
  const std::size_t n = p.size();
  WallCrossings w;
  for (int k = 0; k < p.dim(); ++k) {
    const double lo = d.lo[k], hi = d.hi[k], L = hi - lo;
    auto& x = p.x[k];
    auto& v = p.v[k];
    if (d.bc[k] == Boundary::Periodic) {
#pragma omp parallel for if (n >= kParallelMin)
      for (std::size_t i = 0; i < n; ++i) {
        if (x[i] < lo || x[i] >= hi) {
          x[i] = lo + std::fmod(x[i] - lo, L);
          if (x[i] < lo) x[i] += L;
          if (x[i] >= hi) x[i] -= L;  // fmod rounding at the upper edge
        }
      }
    } else if (d.bc[k] == Boundary::Wall) {
      std::size_t reflected = 0, escaped = 0, first_r = SIZE_MAX, first_e = SIZE_MAX;
#pragma omp parallel for reduction(+ : reflected, escaped) reduction(min : first_r, first_e) if (n >= kParallelMin)
      for (std::size_t i = 0; i < n; ++i) {
        if (!(x[i] < lo) && !(x[i] > hi)) continue;
        x[i] = x[i] < lo ? 2.0 * lo - x[i] : 2.0 * hi - x[i];
        v[i] = -v[i];
        ++reflected;
        first_r = std::min(first_r, i);
        if (x[i] < lo || x[i] > hi) { ++escaped; first_e = std::min(first_e, i); }
      }
      w.reflected += reflected;
      w.escaped += escaped;
      w.first_reflected = std::min(w.first_reflected, first_r);
      w.first_escaped = std::min(w.first_escaped, first_e);
    }
  }
  return w;
}

}  // namespace sph
